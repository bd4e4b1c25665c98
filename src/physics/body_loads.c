/* body_loads.c — the reactions the fluid particles put on rigid bodies, collected per stage (or
 * after a step) for the engine's fixed-order sum (physics/pass_ctx.h). */
#include "base/mem.h"
#include "physics/pass_ctx.h"

void body_load_append(struct body_loads *l, const struct parts *p, long i, int w, enum body_load_source source,
                      const double *dv) {
  if (l->n == l->cap) {
    l->cap = l->cap ? 2 * l->cap : 256;
    l->at = mem_realloc(l->at, mem_bytes((size_t)l->cap, sizeof *l->at, "body loads"), "body loads");
  }
  struct body_load *b = &l->at[l->n++];
  *b = (struct body_load){.id = p->id[i], .wall = w, .source = source};
  for (int d = 0; d < p->dim; d++) {
    b->x[d] = p->x[d][i];
    b->force[d] = -p->m[i] * dv[d];
  }
}
