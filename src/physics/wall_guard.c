/* wall_guard.c — the wall's last line of defence: after every step, a fluid particle closer to
 * a wall's boundary than physics.wall_guard x dx (or already inside its solid) that moves toward
 * the wall loses the normal component of its velocity relative to the wall. The ghost wall pushes
 * back through the pressure field only; a particle much lighter than its neighbours (air beside
 * water under a kernel-scale pressure difference) can be driven through the ghost layers within a
 * few steps whatever pressure the ghosts hold (doc/stability.md). Paper 000 (§2.5, its ref. [69])
 * names a normal-velocity correction of near-wall particles for this; the form here is ours
 * (doc/theory.md §5). It acts on a particle only when it trips, so a flow that keeps its distance
 * from the walls is bitwise unchanged. On a rigid body the guard is a contact force: what it
 * removes from a particle's acceleration (in a stage) or velocity (after a step) goes to the body
 * as a load or an impulse (physics/pass_ctx.h). */
#include <math.h>
#include "case/geometry.h"
#include "physics/passes.h"
#include "physics/wall_guard.h"

/* Signed distance [m] of x (in the current frame) from wall w's boundary, positive on the fluid
 * side, and the unit normal n toward the fluid and the boundary point q, both in the current
 * frame. Returns 0 where the direction is undefined (x on the boundary). */
static int wall_side(const struct pass_ctx *ctx, int w, const double *x, double *dist, double *n, double *q) {
  const struct wall *wl = &ctx->c->walls[w];
  int dim = ctx->p->dim;
  double xw[3] = {x[0], x[1], dim == 3 ? x[2] : 0}, qw[3] = {0, 0, 0}, tip[3] = {0, 0, 0};
  if (wl->moving) frame_reference(&ctx->prm->frames[w], dim, x, xw);
  int inside = shape_contains(&wl->shape, dim, xw);
  int fluid_side = inside == (wl->fluid_side == FLUID_INSIDE);
  double d = shape_nearest_boundary(&wl->shape, dim, xw, qw);
  if (!(d > 0)) return 0;
  double sign = fluid_side ? 1.0 : -1.0;
  for (int k = 0; k < dim; k++) tip[k] = qw[k] + sign * (xw[k] - qw[k]) / d;
  double tip_now[3] = {0, 0, 0};
  if (wl->moving) {
    frame_position(&ctx->prm->frames[w], dim, qw, q);
    frame_position(&ctx->prm->frames[w], dim, tip, tip_now);
  } else
    for (int k = 0; k < dim; k++) q[k] = qw[k], tip_now[k] = tip[k];
  for (int k = 0; k < dim; k++) n[k] = tip_now[k] - q[k];
  *dist = sign * d;
  return 1;
}

/* Within the guard distance of wall w (in guard[], [m]): the particle's normal n toward the
 * fluid, and the wall's velocity and acceleration at its nearest boundary point. Returns 0 if
 * particle i is farther away. */
static int near_wall(const struct pass_ctx *ctx, long i, int w, double guard, double *n, double *u_wall,
                     double *a_wall) {
  int dim = ctx->p->dim;
  double x[3] = {0, 0, 0}, q[3] = {0, 0, 0}, dist;
  for (int k = 0; k < dim; k++) x[k] = ctx->p->x[k][i], u_wall[k] = 0, a_wall[k] = 0;
  if (!wall_side(ctx, w, x, &dist, n, q) || dist >= guard) return 0;
  if (ctx->c->walls[w].moving) {
    frame_velocity(&ctx->prm->frames[w], dim, q, u_wall);
    frame_acceleration(&ctx->prm->frames[w], dim, q, a_wall);
  }
  return 1;
}

/* Normal component of a - b along n. */
static double normal_part(int dim, const double *n, const double *a, const double *b) {
  double s = 0;
  for (int k = 0; k < dim; k++) s += (a[k] - b[k]) * n[k];
  return s;
}

/* Subtract the negative part of component c along n from the field f at particle i, the change
 * into change; returns whether there was one (c < 0). */
static int remove_inward(double *const *f, long i, int dim, const double *n, double c, double *change) {
  if (!(c < 0)) return 0;
  for (int k = 0; k < dim; k++) {
    change[k] = -c * n[k];
    f[k][i] += change[k];
  }
  return 1;
}

/* The reaction on wall w, if it is a rigid body, of the guard's change to particle i. */
static void body_reaction(const struct pass_ctx *ctx, long i, int w, enum body_load_source source,
                          const double *change) {
  if (ctx->prm->body_walls >> w & 1) body_load_append(ctx->loads, ctx->p, i, w, source, change);
}

/* The guard distance [m], 0 when the guard is off. */
static double guard_distance(const struct pass_ctx *ctx) {
  return ctx->c->wall_guard * ctx->c->dx;
}

/* The largest acceleration into the wall [m/s^2, <= 0] the guard leaves a particle whose velocity
 * relative to the wall has the normal component un: none if it is at rest or moving in; moving
 * out, what stops it within one step (without the step, the first one, any). More would turn it
 * within the step and carry it in before the step's velocity correction: a particle a thousand
 * times lighter than its neighbours (air squeezed against a wall by water) gains a dt^2 of
 * inward travel every time (cases/wedge-cavity-wang/README.md). */
static double inward_limit(const struct pass_ctx *ctx, double un) {
  if (!(un > 0)) return 0.0;
  return ctx->prm->dt_step > 0 ? -un / ctx->prm->dt_step : -INFINITY;
}

void pass_wall_guard(struct pass_ctx *ctx) {
  struct parts *p = ctx->p;
  double guard = guard_distance(ctx), n[3], u_wall[3], a_wall[3], v[3], a[3], du[3], zero[3] = {0, 0, 0};
  double change[3] = {0, 0, 0};
  int dim = p->dim;
  for (long i = 0; i < p->n_owned; i++) {
    if (!part_has(p->phase[i], KIND_INTEGRATED)) continue;
    for (int w = 0; w < ctx->c->n_walls; w++) {
      if (!near_wall(ctx, i, w, guard, n, u_wall, a_wall)) continue;
      for (int k = 0; k < dim; k++) v[k] = p->v[k][i], a[k] = ctx->w->dv[k][i];
      double an = normal_part(dim, n, a, a_wall) - inward_limit(ctx, normal_part(dim, n, v, u_wall));
      if (remove_inward(ctx->w->dv, i, dim, n, an, change)) body_reaction(ctx, i, w, LOAD_GUARD, change);
      if (!ctx->w->du[0]) continue;
      for (int k = 0; k < dim; k++) du[k] = ctx->w->du[k][i];
      remove_inward(ctx->w->du, i, dim, n, normal_part(dim, n, du, zero), change);
    }
  }
}

long wall_guard_apply(const struct pass_ctx *ctx) {
  struct parts *p = ctx->p;
  double guard = guard_distance(ctx), n[3], u_wall[3], a_wall[3], v[3], change[3] = {0, 0, 0};
  int dim = p->dim;
  long hits = 0;
  if (!(guard > 0)) return 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (!part_has(p->phase[i], KIND_INTEGRATED)) continue;
    for (int w = 0; w < ctx->c->n_walls; w++) {
      if (!near_wall(ctx, i, w, guard, n, u_wall, a_wall)) continue;
      for (int k = 0; k < dim; k++) v[k] = p->v[k][i];
      double un = normal_part(dim, n, v, u_wall);
      hits += un < 0;
      if (remove_inward(p->v, i, dim, n, un, change)) body_reaction(ctx, i, w, LOAD_GUARD_IMPULSE, change);
    }
  }
  return hits;
}
