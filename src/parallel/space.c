/* space.c — the two-level cell space: top cells and their owners, the fine-cell index over the
 * local top cells, particle sorting by cell (each cell's fluid first) and id. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "parallel/space.h"
#include "base/mem.h"

/* Zeroed cell-index arrays (out of memory ends the run, mem.h). */
static void *xcalloc(size_t n, size_t size) { return mem_calloc(n, size, "cell index"); }

/* Top cells of the grid over g's fine cells with blocks of b fine cells per axis. */
static long top_cells_for(const struct grid *g, long b) {
  long n = 1;
  for (int d = 0; d < g->dim; d++) n *= (g->n[d] + b - 1) / b;
  return n;
}

long space_top_block(const struct grid *g, int n_ranks, long per_rank) {
  long longest = 1, b = 1;
  for (int d = 0; d < g->dim; d++)
    if (g->n[d] > longest) longest = g->n[d];
  while (b < longest && top_cells_for(g, b + 1) >= per_rank * n_ranks) b++;
  while (top_cells_for(g, b) > SPACE_TOP_CELLS_MAX) b++;
  return b;
}

struct grid space_top_grid(const struct grid *g, long b) {
  struct grid t = *g;
  t.n_cells = 1;
  for (int d = 0; d < g->dim; d++) {
    t.n[d] = (g->n[d] + b - 1) / b;
    t.edge[d] = g->edge[d] * (double)b;
    t.max[d] = t.min[d] + t.edge[d] * (double)t.n[d];
    t.n_cells *= t.n[d];
  }
  return t;
}

void space_init(struct space *s, const struct grid *g, int rank, int n_ranks, int halo_layers,
                long top_cells_per_rank) {
  memset(s, 0, sizeof(*s));
  s->grid = *g;
  s->block = space_top_block(g, n_ranks, top_cells_per_rank);
  s->top = space_top_grid(g, s->block);
  s->cells_per_top = 1;
  for (int d = 0; d < g->dim; d++) s->cells_per_top *= s->block;
  s->rank = rank;
  s->n_ranks = n_ranks;
  s->halo_layers = halo_layers;
  s->top_owner = xcalloc(s->top.n_cells, sizeof(int));
  s->top_slot = xcalloc(s->top.n_cells, sizeof(int));
}

/* Free the fine-cell index of the local top cells. */
static void free_fine(struct space *s) {
  free(s->cell_start);
  free(s->cell_count);
  free(s->cell_fluid);
  free(s->local_order);
  free(s->rank_of_local);
  free(s->owned_cells);
  free(s->by_reach);
  free(s->bucket);
  s->cell_start = NULL;
  s->cell_count = s->cell_fluid = s->local_order = s->rank_of_local = s->owned_cells = s->by_reach = s->bucket = NULL;
}

void space_free(struct space *s) {
  free_fine(s);
  free(s->top_owner);
  free(s->top_slot);
  free(s->order);
  free(s->scratch);
  memset(s, 0, sizeof(*s));
}

long space_bytes(const struct space *s) {
  long slots = s->n_local_tops * s->cells_per_top;
  long per_slot = (long)sizeof(long) + 3 * (long)sizeof(int);   /* start; count, rank, bucket */
  return s->top.n_cells * 2 * (long)sizeof(int) + slots * per_slot +
         (s->n_local_cells + 2 * s->n_owned_cells) * (long)sizeof(int) +
         s->scratch_capacity * (long)(sizeof(int) + sizeof(double));
}

/* Mark in top_slot (as 1) the top cells owned by this rank and those within reach of them. */
static void mark_local_tops(struct space *s) {
  int reach = (int)((s->halo_layers + s->block - 1) / s->block);
  long *nb = mem_calloc(grid_stencil_size(&s->top, reach), sizeof(long), "top cell stencil");
  memset(s->top_slot, 0, s->top.n_cells * sizeof(int));
  for (long t = 0; t < s->top.n_cells; t++) {
    if (s->top_owner[t] != s->rank) continue;
    int n = grid_stencil(&s->top, t, reach, nb);
    for (int j = 0; j < n; j++) s->top_slot[nb[j]] = 1;
  }
  free(nb);
  s->n_local_tops = 0;
  for (long t = 0; t < s->top.n_cells; t++)
    s->top_slot[t] = s->top_slot[t] ? (int)s->n_local_tops++ : -1;
}

/* A local fine cell: its global and local index. */
struct cell_pair {
  int global, local;
};

static int by_global(const void *a, const void *b) {
  int x = ((const struct cell_pair *)a)->global, y = ((const struct cell_pair *)b)->global;
  return (x > y) - (x < y);
}

/* The local fine cells inside the domain, sorted by global index. Sets n_local_cells. */
static struct cell_pair *local_cells_sorted(struct space *s) {
  const long *n = s->grid.n, *tn = s->top.n, b = s->block;
  struct cell_pair *cells = mem_calloc(s->n_local_tops * s->cells_per_top + 1, sizeof(*cells),
                                       "local cell list");
  long count = 0;
  for (long t = 0; t < s->top.n_cells; t++) {
    if (s->top_slot[t] < 0) continue;
    long tx = t % tn[0], ty = (t / tn[0]) % tn[1], tz = t / (tn[0] * tn[1]);
    long bz = s->grid.dim == 3 ? b : 1;
    for (long z = tz * bz; z < (tz + 1) * bz && z < n[2]; z++)
      for (long y = ty * b; y < (ty + 1) * b && y < n[1]; y++)
        for (long x = tx * b; x < (tx + 1) * b && x < n[0]; x++)
          cells[count++] = (struct cell_pair){(int)(x + n[0] * (y + n[1] * z)),
                                              (int)space_local_xyz(s, x, y, z)};
  }
  qsort(cells, count, sizeof(*cells), by_global);
  s->n_local_cells = count;
  return cells;
}

/* Allocate the fine-cell index of the local top cells; fill local_order, rank_of_local and the
 * owned cells. */
static void build_fine(struct space *s) {
  long slots = s->n_local_tops * s->cells_per_top;
  s->cell_start = xcalloc(slots + 1, sizeof(long));
  s->cell_count = xcalloc(slots + 1, sizeof(int));
  s->cell_fluid = xcalloc(slots + 1, sizeof(int));
  s->rank_of_local = xcalloc(slots + 1, sizeof(int));
  s->bucket = xcalloc(slots + 1, sizeof(int));
  struct cell_pair *cells = local_cells_sorted(s);
  s->local_order = xcalloc(s->n_local_cells + 1, sizeof(int));
  s->owned_cells = xcalloc(s->n_local_cells + 1, sizeof(int));
  s->n_owned_cells = 0;
  for (long k = 0; k < s->n_local_cells; k++) {
    s->local_order[k] = cells[k].local;
    s->rank_of_local[cells[k].local] = (int)k;
    if (space_cell_owner(s, cells[k].global) == s->rank) s->owned_cells[s->n_owned_cells++] = cells[k].global;
  }
  free(cells);
}

/* Whether every cell around owned cell c (its 3^dim stencil inside the domain) is owned. */
static int is_interior(const struct space *s, long c) {
  long nb[27];
  int n = grid_stencil(&s->grid, c, 1, nb);
  for (int j = 0; j < n; j++)
    if (space_cell_owner(s, nb[j]) != s->rank) return 0;
  return 1;
}

/* Order the owned cells into by_reach: the interior ones, then those next to another rank's. */
static void order_by_reach(struct space *s) {
  s->by_reach = xcalloc(s->n_owned_cells + 1, sizeof(int));
  char *interior = xcalloc(s->n_owned_cells + 1, 1);
  s->n_interior = 0;
  for (long k = 0; k < s->n_owned_cells; k++)
    if ((interior[k] = (char)is_interior(s, s->owned_cells[k]))) s->by_reach[s->n_interior++] = (int)k;
  long next = s->n_interior;
  for (long k = 0; k < s->n_owned_cells; k++)
    if (!interior[k]) s->by_reach[next++] = (int)k;
  free(interior);
}

void space_set_owner(struct space *s, const int *top_owner) {
  memcpy(s->top_owner, top_owner, s->top.n_cells * sizeof(int));
  free_fine(s);
  mark_local_tops(s);
  build_fine(s);
  order_by_reach(s);
}

long space_assign_cells(const struct space *s, struct parts *p, long first, long n) {
  long bad = -1;
  for (long i = first; i < first + n; i++) {
    double x[3] = {p->x[0][i], p->x[1][i], p->dim == 3 ? p->x[2][i] : 0};
    p->cell[i] = grid_cell_of(&s->grid, x);
    if (p->cell[i] < 0 && bad < 0) bad = i;
  }
  return bad;
}

static void ensure_scratch(struct space *s, long n) {
  if (n <= s->scratch_capacity) return;
  free(s->order);
  free(s->scratch);
  s->order = xcalloc(n, sizeof(int));
  s->scratch = xcalloc(n, sizeof(double));
  s->scratch_capacity = n;
}

/* 1 if slot a goes after slot b within their cell: the fluid before the boundary particles (the
 * fluid-only ranges of neighbour_ranges_fluid_within are each cell's first slots), then by id. */
static int after_in_cell(const struct parts *p, int a, int b) {
  int wall_a = part_has(p->phase[a], KIND_BOUNDARY), wall_b = part_has(p->phase[b], KIND_BOUNDARY);
  return wall_a != wall_b ? wall_a > wall_b : p->id[a] > p->id[b];
}

/* Counting sort by the cells' positions in global order into s->order (the keys held in the
 * scratch meanwhile), then insertion sort inside each cell: fluid first, then by id. */
static void sort_order(struct space *s, const struct parts *p, long first, long n) {
  int *bucket = s->bucket, *key = (int *)s->scratch;
  memset(bucket, 0, (s->n_local_cells + 1) * sizeof(int));
  for (long i = 0; i < n; i++) {
    key[i] = s->rank_of_local[space_local_cell(s, p->cell[first + i])];
    bucket[key[i] + 1]++;
  }
  for (long k = 0; k < s->n_local_cells; k++) bucket[k + 1] += bucket[k];
  for (long i = 0; i < n; i++) s->order[bucket[key[i]]++] = (int)(first + i);
  for (long k = 1; k < n; k++) {
    int cur = s->order[k];
    long j = k;
    while (j > 0 && p->cell[s->order[j - 1]] == p->cell[cur] && after_in_cell(p, s->order[j - 1], cur)) {
      s->order[j] = s->order[j - 1];
      j--;
    }
    s->order[j] = cur;
  }
}

/* Put the array a of type T (slots first..first+n) in s->order, through s->scratch. */
#define PERMUTE(T, a)                                                       \
  do {                                                                      \
    T *arr = (T *)(a), *tmp = (T *)s->scratch;                              \
    for (long k = 0; k < n; k++) tmp[k] = arr[s->order[k]];                 \
    memcpy(arr + first, tmp, n * sizeof(T));                                \
  } while (0)

void space_sort(struct space *s, struct parts *p, long first, long n) {
  ensure_scratch(s, n);
  sort_order(s, p, first, n);
  for (const struct part_field *f = parts_fields; f < parts_fields + parts_n_fields; f++) {
    if (!parts_has_field(p, f)) continue;
    for (int k = 0; k < parts_field_ncomp(p, f); k++) {
      void *a = parts_field_array(p, f, k);
      if (f->type == PART_DOUBLE) PERMUTE(double, a);
      else if (f->type == PART_INT) PERMUTE(int, a);
      else PERMUTE(int64_t, a);
    }
  }
}

void space_index(struct space *s, const struct parts *p) {
  memset(s->cell_count, 0, s->n_local_tops * s->cells_per_top * sizeof(int));
  memset(s->cell_fluid, 0, s->n_local_tops * s->cells_per_top * sizeof(int));
  long n = p->n_owned + p->n_halo;
  for (long i = 0; i < n; i++) {
    long l = space_local_cell(s, p->cell[i]);
    int fluid = !part_has(p->phase[i], KIND_BOUNDARY);
    if (fluid && s->cell_fluid[l] != s->cell_count[l]) {   /* space_sort's order, relied on by the ranges */
      fprintf(stderr, "mpsph: internal error: slot %ld, fluid, follows a boundary particle in cell %d\n", i,
              p->cell[i]);
      exit(3);
    }
    if (s->cell_count[l]++ == 0) s->cell_start[l] = i;
    s->cell_fluid[l] += fluid;
  }
}

/* Relative margin on the squared radius of neighbour_ranges_fluid_within: far above the rounding of a
 * cell's bounds and of the cell assignment, so no particle within the radius is left out. */
#define RANGE_CULL_MARGIN 1e-9

/* The squared distance [m^2] from coordinate x to the cells of axis d at indices i - 1, i, i + 1,
 * into gap2[0..2]. */
static void axis_gaps(const struct grid *g, int d, long i, double x, double *gap2) {
  for (int k = 0; k < 3; k++) {
    double lo = g->min[d] + (double)(i - 1 + k) * g->edge[d], hi = lo + g->edge[d];
    double gap = x < lo ? lo - x : (x > hi ? x - hi : 0.0);
    gap2[k] = gap * gap;
  }
}

/* The particle ranges of the cells around c present on this rank, of all their particles (count
 * cell_count) or of their fluid (cell_fluid); with x, only those whose box lies within squared
 * distance cull2 of x. */
static void ranges_around(const struct space *s, long c, const double *x, double cull2, const int *count,
                          struct neighbour_ranges *r) {
  const long *n = s->grid.n;
  const long i[3] = {c % n[0], (c / n[0]) % n[1], c / (n[0] * n[1])}, ix = i[0], iy = i[1], iz = i[2];
  long lz = s->grid.dim == 3 ? 1 : 0;
  double gap2[3][3] = {{0}};
  for (int d = 0; x && d < s->grid.dim; d++) axis_gaps(&s->grid, d, i[d], x[d], gap2[d]);
  r->n = 0;
  for (long z = iz - lz; z <= iz + lz; z++) {
    if (z < 0 || z >= n[2]) continue;
    for (long y = iy - 1; y <= iy + 1; y++) {
      if (y < 0 || y >= n[1]) continue;
      for (long xi = ix - 1; xi <= ix + 1; xi++) {
        if (xi < 0 || xi >= n[0]) continue;
        if (x && gap2[0][xi - ix + 1] + gap2[1][y - iy + 1] + gap2[2][z - iz + 1] > cull2) continue;
        long l = space_local_xyz(s, xi, y, z);
        if (l < 0 || !count[l]) continue;
        r->start[r->n] = s->cell_start[l];
        r->count[r->n++] = count[l];
      }
    }
  }
}

void neighbour_ranges(const struct space *s, long c, struct neighbour_ranges *r) {
  ranges_around(s, c, NULL, 0, s->cell_count, r);
}

void neighbour_ranges_fluid_within(const struct space *s, long c, const double *x, double radius,
                                   struct neighbour_ranges *r) {
  ranges_around(s, c, x, radius * radius * (1 + RANGE_CULL_MARGIN), s->cell_fluid, r);
}

void space_keep_own(const struct space *s, struct parts *p) {
  long kept = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (space_cell_owner(s, p->cell[i]) != s->rank) continue;
    if (kept != i) parts_copy_one(p, kept, p, i);
    kept++;
  }
  p->n_owned = kept;
}
