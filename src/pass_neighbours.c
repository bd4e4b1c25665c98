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

void pass_for_each_owned(struct engine *e, particle_fn fluid, particle_fn wall) {
  const struct space *s = &e->space;
  for (long k = 0; k < s->n_owned_cells; k++) {
    long c = s->owned_cells[k];
    if (!s->cell_count[c]) continue;
    struct neighbour_ranges r;
    neighbour_ranges(s, c, &r);
    for (long i = s->cell_start[c]; i < s->cell_start[c] + s->cell_count[c]; i++) {
      particle_fn fn = e->p.phase[i] == PHASE_WALL ? wall : fluid;
      if (fn) fn(e, i, &r);
    }
  }
}
