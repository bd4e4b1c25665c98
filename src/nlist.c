/* nlist.c — per-step neighbour lists built from the cell index. */
#include <stdlib.h>
#include <string.h>
#include "nlist.h"

static void *grow(void *a, long *capacity, long needed, size_t size) {
  if (needed <= *capacity) return a;
  long n = needed + needed / 4 + 64;
  void *q = realloc(a, n * size);
  if (!q) abort();
  *capacity = n;
  return q;
}

/* Append the slots of the cells around cell c within radius2 of owned slot i; returns the
 * new entry count. */
static long append_neighbours(struct nlist *l, const struct space *s, const struct parts *p,
                              long i, const long *nb, int n_cells, long n) {
  const int dim = p->dim;
  for (int k = 0; k < n_cells; k++) {
    long first = s->cell_start[nb[k]], last = first + s->cell_count[nb[k]];
    l->j = grow(l->j, &l->capacity, n + (last - first), sizeof(int));
    for (long j = first; j < last; j++) {
      double r2 = 0;
      for (int d = 0; d < dim; d++) r2 += (p->x[d][i] - p->x[d][j]) * (p->x[d][i] - p->x[d][j]);
      if (r2 < l->radius2 && j != i) l->j[n++] = (int)j;
    }
  }
  return n;
}

/* The cells around c that hold particles on this rank. */
static int occupied_stencil(const struct space *s, long c, long *nb) {
  long all[27];
  int n_all = grid_stencil(&s->grid, c, 1, all), n = 0;
  for (int k = 0; k < n_all; k++)
    if (s->cell_count[all[k]]) nb[n++] = all[k];
  return n;
}

void nlist_build(struct nlist *l, const struct space *s, const struct parts *p, double radius) {
  l->radius2 = radius * radius;
  l->n_slots = p->n_owned;
  l->offset = grow(l->offset, &l->offset_capacity, p->n_owned + 1, sizeof(long));
  long n = 0;
  l->offset[0] = 0;   /* owned slots are sorted by cell: the scan below visits them in order */
  for (long k = 0; k < s->n_owned_cells; k++) {
    long c = s->owned_cells[k], nb[27];
    if (!s->cell_count[c]) continue;
    int n_cells = occupied_stencil(s, c, nb);
    for (long i = s->cell_start[c]; i < s->cell_start[c] + s->cell_count[c]; i++) {
      l->offset[i] = n;
      if (p->phase[i] != PHASE_WALL) n = append_neighbours(l, s, p, i, nb, n_cells, n);
      l->offset[i + 1] = n;
    }
  }
}

void nlist_free(struct nlist *l) {
  free(l->offset);
  free(l->j);
  memset(l, 0, sizeof(*l));
}

long nlist_bytes(const struct nlist *l) {
  return l->capacity * (long)sizeof(int) + l->offset_capacity * (long)sizeof(long);
}
