/* partition_metis.c — METIS k-way partition of the occupied top cells on rank 0, broadcast to all.
 * Only cells holding particles enter the METIS graph (in a dam break most of the domain is
 * empty); every empty cell takes the rank of the nearest occupied one. The parts are numbered so
 * that the ranks keep as many of their particles as they can. */
#include <metis.h>
#include <stdio.h>
#include <stdlib.h>
#include "parallel/partition.h"
#include "base/mem.h"

#define METIS_SEED 42

/* Whether cell c holds particles. */
static int occupied(const int64_t *weight, long c) { return weight[c * PARTITION_CONSTRAINTS + WEIGHT_PARTICLES] > 0; }

/* The occupied cells numbered 0.. in cell order (vertex[c], -1 for an empty cell); their count. */
static long number_vertices(const struct grid *g, const int64_t *weight, idx_t *vertex) {
  long n = 0;
  for (long c = 0; c < g->n_cells; c++) vertex[c] = occupied(weight, c) ? (idx_t)n++ : -1;
  return n;
}

/* A METIS graph in CSR form: xadj[n_vertices + 1], adjncy[links], vwgt[n_vertices * constraints]. */
struct cell_graph {
  idx_t n_vertices, *xadj, *adjncy, *vwgt;
};

/* The graph of the occupied cells: each linked to its occupied neighbours among the 3^dim - 1
 * around it (adjncy sized exactly), weighing one more than the cell's work and particles, so
 * that no vertex weighs nothing. */
static struct cell_graph graph_of(const struct grid *g, const int64_t *weight, const idx_t *vertex,
                                  long n_vertices) {
  struct cell_graph G = {(idx_t)n_vertices, mem_calloc(n_vertices + 1, sizeof(idx_t), "METIS cell graph"), NULL,
                         mem_calloc(n_vertices * PARTITION_CONSTRAINTS + 1, sizeof(idx_t), "METIS cell weights")};
  long nb[27], links = 0;
  for (int pass = 0; pass < 2; pass++) {   /* count the links, then fill them */
    if (pass) G.adjncy = mem_calloc(links + 1, sizeof(idx_t), "METIS cell graph");
    links = 0;
    for (long c = 0; c < g->n_cells; c++) {
      if (vertex[c] < 0) continue;
      int n = grid_stencil(g, c, 1, nb);
      for (int j = 0; j < n; j++)
        if (nb[j] != c && vertex[nb[j]] >= 0) {
          if (pass) G.adjncy[links] = vertex[nb[j]];
          links++;
        }
      G.xadj[vertex[c] + 1] = (idx_t)links;
    }
  }
  for (long c = 0; c < g->n_cells; c++)
    for (int k = 0; vertex[c] >= 0 && k < PARTITION_CONSTRAINTS; k++)
      G.vwgt[vertex[c] * PARTITION_CONSTRAINTS + k] = (idx_t)weight[c * PARTITION_CONSTRAINTS + k] + 1;
  return G;
}

/* METIS on the graph into part[n_vertices]. Returns the METIS status. */
static int metis_parts(struct cell_graph *G, int n_parts, idx_t *part) {
  idx_t ncon = PARTITION_CONSTRAINTS, nparts = n_parts, objval;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_OBJTYPE] = METIS_OBJTYPE_CUT;
  options[METIS_OPTION_SEED] = METIS_SEED;
  options[METIS_OPTION_NUMBERING] = 0;
  real_t ubvec[PARTITION_CONSTRAINTS];
  for (int k = 0; k < PARTITION_CONSTRAINTS; k++) ubvec[k] = (real_t)partition_tolerance[k];
  return METIS_PartGraphKway(&G->n_vertices, &ncon, G->xadj, G->adjncy, G->vwgt, NULL, NULL, &nparts, NULL,
                             ubvec, options, &objval, part);
}

/* Give every empty cell (owner -1) the owner of the nearest occupied cell: a breadth-first
 * sweep from the occupied cells in cell order, so the result depends on nothing else. */
static void fill_empty(const struct grid *g, int *owner) {
  long *queue = mem_calloc(g->n_cells, sizeof(long), "empty cell sweep"), head = 0, tail = 0, nb[27];
  for (long c = 0; c < g->n_cells; c++)
    if (owner[c] >= 0) queue[tail++] = c;
  while (head < tail) {
    long c = queue[head++];
    int n = grid_stencil(g, c, 1, nb);
    for (int j = 0; j < n; j++)
      if (owner[nb[j]] < 0) {
        owner[nb[j]] = owner[c];
        queue[tail++] = nb[j];
      }
  }
  free(queue);
}

/* Particles a new part shares with a current rank: one entry per (part, rank) pair. */
struct overlap {
  int part, rank;
  int64_t particles;
};

static int by_pair(const void *a, const void *b) {
  const struct overlap *x = a, *y = b;
  if (x->part != y->part) return x->part < y->part ? -1 : 1;
  return x->rank < y->rank ? -1 : x->rank > y->rank;
}

static int by_particles(const void *a, const void *b) {
  const struct overlap *x = a, *y = b;
  if (x->particles != y->particles) return x->particles > y->particles ? -1 : 1;
  return by_pair(a, b);
}

/* The (part, rank) pairs of the n_vertices occupied cells with the particles they share,
 * largest first; *n their number. */
static struct overlap *overlaps(const struct grid *g, const int64_t *weight, long n_vertices, const int *part_of,
                                const int *rank_of, long *n) {
  struct overlap *o = mem_calloc(n_vertices + 1, sizeof(*o), "partition overlaps");
  long m = 0;
  for (long c = 0; c < g->n_cells; c++)
    if (occupied(weight, c))
      o[m++] = (struct overlap){part_of[c], rank_of[c], weight[c * PARTITION_CONSTRAINTS + WEIGHT_PARTICLES]};
  qsort(o, m, sizeof(*o), by_pair);
  long k = 0;
  for (long i = 0; i < m; i++) {
    if (k > 0 && by_pair(&o[k - 1], &o[i]) == 0) o[k - 1].particles += o[i].particles;
    else o[k++] = o[i];
  }
  qsort(o, k, sizeof(*o), by_particles);
  *n = k;
  return o;
}

/* Renumber the parts of owner (n_vertices occupied cells) so that each goes to the current rank (prev) sharing the most
 * particles with it, greedily from the largest overlap; the parts left take the ranks left in
 * increasing order. */
static void match_ranks(const struct grid *g, const int64_t *weight, long n_vertices, const int *prev, int n_parts,
                        int *owner) {
  int *rank_of_part = mem_calloc(n_parts, sizeof(int), "part renumbering");
  char *rank_taken = mem_calloc(n_parts, 1, "part renumbering");
  long n;
  struct overlap *o = overlaps(g, weight, n_vertices, owner, prev, &n);
  for (int p = 0; p < n_parts; p++) rank_of_part[p] = -1;
  for (long i = 0; i < n; i++)
    if (rank_of_part[o[i].part] < 0 && !rank_taken[o[i].rank]) {
      rank_of_part[o[i].part] = o[i].rank;
      rank_taken[o[i].rank] = 1;
    }
  for (int p = 0, r = 0; p < n_parts; p++) {
    if (rank_of_part[p] >= 0) continue;
    while (rank_taken[r]) r++;
    rank_of_part[p] = r;
    rank_taken[r] = 1;
  }
  for (long c = 0; c < g->n_cells; c++) owner[c] = rank_of_part[owner[c]];
  free(o);
  free(rank_of_part);
  free(rank_taken);
}

/* Rank 0: partition the occupied cells with METIS into owner, the empty cells to their nearest
 * occupied neighbour. Returns the METIS status. */
static int metis_partition(const struct grid *g, const int64_t *weight, long n_vertices, idx_t *vertex,
                           int n_parts, int *owner) {
  struct cell_graph G = graph_of(g, weight, vertex, n_vertices);
  idx_t *part = mem_calloc(n_vertices + 1, sizeof(idx_t), "METIS partition");
  int status = metis_parts(&G, n_parts, part);
  for (long c = 0; c < g->n_cells; c++) owner[c] = vertex[c] >= 0 ? (int)part[vertex[c]] : -1;
  free(G.xadj);
  free(G.adjncy);
  free(G.vwgt);
  free(part);
  if (status == METIS_OK) fill_empty(g, owner);
  return status;
}

/* The first part that received no cell, or -1. */
static int empty_part(const struct grid *g, const int *owner, int n_parts) {
  int *count = mem_calloc(n_parts, sizeof(int), "cells per rank");
  for (long c = 0; c < g->n_cells; c++) count[owner[c]]++;
  int empty = -1;
  for (int r = n_parts - 1; r >= 0; r--)
    if (count[r] == 0) empty = r;
  free(count);
  return empty;
}

/* Rank 0: the partition into owner; status[0] 0, 1 (METIS failed) or 2 (fewer occupied cells
 * than parts), status[1] a part without cells or -1, status[2] the occupied cells. */
static void partition_on_root(const struct grid *g, const int64_t *weight, int n_parts, const int *prev,
                              int *owner, long *status) {
  idx_t *vertex = mem_calloc(g->n_cells, sizeof(idx_t), "METIS vertex numbers");
  long n_vertices = number_vertices(g, weight, vertex);
  status[2] = n_vertices;
  if (n_vertices < n_parts) {
    status[0] = 2;
  } else if (n_parts == 1) {
    for (long c = 0; c < g->n_cells; c++) owner[c] = 0;
  } else {
    int metis = metis_partition(g, weight, n_vertices, vertex, n_parts, owner);
    status[0] = metis == METIS_OK ? 0 : 1;
    if (metis == METIS_OK) status[1] = empty_part(g, owner, n_parts);
    if (metis == METIS_OK && prev) match_ranks(g, weight, n_vertices, prev, n_parts, owner);
  }
  free(vertex);
}

int partition_cells(const struct grid *g, const int64_t *weight, int n_parts, const int *prev, MPI_Comm comm,
                    int *owner, char *err, size_t err_len) {
  int rank;
  long status[3] = {0, -1, 0};
  MPI_Comm_rank(comm, &rank);
  if (rank == 0) partition_on_root(g, weight, n_parts, prev, owner, status);
  MPI_Bcast(status, 3, MPI_LONG, 0, comm);
  if (status[0] == 2) {
    snprintf(err, err_len, "the particles fill %ld cells but %d ranks were started: use at most %ld "
             "ranks, or a finer resolution", status[2], n_parts, status[2]);
    return 1;
  }
  if (status[0] == 1) {
    snprintf(err, err_len, "METIS_PartGraphKway failed on the graph of %ld cells", status[2]);
    return 1;
  }
  if (status[1] >= 0) {
    snprintf(err, err_len, "the partition gave rank %ld no cell (%ld cells with particles for %d ranks): "
             "use fewer ranks", status[1], status[2], n_parts);
    return 1;
  }
  MPI_Bcast(owner, (int)g->n_cells, MPI_INT, 0, comm);
  return 0;
}

double partition_imbalance(const struct grid *g, const int64_t *weight, int k, const int *owner,
                           int n_parts) {
  double *load = mem_calloc(n_parts, sizeof(double), "load per rank"), total = 0, max = 0;
  for (long c = 0; c < g->n_cells; c++) load[owner[c]] += (double)weight[c * PARTITION_CONSTRAINTS + k];
  for (int r = 0; r < n_parts; r++) {
    total += load[r];
    if (load[r] > max) max = load[r];
  }
  free(load);
  return total > 0 ? max / (total / n_parts) - 1.0 : 0.0;
}
