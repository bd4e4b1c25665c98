/* load_sum.c — loads gathered from every rank in one order (engine/load_sum.h). */
#include <stdlib.h>
#include <string.h>
#include "engine/load_sum.h"
#include "base/mem.h"

void load_gather_init(struct load_gather *g, int n_ranks) {
  memset(g, 0, sizeof *g);
  g->counts = mem_calloc((size_t)n_ranks, sizeof(int), "loads per rank");
  g->displs = mem_calloc((size_t)n_ranks, sizeof(int), "loads per rank");
  MPI_Type_contiguous((int)sizeof(struct body_load), MPI_BYTE, &g->type);
  MPI_Type_commit(&g->type);
}

/* Order of the gathered loads: by target, then by fluid particle id, then by source. */
static int load_order(const void *a, const void *b) {
  const struct body_load *x = a, *y = b;
  if (x->wall != y->wall) return x->wall < y->wall ? -1 : 1;
  if (x->id != y->id) return x->id < y->id ? -1 : 1;
  return (x->source > y->source) - (x->source < y->source);
}

long load_gather_all(struct load_gather *g, struct body_loads *mine, MPI_Comm comm) {
  int n_ranks, count = (int)mine->n;
  MPI_Comm_size(comm, &n_ranks);
  MPI_Allgather(&count, 1, MPI_INT, g->counts, 1, MPI_INT, comm);
  long total = 0;
  for (int r = 0; r < n_ranks; r++) {
    g->displs[r] = (int)total;
    total += g->counts[r];
  }
  if (total > g->cap) {
    g->cap = total + total / 2;
    g->all = mem_realloc(g->all, mem_bytes((size_t)g->cap, sizeof *g->all, "gathered loads"), "gathered loads");
  }
  MPI_Allgatherv(mine->at, count, g->type, g->all, g->counts, g->displs, g->type, comm);
  qsort(g->all, (size_t)total, sizeof *g->all, load_order);
  mine->n = 0;
  return total;
}

void load_gather_free(struct load_gather *g) {
  if (g->counts) MPI_Type_free(&g->type);
  free(g->all);
  free(g->counts);
  free(g->displs);
  memset(g, 0, sizeof *g);
}
