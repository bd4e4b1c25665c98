/* test_delta_sph.c — the passes of scheme delta-sph (paper 001) on analytic fields, through the
 * real engine (run with 1 and 2 ranks). A two-phase box, water (1000 kg/m^3) below a light phase
 * (1 kg/m^3), no walls, no gravity, at rest:
 *  1. uniform density in each phase on a randomly perturbed lattice: the same-phase Shepard
 *     density is rho0 of the phase to round-off for every particle, the interface rows included
 *     (an all-phase sum would give the water there about half its density), and the pressure is
 *     the EOS of it;
 *  2. a linear density field rho = rho0 (1 + s.x) on the unperturbed lattice: the Shepard density
 *     reproduces it in the bulk and the delta-SPH diffusion of the volume equation, with the factor
 *     2 of the notes restored, vanishes there to round-off;
 *  3. with random velocities, sum_i m_i du_i/dt = 0 to round-off (the pressure and viscous pair
 *     terms are antisymmetric with the integrated volumes).
 * Usage: test_delta_sph */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"
#include "physics/eos.h"

static const char *case_text =
    "name: delta-sph-test\n"
    "dimension: 2\n"
    "scheme: delta-sph\n"
    "resolution: {dx: 0.02}\n"
    "time: {end: 1.0}\n"
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 30, incompressible: true, p_background: 500}\n"
    "  - {name: light, rho0: 1, c0: 400, gamma: 1.4, p_background: 500}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: light, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "physics: {artificial_viscosity: 0.1, free_surface: off}\n"
    "initial: {pressure: zero}\n"
    "output: {progress_interval: 1000}\n";

static const double slope[2] = {0.011, -0.017};   /* relative density gradient [1/m] */

/* Field k: 0 uniform on a perturbed lattice, 1 linear on the lattice, 2 uniform with random
 * velocities. Masses m = rho dx^2, so the volumes are dx^2. */
static void set_fields(struct engine *e, int k) {
  struct parts *p = &e->p;
  double dx = e->c->dx;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    double lin = 1.0;
    for (int d = 0; d < 2; d++) {
      if (k == 0) p->x[d][i] += 0.3 * dx * engine_test_noise(p->id[i], d);
      if (k == 1) lin += slope[d] * p->x[d][i];
      p->v[d][i] = k == 2 ? engine_test_noise(p->id[i], 10 + d) : 0.0;
    }
    p->rho[i] = e->c->phases[p->phase[i]].rho0 * lin;
    p->m[i] = p->rho[i] * dx * dx;
  }
}

static void evaluate(struct engine *e, int k) {
  set_fields(e, k);
  engine_test_rebuild(e);
  e->stage = 0;
  engine_evaluate(e, 0);
}

/* Largest relative Shepard-density error over owned fluid (with bulk_only: those more than 2.2
 * supports inside their phase's region, so that their neighbours' Shepard sums are complete too:
 * on a truncated support the Shepard average of a linear field is biased), and the largest
 * relative |drho| there, over all ranks. */
static void worst(const struct engine *e, int linear, int bulk_only, double *rho_err, double *drho_err) {
  const struct parts *p = &e->p;
  double out[2] = {0, 0}, support = e->prm.kern.support;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    double x = p->x[0][i], y = p->x[1][i], lo = p->phase[i] == 0 ? 0.0 : 0.5;
    if (bulk_only && fmin(fmin(x, 1 - x), fmin(y - lo, lo + 0.5 - y)) < 2.2 * support) continue;
    double rho0 = e->c->phases[p->phase[i]].rho0, exact = rho0;
    if (linear) exact *= 1 + slope[0] * x + slope[1] * y;
    out[0] = fmax(out[0], fabs(e->w.rho_s[i] - exact) / rho0);
    out[1] = fmax(out[1], fabs(e->w.drho[i]) / rho0);
    CHECK(e->p.p[i] == eos_pressure(&e->c->phases[p->phase[i]], e->w.rho_s[i]), "pressure = EOS(rho^S)");
  }
  MPI_Allreduce(MPI_IN_PLACE, out, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  *rho_err = out[0];
  *drho_err = out[1];
}

static void check_momentum(const struct engine *e) {
  const struct parts *p = &e->p;
  double sum[4] = {0, 0, 0, 0};
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < 2 && p->phase[i] != PHASE_WALL; d++) {
      sum[d] += p->m[i] * e->w.dv[d][i];
      sum[2 + d] += fabs(p->m[i] * e->w.dv[d][i]);
    }
  MPI_Allreduce(MPI_IN_PLACE, sum, 4, MPI_DOUBLE, MPI_SUM, e->comm);
  if (e->rank == 0) printf("momentum: sum m du/dt = (%.3g, %.3g), scale (%.3g, %.3g)\n", sum[0], sum[1], sum[2], sum[3]);
  for (int d = 0; d < 2; d++)
    CHECK(fabs(sum[d]) <= 1e-12 * sum[2 + d], "momentum %c: %g, scale %g", "xy"[d], sum[d], sum[2 + d]);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  char dir[256] = "/tmp/mpsph-test-dsph-XXXXXX";
  if (engine_test_scratch(dir, sizeof dir)) return 1;
  static struct case_def c;
  struct engine e;
  if (engine_test_start(dir, case_text, &c, &e)) return check_report("test_delta_sph");
  CHECK(e.prm.features & FEAT_SHEPARD && !(e.prm.features & (FEAT_SHIFT | FEAT_TIC | FEAT_DAMPER)),
        "delta-sph pipeline: Shepard density, no shifting, tensile control or damper");
  double rho_err, drho_err;
  evaluate(&e, 1);   /* first: the lattice is still unperturbed */
  worst(&e, 1, 1, &rho_err, &drho_err);
  if (rank == 0) printf("linear field, bulk: Shepard density error %.3g, |drho/dt|/rho0 %.3g\n", rho_err, drho_err);
  CHECK(rho_err <= 1e-13 && drho_err <= 1e-11, "linear density: Shepard error %g, diffusion %g", rho_err, drho_err);
  evaluate(&e, 0);
  worst(&e, 0, 0, &rho_err, &drho_err);
  if (rank == 0) printf("uniform, perturbed lattice: Shepard density error %.3g (all particles)\n", rho_err);
  CHECK(rho_err <= 1e-13, "uniform density: Shepard error %g", rho_err);
  evaluate(&e, 2);
  check_momentum(&e);
  return engine_test_finish(&e, dir, "test_delta_sph");
}
