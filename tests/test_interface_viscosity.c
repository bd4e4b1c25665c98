/* test_interface_viscosity.c — the laminar viscosity between two phases (physics.interface_viscosity,
 * run with 1 and 2 ranks). Two fluids of equal density (so no pressure, no gravity) fill [0, 1]^2,
 * mu_A = 1 Pa s below y = 0.5 and mu_B = 4 Pa s above, no walls. Checked on the particles more than
 * one support from the box's free sides:
 *  1. two-layer Couette flow u_x = tau (y - 0.5)/mu(y), the same shear stress tau on both sides:
 *     with `none` (paper 000: same-phase sums) the rows at the interface feel only their own side's
 *     stress and accelerate, with `harmonic` (mu_ij = 2 mu_i mu_j/(mu_i + mu_j) for the other-phase
 *     pairs) the stress is passed across, and the largest |dv/dt| within a support of the interface
 *     must fall to a tenth of that of `none` or less; in the bulk rows the field is linear and
 *     |dv/dt| stays at round-off with both;
 *  2. with random velocities the harmonic pair term conserves momentum: sum m dv/dt = 0 to
 *     round-off (mu_ij and pi_ij are symmetric in i, j).
 * Usage: test_interface_viscosity [TMPDIR] */
#include <math.h>
#include <stdio.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"

#define TAU 1.0   /* shear stress of the Couette flow [Pa] */

static const char *case_text =
    "name: interface-viscosity-test\n"
    "dimension: 2\n"
    "resolution: {dx: 0.02}\n"
    "gravity: [0, 0]\n"
    "time: {end: 1.0}\n"
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
    "phases:\n"
    "  - {name: lower, rho0: 1000, c0: 10, viscosity: 1, incompressible: true}\n"
    "  - {name: upper, rho0: 1000, c0: 10, viscosity: 4, incompressible: true}\n"
    "fluids:\n"
    "  - {phase: lower, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: upper, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "physics: {shifting: none, acoustic_damper: 0, artificial_viscosity: 0, delta: 0,\n"
    "          tensile_control: false, free_surface: off}\n"
    "output: {progress_interval: 1000}\n";

/* Largest |dv/dt| [m/s^2] over the particles more than one support from the box's sides, within
 * (near = 1) or beyond (near = 0) one support of the interface y = 0.5, over all ranks. */
static double max_acceleration(const struct engine *e, int near) {
  const struct parts *p = &e->p;
  double support = e->prm.kern.support, worst = 0;
  for (long i = 0; i < p->n_owned; i++) {
    double x = p->x[0][i], y = p->x[1][i];
    if (p->phase[i] == PHASE_WALL || fmin(x, 1 - x) < support || fmin(y, 1 - y) < support) continue;
    if ((fabs(y - 0.5) < support) != near) continue;
    worst = fmax(worst, hypot(e->w.dv[0][i], e->w.dv[1][i]));
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  return worst;
}

/* |sum m dv/dt| (both components) and sum |m dv/dt| over all fluid particles and ranks. */
static void momentum_residual(const struct engine *e, double *residual, double *scale) {
  const struct parts *p = &e->p;
  double sum[3] = {0, 0, 0};
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    for (int d = 0; d < 2; d++) {
      sum[d] += p->m[i] * e->w.dv[d][i];
      sum[2] += fabs(p->m[i] * e->w.dv[d][i]);
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, sum, 3, MPI_DOUBLE, MPI_SUM, e->comm);
  *residual = hypot(sum[0], sum[1]);
  *scale = sum[2];
}

/* The Couette field u_x = TAU (y - 0.5)/mu of the particle's phase, or random velocities. */
static void set_velocities(struct engine *e, const struct case_def *c, int random) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    for (int d = 0; d < 2; d++)
      p->v[d][i] = random ? engine_test_noise(p->id[i], d)
                          : d == 0 ? TAU * (p->x[1][i] - 0.5) / c->phases[p->phase[i]].viscosity : 0.0;
  }
}

/* Right-hand sides of the current state with the given interface viscosity. */
static void evaluate(struct engine *e, struct case_def *c, enum interface_viscosity mode) {
  c->interface_viscosity = mode;
  engine_test_evaluate(e);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  char dir[256] = "/tmp/mpsph-test-iface-visc-XXXXXX";
  static struct case_def c;
  struct engine e;
  if (engine_test_open(dir, sizeof dir, case_text, &c, &e)) return check_report("test_interface_viscosity");
  const int rank = e.rank;
  set_velocities(&e, &c, 0);
  evaluate(&e, &c, IFACE_VISC_NONE);
  double a_none = max_acceleration(&e, 1), bulk_none = max_acceleration(&e, 0);
  evaluate(&e, &c, IFACE_VISC_HARMONIC);
  double a_harm = max_acceleration(&e, 1), bulk_harm = max_acceleration(&e, 0);
  /* the scale of a one-sided stress: tau over a particle spacing, per unit density */
  double scale_a = TAU / (c.dx * c.phases[0].rho0), residual, scale;
  if (rank == 0)
    printf("Couette, max |dv/dt| at the interface: none %.4g, harmonic %.4g m/s^2 (tau/(rho dx) = %.3g); "
           "bulk: %.3g, %.3g\n", a_none, a_harm, scale_a, bulk_none, bulk_harm);
  CHECK(a_harm <= 0.1 * a_none, "harmonic: interface |dv/dt| %g, none %g: expected at most a tenth", a_harm, a_none);
  CHECK(bulk_none <= 1e-9 * scale_a && bulk_harm <= 1e-9 * scale_a, "bulk |dv/dt| %g, %g (scale %g)", bulk_none,
        bulk_harm, scale_a);
  set_velocities(&e, &c, 1);
  evaluate(&e, &c, IFACE_VISC_HARMONIC);
  momentum_residual(&e, &residual, &scale);
  if (rank == 0) printf("harmonic, random velocities: |sum m dv/dt| = %.3g (scale %.3g)\n", residual, scale);
  CHECK(residual <= 1e-12 * scale, "momentum: |sum m dv/dt| = %g, scale %g", residual, scale);
  return engine_test_finish(&e, dir, "test_interface_viscosity");
}
