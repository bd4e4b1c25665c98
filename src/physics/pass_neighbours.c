/* pass_neighbours.c — the loop over owned particles with their neighbour lists. */
#include "physics/passes.h"

#define PROGRESS_EVERY_CELLS 64   /* cells between two calls of ctx->progress */

void pass_for_each_owned(struct pass_ctx *ctx, particle_fn fluid, particle_fn wall) {
  const struct space *s = ctx->space;
  const struct parts *p = ctx->p;
  long n = ctx->cells ? ctx->n_cells : s->n_owned_cells;
  for (long q = 0; q < n; q++) {
    if (ctx->progress && q % PROGRESS_EVERY_CELLS == 0) ctx->progress(ctx->progress_arg);
    long k = ctx->cells ? ctx->cells[q] : q;
    long c = s->owned_cells[k], count = space_cell_size(s, c);
    if (!count) continue;
    long first = space_cell_first(s, c);
    struct neighbour_ranges r;
    neighbour_ranges(s, c, &r);
    nlist_enter_cell(ctx->nl, &r);
    long f = 0;   /* particles of the cell with a neighbour list before slot i */
    for (long i = first; i < first + count; i++) {
      int listed = part_has(p->phase[i], KIND_LISTED);
      particle_fn fn = listed ? fluid : wall;
      if (fn) {
        struct neighbours nb = listed ? nlist_of(ctx->nl, k, f) : nlist_none();
        fn(ctx, i, &nb);
      }
      f += listed;
    }
  }
}

_Static_assert(NLIST_MAX_PHASES >= CASE_MAX_PHASES, "the lists by phase hold every phase");

void pass_neighbour_lists(struct pass_ctx *ctx) {
  const struct physics_params *prm = ctx->prm;
  nlist_build(ctx->nl, ctx->space, ctx->p, prm->list_radius, prm->multires ? prm->phase_list_radius : NULL,
              ctx->c->n_phases);
}
