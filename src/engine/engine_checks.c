/* engine_checks.c — the instability checks (exit status 2). After every RK stage: a non-finite
 * derivative, or a particle that moved farther within the step than the cell skin allows. After the first stage: a time step below time.dt_min. After every step, on the new
 * state: a particle outside the domain, deeper than SOLID_DEPTH_DX inside the solid of a wall, or
 * with a density outside its phase's band; then the energy check (energy_check.c). The checks only
 * read the state; each makes one pass over the owned particles and one global reduction (none for
 * the time step, which every rank knows), so all ranks stop at the same step. */
#include <math.h>
#include <stdio.h>
#include "engine/engine.h"
#include "case/geometry.h"

#define SOLID_DEPTH_DX 0.5   /* depth inside a wall's solid [dx] beyond which a particle trips */

/* 1 if owned particle i has moved farther since the start of the step than the cell skin allows:
 * the cells and neighbour lists of the step then no longer hold all its neighbours. */
static int moved_too_far(const struct engine *e, long i) {
  double limit = engine_shift_max(e), shift2 = 0;
  for (int d = 0; d < e->p.dim; d++) shift2 += (e->p.x[d][i] - e->w.x0[d][i]) * (e->p.x[d][i] - e->w.x0[d][i]);
  return !(shift2 <= limit * limit);
}

/* The first owned fluid particle (or moving-wall ghost) with a non-finite derivative or which
 * moved too far within the step; what tripped in *what. */
static long first_non_finite(const struct engine *e, const char **what) {
  const struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    *what = "moved farther within one step than the cell skin allows (time step too large)";
    int integrated = part_has(p->phase[i], KIND_INTEGRATED);
    if ((integrated || engine_moving_ghost(e, i)) && moved_too_far(e, i)) return i;
    if (!integrated) continue;
    *what = "drho/dt";
    if (!isfinite(e->w.drho[i])) return i;
    for (int d = 0; d < p->dim; d++) {
      *what = "du/dt";
      if (!isfinite(e->w.dv[d][i])) return i;
      *what = "shifting velocity";
      if (e->w.du[d] && !isfinite(e->w.du[d][i])) return i;
    }
  }
  return -1;
}

/* Stop all ranks if any holds an offending particle (bad >= 0 here): report the local one with
 * `what` and return 2; 0 when none does. */
static int stop_if_any(struct engine *e, long bad, const char *what) {
  int any = bad >= 0;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, e->comm);
  if (bad >= 0) engine_report_particle(e, bad, what);
  return any ? 2 : 0;
}

int engine_check_derivatives(struct engine *e) {
  const char *what = "";
  long bad = first_non_finite(e, &what);
  return stop_if_any(e, bad, what);
}

/* 1 if particle i lies deeper than SOLID_DEPTH_DX inside the solid of a wall (described in what). */
static int in_solid(const struct engine *e, long i, char *what, size_t len) {
  double x[3] = {0, 0, 0}, depth;
  for (int d = 0; d < e->p.dim; d++) x[d] = e->p.x[d][i];
  int w = walls_solid_at(e->c, e->prm.frames, x, &depth);
  if (w < 0 || depth <= SOLID_DEPTH_DX * e->c->dx) return 0;
  snprintf(what, len, "entered the solid of walls.%d, %.3g dx beyond its boundary", w,
           depth / e->c->dx);
  return 1;
}

/* 1 if the density of particle i lies outside its phase's band (described in what). */
static int out_of_band(const struct engine *e, long i, char *what, size_t len) {
  int ph = e->p.phase[i];
  const struct phase *f = &e->c->phases[ph];
  double ratio = e->p.rho[i] / f->rho0;
  if (ratio >= f->density_band[0] && ratio <= f->density_band[1]) return 0;
  snprintf(what, len, "density %.6g rho0 outside phases.%d.density_band [%g, %g]", ratio, ph,
           f->density_band[0], f->density_band[1]);
  return 1;
}

/* The first owned fluid particle inside a solid or out of its density band, or -1. */
static long first_bad_state(const struct engine *e, char *what, size_t len) {
  for (long i = 0; i < e->p.n_owned; i++)
    if (part_has(e->p.phase[i], KIND_INTEGRATED) && (in_solid(e, i, what, len) || out_of_band(e, i, what, len)))
      return i;
  return -1;
}

int engine_check_state(struct engine *e, long left_domain) {
  char what[160] = "left the domain";
  long bad = left_domain >= 0 ? left_domain : first_bad_state(e, what, sizeof what);
  int status = stop_if_any(e, bad, what);
  return status ? status : engine_check_energy(e);
}

long engine_largest_vector(const struct engine *e, double *const vec[3], double *norm) {
  struct { double a2; int rank; } local = {-1, e->rank}, global;
  long best = -1;
  for (long i = 0; i < e->p.n_owned; i++) {
    if (!part_has(e->p.phase[i], KIND_INTEGRATED)) continue;
    double a2 = 0;
    for (int d = 0; d < e->p.dim; d++) a2 += vec[d][i] * vec[d][i];
    if (a2 > local.a2) local.a2 = a2, best = i;
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, e->comm);
  *norm = sqrt(global.a2);
  return global.rank == e->rank ? best : -1;
}

int engine_check_dt(struct engine *e, const char *limit) {
  if (e->dt >= e->c->dt_min && isfinite(e->dt)) return 0;
  double a_max;
  long i = engine_largest_vector(e, e->w.dv, &a_max);
  char what[256];
  snprintf(what, sizeof what, "time step %.3g s below time.dt_min %.3g s, set by the %s limit; "
           "this particle has the largest acceleration, %.3g m/s^2", e->dt, e->c->dt_min, limit,
           a_max);
  if (i >= 0) engine_report_particle(e, i, what);
  return 2;
}
