/* pass_neighbours.c — the neighbour cells of a cell as ranges of particle slots; the loop over
 * owned particles with their neighbour lists. */
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
  const struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    particle_fn fn = p->phase[i] == PHASE_WALL ? wall : fluid;
    struct neighbours nb = nlist_of(&e->nl, i);
    if (fn) fn(e, i, &nb);
  }
}

void pass_neighbour_lists(struct engine *e) {
  nlist_build(&e->nl, &e->space, &e->p, e->kern.support * ENGINE_CELL_SKIN);
}
