/* nlist.c — per-step neighbour lists built from the cell index, stored as bit masks over the
 * candidates of each cell's stencil: of the owned fluid, and of fixed points (mirror points). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "parallel/nlist.h"
#include "base/mem.h"

#define WORD_BITS 64

static void *grow(void *a, long *capacity, long needed, size_t size) {
  if (needed <= *capacity) return a;
  long n = needed + needed / 4 + 64;
  void *q = mem_realloc(a, mem_bytes((size_t)n, size, "neighbour lists"), "neighbour lists");
  *capacity = n;
  return q;
}

/* mark_within in `dim` dimensions (a constant where it is inlined: the axis loop unrolls); with
 * BY_PHASE (a constant too) a fluid candidate j's radius^2 is the larger of radius2 and
 * phase_radius2[its phase]. */
static inline void mark_within_dim(const struct parts *p, const int dim, const double *x, long self,
                                   double radius2, const double *phase_radius2, const int BY_PHASE,
                                   const struct neighbour_ranges *r, uint64_t *mask) {
  const double *xj[3] = {p->x[0], p->x[1], dim == 3 ? p->x[2] : NULL};
  long b = 0;
  for (int k = 0; k < r->n; k++)
    for (long j = r->start[k]; j < r->start[k] + r->count[k]; j++, b++) {
      double r2 = 0, limit2 = radius2;
      for (int d = 0; d < dim; d++) r2 += (x[d] - xj[d][j]) * (x[d] - xj[d][j]);
      if (BY_PHASE && p->phase[j] >= 0) limit2 = fmax(limit2, phase_radius2[p->phase[j]]);
      if (r2 < limit2 && j != self) mask[b / WORD_BITS] |= (uint64_t)1 << (b % WORD_BITS);
    }
}

/* Set in mask the bits of the candidates r within radius2 of point x, but slot self (with
 * phase_radius2, within the larger of radius2 and the candidate's phase's). The squared
 * distance is summed as the pair loops sum it, so a candidate is listed exactly when they find it
 * near. */
static inline void mark_within(const struct parts *p, const double *x, long self, double radius2,
                               const double *phase_radius2, const struct neighbour_ranges *r, uint64_t *mask) {
  if (phase_radius2 && p->dim == 3) mark_within_dim(p, 3, x, self, radius2, phase_radius2, 1, r, mask);
  else if (phase_radius2) mark_within_dim(p, 2, x, self, radius2, phase_radius2, 1, r, mask);
  else if (p->dim == 3) mark_within_dim(p, 3, x, self, radius2, NULL, 0, r, mask);
  else mark_within_dim(p, 2, x, self, radius2, NULL, 0, r, mask);
}

/* Set in mask the bits of the candidates r within the build radius of owned slot i (not i itself):
 * with radii by phase, i's phase's, or a fluid candidate's phase's when larger. */
static void mark_neighbours(const struct nlist *l, const struct parts *p, long i,
                            const struct neighbour_ranges *r, uint64_t *mask) {
  double x[3] = {0, 0, 0};
  for (int d = 0; d < p->dim; d++) x[d] = p->x[d][i];
  if (!l->by_phase) mark_within(p, x, i, l->radius2, NULL, r, mask);
  else mark_within(p, x, i, l->phase_radius2[p->phase[i]], l->phase_radius2, r, mask);
}

/* Particles of cell c that have a neighbour list (of a KIND_LISTED kind, base/kinds.h). */
static long listed_in_cell(const struct space *s, const struct parts *p, long c) {
  long n = 0;
  long first = space_cell_first(s, c), end = first + space_cell_size(s, c);
  for (long i = first; i < end; i++) n += part_has(p->phase[i], KIND_LISTED);
  return n;
}

/* Place the masks of the n_listed listed particles of owned cell k (stencil ranges r) from word n
 * on; returns the words they take. */
static long place_cell(struct nlist *l, long k, const struct neighbour_ranges *r, long n_listed, long n) {
  long candidates = 0;
  for (int q = 0; q < r->n; q++) candidates += r->count[q];
  int words = (int)((candidates + WORD_BITS - 1) / WORD_BITS);
  l->candidates = grow(l->candidates, &l->candidate_capacity, candidates, sizeof(int));
  l->cells[k] = (struct nlist_cell){n, words};
  return words * n_listed;
}

void nlist_build(struct nlist *l, const struct space *s, const struct parts *p, double radius,
                 const double *phase_radius, int n_phases) {
  l->radius2 = radius * radius;
  l->by_phase = phase_radius != NULL;
  for (int ph = 0; l->by_phase && ph < n_phases; ph++) l->phase_radius2[ph] = phase_radius[ph] * phase_radius[ph];
  l->cells = grow(l->cells, &l->cell_capacity, s->n_owned_cells, sizeof(struct nlist_cell));
  long n = 0;
  for (long k = 0; k < s->n_owned_cells; k++) {
    long c = s->owned_cells[k], first = space_cell_first(s, c), end = first + space_cell_size(s, c);
    struct neighbour_ranges r;
    neighbour_ranges(s, c, &r);
    long words = place_cell(l, k, &r, listed_in_cell(s, p, c), n);
    l->bits = grow(l->bits, &l->capacity, n + words, sizeof(uint64_t));
    if (words > 0) memset(l->bits + n, 0, words * sizeof(uint64_t));   /* bits may still be NULL */
    for (long i = first; i < end; i++) {
      if (!part_has(p->phase[i], KIND_LISTED)) continue;
      mark_neighbours(l, p, i, &r, l->bits + n);
      n += l->cells[k].words;
    }
  }
}

void nlist_points_clear(struct nlist *l, double radius) {
  l->radius2 = radius * radius;
  l->point_words = 0;
}

void nlist_point_add(struct nlist *l, const struct parts *p, const double *x, const struct neighbour_ranges *r) {
  long first = l->point_words;
  int words = nlist_words(r), lo = 0, hi;
  l->point_bits = grow(l->point_bits, &l->point_capacity, first + 1 + words, sizeof(uint64_t));
  uint64_t *mask = l->point_bits + first + 1;
  if (words > 0) memset(mask, 0, words * sizeof(uint64_t));
  mark_within(p, x, -1, l->radius2, NULL, r, mask);
  for (hi = words; hi > 0 && !mask[hi - 1]; hi--) continue;
  while (lo < hi && !mask[lo]) lo++;
  if (lo > 0) memmove(mask, mask + lo, (size_t)(hi - lo) * sizeof(uint64_t));
  l->point_bits[first] = hi > lo ? nlist_point_header(lo, hi - lo) : 0;
  l->point_words = first + 1 + (hi - lo);
}

void nlist_enter_cell(struct nlist *l, const struct neighbour_ranges *r) {
  int *slot = l->candidates;
  for (int q = 0; q < r->n; q++)
    for (long j = r->start[q]; j < r->start[q] + r->count[q]; j++) *slot++ = (int)j;
}

void nlist_free(struct nlist *l) {
  free(l->cells);
  free(l->bits);
  free(l->candidates);
  free(l->point_bits);
  memset(l, 0, sizeof(*l));
}

long nlist_bytes(const struct nlist *l) {
  return l->capacity * (long)sizeof(uint64_t) + l->cell_capacity * (long)sizeof(struct nlist_cell) +
         l->candidate_capacity * (long)sizeof(int) + l->point_capacity * (long)sizeof(uint64_t);
}
