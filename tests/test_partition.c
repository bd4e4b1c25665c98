/* test_partition.c — METIS partition of the cell graph: every cell gets exactly one valid part,
 * every part gets cells, the work is balanced within 10 % and the particles within 15 %; an
 * empty cell goes to the rank of a nearest occupied cell; a re-partition keeps each part on the
 * rank that holds it; fewer occupied cells than parts is an error. */
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "parallel/partition.h"

/* Partition g into n_parts with cells of random particles: in the left half of the cells wall
 * ghosts (2 work units each), in the right half fluid (8 units), so that the work alone would
 * give a left rank about four times the particles of a right one. */
static void check_parts(const struct grid *g, int n_parts, unsigned seed) {
  int64_t *w = malloc(g->n_cells * PARTITION_CONSTRAINTS * sizeof(int64_t));
  int *owner = malloc(g->n_cells * sizeof(int)), *count = calloc(n_parts, sizeof(int));
  char err[256];
  srand(seed);
  for (long c = 0; c < g->n_cells; c++) {
    int64_t n = 1 + rand() % 64, wall = c % g->n[0] < g->n[0] / 2;
    w[c * PARTITION_CONSTRAINTS + WEIGHT_PARTICLES] = wall ? 4 * n : n;
    w[c * PARTITION_CONSTRAINTS + WEIGHT_WORK] = 8 * n;
  }
  int status = partition_cells(g, w, n_parts, NULL, MPI_COMM_WORLD, owner, err, sizeof(err));
  CHECK(status == 0, "%d parts: partition failed: %s", n_parts, err);
  long valid = 0;
  for (long c = 0; c < g->n_cells; c++)
    if (owner[c] >= 0 && owner[c] < n_parts) {
      valid++;
      count[owner[c]]++;
    }
  CHECK(valid == g->n_cells, "%d parts: %ld of %ld cells have a valid owner", n_parts, valid, g->n_cells);
  for (int r = 0; r < n_parts; r++) CHECK(count[r] > 0, "%d parts: part %d got no cell", n_parts, r);
  double work = partition_imbalance(g, w, WEIGHT_WORK, owner, n_parts);
  double particles = partition_imbalance(g, w, WEIGHT_PARTICLES, owner, n_parts);
  CHECK(work <= 0.10, "%d parts: work imbalance %.3f > 0.10", n_parts, work);
  CHECK(particles <= 0.15, "%d parts: particle imbalance %.3f > 0.15", n_parts, particles);
  free(w);
  free(owner);
  free(count);
}

/* Chebyshev distance between cells a and b of g [cells]. */
static long cell_distance(const struct grid *g, long a, long b) {
  long d = 0, na = a, nb = b;
  for (int k = 0; k < g->dim; k++) {
    long da = labs(na % g->n[k] - nb % g->n[k]);
    if (da > d) d = da;
    na /= g->n[k];
    nb /= g->n[k];
  }
  return d;
}

/* Whether empty cell c's owner is the owner of an occupied cell at the least distance. */
static int owned_as_nearest(const struct grid *g, const int64_t *w, const int *owner, long c) {
  long best = -1;
  int match = 0;
  for (long o = 0; o < g->n_cells; o++) {
    if (w[o * PARTITION_CONSTRAINTS + WEIGHT_PARTICLES] == 0) continue;
    long d = cell_distance(g, c, o);
    if (best < 0 || d < best) {
      best = d;
      match = 0;
    }
    if (d == best && owner[o] == owner[c]) match = 1;
  }
  return match;
}

/* Cells of the upper-right quarter of g empty, the rest occupied: every empty cell takes the
 * rank of a nearest occupied one; a second partition given the first, its ranks renumbered
 * (r -> r + 1 mod n), as the current owners returns that renumbered partition. */
static void check_empty_and_kept(const struct grid *g, int n_parts) {
  int64_t *w = calloc(g->n_cells * PARTITION_CONSTRAINTS, sizeof(int64_t));
  int *first = malloc(g->n_cells * sizeof(int)), *prev = malloc(g->n_cells * sizeof(int)),
      *again = malloc(g->n_cells * sizeof(int));
  char err[256];
  for (long c = 0; c < g->n_cells; c++) {
    int empty = c % g->n[0] >= g->n[0] / 2 && (c / g->n[0]) % g->n[1] >= g->n[1] / 2;
    w[c * PARTITION_CONSTRAINTS + WEIGHT_PARTICLES] = empty ? 0 : 5 + c % 7;
    w[c * PARTITION_CONSTRAINTS + WEIGHT_WORK] = empty ? 0 : 3 * (5 + c % 7);
  }
  CHECK(partition_cells(g, w, n_parts, NULL, MPI_COMM_WORLD, first, err, sizeof(err)) == 0, "%s", err);
  long wrong = 0, kept = 0;
  for (long c = 0; c < g->n_cells; c++)
    if (w[c * PARTITION_CONSTRAINTS + WEIGHT_PARTICLES] == 0 && !owned_as_nearest(g, w, first, c)) wrong++;
  CHECK(wrong == 0, "%d parts: %ld empty cells not owned as their nearest occupied cell", n_parts, wrong);
  for (long c = 0; c < g->n_cells; c++) prev[c] = (first[c] + 1) % n_parts;
  CHECK(partition_cells(g, w, n_parts, prev, MPI_COMM_WORLD, again, err, sizeof(err)) == 0, "%s", err);
  for (long c = 0; c < g->n_cells; c++) kept += again[c] == prev[c];
  CHECK(kept == g->n_cells, "%d parts: the re-partition kept %ld of %ld cells on their rank", n_parts, kept,
        g->n_cells);
  free(w);
  free(first);
  free(prev);
  free(again);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  struct grid g2, g3, tiny;
  double lo[3] = {0, 0, 0}, hi[3] = {1, 0.5, 0.25};
  grid_init(&g2, 2, lo, hi, 0.01);
  grid_init(&g3, 3, lo, hi, 0.02);
  for (int n = 1; n <= 8; n *= 2) check_parts(&g2, n, 3u + n);
  check_parts(&g2, 3, 99u);
  check_parts(&g3, 4, 5u);
  check_parts(&g3, 7, 6u);
  check_empty_and_kept(&g2, 5);
  check_empty_and_kept(&g3, 6);
  grid_init(&tiny, 2, lo, hi, 0.3);   /* 3 x 1 cells */
  int64_t w[3 * PARTITION_CONSTRAINTS] = {1, 1, 1, 1, 0, 0};
  int owner[3];
  char err[256] = "";
  CHECK(partition_cells(&tiny, w, 4, NULL, MPI_COMM_WORLD, owner, err, sizeof(err)) == 1, "4 parts of 2 occupied cells refused");
  CHECK(strstr(err, "fill 2 cells") && strstr(err, "4 ranks"), "message names the counts: %s", err);
  int status = check_report("test_partition");
  MPI_Finalize();
  return status;
}
