/* test_interface_pressure.c — the other-phase pressure of the momentum pair sum at a 1000:1
 * interface at rest (run with 1 and 2 ranks). Water (1000 kg/m^3) below y = 0.5, air (1 kg/m^3)
 * above, on the lattice with the exact hydrostatic pressure of the initial state, no walls: at
 * equilibrium every particle's acceleration dv/dt is zero. Checked on the particles away from the
 * box's free sides (more than one support from x = 0, 1 and from y = 0, 1):
 *  1. interface_pressure: sum (paper 000) — the first air row's |dv/dt| exceeds 100 g: the light
 *     particle's kernel spans the water's gradient rho_w g, which gives it an acceleration of the
 *     order of (rho_w / rho_a) g times the water's share of the kernel (doc/theory.md §4);
 *  2. interface_pressure: density-weighted — |dv/dt| <= 2 g for every particle, both phases: for
 *     an air particle the water's part of the sum is 2 (rho_a/rho_w) sum p_j gradW V_j / rho_a,
 *     at most the water's share of rho_w g / rho_w = g, and the air's own part is its one-sided
 *     gradient, at most g; a water particle sees a free surface at the interface pressure, whose
 *     one-sided sum is within g in the rows below it;
 *  3. with density-weighted, the pressure term conserves momentum: sum m dv/dt = sum m g to
 *     round-off (the pair term 2 p_ij is symmetric in i, j);
 *  4. with density-weighted and random velocities, the pressure's work and the internal energy
 *     change of the continuity equation cancel: sum m u.(dv/dt - g) + sum m p/rho^2 drho/dt = 0
 *     to round-off, because an other-phase pair enters the divergence of i with the weight
 *     2 rho_j/(rho_i + rho_j) (doc/theory.md section 3); with the unweighted divergence the
 *     balance is off by the pairs' (p_i + p_j - 2 p_ij) V_i V_j u_ji.grad_i W_ij.
 * Usage: test_interface_pressure [TMPDIR] */
#include <math.h>
#include <stdio.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"

#define G 9.81

static const char *case_text =
    "name: interface-pressure-test\n"
    "dimension: 2\n"
    "resolution: {dx: 0.02}\n"
    "gravity: [0, -9.81]\n"
    "time: {end: 1.0}\n"
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 30, incompressible: true}\n"
    "  - {name: air, rho0: 1, c0: 340, gamma: 1.4}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: air, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "physics: {shifting: none, acoustic_damper: 0, artificial_viscosity: 0, delta: 0,\n"
    "          tensile_control: false, free_surface: off}\n"
    "output: {progress_interval: 1000}\n";

/* Largest |dv/dt| [m/s^2] over interior particles of phase ph (-1: both) within band [m] of the
 * interface y = 0.5 (band <= 0: all interior particles), over all ranks. */
static double max_acceleration(const struct engine *e, int ph, double band) {
  const struct parts *p = &e->p;
  double support = e->prm.kern.support, worst = 0;
  for (long i = 0; i < p->n_owned; i++) {
    double x = p->x[0][i], y = p->x[1][i];
    if (p->phase[i] == PHASE_WALL || (ph >= 0 && p->phase[i] != ph)) continue;
    if (fmin(x, 1 - x) < support || fmin(y, 1 - y) < support) continue;
    if (band > 0 && fabs(y - 0.5) > band) continue;
    worst = fmax(worst, hypot(e->w.dv[0][i], e->w.dv[1][i]));
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  return worst;
}

/* sum m (dv/dt - g) and sum |m dv/dt| over all fluid particles and ranks (y components). */
static void momentum_residual(const struct engine *e, double *residual, double *scale) {
  const struct parts *p = &e->p;
  double sum[2] = {0, 0};
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    sum[0] += p->m[i] * (e->w.dv[1][i] + G);
    sum[1] += fabs(p->m[i] * e->w.dv[1][i]);
  }
  MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, e->comm);
  *residual = sum[0];
  *scale = sum[1];
}

/* The power of the pressure and gravity terms and of the continuity equation over all fluid
 * particles and ranks, sum m u.(dv/dt - g) + sum m p/rho^2 drho/dt [W/m], into *residual, and
 * the sum of the magnitudes of its terms into *scale. */
static void energy_residual(const struct engine *e, double *residual, double *scale) {
  const struct parts *p = &e->p;
  double sum[2] = {0, 0};
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    double kinetic = p->m[i] * (p->v[0][i] * e->w.dv[0][i] + p->v[1][i] * (e->w.dv[1][i] + G));
    double internal = p->m[i] * p->p[i] / (p->rho[i] * p->rho[i]) * e->w.drho[i];
    sum[0] += kinetic + internal;
    sum[1] += fabs(kinetic) + fabs(internal);
  }
  MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, e->comm);
  *residual = sum[0];
  *scale = sum[1];
}

/* Random velocities of every fluid particle, the same on any number of ranks [m/s]. */
static void random_velocities(struct engine *e) {
  for (long i = 0; i < e->p.n_owned; i++)
    for (int d = 0; d < 2; d++) e->p.v[d][i] = e->p.phase[i] == PHASE_WALL ? 0 : engine_test_noise(e->p.id[i], d);
}

/* Right-hand sides of the initial state with the given interface pressure. */
static void evaluate(struct engine *e, struct case_def *c, enum interface_pressure mode) {
  c->interface_pressure = mode;
  engine_test_evaluate(e);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  char dir[256] = "/tmp/mpsph-test-iface-XXXXXX";
  static struct case_def c;
  struct engine e;
  if (engine_test_open(dir, sizeof dir, case_text, &c, &e)) return check_report("test_interface_pressure");
  double dx = c.dx;
  evaluate(&e, &c, IFACE_P_SUM);
  double a_sum = max_acceleration(&e, 1, dx);
  evaluate(&e, &c, IFACE_P_DENSITY_WEIGHTED);
  double a_air = max_acceleration(&e, 1, 0), a_water = max_acceleration(&e, 0, 0), residual, scale;
  momentum_residual(&e, &residual, &scale);
  if (rank == 0)
    printf("first air row, sum: max |dv/dt| = %.4g g; density-weighted: air %.4g g, water %.4g g; "
           "sum m (dv/dt - g) = %.3g (scale %.3g)\n", a_sum / G, a_air / G, a_water / G, residual, scale);
  CHECK(a_sum > 100 * G, "sum form: first air row |dv/dt| = %g g, expected > 100 g", a_sum / G);
  CHECK(a_air <= 2 * G && a_water <= 2 * G, "density-weighted: |dv/dt| air %g g, water %g g (limit 2 g)",
        a_air / G, a_water / G);
  CHECK(fabs(residual) <= 1e-12 * scale, "momentum: sum m (dv/dt - g) = %g, scale %g", residual, scale);
  random_velocities(&e);
  evaluate(&e, &c, IFACE_P_DENSITY_WEIGHTED);
  energy_residual(&e, &residual, &scale);
  if (rank == 0) printf("density-weighted, random velocities: power residual %.3g (scale %.3g)\n", residual, scale);
  CHECK(fabs(residual) <= 1e-12 * scale, "energy: pressure work + internal energy rate = %g, scale %g", residual, scale);
  return engine_test_finish(&e, dir, "test_interface_pressure");
}
