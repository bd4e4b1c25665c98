/* space.c — cell ownership, particle sorting by (cell, id) and the cell index. */
#include <stdlib.h>
#include <string.h>
#include "parallel/space.h"
#include "base/mem.h"

/* Zeroed cell-index arrays (out of memory ends the run, mem.h). */
static void *xcalloc(size_t n, size_t size) { return mem_calloc(n, size, "cell index"); }

void space_init(struct space *s, const struct grid *g, int rank, int n_ranks, int halo_layers) {
  memset(s, 0, sizeof(*s));
  s->grid = *g;
  s->rank = rank;
  s->n_ranks = n_ranks;
  s->halo_layers = halo_layers;
  s->owner = xcalloc(g->n_cells, sizeof(int));
  s->cell_start = xcalloc(g->n_cells, sizeof(long));
  s->cell_count = xcalloc(g->n_cells, sizeof(int));
  s->owned_cells = xcalloc(g->n_cells, sizeof(int));
  s->bucket = xcalloc(g->n_cells + 1, sizeof(int));
}

void space_free(struct space *s) {
  free(s->owner);
  free(s->cell_start);
  free(s->cell_count);
  free(s->owned_cells);
  free(s->bucket);
  free(s->order);
  free(s->scratch);
  memset(s, 0, sizeof(*s));
}

long space_bytes(const struct space *s) {
  long per_cell = 4 * (long)sizeof(int) + (long)sizeof(long);   /* owner, count, owned, bucket; start */
  return s->grid.n_cells * per_cell + s->scratch_capacity * (long)(sizeof(int) + sizeof(double));
}

void space_set_owner(struct space *s, const int *owner) {
  memcpy(s->owner, owner, s->grid.n_cells * sizeof(int));
  s->n_owned_cells = 0;
  for (long c = 0; c < s->grid.n_cells; c++)
    if (owner[c] == s->rank) s->owned_cells[s->n_owned_cells++] = (int)c;
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

/* Counting sort by cell into s->order, then insertion sort by id inside each cell. */
static void sort_order(struct space *s, const struct parts *p, long first, long n) {
  int *bucket = s->bucket;
  memset(bucket, 0, (s->grid.n_cells + 1) * sizeof(int));
  for (long i = 0; i < n; i++) bucket[p->cell[first + i] + 1]++;
  for (long c = 0; c < s->grid.n_cells; c++) bucket[c + 1] += bucket[c];
  for (long i = 0; i < n; i++) s->order[bucket[p->cell[first + i]]++] = (int)(first + i);
  for (long k = 1; k < n; k++) {
    int cur = s->order[k];
    long j = k;
    while (j > 0 && p->cell[s->order[j - 1]] == p->cell[cur] && p->id[s->order[j - 1]] > p->id[cur]) {
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
  memset(s->cell_count, 0, s->grid.n_cells * sizeof(int));
  long n = p->n_owned + p->n_halo;
  for (long i = 0; i < n; i++) {
    int c = p->cell[i];
    if (s->cell_count[c]++ == 0) s->cell_start[c] = i;
  }
}

void neighbour_ranges(const struct space *s, long c, struct neighbour_ranges *r) {
  long nb[27];
  int n = grid_stencil(&s->grid, c, 1, nb);
  r->n = 0;
  for (int k = 0; k < n; k++) {
    int count = s->cell_count[nb[k]];
    if (!count) continue;
    r->start[r->n] = s->cell_start[nb[k]];
    r->count[r->n++] = count;
  }
}
