/* test_cells.c — the cell-list neighbours (sorted by cell and id, 3^dim stencil) equal the
 * brute-force neighbour set on random particles, in 2D and 3D, the sort is by cell, each cell's
 * fluid first, then by id, the fluid-only ranges hold exactly the fluid within their radius, and
 * the neighbour lists (bit masks over the stencil) read back every slot within their radius, in
 * the stencil's order (global cell order, then slot order), also with radii by phase
 * (multi-resolution: a pair within the larger of its two particles' radii). */
#include <stdlib.h>
#include "check.h"
#include "physics/passes.h"

/* Random particles in [0, 1]^dim, ids shuffled. */
static void random_parts(struct parts *p, int dim, long n, unsigned seed) {
  srand(seed);
  parts_init(p, dim, n, 0);
  for (long i = 0; i < n; i++) {
    for (int d = 0; d < dim; d++) p->x[d][i] = rand() / (double)RAND_MAX;
    p->id[i] = (int64_t)((i * 7919) % n);
    p->phase[i] = i % 5 ? 0 : PHASE_WALL;   /* some wall ghosts: they have no neighbour list */
  }
  p->n_owned = n;
}

static long brute_count(const struct parts *p, long i, double support2) {
  long count = 0;
  for (long j = 0; j < p->n_owned; j++) {
    double r2 = 0;
    for (int d = 0; d < p->dim; d++) r2 += (p->x[d][i] - p->x[d][j]) * (p->x[d][i] - p->x[d][j]);
    count += r2 < support2;
  }
  return count;
}

/* The fluid slots within radius2 of point x, by brute force. */
static long brute_fluid_near(const struct parts *p, const double *x, double radius2) {
  long count = 0;
  for (long j = 0; j < p->n_owned; j++) {
    double r2 = 0;
    for (int d = 0; d < p->dim; d++) r2 += (x[d] - p->x[d][j]) * (x[d] - p->x[d][j]);
    count += r2 < radius2 && p->phase[j] != PHASE_WALL;
  }
  return count;
}

/* The slots within radius of point x over the fluid-only ranges of the cells around x's cell. */
static long ranged_fluid_near(const struct space *s, const struct parts *p, const double *x, double radius) {
  struct neighbour_ranges r;
  long count = 0;
  neighbour_ranges_fluid_within(s, grid_cell_clamped(&s->grid, x), x, radius, &r);
  for (int k = 0; k < r.n; k++)
    for (long j = r.start[k]; j < r.start[k] + r.count[k]; j++) {
      double r2 = 0;
      for (int d = 0; d < p->dim; d++) r2 += (x[d] - p->x[d][j]) * (x[d] - p->x[d][j]);
      count += r2 < radius * radius;   /* a wall ghost in the ranges would count too */
    }
  return count;
}

/* Slot j goes after slot i in the sort: a later cell, or the same cell's boundary after its fluid,
 * or the same cell and kind with a larger id. */
static int sorted_after(const struct parts *p, long i, long j) {
  int wall_i = p->phase[i] == PHASE_WALL, wall_j = p->phase[j] == PHASE_WALL;
  if (p->cell[i] != p->cell[j]) return p->cell[i] < p->cell[j];
  return wall_i != wall_j ? wall_j : p->id[i] < p->id[j];
}

static long cell_count_pairs(const struct space *s, const struct parts *p, long i, double support2) {
  struct neighbour_ranges r;
  long count = 0;
  neighbour_ranges(s, p->cell[i], &r);
  for (int k = 0; k < r.n; k++)
    for (long j = r.start[k]; j < r.start[k] + r.count[k]; j++) {
      double r2 = 0;
      for (int d = 0; d < p->dim; d++) r2 += (p->x[d][i] - p->x[d][j]) * (p->x[d][i] - p->x[d][j]);
      count += r2 < support2;
    }
  return count;
}

/* The squared build radius of the pair of listed slot i and slot j: radius2, or with phase_radius2
 * i's phase's, or j's when j is fluid and its phase's is larger. */
static double pair_radius2(const struct parts *p, long i, long j, double radius2, const double *phase_radius2) {
  if (!phase_radius2) return radius2;
  double ri = phase_radius2[p->phase[i]], rj = p->phase[j] >= 0 ? phase_radius2[p->phase[j]] : 0.0;
  return ri > rj ? ri : rj;
}

/* Owned slot i (in owned cell k, its f-th fluid particle) against its neighbour list: the same
 * slots, in the same order, as a scan of the stencil for the other slots within the pair's radius
 * (pair_radius2). Returns 1 on a mismatch. */
static int list_differs(struct nlist *l, const struct space *s, const struct parts *p, long k, long f,
                        long i, double radius2, const double *phase_radius2) {
  struct neighbour_ranges r;
  neighbour_ranges(s, s->owned_cells[k], &r);
  nlist_enter_cell(l, &r);
  struct neighbours nb = nlist_of(l, k, f);
  int differs = 0;
  long listed;
  for (int q = 0; q < r.n; q++)
    for (long j = r.start[q]; j < r.start[q] + r.count[q]; j++) {
      double r2 = 0;
      for (int d = 0; d < p->dim; d++) r2 += (p->x[d][i] - p->x[d][j]) * (p->x[d][i] - p->x[d][j]);
      if (r2 < pair_radius2(p, i, j, radius2, phase_radius2) && j != i)
        differs |= !neighbours_next(&nb, &listed) || listed != j;
    }
  return differs || neighbours_next(&nb, &listed);
}

/* Every owned fluid particle's neighbour list, built with radius `radius` (and phase_radius, the
 * radii of n_phases phases, or NULL), against the stencil scan. */
static long list_mismatches(const struct space *s, const struct parts *p, double radius, const double *phase_radius,
                            int n_phases) {
  struct nlist l = {0};
  long bad = 0;
  double phase_radius2[NLIST_MAX_PHASES];
  for (int ph = 0; ph < n_phases; ph++) phase_radius2[ph] = phase_radius[ph] * phase_radius[ph];
  nlist_build(&l, s, p, radius, phase_radius, n_phases);
  for (long k = 0; k < s->n_owned_cells; k++) {
    long c = s->owned_cells[k], f = 0;
    for (long i = space_cell_first(s, c); i < space_cell_first(s, c) + space_cell_size(s, c); i++)
      if (p->phase[i] != PHASE_WALL)
        bad += list_differs(&l, s, p, k, f++, i, radius * radius, phase_radius ? phase_radius2 : NULL);
  }
  nlist_free(&l);
  return bad;
}

/* The cell neighbours and lists of n random particles with cells of about `support` in top cells
 * of at least top_per_rank per rank (1 rank: the larger blocks the smaller top_per_rank). */
static void check_dim(int dim, long n, double support, long top_per_rank) {
  struct parts p;
  struct grid g;
  struct space s;
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  random_parts(&p, dim, n, 17u + dim);
  grid_init(&g, dim, lo, hi, support);
  space_init(&s, &g, 0, 1, 1, top_per_rank);
  int *owner = calloc(s.top.n_cells, sizeof(int));
  space_set_owner(&s, owner);
  CHECK(space_assign_cells(&s, &p, 0, n) < 0, "all particles inside");
  space_sort(&s, &p, 0, n);
  space_index(&s, &p);
  long sorted = 1, mismatches = 0;
  for (long i = 1; i < n; i++) sorted &= sorted_after(&p, i - 1, i);
  CHECK(sorted, "%dD, blocks of %ld: particles sorted by cell, fluid first, then id", dim, s.block);
  for (long i = 0; i < n; i++) {   /* points between the particles, radii below and up to the cell edge */
    double x[3] = {0, 0, 0}, radius = support * (0.5 + 0.5 * (i % 3) / 2.0);
    for (int d = 0; d < dim; d++) x[d] = 0.5 * (p.x[d][i] + p.x[d][(i * 31 + 7) % n]);
    mismatches += brute_fluid_near(&p, x, radius * radius) != ranged_fluid_near(&s, &p, x, radius);
  }
  CHECK(mismatches == 0, "%dD, blocks of %ld: %ld points whose fluid-only ranges miss or add fluid", dim,
        s.block, mismatches);
  mismatches = 0;
  for (long i = 0; i < n; i++)
    mismatches += brute_count(&p, i, support * support) != cell_count_pairs(&s, &p, i, support * support);
  CHECK(mismatches == 0, "%dD, blocks of %ld: %ld particles with a wrong neighbour count", dim,
        s.block, mismatches);
  mismatches = list_mismatches(&s, &p, support, NULL, 0);
  CHECK(mismatches == 0, "%dD, blocks of %ld: %ld particles with a wrong neighbour list", dim,
        s.block, mismatches);
  for (long i = 0; i < n; i += 3) p.phase[i] = p.phase[i] == PHASE_WALL ? PHASE_WALL : 1;
  const double phase_radius[2] = {0.6 * support, support};   /* radius (0.3 support) unused */
  mismatches = list_mismatches(&s, &p, 0.3 * support, phase_radius, 2);
  CHECK(mismatches == 0, "%dD, blocks of %ld: %ld particles with a wrong neighbour list, radii by phase", dim,
        s.block, mismatches);
  free(owner);
  space_free(&s);
  parts_free(&p);
}

int main(void) {
  for (long top_per_rank = 1; top_per_rank <= 256; top_per_rank *= 16) {
    check_dim(2, 3000, 0.07, top_per_rank);
    check_dim(3, 3000, 0.15, top_per_rank);
  }
  return check_report("test_cells");
}
