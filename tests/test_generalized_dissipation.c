/* test_generalized_dissipation.c — the passes of scheme generalized-dissipation (paper 004) on
 * analytic fields, through the real engine (run with 1 and 2 ranks). A two-phase box, water
 * (1000 kg/m^3, c0 30 m/s) below a light phase (1 kg/m^3, c0 300 m/s), no walls, no gravity,
 * m = rho dx^2 so that every volume is dx^2; the density follows from the pressure by each
 * phase's EOS:
 *  1. uniform pressure on a randomly perturbed lattice, at rest: drho/dt = 0 to round-off for every
 *     particle, in both dissipation forms;
 *  2. a pressure linear across both phases (p continuous, rho jumping by 1000 at the interface) on
 *     the lattice, at rest: the consistent dissipation vanishes to round-off for every particle,
 *     the edges of the box included (the renormalised gradient correction); the printed Eq. 49
 *     does not vanish at the edges (its correction is identically zero for a linear field);
 *  3. a pressure step at the interface (p_w in the water, p_l in the light phase) on the lattice,
 *     at rest: the water (at the higher pressure) expands, and with the volume correction factor
 *     the volume it gains is the volume the light phase loses, sum_water (m/rho^2) D = -sum_light (m/rho^2) D, to round-off (without
 *     it, the ratio of the two would be rho_l / rho_w);
 *  4. random pressures and velocities on the perturbed lattice: sum_i m_i du_i/dt = 0 to
 *     round-off; at rest, the volume sum sum_i (m_i / rho_i^2) D_i of the consistent
 *     dissipation is zero to round-off (the printed form's correction is symmetric in i, j and
 *     breaks it: printed only).
 * Usage: test_generalized_dissipation */
#include <math.h>
#include <stdio.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"
#include "physics/eos.h"

static const char *case_text =
    "name: gd-test\n"
    "dimension: 2\n"
    "scheme: generalized-dissipation\n"
    "resolution: {dx: 0.02}\n"
    "time: {end: 1.0}\n"
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 30, incompressible: true, viscosity: 0.01}\n"
    "  - {name: light, rho0: 1, c0: 300, gamma: 1.4, viscosity: 0.0001}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: light, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "physics: {artificial_viscosity: 0.1}\n"
    "initial: {pressure: zero}\n"
    "output: {progress_interval: 1000}\n";

enum field { UNIFORM, LINEAR, STEP, RANDOM };
static const double P0 = 2000.0, GRAD[2] = {-300.0, 700.0};   /* [Pa], [Pa/m] */

/* The pressure of field k at particle i of phase ph [Pa]. */
static double pressure_of(const struct parts *p, long i, int ph, enum field k) {
  switch (k) {
  case UNIFORM: return P0;
  case LINEAR: return P0 + GRAD[0] * p->x[0][i] + GRAD[1] * p->x[1][i];
  case STEP: return ph == 0 ? P0 : -0.5 * P0;
  default: return P0 * (1.0 + engine_test_noise(p->id[i], 7));
  }
}

/* Set field k (perturbing the lattice for UNIFORM and RANDOM, with random velocities for RANDOM)
 * and evaluate the stage pipeline on it. */
static void evaluate(struct engine *e, enum field k) {
  struct parts *p = &e->p;
  double dx = e->c->dx;
  for (long i = 0; i < p->n_owned; i++) {
    int ph = p->phase[i];
    for (int d = 0; d < 2; d++) {
      if (k == UNIFORM || k == RANDOM) p->x[d][i] += 0.2 * dx * engine_test_noise(p->id[i], d);
      p->v[d][i] = k == RANDOM ? engine_test_noise(p->id[i], 10 + d) : 0.0;
    }
    p->p[i] = pressure_of(p, i, ph, k);
    p->rho[i] = eos_density(&e->c->phases[ph], p->p[i]);
    p->m[i] = p->rho[i] * dx * dx;
  }
  engine_test_rebuild(e);
  e->stage = 0;
  engine_evaluate(e, 0);
}

/* Largest |drho/dt| / rho over owned particles, with edge_only those within one kernel support
 * of the box's sides, on all ranks [1/s]. */
static double worst_rate(const struct engine *e, int edge_only) {
  const struct parts *p = &e->p;
  double worst = 0, s = e->prm.kern.support;
  for (long i = 0; i < p->n_owned; i++) {
    double x = p->x[0][i], y = p->x[1][i];
    if (edge_only && fmin(fmin(x, 1 - x), fmin(y, 1 - y)) > s) continue;
    worst = fmax(worst, fabs(e->w.drho[i]) / p->rho[i]);
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  return worst;
}

/* The volume rates dV/dt = -sum_i (m_i / rho_i^2) drho_i/dt of the water (out[0]) and of the
 * light phase (out[1]), and the sum of their magnitudes (out[2]), over all ranks [m^2/s]. */
static void volume_rates(const struct engine *e, double *out) {
  const struct parts *p = &e->p;
  out[0] = out[1] = out[2] = 0;
  for (long i = 0; i < p->n_owned; i++) {
    double vol_rate = -p->m[i] / (p->rho[i] * p->rho[i]) * e->w.drho[i];
    out[p->phase[i] != 0] += vol_rate;
    out[2] += fabs(vol_rate);
  }
  MPI_Allreduce(MPI_IN_PLACE, out, 3, MPI_DOUBLE, MPI_SUM, e->comm);
}

/* sum_i m_i du_i/dt relative to sum_i |m_i du_i/dt|, the larger of the two components. */
static double momentum_defect(const struct engine *e) {
  const struct parts *p = &e->p;
  double sum[4] = {0, 0, 0, 0};
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < 2; d++) {
      sum[d] += p->m[i] * e->w.dv[d][i];
      sum[2 + d] += fabs(p->m[i] * e->w.dv[d][i]);
    }
  MPI_Allreduce(MPI_IN_PLACE, sum, 4, MPI_DOUBLE, MPI_SUM, e->comm);
  return fmax(fabs(sum[0]) / sum[2], fabs(sum[1]) / sum[3]);
}

static const char *form_name(enum dissipation_form f) { return f == DISSIPATION_PRINTED ? "printed" : "consistent"; }

/* Check 1: uniform pressure, both forms. */
static void check_uniform(struct engine *e, struct case_def *c) {
  evaluate(e, UNIFORM);
  for (int f = 0; f < 2; f++) {
    c->dissipation_form = (enum dissipation_form)f;
    engine_evaluate(e, 0);
    double worst = worst_rate(e, 0);
    if (e->rank == 0) printf("%s, uniform p: max |drho/dt|/rho %.3g 1/s\n", form_name(c->dissipation_form), worst);
    CHECK(worst <= 1e-12, "%s, uniform pressure: drho/dt/rho = %g", form_name(c->dissipation_form), worst);
  }
}

/* Check 2: pressure linear across the phases. */
static void check_linear(struct engine *e, struct case_def *c) {
  evaluate(e, LINEAR);
  for (int f = 0; f < 2; f++) {
    c->dissipation_form = (enum dissipation_form)f;
    engine_evaluate(e, 0);
    double all = worst_rate(e, 0), edge = worst_rate(e, 1);
    if (e->rank == 0)
      printf("%s, linear p: max |drho/dt|/rho %.3g 1/s (all), %.3g 1/s (edges)\n", form_name(c->dissipation_form), all, edge);
    if (f == DISSIPATION_CONSISTENT) CHECK(all <= 1e-10, "consistent, linear p: drho/dt/rho = %g", all);
    else CHECK(edge >= 1e-3, "printed, linear p, edges: %g (expected non-zero)", edge);
  }
}

/* Check 3: pressure step at the interface; the volume the water gains is the volume the light
 * phase loses (consistent form; the printed form's balance is printed only). */
static void check_step(struct engine *e, struct case_def *c) {
  evaluate(e, STEP);
  for (int f = 0; f < 2; f++) {
    double r[3];
    c->dissipation_form = (enum dissipation_form)f;
    engine_evaluate(e, 0);
    volume_rates(e, r);
    double defect = fabs(r[0] + r[1]) / r[2];
    if (e->rank == 0)
      printf("%s, p step: volume rates water %.6g, light %.6g m^2/s, defect %.3g\n", form_name(c->dissipation_form),
             r[0], r[1], defect);
    if (f == DISSIPATION_CONSISTENT) {
      CHECK(r[0] > 0 && defect <= 1e-13, "consistent, p step: water %g, light %g m^2/s", r[0], r[1]);
    }
  }
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  char dir[256] = "/tmp/mpsph-test-gd-XXXXXX";
  if (engine_test_scratch(dir, sizeof dir)) return 1;
  static struct case_def c;
  struct engine e;
  if (engine_test_start(dir, case_text, &c, &e)) return check_report("test_generalized_dissipation");
  CHECK(e.prm.features & FEAT_GENERALIZED_DISSIPATION && !(e.prm.features & (FEAT_SHIFT | FEAT_TIC | FEAT_DAMPER)),
        "generalized-dissipation pipeline: no shifting, tensile control or damper");
  CHECK(c.delta == 0.5 && c.cfl == 0.25 && c.h_over_dx == 1.1, "scheme defaults delta 0.5, cfl 0.25, h 1.1 dx");
  check_linear(&e, &c);   /* first two: on the lattice, not yet perturbed */
  check_step(&e, &c);
  check_uniform(&e, &c);
  evaluate(&e, RANDOM);
  double momentum = momentum_defect(&e);
  if (rank == 0) printf("random p and u: momentum sum %.3g (relative)\n", momentum);
  CHECK(momentum <= 1e-13, "momentum sum %g", momentum);
  for (long i = 0; i < e.p.n_owned; i++)   /* at rest: drho/dt is the dissipation alone */
    for (int d = 0; d < 2; d++) e.p.v[d][i] = 0.0;
  for (int f = 0; f < 2; f++) {
    double r[3];
    c.dissipation_form = (enum dissipation_form)f;
    engine_evaluate(&e, 0);
    volume_rates(&e, r);
    double defect = fabs(r[0] + r[1]) / r[2];
    if (rank == 0) printf("%s, random p: volume sum %.3g (relative)\n", form_name(c.dissipation_form), defect);
    if (f == DISSIPATION_CONSISTENT) CHECK(defect <= 1e-13, "consistent, random p: volume sum %g", defect);
  }
  return engine_test_finish(&e, dir, "test_generalized_dissipation");
}
