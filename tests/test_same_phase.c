/* test_same_phase.c — the passes and the step of scheme same-phase-continuity (paper 003) on
 * analytic fields, through the real engine (run with 1 and 2 ranks). A two-phase box, water
 * (1000 kg/m^3) below a light phase (1 kg/m^3), both with the paper's linear EOS (gamma = 1) and
 * one c0, p_b = 500 Pa, no walls:
 *  1. a linear velocity u = (0, b y) at uniform pressure: in the bulk drho/dt = -rho b M, M the
 *     kernel's moment sum on the lattice (1 - 9.8e-4 here: the Gaussian truncated at 3h), and
 *     drho/dt of every water particle is bitwise the same when the other phase's velocities are
 *     replaced by random ones (continuity over chi_i only; with one pressure in both phases the
 *     diffusion vanishes, rho*_j = rho_i); with physics.spc_model: conventional the water rows
 *     near the interface do change, the bulk stays exact; with random water velocities instead,
 *     the light rows within one support of the interface do change (the light phase's divergence
 *     reads the heavier phase, a deviation from Eq. 23), the light rows beyond do not;
 *  2. a constant pressure on a perturbed lattice: the Shepard pressure reproduces it for every
 *     particle, the interface rows included, and the diffusion vanishes for every particle;
 *  3. a linear pressure field p = p_b + s.x in both phases (densities from each phase's EOS): the
 *     Shepard pressure reproduces it and the diffusion vanishes wherever the supports are full,
 *     the interface rows included (rho*_j is linear across the interface, although rho jumps by
 *     1000);
 *  4. random velocities at p = p_b: sum_i m_i (du_i/dt - g) = 0 to round-off (pressure and
 *     viscous pair terms, harmonic-mean viscosity across the phases); with a random pressure too,
 *     all particles of one phase, likewise; with a random pressure in both phases the cross-phase
 *     pairs do not conserve momentum (notes AMB-003-4): printed, not asserted;
 *  5. one step: dt = CFL h / c0, two rhs evaluations (the midpoint predictor-corrector of Eqs.
 *     40-42), a uniform state falls by g dt^2 / 2, and a particle left with a negative pressure
 *     ends at p = 0 (density threshold, Eq. 28);
 *  6. the wall repulsion of Eq. 39 on a gas particle beside a wall ghost (a second engine: a gas
 *     in a walled box), approaching and receding.
 * Usage: test_same_phase */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"
#include "physics/eos.h"
#include "physics/passes.h"

static const char *case_text =
    "name: same-phase-test\n"
    "dimension: 2\n"
    "scheme: same-phase-continuity\n"
    "resolution: {dx: 0.02}\n"
    "gravity: [0, -1.0]\n"
    "time: {end: 1.0, cfl: 0.5}\n"
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 30, gamma: 1, incompressible: true, p_background: 500}\n"
    "  - {name: light, rho0: 1, c0: 30, gamma: 1, p_background: 500, viscosity: 0.01}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: light, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "physics: {free_surface: off}\n"
    "initial: {pressure: zero}\n"
    "output: {progress_interval: 1000}\n";

enum field { LINEAR_U, LINEAR_U_OTHER_RANDOM, LINEAR_U_WATER_RANDOM, CONSTANT_P, LINEAR_P, RANDOM_U, RANDOM_UP_ONE_PHASE, RANDOM_UP };
static const double b_strain = 0.3;                  /* du_y/dy [1/s] */
static const double slope[2] = {300.0, -700.0};      /* pressure gradient [Pa/m] */
static const double p_b = 500.0;

/* Set field k on the unperturbed lattice (CONSTANT_P: perturbed); masses m = rho dx^2, so the
 * volumes are dx^2. Phases are set from the height (the box's initial layout). */
static void set_fields(struct engine *e, enum field k) {
  struct parts *p = &e->p;
  double dx = e->c->dx;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    p->phase[i] = k == RANDOM_UP_ONE_PHASE || p->x[1][i] < 0.5 ? 0 : 1;
    double pr = p_b;
    int random_u = k == RANDOM_U || k == RANDOM_UP_ONE_PHASE || k == RANDOM_UP ||
                   (k == LINEAR_U_OTHER_RANDOM && p->phase[i] == 1) || (k == LINEAR_U_WATER_RANDOM && p->phase[i] == 0);
    for (int d = 0; d < 2; d++) {
      if (k == CONSTANT_P) p->x[d][i] += 0.3 * dx * engine_test_noise(p->id[i], d);
      if (k == LINEAR_P) pr += slope[d] * p->x[d][i];
      p->v[d][i] = random_u ? engine_test_noise(p->id[i], 10 + d) : d == 1 && k <= LINEAR_U_WATER_RANDOM ? b_strain * p->x[1][i] : 0.0;
    }
    if (k == RANDOM_UP_ONE_PHASE || k == RANDOM_UP) pr += 200.0 * engine_test_noise(p->id[i], 20);
    p->rho[i] = eos_density(&e->c->phases[p->phase[i]], pr);
    p->p[i] = pr;
    p->m[i] = p->rho[i] * dx * dx;
  }
}

static void evaluate(struct engine *e, enum field k) {
  set_fields(e, k);
  engine_test_rebuild(e);
  e->stage = 0;
  engine_evaluate(e, 0);
}

/* Distance of owned particle i from the box edges [m]. */
static double edge_distance(const struct parts *p, long i) {
  double x = p->x[0][i], y = p->x[1][i];
  return fmin(fmin(x, 1 - x), fmin(y, 1 - y));
}

/* sum_j dy_j^2 (-F(r_j)) dx^2 over the lattice offsets in the kernel support: the factor of the
 * discrete divergence of u = (0, b y) at a particle with a full support (1 - 10 e^-9 for the
 * continuous truncated Gaussian) [-]. */
static double lattice_moment(const struct engine *e) {
  double dx = e->c->dx, sum = 0;
  for (int a = -8; a <= 8; a++)
    for (int b = -8; b <= 8; b++) {
      double r2 = (a * a + b * b) * dx * dx;
      if (r2 > 0 && r2 < e->prm.kern.support2) sum += b * dx * b * dx * -kernel_f(&e->prm.kern, r2) * dx * dx;
    }
  return sum;
}

/* Over all ranks: the largest |drho/dt + rho b M| / (rho b) of the particles 1.1 supports inside
 * their phase's region (M: lattice_moment), and the number of owned particles whose drho/dt
 * differs from ref (NULL: none). */
static void check_continuity(const struct engine *e, const double *ref, double *err, long *changed) {
  const struct parts *p = &e->p;
  const double moment = lattice_moment(e);
  double out = 0;
  long n = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    if (ref && memcmp(&ref[i], &e->w.drho[i], sizeof(double))) n++;
    if (fmin(edge_distance(p, i), fabs(p->x[1][i] - 0.5)) < 1.1 * e->prm.kern.support) continue;
    out = fmax(out, fabs(e->w.drho[i] + p->rho[i] * b_strain * moment) / (p->rho[i] * b_strain));
  }
  MPI_Allreduce(&out, err, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  MPI_Allreduce(&n, changed, 1, MPI_LONG, MPI_SUM, e->comm);
}

/* Over all ranks, for the particles at least `inside` [m] from the box edges: the largest
 * |p~ - p_exact| / p_b and the largest |drho/dt| / rho0; *n_interface counts those among them
 * within one support of the interface. */
static void check_pressure_field(const struct engine *e, int linear, double inside, double *p_err,
                                 double *drho_err, long *n_interface) {
  const struct parts *p = &e->p;
  double out[2] = {0, 0};
  long n = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL || edge_distance(p, i) < inside) continue;
    double exact = p_b + (linear ? slope[0] * p->x[0][i] + slope[1] * p->x[1][i] : 0.0);
    out[0] = fmax(out[0], fabs(e->w.p_shepard[i] - exact) / p_b);
    out[1] = fmax(out[1], fabs(e->w.drho[i]) / e->c->phases[p->phase[i]].rho0);
    n += fabs(p->x[1][i] - 0.5) < e->prm.kern.support;
  }
  MPI_Allreduce(MPI_IN_PLACE, out, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  MPI_Allreduce(&n, n_interface, 1, MPI_LONG, MPI_SUM, e->comm);
  *p_err = out[0];
  *drho_err = out[1];
}

/* sum_i m_i (du_i/dt - g) and the sum of its magnitudes, over all ranks. */
static void net_force(const struct engine *e, double *sum) {
  const struct parts *p = &e->p;
  for (int k = 0; k < 4; k++) sum[k] = 0;
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < 2 && p->phase[i] != PHASE_WALL; d++) {
      double f = p->m[i] * (e->w.dv[d][i] - e->c->gravity[d]);
      sum[d] += f;
      sum[2 + d] += fabs(f);
    }
  MPI_Allreduce(MPI_IN_PLACE, sum, 4, MPI_DOUBLE, MPI_SUM, e->comm);
}

static void check_momentum(struct engine *e, enum field k, const char *what) {
  double sum[4];
  evaluate(e, k);
  net_force(e, sum);
  if (e->rank == 0) printf("%s: sum m (du/dt - g) = (%.3g, %.3g), scale (%.3g, %.3g)\n", what, sum[0], sum[1], sum[2], sum[3]);
  if (k != RANDOM_UP)
    for (int d = 0; d < 2; d++)
      CHECK(fabs(sum[d]) <= 1e-13 * sum[2 + d], "%s: momentum %c %g, scale %g", what, "xy"[d], sum[d], sum[2 + d]);
}

/* With conventional (physics.spc_model, paper 003 section 2.3) the divergence runs over every
 * neighbour, so that the water rows near the interface do read the light phase's velocities. */
static void test_continuity(struct engine *e, int conventional) {
  double err, err2;
  long changed;
  evaluate(e, LINEAR_U);
  double *ref = malloc((e->p.n_owned + 1) * sizeof(double));
  memcpy(ref, e->w.drho, e->p.n_owned * sizeof(double));
  check_continuity(e, NULL, &err, &changed);
  evaluate(e, LINEAR_U_OTHER_RANDOM);
  /* the light phase's own drho changes: compare the water's only */
  long n_water_changed = 0;
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.phase[i] == 0 && memcmp(&ref[i], &e->w.drho[i], sizeof(double))) n_water_changed++;
  MPI_Allreduce(MPI_IN_PLACE, &n_water_changed, 1, MPI_LONG, MPI_SUM, e->comm);
  check_continuity(e, ref, &err2, &changed);
  if (e->rank == 0)
    printf("%slinear u: bulk |drho/dt + rho b M| / (rho b) = %.3g (lattice moment M = 1 - %.3g); water drho/dt "
           "changed by random light-phase velocities: %ld particles (light ones changed: %ld)\n",
           conventional ? "conventional model: " : "", err, 1.0 - lattice_moment(e), n_water_changed,
           changed - n_water_changed);
  CHECK(err <= 1e-12, "bulk continuity error %g", err);
  if (conventional) CHECK(n_water_changed > 0, "conventional continuity ignores other-phase velocities");
  else CHECK(n_water_changed == 0 && changed > 0, "continuity reads other-phase velocities");
  free(ref);
}

/* Over all ranks: the largest |drho/dt + rho b M| / (rho b) of the light particles within one
 * support above the interface and 1.1 supports from the box's sides (M: lattice_moment). */
static double light_interface_error(const struct engine *e) {
  const struct parts *p = &e->p;
  const double moment = lattice_moment(e), support = e->prm.kern.support;
  double out = 0;
  for (long i = 0; i < p->n_owned; i++) {
    double above = p->x[1][i] - 0.5, side = fmin(p->x[0][i], 1 - p->x[0][i]);
    if (p->phase[i] != 1 || above >= support || side < 1.1 * support) continue;
    out = fmax(out, fabs(e->w.drho[i] + p->rho[i] * b_strain * moment) / (p->rho[i] * b_strain));
  }
  MPI_Allreduce(MPI_IN_PLACE, &out, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  return out;
}

/* The light phase's divergence reads the heavier phase's velocities too (a deviation from Eq. 23,
 * doc/theory.md section 11): with the linear velocity in both phases the light rows next to the
 * interface have the bulk's divergence (their velocity support is whole); with random water
 * velocities the light rows within one support of the interface change their drho/dt, the light
 * rows farther up do not. */
static void test_light_reads_heavier(struct engine *e) {
  evaluate(e, LINEAR_U);
  double err = light_interface_error(e);
  if (e->rank == 0) printf("linear u: light rows at the interface |drho/dt + rho b M| / (rho b) = %.3g\n", err);
  CHECK(err <= 1e-12, "light rows at the interface: continuity error %g", err);
  double *ref = malloc((e->p.n_owned + 1) * sizeof(double));
  memcpy(ref, e->w.drho, e->p.n_owned * sizeof(double));
  evaluate(e, LINEAR_U_WATER_RANDOM);
  long n[2] = {0, 0};   /* light rows near the interface changed, light rows beyond it changed */
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.phase[i] == 1 && memcmp(&ref[i], &e->w.drho[i], sizeof(double)))
      n[e->p.x[1][i] - 0.5 >= e->prm.kern.support]++;
  MPI_Allreduce(MPI_IN_PLACE, n, 2, MPI_LONG, MPI_SUM, e->comm);
  if (e->rank == 0)
    printf("random water velocities: light drho/dt changed near the interface %ld, beyond one support %ld\n", n[0], n[1]);
  CHECK(n[0] > 0, "the light phase's continuity ignores the heavier phase's velocities");
  CHECK(n[1] == 0, "light particles beyond one support read the water's velocities");
  free(ref);
}

/* Constant pressure on the perturbed lattice (perturbs the positions for the rest of the test). */
static void test_constant_pressure(struct engine *e) {
  double p_err, drho_err;
  long n_iface;
  evaluate(e, CONSTANT_P);
  check_pressure_field(e, 0, 0.0, &p_err, &drho_err, &n_iface);
  if (e->rank == 0)
    printf("constant p, perturbed lattice, all particles: Shepard error %.3g p_b, |drho/dt| %.3g rho0\n", p_err, drho_err);
  CHECK(p_err <= 1e-14 && drho_err <= 1e-12, "constant pressure: Shepard %g, diffusion %g", p_err, drho_err);
}

/* Linear pressure on the lattice. */
static void test_linear_pressure(struct engine *e) {
  double p_err, drho_err;
  long n_iface;
  evaluate(e, LINEAR_P);
  check_pressure_field(e, 1, 2.2 * e->prm.kern.support, &p_err, &drho_err, &n_iface);
  if (e->rank == 0)
    printf("linear p, full supports (%ld near the interface): Shepard error %.3g p_b, |drho/dt| %.3g rho0\n",
           n_iface, p_err, drho_err);
  CHECK(n_iface > 0 && p_err <= 1e-14 && drho_err <= 1e-12, "linear pressure: Shepard %g, diffusion %g", p_err, drho_err);
}

/* The index of the pipeline's operation called name, or -1. */
static int op_index(const struct engine *e, const char *name) {
  for (int k = 0; k < e->n_ops; k++)
    if (!strcmp(e->ops[k].name, name)) return k;
  return -1;
}

/* Set every fluid particle to the pressure pr [Pa] of its phase's EOS, at rest. */
static void set_uniform_pressure(struct engine *e, double pr) {
  struct parts *p = &e->p;
  set_fields(e, LINEAR_P);   /* phases and masses; the positions stay */
  for (long i = 0; i < p->n_owned; i++)
    if (p->phase[i] != PHASE_WALL) {
      p->rho[i] = eos_density(&e->c->phases[p->phase[i]], pr);
      p->p[i] = pr;
      p->m[i] = p->rho[i] * e->c->dx * e->c->dx;
      p->v[0][i] = p->v[1][i] = 0;
    }
  engine_test_rebuild(e);
}

/* One step from rest at p = 0 on the perturbed lattice (no pair force: only gravity acts): dt,
 * two rhs evaluations, the fall g dt^2 / 2. */
static void test_step(struct engine *e) {
  set_uniform_pressure(e, 0.0);
  int rhs = op_index(e, "same-phase continuity and momentum rhs");
  CHECK(rhs >= 0, "no same-phase rhs operation");
  if (rhs < 0) return;
  e->stage = 0;
  long pairs0 = e->ops[rhs].pairs;
  engine_evaluate(e, 0);
  long pairs_one = e->ops[rhs].pairs - pairs0, n0 = e->p.n_owned;
  pairs0 = e->ops[rhs].pairs;
  double y0 = n0 ? e->p.x[1][0] : 0, v0 = n0 ? e->p.v[1][0] : 0;
  long id0 = n0 ? e->p.id[0] : -1;
  CHECK(engine_step(e) == 0, "step");
  double dt_paper = e->c->cfl * e->prm.h / e->c->phases[0].c0;
  long pairs = e->ops[rhs].pairs - pairs0;
  long both[2] = {pairs, pairs_one};
  MPI_Allreduce(MPI_IN_PLACE, both, 2, MPI_LONG, MPI_SUM, e->comm);
  double fall = 0;
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.id[i] == id0) fall = fabs(e->p.x[1][i] - y0 - (v0 * e->dt - 0.5 * e->dt * e->dt));
  MPI_Allreduce(MPI_IN_PLACE, &fall, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  if (e->rank == 0)
    printf("step: dt = %.6g s (CFL h / c0 = %.6g s), rhs pairs %ld in the step, %ld per evaluation, fall error %.3g m\n",
           e->dt, dt_paper, both[0], both[1], fall);
  CHECK(e->dt == dt_paper, "dt %g, paper %g", e->dt, dt_paper);
  CHECK(both[1] > 0 && both[0] == 2 * both[1], "rhs evaluations per step: pairs %ld, per evaluation %ld", both[0], both[1]);
  CHECK(fall <= 1e-15, "fall error %g", fall);
}

/* Density threshold: one step from rest at p = -100 Pa (nothing but the threshold raises it). */
static void test_threshold(struct engine *e) {
  struct parts *p = &e->p;
  set_uniform_pressure(e, -100.0);
  CHECK(engine_step(e) == 0, "step");
  long bad = 0, at_zero = 0, fluid = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    fluid++;
    bad += !(p->p[i] >= 0);
    at_zero += p->p[i] == 0 && p->rho[i] == eos_density(&e->c->phases[p->phase[i]], 0.0);
  }
  long c[3] = {bad, at_zero, fluid};
  MPI_Allreduce(MPI_IN_PLACE, c, 3, MPI_LONG, MPI_SUM, e->comm);
  if (e->rank == 0) printf("threshold: %ld of %ld at p = 0 after a step from p < 0, %ld negative\n", c[1], c[2], c[0]);
  CHECK(c[0] == 0 && c[1] == c[2], "density threshold: %ld negative, %ld of %ld at zero", c[0], c[1], c[2]);
}

/* A gas in a walled box, for the wall repulsion of Eq. 39. */
static const char *wall_case_text =
    "name: same-phase-wall-test\n"
    "dimension: 2\n"
    "scheme: same-phase-continuity\n"
    "resolution: {dx: 0.05, origin: [0, 0]}\n"
    "gravity: [0, 0]\n"
    "time: {end: 1.0, cfl: 0.5}\n"
    "domain: {min: [-0.3, -0.3], max: [1.3, 1.3]}\n"
    "phases:\n"
    "  - {name: air, rho0: 1, c0: 30, gamma: 1, p_background: 500}\n"
    "fluids:\n"
    "  - {phase: air, box: {min: [0, 0], max: [1, 1]}}\n"
    "walls:\n"
    "  - {box: {min: [0, 0], max: [1, 1]}, slip: free}\n"
    "physics: {free_surface: off}\n"
    "initial: {pressure: zero}\n"
    "output: {progress_interval: 1000}\n";

/* Eq. 39 between an owned gas particle of the first column at mid-height and the ghost of the
 * first layer one dx to its left, all gas moving with u = (ux, 0): the ghost's mirrored velocity
 * (ux_b = -ux) gives c0 2|ux| W(dx) h^2 / dx along +x while the gas approaches, nothing while it
 * recedes. The pair exists on one rank; the count of checked pairs is agreed on. */
static void test_wall_repulsion(struct engine *e) {
  struct parts *p = &e->p;
  const double dx = e->c->dx, u_x[2] = {-0.7, 0.7};
  long checked = 0;
  for (int k = 0; k < 2; k++) {
    for (long i = 0; i < p->n_owned; i++)
      if (p->phase[i] != PHASE_WALL) p->v[0][i] = u_x[k], p->v[1][i] = 0;
    e->stage = 0;
    engine_evaluate(e, 0);   /* the ghosts' velocities */
    for (long i = 0; i < p->n_owned; i++) {
      if (p->phase[i] == PHASE_WALL || fabs(p->x[0][i] - 0.5 * dx) > 1e-9 || fabs(p->x[1][i] - 0.525) > 1e-9) continue;
      for (long b = 0; b < p->n_owned + p->n_halo; b++) {
        if (p->phase[b] != PHASE_WALL || fabs(p->x[0][b] + 0.5 * dx) > 1e-9 || fabs(p->x[1][b] - p->x[1][i]) > 1e-9) continue;
        double acc[3] = {0, 0, 0}, r2 = dx * dx;
        struct pass_ctx ctx = engine_pass_ctx(e);
        spc_wall_repulsion(&ctx, i, b, acc);
        double expect = k == 0 ? 30.0 * (u_x[0] - p->v[0][b]) * -1.0 * kernel_w(&e->prm.kern, r2) * e->prm.h * e->prm.h / dx : 0.0;
        printf("wall repulsion, gas %s the wall: ghost u_x = %g, a = (%.6g, %.3g), Eq. 39 gives %.6g m/s^2\n",
               k == 0 ? "approaching" : "receding", p->v[0][b], acc[0], acc[1], expect);
        CHECK(fabs(p->v[0][b] + u_x[k]) <= 1e-12, "ghost velocity %.17g, want %g", p->v[0][b], -u_x[k]);
        CHECK(fabs(acc[0] - expect) <= 1e-14 * fabs(expect) && acc[1] == 0 && (k == 1 || expect > 0),
              "repulsion (%g, %g), expected (%g, 0)", acc[0], acc[1], expect);
        checked++;
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &checked, 1, MPI_LONG, MPI_SUM, e->comm);
  CHECK(checked == 2, "wall-repulsion pairs checked: %ld", checked);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  char dir[256] = "/tmp/mpsph-test-spc-XXXXXX";
  if (engine_test_scratch(dir, sizeof dir)) return 1;
  static struct case_def c;
  struct engine e;
  if (engine_test_start(dir, case_text, &c, &e)) return check_report("test_same_phase");
  CHECK((e.prm.features & FEAT_SAME_PHASE_CONTINUITY) && !(e.prm.features & (FEAT_SHIFT | FEAT_TIC | FEAT_DAMPER | FEAT_SHEPARD)),
        "same-phase-continuity pipeline: no shifting, tensile control, damper or Shepard density");
  CHECK(c.alpha == 0.05, "paper 003 default alpha_w = 0.05, got %g", c.alpha);
  test_continuity(&e, 0);   /* first: the lattice is still unperturbed */
  test_light_reads_heavier(&e);
  c.spc_model = SPC_CONVENTIONAL;
  engine_assemble(&e);
  CHECK(op_index(&e, "Shepard pressure over all phases (same-phase-continuity)") < 0, "conventional: no Shepard pass");
  test_continuity(&e, 1);
  c.spc_model = SPC_PRESENT;
  engine_assemble(&e);
  test_linear_pressure(&e);
  check_momentum(&e, RANDOM_U, "random u, p = p_b");
  check_momentum(&e, RANDOM_UP_ONE_PHASE, "random u and p, one phase");
  check_momentum(&e, RANDOM_UP, "random u and p, two phases (not conserved, AMB-003-4)");
  test_constant_pressure(&e);
  test_step(&e);
  test_threshold(&e);
  engine_close_output(&e);
  engine_free(&e);
  char wall_dir[300];
  snprintf(wall_dir, sizeof wall_dir, "%s/wall", dir);
  if (e.rank == 0) CHECK(mkdir(wall_dir, 0700) == 0, "mkdir %s", wall_dir);
  MPI_Barrier(MPI_COMM_WORLD);
  static struct case_def c_wall;
  if (engine_test_start(wall_dir, wall_case_text, &c_wall, &e)) return check_report("test_same_phase");
  test_wall_repulsion(&e);
  return engine_test_finish(&e, dir, "test_same_phase");
}
