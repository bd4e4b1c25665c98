/* pass_neighbours.c — the neighbour cells of a cell as ranges of particle slots. */
#include "passes.h"

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
