/* test_scheme.c — the delta-plus passes on analytic fields, through the real engine (run with
 * 1 and 2 ranks): a two-phase box (water below, a light phase above, no walls, no gravity) on a
 * randomly perturbed lattice,
 *  1. the renormalised density gradient reproduces a linear density field to round-off for every
 *     particle whose same-phase support is complete;
 *  2. with random velocities and densities, shifting (delta-u terms), viscosity and the interface
 *     sharpness force on, the total momentum change sum_i m_i du_i/dt vanishes to round-off
 *     (every pair term is antisymmetric; tensile control and the damper, which are not, are off);
 *  3. with delta = 0 and alpha = 0 the density diffusion, the renormalised gradient and the
 *     viscosity leave the pipeline, and the right-hand sides without them equal, value for value,
 *     those of the full evaluation with zero coefficients (what is skipped is only what is zero).
 * Usage: test_scheme [TMPDIR] */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine.h"
#include "eos.h"

static const char *case_text =
    "name: scheme-test\n"
    "dimension: 2\n"
    "resolution: {dx: 0.02}\n"
    "time: {end: 1.0}\n"
    "domain: {min: [-0.1, -0.1], max: [1.1, 1.1]}\n"
    "phases:\n"
    "  - {name: water, rho0: 1000, c0: 30, incompressible: true, p_background: 1000}\n"
    "  - {name: light, rho0: 10, c0: 100, gamma: 1.4, p_background: 1000}\n"
    "fluids:\n"
    "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"
    "  - {phase: light, box: {min: [0, 0.5], max: [1, 1]}}\n"
    "physics: {shifting: consistent, acoustic_damper: 0, tensile_control: false, free_surface: off,\n"
    "          interface_sharpness: 0.08, u_max: 3}\n"
    "initial: {pressure: zero}\n"
    "output: {progress_interval: 1000}\n";

static const double slope[2] = {0.013, -0.021};   /* relative density gradient [1/m] */

/* Perturb positions by up to 0.3 dx and set rho = rho0 (1 + slope.x) (+ noise if noisy), random u. */
static void set_fields(struct engine *e, int noisy) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    const struct phase *ph = &e->c->phases[p->phase[i]];
    double lin = 1.0;
    for (int d = 0; d < 2; d++) {
      if (!noisy) p->x[d][i] += 0.3 * e->c->dx * engine_test_noise(p->id[i], d);
      lin += slope[d] * p->x[d][i];
      p->v[d][i] = noisy ? engine_test_noise(p->id[i], 10 + d) : 0.0;
    }
    p->rho[i] = ph->rho0 * (lin + (noisy ? 0.01 * engine_test_noise(p->id[i], 20) : 0.0));
    p->p[i] = eos_pressure(ph, p->rho[i]);
  }
}

/* Distance from x to the boundary of its phase's region (the half box it started in). */
static double depth_in_phase(const struct parts *p, long i) {
  double x = p->x[0][i], y = p->x[1][i], lo = p->phase[i] == 0 ? 0.0 : 0.5, hi = lo + 0.5;
  return fmin(fmin(x, 1 - x), fmin(y - lo, hi - y));
}

static void check_gradient(struct engine *e) {
  const struct parts *p = &e->p;
  long tested = 0, bad = 0;
  double worst = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL || depth_in_phase(p, i) < 1.5 * e->kern.support) continue;
    double rho0 = e->c->phases[p->phase[i]].rho0;
    for (int d = 0; d < 2; d++) {
      double err = fabs(e->w.grad_rho[d][i] - rho0 * slope[d]) / (rho0 * 0.02);
      worst = fmax(worst, err);
      bad += err > 1e-9;
    }
    tested++;
  }
  MPI_Allreduce(MPI_IN_PLACE, &tested, 1, MPI_LONG, MPI_SUM, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_LONG, MPI_SUM, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  if (e->rank == 0) printf("linear density gradient: %ld interior particles, worst relative error %.3g\n", tested, worst);
  CHECK(tested > 200 && bad == 0, "linear density gradient: %ld of %ld particles off (worst relative %g)",
        bad, tested, worst);
}

static void check_momentum(struct engine *e) {
  const struct parts *p = &e->p;
  double sum[4] = {0, 0, 0, 0};   /* sum m dv, sum |m dv| per component */
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    for (int d = 0; d < 2; d++) {
      sum[d] += p->m[i] * e->w.dv[d][i];
      sum[2 + d] += fabs(p->m[i] * e->w.dv[d][i]);
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, sum, 4, MPI_DOUBLE, MPI_SUM, e->comm);
  if (e->rank == 0) printf("momentum: sum m du/dt = (%.3g, %.3g), scale (%.3g, %.3g)\n", sum[0], sum[1], sum[2], sum[3]);
  for (int d = 0; d < 2; d++)
    CHECK(fabs(sum[d]) <= 1e-12 * sum[2 + d], "momentum %c: sum m du/dt = %g, scale %g", "xy"[d],
          sum[d], sum[2 + d]);
}

/* Copy (save) or compare (!save) drho/dt and du/dt of the owned fluid with buf (3 per particle);
 * returns the count of values that differ. */
static long rhs_values(struct engine *e, double *buf, int save) {
  const struct parts *p = &e->p;
  long differ = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (p->phase[i] == PHASE_WALL) continue;
    const double now[3] = {e->w.drho[i], e->w.dv[0][i], e->w.dv[1][i]};
    for (int k = 0; k < 3; k++) {
      if (save) buf[3 * i + k] = now[k];
      else differ += buf[3 * i + k] != now[k];
    }
  }
  return differ;
}

/* Check 3: delta and alpha set to zero; the skipped terms against the full evaluation. */
static void check_terms_off(struct engine *e, struct case_def *c) {
  c->delta = 0;
  c->alpha = 0;
  engine_assemble(e);
  int gradient_op = 0;
  for (int k = 0; k < e->n_ops; k++) gradient_op |= strstr(e->ops[k].name, "density gradient") != NULL;
  CHECK(!(e->features & (FEAT_DIFFUSION | FEAT_VISCOSITY)) && !gradient_op,
        "delta = alpha = 0: diffusion, viscosity and the density gradient are out of the pipeline");
  double *buf = malloc(3 * sizeof(double) * (e->p.n_owned + 1));
  e->stage = 0;
  engine_evaluate(e, 0);
  rhs_values(e, buf, 1);
  e->features |= FEAT_DIFFUSION | FEAT_VISCOSITY;   /* the full loops, with zero coefficients */
  engine_evaluate(e, 0);
  long differ = rhs_values(e, buf, 0);
  MPI_Allreduce(MPI_IN_PLACE, &differ, 1, MPI_LONG, MPI_SUM, e->comm);
  CHECK(differ == 0, "terms skipped vs evaluated with zero coefficients: %ld values differ", differ);
  free(buf);
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  char dir[256] = "/tmp/mpsph-test-scheme-XXXXXX";
  if (engine_test_scratch(dir, sizeof dir)) return 1;
  static struct case_def c;
  struct engine e;
  if (engine_test_start(dir, case_text, &c, &e)) return check_report("test_scheme");
  for (int noisy = 0; noisy <= 1; noisy++) {
    set_fields(&e, noisy);
    CHECK(engine_rebuild(&e) == 0, "rebuild");
    e.stage = 0;
    engine_evaluate(&e, 0);
    if (!noisy) check_gradient(&e);
    else check_momentum(&e);
  }
  check_terms_off(&e, &c);
  return engine_test_finish(&e, dir, "test_scheme");
}
