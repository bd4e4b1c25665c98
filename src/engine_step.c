/* engine_step.c — the stage pipeline, the RK4 step and the time-step limits (paper 000 Eq. 12). */
#include <math.h>
#include <stdlib.h>
#include "eos.h"
#include "passes.h"

enum { HF_POS = 1, HF_VEL = 2, HF_RHO = 4, HF_P = 8, HF_MASS = 16, HF_GRAD_RHO = 32 };

static double *grow(double *a, long n) {
  double *q = realloc(a, (n ? n : 1) * sizeof(double));
  if (!q) abort();
  return q;
}

void engine_work_reserve(struct engine *e) {
  struct work *w = &e->w;
  long n = e->p.capacity;
  if (n <= w->capacity) return;
  for (int d = 0; d < e->p.dim; d++) {
    w->grad_rho[d] = grow(w->grad_rho[d], n);
    w->dv[d] = grow(w->dv[d], n);
    w->x0[d] = grow(w->x0[d], n);
    w->v0[d] = grow(w->v0[d], n);
    w->sum_x[d] = grow(w->sum_x[d], n);
    w->sum_v[d] = grow(w->sum_v[d], n);
  }
  w->vol = grow(w->vol, n);
  w->drho = grow(w->drho, n);
  w->rho0 = grow(w->rho0, n);
  w->sum_rho = grow(w->sum_rho, n);
  w->capacity = n;
}

/* The arrays named by a halo field mask. */
static int halo_field_list(struct engine *e, int mask, double **f) {
  struct parts *p = &e->p;
  int n = 0;
  for (int d = 0; d < p->dim; d++) {
    if (mask & HF_POS) f[n++] = p->x[d];
    if (mask & HF_VEL) f[n++] = p->v[d];
    if (mask & HF_GRAD_RHO) f[n++] = e->w.grad_rho[d];
  }
  if (mask & HF_RHO) f[n++] = p->rho;
  if (mask & HF_P) f[n++] = p->p;
  if (mask & HF_MASS) f[n++] = p->m;
  return n;
}

static void add_op(struct engine *e, const char *name, void (*pass)(struct engine *), int mask) {
  e->ops[e->n_ops++] = (struct stage_op){.name = name, .pass = pass, .halo_fields = mask};
}

void engine_assemble(struct engine *e) {
  int walls = e->c->n_walls > 0;
  e->n_ops = 0;
  add_op(e, "halo: positions, velocities, densities, pressures", NULL, HF_POS | HF_VEL | HF_RHO | HF_P);
  if (walls) add_op(e, "wall ghosts: Shepard interpolation at mirror points", pass_wall_ghosts, 0);
  add_op(e, "density gradient: renormalised, same phase", pass_density_gradient, 0);
  add_op(e, walls ? "halo: density gradients, wall ghost values" : "halo: density gradients", NULL,
         HF_GRAD_RHO | (walls ? HF_VEL | HF_RHO | HF_P | HF_MASS : 0));
  add_op(e, "fluid rhs: continuity + delta diffusion, pressure, viscosity, gravity", pass_fluid_rhs, 0);
  if (e->rank) return;
  printf("pipeline per RK stage (%d operations):\n", e->n_ops);
  for (int k = 0; k < e->n_ops; k++) printf("  %d. %s\n", k + 1, e->ops[k].name);
}

void engine_evaluate(struct engine *e, int skip_state_halo) {
  double *fields[16];
  for (int k = skip_state_halo ? 1 : 0; k < e->n_ops; k++) {
    struct stage_op *op = &e->ops[k];
    double t0 = MPI_Wtime();
    if (op->pass) {
      e->pass_pairs = 0;
      op->pass(e);
      op->pairs += e->pass_pairs;
    } else {
      halo_update(&e->halo, &e->p, fields, halo_field_list(e, op->halo_fields, fields));
    }
    op->seconds += MPI_Wtime() - t0;
    if (op->pass) e->t_compute += MPI_Wtime() - t0;
  }
}

/* Global time step from the first-stage accelerations: acoustic, acceleration, viscous limits. */
static double time_step(struct engine *e) {
  const struct case_def *c = e->c;
  double a_max = 0;
  for (long i = 0; i < e->p.n_owned; i++) {
    if (e->p.phase[i] == PHASE_WALL) continue;
    double a2 = 0;
    for (int d = 0; d < e->p.dim; d++) a2 += e->w.dv[d][i] * e->w.dv[d][i];
    if (!(a2 <= a_max)) a_max = a2;   /* NaN propagates into a_max */
  }
  MPI_Allreduce(MPI_IN_PLACE, &a_max, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  double dt = c->cfl * e->h / e->c_max;
  if (a_max > 0) dt = fmin(dt, 0.25 * sqrt(e->h / sqrt(a_max)));
  for (int ph = 0; ph < c->n_phases; ph++) {
    const struct phase *f = &c->phases[ph];
    if (c->alpha > 0) dt = fmin(dt, e->h / (c->alpha * f->c0));
    if (f->viscosity > 0) dt = fmin(dt, 0.125 * e->h * e->h * f->rho0 / f->viscosity);
  }
  return fmin(dt, c->t_end - e->time);
}

static void save_state(struct engine *e) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    for (int d = 0; d < p->dim; d++) {
      e->w.x0[d][i] = p->x[d][i];
      e->w.v0[d][i] = p->v[d][i];
    }
    e->w.rho0[i] = p->rho[i];
  }
}

/* Accumulate stage s's derivatives with RK4 weight and move owned fluid to the next stage state. */
static void rk4_update(struct engine *e, int s) {
  static const double weight[4] = {1, 2, 2, 1}, next[3] = {0.5, 0.5, 1.0};
  struct parts *p = &e->p;
  struct work *w = &e->w;
  double ws = weight[s], step = s < 3 ? next[s] * e->dt : e->dt / 6.0;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    for (int d = 0; d < p->dim; d++) {
      w->sum_x[d][i] = (s ? w->sum_x[d][i] : 0) + ws * p->v[d][i];
      w->sum_v[d][i] = (s ? w->sum_v[d][i] : 0) + ws * w->dv[d][i];
    }
    w->sum_rho[i] = (s ? w->sum_rho[i] : 0) + ws * w->drho[i];
    for (int d = 0; d < p->dim; d++) {
      p->x[d][i] = w->x0[d][i] + step * (s < 3 ? p->v[d][i] : w->sum_x[d][i]);
      p->v[d][i] = w->v0[d][i] + step * (s < 3 ? w->dv[d][i] : w->sum_v[d][i]);
    }
    p->rho[i] = w->rho0[i] + step * (s < 3 ? w->drho[i] : w->sum_rho[i]);
    p->p[i] = eos_pressure(&e->c->phases[p->phase[i]], p->rho[i]);
  }
}

int engine_step(struct engine *e) {
  engine_work_reserve(e);
  save_state(e);
  for (int s = 0; s < 4; s++) {
    engine_evaluate(e, s == 0);
    if (s == 0) {
      e->dt = time_step(e);
      if (!(e->dt > 0) || !isfinite(e->dt)) return 2;
    }
    rk4_update(e, s);
  }
  e->time += e->dt;
  e->step++;
  return 0;
}
