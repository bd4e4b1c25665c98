/* startup.c — the initial particles generated where they belong (issue 22). The rows of
 * candidate lattice nodes (case/init.h) are counted in parallel, each rank a contiguous block of
 * rows; the counts are shared, so every rank knows the first id of every row; the top cells are
 * partitioned from the counted work; then each rank generates only the particles of its own top
 * cells, numbered as a serial generation numbers them. No rank enumerates the whole domain twice
 * and no particle is sent anywhere. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "engine/engine.h"
#include "case/init.h"
#include "base/mem.h"

#define ERR_LEN 1024

/* The first row of rank r's block: the blocks split the candidate nodes evenly. */
static long block_start(const struct init_rows *rows, int r, int n_ranks) {
  double total = 0, before = 0;
  for (int k = 0; k < rows->n_sources; k++)
    total += (double)rows->src[k].n[0] * (double)(rows->src[k].n[1] * rows->src[k].n[2]);
  double bound = total * r / n_ranks;
  for (int k = 0; k < rows->n_sources; k++) {
    const struct init_source *s = &rows->src[k];
    double nodes = (double)s->n[0] * (double)(s->n[1] * s->n[2]);
    if (bound < before + nodes) return s->first_row + (long)((bound - before) / (double)s->n[0]);
    before += nodes;
  }
  return rows->n_rows;
}

/* What the counting pass gathers: the partition weights per top cell, whether a particle lies outside the
 * domain. */
struct count_ctx {
  const struct engine *e;
  int64_t *weight;
  int outside;
};

static void count_node(void *ctx, const double *x, int source, long ordinal) {
  (void)ordinal;
  struct count_ctx *q = ctx;
  const struct space *s = &q->e->space;
  int cell = grid_cell_of(&s->grid, x);
  if (cell < 0) {
    q->outside = 1;
    return;
  }
  engine_weight_add(q->e, q->weight, cell, source < q->e->c->n_fluids ? KIND_FLUID : KIND_WALL);
}

/* Agree on the first row where bad input was found (bad_row: this rank's, or -1); rank 0 prints
 * the message of the rank that found it. Returns 1 when there is one. */
static int agree_bad_row(const struct engine *e, long bad_row, const long *starts, char *err) {
  long mine = bad_row < 0 ? LONG_MAX : bad_row, first;
  MPI_Allreduce(&mine, &first, 1, MPI_LONG, MPI_MIN, e->comm);
  if (first == LONG_MAX) return 0;
  int root = 0;
  while (root + 1 < e->n_ranks && starts[root + 1] <= first) root++;
  MPI_Bcast(err, ERR_LEN, MPI_CHAR, root, e->comm);
  if (e->rank == 0) fprintf(stderr, "mpsph: %s\n", err);
  return 1;
}

/* Every row's count on every rank (the blocks gathered). Returns NULL, with a message on rank 0,
 * when there are too many rows to gather. */
static int *gather_counts(const struct engine *e, const struct init_rows *rows, const long *starts,
                          const int *mine) {
  if (rows->n_rows > INT_MAX) {
    if (e->rank == 0) fprintf(stderr, "mpsph: the case has %ld rows of lattice nodes, more than "
                              "2^31: use a coarser resolution.dx\n", rows->n_rows);
    return NULL;
  }
  int *size = mem_calloc(2 * e->n_ranks, sizeof(int), "row blocks"), *displ = size + e->n_ranks;
  for (int r = 0; r < e->n_ranks; r++) {
    size[r] = (int)(starts[r + 1] - starts[r]);
    displ[r] = (int)starts[r];
  }
  int *all = mem_calloc(rows->n_rows + 1, sizeof(int), "particles per row");
  MPI_Allgatherv(mine, size[e->rank], MPI_INT, all, size, displ, MPI_INT, e->comm);
  free(size);
  return all;
}

/* The global counts from every row's count; the first id of each row into first_id. */
static void number_rows(const struct case_def *c, const struct init_rows *rows, const int *all,
                        int64_t *first_id, struct init_counts *n) {
  memset(n, 0, sizeof *n);
  int64_t id = 0;
  for (long row = 0; row < rows->n_rows; row++) {
    first_id[row] = id;
    id += all[row];
    int k = init_row_source(rows, row);
    if (k < c->n_fluids) {
      n->fluid[c->fluids[k].phase] += all[row];
      n->n_fluid += all[row];
    } else {
      n->n_wall += all[row];
    }
  }
}

/* A row this rank generates, up to which node. */
struct row_need {
  long row, ix_end;
};

static int by_row(const void *a, const void *b) {
  long x = ((const struct row_need *)a)->row, y = ((const struct row_need *)b)->row;
  return (x > y) - (x < y);
}

/* Append to *list the rows of every source crossing top cell t (grown by a node spacing). */
static void rows_of_top(const struct engine *e, const struct init_rows *rows, long t,
                        struct row_need **list, long *n, long *cap) {
  const struct grid *top = &e->space.top;
  long idx[3] = {t % top->n[0], (t / top->n[0]) % top->n[1], t / (top->n[0] * top->n[1])};
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int d = 0; d < top->dim; d++) {
    lo[d] = top->min[d] + top->edge[d] * (double)idx[d] - e->c->dx;
    hi[d] = top->min[d] + top->edge[d] * (double)(idx[d] + 1) + e->c->dx;
  }
  for (int k = 0; k < rows->n_sources; k++) {
    const struct init_source *s = &rows->src[k];
    long first[3], last[3];
    if (!init_rows_in_box(rows, k, top->dim, lo, hi, first, last)) continue;
    for (long iz = first[2]; iz <= last[2]; iz++)
      for (long iy = first[1]; iy <= last[1]; iy++) {
        if (*n == *cap) {
          *cap = 2 * *cap + 64;
          *list = mem_realloc(*list, mem_bytes(*cap, sizeof **list, "rows to generate"), "rows to generate");
        }
        (*list)[(*n)++] = (struct row_need){s->first_row + iy + s->n[1] * iz, last[0] + 1};
      }
  }
}

/* The rows crossing this rank's top cells, each once with its largest node bound, in row order.
 * Returns their number. */
static long rows_needed(const struct engine *e, const struct init_rows *rows, struct row_need **out) {
  struct row_need *list = NULL;
  long n = 0, cap = 0, unique = 0;
  for (long t = 0; t < e->space.top.n_cells; t++)
    if (e->space.top_owner[t] == e->rank) rows_of_top(e, rows, t, &list, &n, &cap);
  qsort(list, n, sizeof *list, by_row);
  for (long k = 0; k < n; k++) {
    if (unique && list[unique - 1].row == list[k].row) {
      if (list[k].ix_end > list[unique - 1].ix_end) list[unique - 1].ix_end = list[k].ix_end;
      continue;
    }
    list[unique++] = list[k];
  }
  *out = list;
  return unique;
}

/* What the generating pass needs: the engine, the first id of the row being generated. */
struct make_ctx {
  struct engine *e;
  int64_t first_id;
};

/* Keep the particle at x if its cell is this rank's. */
static void make_node(void *ctx, const double *x, int source, long ordinal) {
  struct make_ctx *q = ctx;
  struct engine *e = q->e;
  int cell = grid_cell_of(&e->space.grid, x);
  if (space_cell_owner(&e->space, cell) != e->rank) return;
  if (source < e->c->n_fluids) init_add_fluid(e->c, source, x, q->first_id + ordinal, &e->p);
  else init_add_ghost(e->c, source - e->c->n_fluids, x, q->first_id + ordinal, &e->p);
}

/* Generate this rank's particles; 1 (with a message on rank 0) if the total differs from the
 * count, which would be a defect. */
static int generate_own(struct engine *e, const struct init_rows *rows, const int64_t *first_id,
                        const struct init_counts *n) {
  struct row_need *need;
  long n_need = rows_needed(e, rows, &need);
  struct make_ctx q = {e, 0};
  for (long k = 0; k < n_need; k++) {
    q.first_id = first_id[need[k].row];
    init_visit_row(e->c, rows, need[k].row, need[k].ix_end, make_node, &q);
  }
  free(need);
  long made = e->p.n_owned, total;
  MPI_Allreduce(&made, &total, 1, MPI_LONG, MPI_SUM, e->comm);
  if (total == n->n_fluid + n->n_wall) return 0;
  if (e->rank == 0)
    fprintf(stderr, "mpsph: internal error: the ranks generated %ld particles of the %ld counted\n",
            total, n->n_fluid + n->n_wall);
  return 1;
}

/* Count the rows of this rank's block, with the partition weights per top cell summed onto rank 0. Returns
 * 0, or 1 with the message printed (bad input, a particle outside the domain). */
static int count_block(struct engine *e, const struct init_rows *rows, const long *starts,
                       int *mine, int64_t *weight) {
  char err[ERR_LEN] = "";
  struct count_ctx q = {e, weight, 0};
  long bad = init_count_rows(e->c, rows, starts[e->rank], starts[e->rank + 1], mine, count_node, &q,
                             err, sizeof err);
  if (agree_bad_row(e, bad, starts, err)) return 1;
  MPI_Allreduce(MPI_IN_PLACE, &q.outside, 1, MPI_INT, MPI_MAX, e->comm);
  if (q.outside) {
    if (e->rank == 0) fprintf(stderr, "mpsph: a particle lies outside the domain at start-up\n");
    return 1;
  }
  engine_weights_reduce(e, weight);
  return 0;
}

/* Number the rows, partition the top cells by the counted work and generate this rank's own
 * particles. Returns 0 or 1. */
static int number_and_generate(struct engine *e, const struct init_rows *rows, const int *all,
                               const int64_t *weight) {
  char err[ERR_LEN];
  struct init_counts n;
  int64_t *first_id = mem_calloc(rows->n_rows + 1, sizeof(int64_t), "first id per row");
  number_rows(e->c, rows, all, first_id, &n);
  int status = init_no_fluid(e->c, n.n_fluid, err, sizeof err);
  if (status && e->rank == 0) fprintf(stderr, "mpsph: %s\n", err);
  if (!status) engine_print_layout(e, (double)n.n_fluid, (double)n.n_wall);
  if (!status) status = engine_adopt_partition(e, weight, 0);
  if (!status) status = generate_own(e, rows, first_id, &n);
  free(first_id);
  return status;
}

/* On rank 0, a warning for each box region of a coarser phase (dx_ratio > 1) that is not a whole
 * number of its spacings across: its last row stands off the box's far face (a gap at a wall or at
 * the next region). */
static void warn_coarse_misfit(const struct engine *e) {
  const struct case_def *c = e->c;
  if (e->rank != 0) return;
  for (int k = 0; k < c->n_fluids; k++) {
    const struct shape *s = &c->fluids[k].shape;
    double dx = case_phase_dx(c, c->fluids[k].phase);
    if (s->kind != SHAPE_BOX || dx == c->dx) continue;
    for (int d = 0; d < c->dimension; d++) {
      double n = (s->max[d] - s->min[d]) / dx;
      if (fabs(n - round(n)) <= 1e-6 * n) continue;
      fprintf(stderr, "mpsph: warning: fluids.%d (phase %s at %g m): its box is %g spacings wide along axis %d, "
              "not a whole number: its last row stands off the box's upper face\n", k,
              c->phases[c->fluids[k].phase].name, dx, n, d);
      break;
    }
  }
}

int engine_generate(struct engine *e) {
  warn_coarse_misfit(e);
  struct init_rows rows;
  init_rows_open(&rows, e->c, e->prm.support_max);
  long *starts = mem_calloc(e->n_ranks + 1, sizeof(long), "row blocks");
  for (int r = 0; r < e->n_ranks; r++) starts[r] = block_start(&rows, r, e->n_ranks);
  starts[e->n_ranks] = rows.n_rows;
  int *mine = mem_calloc(starts[e->rank + 1] - starts[e->rank] + 1, sizeof(int), "particles per row");
  int64_t *weight = mem_calloc((size_t)e->space.top.n_cells * PARTITION_CONSTRAINTS, sizeof(int64_t),
                               "top cell weights");
  parts_init(&e->p, e->c->dimension, 1024, e->c->n_walls > 0);
  int status = count_block(e, &rows, starts, mine, weight);
  int *all = status ? NULL : gather_counts(e, &rows, starts, mine);
  if (!status) status = all ? number_and_generate(e, &rows, all, weight) : 1;
  if (!status) space_assign_cells(&e->space, &e->p, 0, e->p.n_owned);
  free(all);
  free(weight);
  free(mine);
  free(starts);
  init_rows_close(&rows);
  return status;
}
