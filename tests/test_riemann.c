/* test_riemann.c — scheme riemann (paper 002) on analytic fields, through the real engine (run
 * with 1 and 2 ranks):
 *  1. the solver alone: p* symmetric under left <-> right; no dissipation in expansion (beta = 0);
 *     equal states give p; the dissipation is capped at the acoustic value rho c dU / 2; a light
 *     left state next to a heavy right one at rest gives p* -> p_left;
 *  2. two phases (water under a light phase, no walls, no gravity) on the undisturbed lattice at
 *     rho0: the density re-initialisation gives rho0 to round-off for every heavy particle
 *     (interface and free edges included: Eq. 10 keeps rho* = rho0) and for every light particle
 *     whose kernel support is complete (Eq. 11 counts the heavy neighbours);
 *  3. one density, a linear pressure field and a pure dilatation v = s r (every pair separates, so
 *     the limiter gives beta = 0 and p* = (p_i + p_j)/2): du/dt equals the plain symmetric pressure
 *     term -(1/rho_i) sum_j V_j (p_i + p_j) grad_i W_ij and drho/dt equals rho_i sum_j V_j v_ij.grad_i W_ij
 *     + (1/c) sum_j V_j (p_i - p_j) r_ij F_ij, both summed here by brute force, to round-off;
 *  4. random velocities and densities in both phases: sum_i m_i du_i/dt = 0 to round-off;
 *  5. walls: one phase at rest at a uniform pressure p_b in a closed tank (no gravity) on the
 *     undisturbed lattice; the ghosts carry each particle's dummy state (p_j = p_i, v_j = 0), so
 *     p*_ij = p_i and du/dt = -(2 p_i/rho_i) sum_j V_j grad_i W_ij = 0 and drho/dt = 0 to round-off
 *     for every particle, those beside the walls and in the corners included;
 *  6. the dual stepper on one phase moving uniformly at speed U (no force acts): the advection step
 *     is 0.25 h / u_max for U << u_max and the cell-skin limit B / U for U >> u_max (B = 0.75 of
 *     the allowed motion), 2B / (U + sqrt(U^2 + 2 a B)) with a transport acceleration a; one
 *     advection step takes ceil(dt_ad / dt_ac) acoustic sub-steps, dt_ac = cfl h / (c0 + U), and
 *     moves every particle by U dt_ad;
 *  7. two liquids (both `incompressible`, neither a light phase) on lattices offset by (dx/2, dx/2),
 *     so that the rows at their interface lie 0.71 dx apart, at rho0 and rest: the re-initialisation
 *     gives rho0 to round-off for every particle (each liquid's Eq. 10 sum counts its own phase
 *     only; counting the other liquid's crowded rows gave 1.28 rho0 at the interface);
 *  8. an elastic solid as a moving wall (doc/theory.md section 14): water with random velocities and
 *     densities on a solid plate, no gravity: the loads the momentum pass records on the solid sum
 *     to minus sum_i m_i du_i/dt (every fluid-solid pair once, on any rank count; the fluid pairs
 *     cancel) to round-off; and with every fluid velocity and the solid's averaged velocity shifted
 *     by the same V, du/dt and drho/dt are unchanged to round-off (the dummy velocity 2 v~ - v_i
 *     makes the treatment Galilean invariant);
 *  9. the penalty force (paper 002 Eqs. 21-23, physics.light_penalty): a gas particle of a closed
 *     tank at rest and uniform pressure pushed to 0.1 dx from the lid: its du/dt with the penalty
 *     less that without is the sum over the lid's ghosts -(2/rho_i) V_a Gamma n_a W'(r) to
 *     round-off (brute force here), points away from the lid, and no other particle's changes;
 *     with the gas at twice the spacing (test 10) the same with the pair's kernel at 2h and the
 *     prefactor h_S/h^chi = 1/2 (the gas particle under the lid likewise pushed to 0.1 dx);
 * 10. multi-resolution (paper 002 section 3.5): test 2's phases with the light one at twice the
 *     spacing (dx_ratio 2): the same checks as tests 2-4, with each pair's kernel the one of the
 *     larger smoothing length and each neighbour counted as V0_j/V0_i lattice sites in the
 *     re-initialisation (brute force here): the re-initialisation as Eqs. 10-11 state it, rho0 back
 *     for the particles whose support holds their own phase only; the Riemann terms equal to the
 *     plain terms in equal states; sum_i m_i du_i/dt = 0 (h^chi is the same both ways). The largest
 *     departure from rho0 of a light particle beside the heavy phase is printed (the quadrature of
 *     the two lattices); and test 9's closed tank with the gas at 2 dx: the re-initialisation with
 *     the wall ghosts counted as (dx / 2dx)^2 of a gas particle's lattice site, and the penalty.
 * Usage: test_riemann */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"
#include "physics/eos.h"
#include "physics/passes.h"
#include "physics/riemann.h"

/* The scheme, kernel, resolution, time and domain of the cases in the unit box at dx = 0.02, and
 * the keys that end every case here. */
#define UNIT_BOX_HEAD "dimension: 2\nscheme: riemann\nkernel: wendland-c2\n" \
    "resolution: {dx: 0.02, h_over_dx: 1.3}\ntime: {end: 1.0, cfl: 0.6}\n"      \
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
#define CASE_TAIL "physics: {u_max: 2}\ninitial: {pressure: zero}\noutput: {progress_interval: 1000}\n"

static const char *two_phase_case =
    "name: riemann-test\n" UNIT_BOX_HEAD
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 20, gamma: 1, incompressible: true}\n"
    "  - {name: light, rho0: 1, c0: 20, gamma: 1, density_band: [0.5, 2000]}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: light, box: {min: [0, 0.5], max: [1, 1]}}\n"
    CASE_TAIL;

static const char *one_phase_case =
    "name: riemann-step-test\n"
    "dimension: 2\n"
    "scheme: riemann\n"
    "kernel: wendland-c2\n"
    "resolution: {dx: 0.05, h_over_dx: 1.3}\n"
    "time: {end: 10.0, cfl: 0.6}\n"
    "domain: {min: [-1, -1], max: [3, 2]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 200, gamma: 1, incompressible: true}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 1]}}\n"
    CASE_TAIL;

static const char *wall_case =
    "name: riemann-wall-test\n"
    "dimension: 2\n"
    "scheme: riemann\n"
    "kernel: wendland-c2\n"
    "resolution: {dx: 0.05, h_over_dx: 1.3}\n"
    "time: {end: 1.0, cfl: 0.6}\n"
    "domain: {min: [-0.5, -0.5], max: [1.5, 1.5]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 20, gamma: 1, incompressible: true, p_background: 5000}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 1]}}\n"
    "walls:\n"
    "  - {box: {min: [0, 0], max: [1, 1]}, slip: no}\n"
    CASE_TAIL;

/* Test 8: water on a solid plate, no gravity. */
static const char *solid_case =
    "name: riemann-solid-test\n" UNIT_BOX_HEAD
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 20, gamma: 1, incompressible: true}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "solids:\n"
    "  - {min: [0, -0.08], max: [1, 0], rho0: 1100, youngs_modulus: 1e6, poisson_ratio: 0.3, probe: [0.5, -0.04]}\n"
    CASE_TAIL;

/* Test 9: water under a gas in a closed tank, at rest. */
static const char *penalty_case =
    "name: riemann-penalty-test\n" UNIT_BOX_HEAD
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 20, gamma: 1, incompressible: true, p_background: 5000}\n"
    "  - {name: gas, rho0: 1, c0: 20, gamma: 1, p_background: 5000, density_band: [0.5, 2000]}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: gas, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "walls:\n"
    "  - {box: {min: [0, 0], max: [1, 1]}, slip: no}\n"
    CASE_TAIL;

/* Test 10: test 2's phases, the light one at twice the spacing (0.52 m = 13 of its dx). */
static const char *multires_case =
    "name: riemann-multires-test\n" UNIT_BOX_HEAD
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 20, gamma: 1, incompressible: true}\n"
    "  - {name: light, rho0: 1, c0: 20, gamma: 1, density_band: [0.5, 2000], dx_ratio: 2}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.48]}}\n"
    "  - {phase: light, box: {min: [0, 0.48], max: [1, 1]}}\n"
    CASE_TAIL;

/* Tests 9 and 10: test 9's tank with the gas at twice the spacing (0.52 m = 13 of its dx), room for
 * 6 ghost layers. */
static const char *multires_penalty_case =
    "name: riemann-multires-penalty-test\n"
    "dimension: 2\nscheme: riemann\nkernel: wendland-c2\n"
    "resolution: {dx: 0.02, h_over_dx: 1.3}\ntime: {end: 1.0, cfl: 0.6}\n"
    "domain: {min: [-0.15, -0.15], max: [1.15, 1.15]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 20, gamma: 1, incompressible: true, p_background: 5000}\n"
    "  - {name: gas, rho0: 1, c0: 20, gamma: 1, p_background: 5000, density_band: [0.5, 2000], dx_ratio: 2}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.48]}}\n"
    "  - {phase: gas, box: {min: [0, 0.48], max: [1, 1]}}\n"
    "walls:\n"
    "  - {box: {min: [0, 0], max: [1, 1]}, slip: no}\n"
    CASE_TAIL;

/* Test 7: two liquids whose lattices are offset by (dx/2, dx/2) (anchors at their boxes' corners). */
static const char *liquids_case =
    "name: riemann-liquids-test\n" UNIT_BOX_HEAD
    "phases:\n"
    "  - {name: heavy, rho0: 1, c0: 15, gamma: 7, incompressible: true}\n"
    "  - {name: lighter, rho0: 0.01, c0: 150, gamma: 7, incompressible: true}\n"
    "fluids:\n"
    "  - {phase: heavy, box: {min: [0, 0], max: [1, 0.495]}}\n"
    "  - {phase: lighter, box: {min: [0.01, 0.49], max: [1.01, 1]}}\n"
    CASE_TAIL;

static void check_solver(void) {
  double zl = 1000 * 20, zr = 1 * 20, pl = 300, pr = 100;
  CHECK(riemann_pressure(zl, pl, zr, pr, 0.7, 20) == riemann_pressure(zr, pr, zl, pl, 0.7, 20), "p* symmetric");
  CHECK_CLOSE(riemann_pressure(zl, pl, zr, pr, -0.7, 20), (zl * pr + zr * pl) / (zl + zr), 1e-12, "expansion: no dissipation");
  CHECK_CLOSE(riemann_pressure(zl, pl, zl, pl, 0.0, 20), pl, 1e-12, "equal states");
  double z = 1000 * 20, big = 50;   /* 3 dU > c: beta = c */
  CHECK_CLOSE(riemann_pressure(z, pl, z, pl, big, 20), pl + 0.5 * z * big, 1e-9, "dissipation capped at rho c dU / 2");
  double small = 0.1;   /* 3 dU < c: beta = 3 dU */
  CHECK_CLOSE(riemann_pressure(z, pl, z, pl, small, 20), pl + 0.5 * 1000 * 3 * small * small, 1e-9, "beta = 3 dU");
  CHECK(fabs(riemann_pressure(1e-6 * z, pl, z, pr, 0.0, 20) - pl) <= 1e-6 * fabs(pl - pr), "light left, heavy right: p* -> p_left");
}

/* Field k on the lattice: 0 rho0 at rest; 1 one density (the water's), p linear, v = s r;
 * 2 random velocities and densities. Masses rho0 dx^2; pressures from the EOS except in field 1. */
static void set_fields(struct engine *e, int k) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] < 0) continue;   /* a wall ghost or a solid's particle */
    const struct phase *f = &e->c->phases[p->phase[i]];
    const double vol0 = e->prm.phase_vol0[p->phase[i]];
    p->m[i] = f->rho0 * vol0;
    p->rho[i] = k == 2 ? f->rho0 * (1 + 0.01 * engine_test_noise(p->id[i], 5)) : f->rho0;
    p->p[i] = eos_pressure(f, p->rho[i]);
    for (int d = 0; d < 2; d++) p->v[d][i] = k == 1 ? 0.3 * p->x[d][i] : k == 2 ? engine_test_noise(p->id[i], 10 + d) : 0;
    if (k == 1) {
      p->m[i] = 1000 * vol0;
      p->rho[i] = 1000;
      p->p[i] = 500 + 700 * p->x[0][i] - 300 * p->x[1][i];
    }
  }
}

/* Halo and volumes of the state set, then pass op of the pipeline. */
static void run_pass(struct engine *e, const char *name) {
  for (int k = 0; k < e->n_ops; k++)
    if (!e->ops[k].pass || !strcmp(e->ops[k].name, "volumes m/rho of owned and halo particles") ||
        !strncmp(e->ops[k].name, "neighbour lists", 15) || !strncmp(e->ops[k].name, name, strlen(name))) {
      if (!strncmp(e->ops[k].name, "halo: re-init", 13)) continue;
      engine_run_op(e, k);
      if (!strncmp(e->ops[k].name, name, strlen(name))) return;
    }
}

static void set_and_rebuild(struct engine *e, int k) {
  set_fields(e, k);
  engine_test_rebuild(e);
}

/* The kernel of the pair of owned particle i and slot j (h^chi). */
static const struct kernel *pair_kernel(const struct engine *e, long i, long j) {
  return riemann_pair_kernel(&e->prm, e->p.phase[i], e->p.phase[j]);
}

/* 1 if owned particle i's kernel support (the largest of its pairs') lies inside the box [0,1]^2. */
static int support_inside(const struct engine *e, long i) {
  double x = e->p.x[0][i], y = e->p.x[1][i], s = e->prm.chunk_kern[e->p.phase[i]].support;
  return fmin(fmin(x, 1 - x), fmin(y, 1 - y)) > s;
}

/* The re-initialised density of owned particle i by brute force over every slot (Eqs. 10-11 as
 * doc/theory.md section 10 states them), from the continuity density rho_star [kg/m^3]. */
static double expected_reinit(const struct engine *e, long i, double rho_star) {
  const struct parts *p = &e->p;
  const int ph = p->phase[i], light = riemann_light_phase(e->c, ph);
  const double rho0 = e->c->phases[ph].rho0;
  double sum = kernel_w(&e->prm.phase_kern[ph], 0.0);
  for (long j = 0; j < p->n_owned + p->n_halo; j++) {
    if (j == i || (!light && p->phase[j] != PHASE_WALL && p->phase[j] != ph)) continue;
    double dx[3], r2 = pair_separation(p, 2, i, j, dx), sites = p->phase[j] >= 0 ? e->prm.phase_vol0[p->phase[j]] : e->prm.vol0;
    if (r2 < pair_kernel(e, i, j)->support2) sum += sites / e->prm.phase_vol0[ph] * kernel_w(pair_kernel(e, i, j), r2);
  }
  double rho_sum = rho0 * sum / e->prm.lattice_w_sum[ph];
  return light ? rho_sum : rho_sum + fmax(0.0, rho_star - rho_sum) * rho0 / rho_star;
}

/* 1 if no fluid slot of another phase than owned particle i's lies within its support. */
static int support_of_own_phase(const struct engine *e, long i) {
  const struct parts *p = &e->p;
  for (long j = 0; j < p->n_owned + p->n_halo; j++) {
    double dx[3];
    if (p->phase[j] != PHASE_WALL && p->phase[j] != p->phase[i] &&
        pair_separation(p, 2, i, j, dx) < pair_kernel(e, i, j)->support2)
      return 0;
  }
  return 1;
}

/* Re-initialise from the continuity density 0.99 rho0; into err[0] the largest relative distance
 * of any particle from expected_reinit, into err[1] (heavy) and err[2] (light) that from rho0 of
 * the particles whose support lies inside [0,1]^2 and, for a heavy one (and any at
 * multi-resolution), holds no other phase (a light one counts every phase), into err[3] that of
 * the other light particles whose support lies inside, over all ranks. */
static void reinit_errors(struct engine *e, double *err) {
  set_and_rebuild(e, 0);
  for (long i = 0; i < e->p.n_owned; i++) e->p.rho[i] *= 0.99;
  double rho_star[e->p.n_owned > 0 ? e->p.n_owned : 1];
  for (long i = 0; i < e->p.n_owned; i++) rho_star[i] = e->p.rho[i];
  run_pass(e, "density re-initialisation");
  err[0] = err[1] = err[2] = err[3] = 0;
  for (long i = 0; i < e->p.n_owned; i++) {
    int ph = e->p.phase[i];
    if (ph == PHASE_WALL) continue;
    double rho0 = e->c->phases[ph].rho0;
    err[0] = fmax(err[0], fabs(e->p.rho[i] - expected_reinit(e, i, rho_star[i])) / rho0);
    int light = riemann_light_phase(e->c, ph), own = support_of_own_phase(e, i);
    if (support_inside(e, i) && ((light && !e->prm.multires) || own))
      err[1 + light] = fmax(err[1 + light], fabs(e->p.rho[i] - rho0) / rho0);
    else if (support_inside(e, i) && light)
      err[3] = fmax(err[3], fabs(e->p.rho[i] - rho0) / rho0);
  }
  MPI_Allreduce(MPI_IN_PLACE, err, 4, MPI_DOUBLE, MPI_MAX, e->comm);
}

static void check_reinit(struct engine *e) {
  double err[4];
  reinit_errors(e, err);
  if (e->rank == 0)
    printf("re-initialised density from 0.99 rho0: off Eqs. 10-11 by %.3g; off rho0 with complete supports "
           "(heavy%s: of its own phase): heavy %.3g, light %.3g\n", err[0], e->prm.multires ? " and light" : "",
           err[1], err[2]);
  if (e->rank == 0 && e->prm.multires)
    printf("multi-resolution: light particles beside the heavy phase off rho0 by up to %.3g\n", err[3]);
  CHECK(err[0] <= 1e-13 && err[1] <= 1e-13 && err[2] <= 1e-13, "re-initialisation on the lattice: %g %g %g",
        err[0], err[1], err[2]);
}

/* Test 7: two liquids at rest whose interface rows are crowded (0.71 dx apart): each one's
 * re-initialised density counts its own phase only (brute force), and the particles whose support
 * holds their own phase only come back to rho0 from 0.99 rho0. Counting the other liquid's
 * crowded rows as well reads as a compression of 28 % at the interface. */
static void check_liquid_reinit(struct engine *e) {
  double err[4];
  reinit_errors(e, err);
  if (e->rank == 0)
    printf("two liquids, crowded interface: re-initialised density off Eqs. 10-11 by %.3g, off rho0 %.3g\n",
           err[0], err[1]);
  CHECK(err[0] <= 1e-13 && err[1] <= 1e-13, "re-initialisation at a crowded liquid-liquid interface: %g %g",
        err[0], err[1]);
}

/* The plain symmetric pressure term and the expected continuity of owned particle i by brute force
 * over every slot; scale: the sums of the magnitudes. */
static void plain_terms(const struct engine *e, long i, double *acc, double *drho, double *scale) {
  const struct parts *p = &e->p;
  double c = e->c->phases[0].c0;
  acc[0] = acc[1] = *drho = scale[0] = scale[1] = 0;
  for (long j = 0; j < p->n_owned + p->n_halo; j++) {
    double dx[3], r2 = pair_separation(p, 2, i, j, dx);
    if (j == i || r2 >= pair_kernel(e, i, j)->support2 || p->phase[j] == PHASE_WALL) continue;
    double fv = kernel_f(pair_kernel(e, i, j), r2) * p->m[j] / p->rho[j], vdx = 0;
    for (int d = 0; d < 2; d++) {
      acc[d] -= (p->p[i] + p->p[j]) * fv * dx[d] / p->rho[i];
      scale[0] += fabs((p->p[i] + p->p[j]) * fv * dx[d] / p->rho[i]);
      vdx += (p->v[d][i] - p->v[d][j]) * dx[d];
    }
    double t = p->rho[i] * fv * vdx + fv * (p->p[i] - p->p[j]) * sqrt(r2) / c;
    *drho += t;
    scale[1] += fabs(t);
  }
}

static void check_equal_states(struct engine *e) {
  set_and_rebuild(e, 1);
  run_pass(e, "Riemann momentum");
  run_pass(e, "Riemann continuity");
  double worst[2] = {0, 0};
  for (long i = 0; i < e->p.n_owned; i++) {
    double acc[2], drho, scale[2];
    plain_terms(e, i, acc, &drho, scale);
    for (int d = 0; d < 2; d++) worst[0] = fmax(worst[0], fabs(e->w.dv[d][i] - acc[d]) / scale[0]);
    worst[1] = fmax(worst[1], fabs(e->w.drho[i] - drho) / scale[1]);
  }
  MPI_Allreduce(MPI_IN_PLACE, worst, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  if (e->rank == 0) printf("equal states, expansion: |du/dt - plain| / scale %.3g, |drho/dt - expected| / scale %.3g\n", worst[0], worst[1]);
  CHECK(worst[0] <= 1e-13 && worst[1] <= 1e-13, "Riemann terms = plain terms: %g %g", worst[0], worst[1]);
}

static void check_momentum(struct engine *e) {
  set_and_rebuild(e, 2);
  run_pass(e, "Riemann momentum");
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
    CHECK(fabs(sum[d]) <= 1e-13 * sum[2 + d], "momentum %c: %g, scale %g", "xy"[d], sum[d], sum[2 + d]);
}

static void check_walls(struct engine *e) {
  set_and_rebuild(e, 0);
  run_pass(e, "Riemann momentum");
  run_pass(e, "Riemann continuity");
  double worst[2] = {0, 0}, scale = 2 * 5000 / 1000.0 / e->prm.h;   /* 2 p / (rho h) */
  for (long i = 0; i < e->p.n_owned; i++) {
    if (e->p.phase[i] == PHASE_WALL) continue;
    worst[0] = fmax(worst[0], hypot(e->w.dv[0][i], e->w.dv[1][i]) / scale);
    worst[1] = fmax(worst[1], fabs(e->w.drho[i]));
  }
  MPI_Allreduce(MPI_IN_PLACE, worst, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  if (e->rank == 0) printf("walls, uniform pressure at rest: |du/dt| / (2p/(rho h)) %.3g, |drho/dt| %.3g\n", worst[0], worst[1]);
  CHECK(worst[0] <= 1e-13 && worst[1] == 0, "walls at rest: du/dt %g, drho/dt %g", worst[0], worst[1]);
}

/* The momentum pass's du/dt (2 per owned particle) and the continuity pass's drho/dt of the state
 * set, into rate (3 per owned particle); the solid loads recorded summed over the ranks into load,
 * and cleared. */
static void solid_rates(struct engine *e, double *rate, double *load) {
  run_pass(e, "Riemann momentum");
  for (long i = 0; i < e->p.n_owned; i++)
    for (int d = 0; d < 2; d++) rate[3 * i + d] = e->w.dv[d][i];
  load[0] = load[1] = 0;
  for (long k = 0; k < e->solids.loads.n; k++)
    for (int d = 0; d < 2; d++) load[d] += e->solids.loads.at[k].force[d];
  e->solids.loads.n = 0;
  MPI_Allreduce(MPI_IN_PLACE, load, 2, MPI_DOUBLE, MPI_SUM, e->comm);
  run_pass(e, "Riemann continuity");
  for (long i = 0; i < e->p.n_owned; i++) rate[3 * i + 2] = e->w.drho[i];
}

static void check_solid_wall(struct engine *e) {
  set_and_rebuild(e, 2);
  const struct parts *p = &e->p;
  double *rate = calloc(3 * (size_t)p->n_owned + 1, sizeof(double)), *moved = calloc(3 * (size_t)p->n_owned + 1, sizeof(double));
  double load[2], load_moved[2], sum[6] = {0, 0, 0, 0, 0, 0}, worst[2] = {0, 0}, V[2] = {0.7, -0.4};
  solid_rates(e, rate, load);
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < 2 && p->phase[i] >= 0; d++) {
      sum[d] += p->m[i] * rate[3 * i + d];
      sum[2 + d] += fabs(p->m[i] * rate[3 * i + d]);
      sum[4] = fmax(sum[4], fabs(rate[3 * i + d]));
      sum[5] = fmax(sum[5], fabs(rate[3 * i + 2]));
    }
  MPI_Allreduce(MPI_IN_PLACE, sum, 4, MPI_DOUBLE, MPI_SUM, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, sum + 4, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  for (long g = 0; g < e->solids.view.n; g++)
    for (int d = 0; d < 2; d++) e->solids.v_avg[2 * g + d] = V[d];
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < 2 && p->phase[i] >= 0; d++) p->v[d][i] += V[d];
  solid_rates(e, moved, load_moved);
  for (long i = 0; i < p->n_owned; i++)
    for (int k = 0; k < 3 && p->phase[i] >= 0; k++) worst[k / 2] = fmax(worst[k / 2], fabs(moved[3 * i + k] - rate[3 * i + k]));
  MPI_Allreduce(MPI_IN_PLACE, worst, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  if (e->rank == 0)
    printf("solid as a moving wall: sum m du/dt = (%.6g, %.6g), the loads (%.6g, %.6g); shifted by V: |d du/dt| %.3g "
           "of %.3g, |d drho/dt| %.3g of %.3g\n", sum[0], sum[1], load[0], load[1], worst[0], sum[4], worst[1], sum[5]);
  CHECK(fabs(sum[1]) > 1e-3 * sum[3], "the solid carries a load: sum m dv_y %g of %g", sum[1], sum[3]);
  for (int d = 0; d < 2; d++)
    CHECK(fabs(sum[d] + load[d]) <= 1e-12 * sum[2 + d], "loads %c: %g against -sum m du/dt %g", "xy"[d], load[d], -sum[d]);
  CHECK(worst[0] <= 1e-12 * sum[4] && worst[1] <= 1e-12 * sum[5], "Galilean: du/dt %g, drho/dt %g", worst[0], worst[1]);
  free(rate);
  free(moved);
}

/* The penalty of the lid's ghosts on gas particle i by brute force (doc/theory.md section 14). */
static void penalty_expected(const struct engine *e, long i, double k, double *acc) {
  const struct parts *p = &e->p;
  acc[0] = acc[1] = 0;
  for (long j = 0; j < p->n_owned + p->n_halo; j++) {
    double dx[3], r2 = pair_separation(p, 2, i, j, dx);
    const struct kernel *kp = pair_kernel(e, i, j);   /* i's: h^chi of a light particle and a wall */
    if (p->phase[j] != PHASE_WALL || r2 >= kp->support2) continue;
    double m = hypot(p->mirror[0][j], p->mirror[1][j]), n[2] = {p->mirror[0][j] / m, p->mirror[1][j] / m};
    double r = sqrt(r2), rn = dx[0] * n[0] + dx[1] * n[1], beta = 2 * rn / e->prm.h;
    if (beta > 1) continue;
    double gamma = k * (e->prm.h / kp->h) * fabs(p->p[i] * rn / r) * (1 - beta) * (1 - beta), dw = kernel_f(kp, r2) * r;
    for (int d = 0; d < 2; d++) acc[d] -= 2.0 / p->rho[i] * e->prm.vol0 * gamma * n[d] * dw;
  }
}

static void check_penalty(struct engine *e, struct case_def *c) {
  set_fields(e, 0);
  const double dx = case_phase_dx(e->c, 1);
  const double x0 = (floor(0.5 / dx - 0.5) + 0.5) * dx;   /* the gas's lattice column nearest 0.5 from below */
  long target = -1;   /* the gas particle at (x0, 1 - dx/2), in the row under the lid, at the gas's dx */
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.phase[i] == 1 && fabs(e->p.x[0][i] - x0) < 1e-9 && fabs(e->p.x[1][i] - (1 - dx / 2)) < 1e-9)
      target = e->p.id[i];
  MPI_Allreduce(MPI_IN_PLACE, &target, 1, MPI_LONG, MPI_MAX, e->comm);
  CHECK(target >= 0, "the gas particle at the lid");
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.id[i] == target) e->p.x[1][i] = 1.0 - 0.1 * e->c->dx;   /* within h/2 of the first ghost row */
  engine_test_rebuild(e);
  const long n = e->p.n_owned;
  double *without = calloc(2 * (size_t)n + 1, sizeof(double)), worst_other = 0, got[2] = {0, 0}, want[2] = {0, 0};
  double scale = 0;   /* the target's |du/dt|: got is a difference of two such, to its round-off */
  c->light_penalty = 0;
  engine_assemble(e);   /* the pipeline's parameters from the case */
  run_pass(e, "Riemann momentum");
  for (long i = 0; i < n; i++)
    for (int d = 0; d < 2; d++) without[2 * i + d] = e->w.dv[d][i];
  c->light_penalty = 0.01;
  engine_assemble(e);
  run_pass(e, "Riemann momentum");
  for (long i = 0; i < n; i++) {
    if (e->p.phase[i] < 0) continue;
    if (e->p.id[i] != target) {
      for (int d = 0; d < 2; d++) worst_other = fmax(worst_other, fabs(e->w.dv[d][i] - without[2 * i + d]));
      continue;
    }
    for (int d = 0; d < 2; d++) got[d] = e->w.dv[d][i] - without[2 * i + d];
    scale = fmax(hypot(without[2 * i], without[2 * i + 1]), hypot(e->w.dv[0][i], e->w.dv[1][i]));
    penalty_expected(e, i, 0.01, want);
  }
  MPI_Allreduce(MPI_IN_PLACE, got, 2, MPI_DOUBLE, MPI_SUM, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, want, 2, MPI_DOUBLE, MPI_SUM, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, &worst_other, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, &scale, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  if (e->rank == 0)
    printf("penalty at 0.1 dx from the lid: (%.6g, %.6g) m/s^2, brute force (%.6g, %.6g), |du/dt| %.3g; largest change "
           "elsewhere %g\n", got[0], got[1], want[0], want[1], scale, worst_other);
  CHECK(got[1] < 0 && fabs(got[1]) > 1.0, "the penalty pushes off the lid: %g", got[1]);
  CHECK(fabs(got[0] - want[0]) <= 1e-13 * scale && fabs(got[1] - want[1]) <= 1e-13 * scale,
        "penalty (%g, %g) against (%g, %g), |du/dt| %g", got[0], got[1], want[0], want[1], scale);
  CHECK(worst_other == 0, "no other particle's du/dt changes: %g", worst_other);
  free(without);
}

/* Every fluid particle at rest density with velocity (u, 0). */
static void uniform_flow(struct engine *e, double u) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    p->rho[i] = e->c->phases[0].rho0;
    p->p[i] = eos_pressure(&e->c->phases[0], p->rho[i]);
    p->v[0][i] = u;
    p->v[1][i] = 0;
  }
}

static void check_stepper(struct engine *e) {
  double h = e->prm.h, b = 0.75 * engine_shift_max(e), u_ref = e->c->u_max;
  uniform_flow(e, 0.1 * u_ref);
  CHECK_CLOSE(dual_advection_dt(e, 0.0), 0.25 * h / u_ref, 1e-15, "dt_ad, U << u_max");
  double u = 10 * u_ref, a = 500;
  uniform_flow(e, u);
  CHECK_CLOSE(dual_advection_dt(e, 0.0), b / u, 1e-15, "dt_ad, U >> u_max: the cell-skin limit");
  CHECK_CLOSE(dual_advection_dt(e, a), 2 * b / (u + sqrt(u * u + 2 * a * b)), 1e-15, "dt_ad with a transport shift");
  u = 3.0;
  uniform_flow(e, u);
  double dt_ad = fmin(0.25 * h / fmax(u_ref, u), b / u), dt_ac = e->c->cfl * h / (e->c->phases[0].c0 + u), x0[2] = {0, 0};
  long first = -1;
  for (long i = 0; i < e->p.n_owned && first < 0; i++) first = i;
  if (first >= 0) for (int d = 0; d < 2; d++) x0[d] = e->p.x[d][first];
  CHECK(engine_step_dual(e) == 0, "advection step");
  long expected = (long)ceil(dt_ad / dt_ac);
  if (e->rank == 0) printf("stepper: dt_ad %.6g (expected %.6g), %ld acoustic sub-steps (expected %ld)\n", e->dt, dt_ad, e->n_acoustic, expected);
  CHECK_CLOSE(e->dt, dt_ad, 1e-15, "advection step");
  CHECK(e->n_acoustic == expected, "sub-steps %ld, expected %ld", e->n_acoustic, expected);
  if (first >= 0) {
    CHECK_CLOSE(e->p.x[0][first] - x0[0], u * dt_ad, 1e-13, "moved by U dt_ad");
    CHECK_CLOSE(e->p.x[1][first] - x0[1], 0.0, 1e-15, "no transverse motion");
    CHECK_CLOSE(e->p.v[0][first], u, 1e-12, "velocity kept");
  }
}

/* Tests 2-4 (and 10) on engine e, which is then closed. */
static void check_lattice_terms(struct engine *e) {
  check_reinit(e);
  check_equal_states(e);
  check_momentum(e);
  engine_close_output(e);
  engine_free(e);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) check_solver();
  char dir[256] = "/tmp/mpsph-test-riemann-XXXXXX", dir1[256] = "/tmp/mpsph-test-riemann1-XXXXXX";
  char dir2[256] = "/tmp/mpsph-test-riemann2-XXXXXX", dir3[256] = "/tmp/mpsph-test-riemann3-XXXXXX";
  if (engine_test_scratch(dir, sizeof dir) || engine_test_scratch(dir1, sizeof dir1) ||
      engine_test_scratch(dir2, sizeof dir2) || engine_test_scratch(dir3, sizeof dir3))
    return 1;
  static struct case_def c, c1, c2, c3;
  struct engine e, e1, e2, e3;
  if (engine_test_start(dir, two_phase_case, &c, &e)) return check_report("test_riemann");
  CHECK((e.prm.features & FEAT_RIEMANN) && (e.prm.features & FEAT_TRANSPORT_VELOCITY) && !(e.prm.features & (FEAT_SHIFT | FEAT_DAMPER | FEAT_TIC)),
        "riemann pipeline: its own terms only, transport velocity with a light phase");
  check_lattice_terms(&e);
  char dir6[256] = "/tmp/mpsph-test-riemann6-XXXXXX";
  static struct case_def c6;
  struct engine e6;
  if (engine_test_open(dir6, sizeof dir6, multires_case, &c6, &e6)) return check_report("test_riemann");
  CHECK(e6.prm.multires && e6.prm.support_max == 2 * e6.prm.kern.support, "multi-resolution: the light kernel twice h");
  check_lattice_terms(&e6);
  char dir7[256] = "/tmp/mpsph-test-riemann7-XXXXXX";
  static struct case_def c7;
  struct engine e7;
  if (engine_test_open(dir7, sizeof dir7, multires_penalty_case, &c7, &e7)) return check_report("test_riemann");
  check_reinit(&e7);   /* the ghosts counted as 1/4 of a gas particle's lattice site */
  check_penalty(&e7, &c7);
  engine_close_output(&e7);
  engine_free(&e7);
  if (engine_test_start(dir2, wall_case, &c2, &e2)) return check_report("test_riemann");
  check_walls(&e2);
  engine_close_output(&e2);
  engine_free(&e2);
  char dir4[256] = "/tmp/mpsph-test-riemann4-XXXXXX", dir5[256] = "/tmp/mpsph-test-riemann5-XXXXXX";
  static struct case_def c4, c5;
  struct engine e4, e5;
  if (engine_test_open(dir5, sizeof dir5, penalty_case, &c5, &e5)) return check_report("test_riemann");
  check_penalty(&e5, &c5);
  engine_close_output(&e5);
  engine_free(&e5);
  if (engine_test_open(dir4, sizeof dir4, solid_case, &c4, &e4)) return check_report("test_riemann");
  check_solid_wall(&e4);
  engine_close_output(&e4);
  engine_free(&e4);
  if (engine_test_start(dir3, liquids_case, &c3, &e3)) return check_report("test_riemann");
  CHECK(!(e3.prm.features & FEAT_TRANSPORT_VELOCITY), "two liquids: no light phase, no transport velocity");
  check_liquid_reinit(&e3);
  engine_close_output(&e3);
  engine_free(&e3);
  if (engine_test_start(dir1, one_phase_case, &c1, &e1)) return check_report("test_riemann");
  CHECK(!(e1.prm.features & FEAT_TRANSPORT_VELOCITY), "one phase: no transport velocity");
  check_stepper(&e1);
  if (rank == 0) {
    char cmd[900];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' '%s' '%s' '%s' '%s' '%s' '%s'", dir, dir2, dir3, dir4, dir5, dir6, dir7);
    if (system(cmd)) printf("could not remove %s, %s, %s\n", dir, dir2, dir3);
  }
  return engine_test_finish(&e1, dir1, "test_riemann");
}
