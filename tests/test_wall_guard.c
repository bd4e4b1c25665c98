/* test_wall_guard.c — the wall guard (src/physics/wall_guard.c) on single particles placed by hand in a
 * tank [0, 1] x [0, 1] with dx = 0.05 and physics.wall_guard = 0.25 (a guard distance of
 * 0.0125 m):
 *  1. fixed tank, after a step (wall_guard_apply, through engine_wall_guard): a particle 0.2 dx
 *     above the floor moving down loses its normal velocity and keeps its tangential one; moving
 *     up, or 0.6 dx above the floor,
 *     it is untouched; inside the floor's solid it loses the velocity that carries it deeper; near
 *     the left wall the normal is x; the number of corrections is counted;
 *  2. fixed tank, per stage (pass_wall_guard): the acceleration into the floor is removed for a
 *     particle at rest or approaching, kept for one moving away unless it would turn it within
 *     the step (then cut to what stops it); the inward shifting velocity is removed in both cases;
 *  3. a tank moving up at 0.2 pi m/s (sinusoid at t = 0): the velocity relative to the floor is
 *     what counts, and the corrected particle moves with the floor; likewise the acceleration,
 *     relative to the floor's (zero at t = 0 for a sinusoid started at its zero);
 *  4. a free rigid body (a box above the water, no gravity): the velocity the guard takes from a
 *     particle closing on its bottom goes to the body as an impulse (momentum and angular
 *     momentum conserved), and the acceleration it removes in a stage becomes a load on it.
 * Usage: test_wall_guard [TMPDIR] */
#include <math.h>
#include <stdio.h>
#include "case/case_load.h"
#include "check.h"
#include "engine_test.h"
#include "engine/engine.h"
#include "case/motion.h"
#include "physics/passes.h"

#define TOL 1e-14

/* The tank's case: a name, the domain's top y, the walls' items and the physics and output keys
 * every case here shares. */
#define TANK_CASE(name, top, walls)                                     \
  "name: " name "\n"                                                    \
  "dimension: 2\n"                                                      \
  "resolution: {dx: 0.05}\n"                                            \
  "time: {end: 1.0}\n"                                                  \
  "domain: {min: [-0.3, -0.3], max: [1.3, " top "]}\n"                  \
  "phases:\n"                                                           \
  "  - {name: water, rho0: 1000, c0: 20, incompressible: true}\n"       \
  "fluids:\n"                                                           \
  "  - {phase: water, box: {min: [0, 0], max: [1, 0.5]}}\n"             \
  "walls:\n" walls                                                      \
  "physics: {wall_guard: 0.25, free_surface: off}\n"                    \
  "output: {progress_interval: 1000}\n"

static const char *fixed_case =
    TANK_CASE("wall-guard-test", "1.3", "  - {box: {min: [0, 0], max: [1, 1]}, slip: free}\n");

static const char *moving_case =
    TANK_CASE("wall-guard-moving", "1.5", "  - {box: {min: [0, 0], max: [1, 1]}, slip: free,\n"
                                          "     motion: {translation: {amplitude: [0, 0.1], period: 1.0}}}\n");

static const char *body_case =
    TANK_CASE("wall-guard-body", "1.3", "  - {box: {min: [0, 0], max: [1, 1]}, slip: free}\n"
                                        "  - {box: {min: [0.4, 0.6], max: [0.6, 0.7]}, fluid_side: outside, "
                                        "body: {mass: 4, inertia: 0.5}}\n");

/* The first owned fluid particle (every rank owns some in these tests). */
static long first_fluid(const struct engine *e) {
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.phase[i] != PHASE_WALL) return i;
  return -1;
}

/* Place particle i at (x, y) with velocity (u, v); zero its derivatives. */
static void place(struct engine *e, long i, double x, double y, double u, double v) {
  e->p.x[0][i] = x, e->p.x[1][i] = y;
  e->p.v[0][i] = u, e->p.v[1][i] = v;
  e->w.dv[0][i] = e->w.dv[1][i] = 0;
  if (e->w.du[0]) e->w.du[0][i] = e->w.du[1][i] = 0;
}

/* After one wall_guard_apply with particle i alone placed: its velocity (u, v) and the count. */
static void expect_after_step(struct engine *e, long i, double u, double v, long hits, const char *what) {
  long n = engine_wall_guard(e);
  CHECK(n == hits && fabs(e->p.v[0][i] - u) < TOL && fabs(e->p.v[1][i] - v) < TOL,
        "%s: v = (%g, %g), %ld corrections; want (%g, %g), %ld", what, e->p.v[0][i], e->p.v[1][i], n, u, v, hits);
}

/* pass_wall_guard on the engine's particles, as the stage pipeline runs it. */
static void guard_stage(struct engine *e) {
  struct pass_ctx ctx = engine_pass_ctx(e);
  pass_wall_guard(&ctx);
}

/* Park every owned fluid particle in the middle of the tank at rest (away from the guard). */
static void park_all(struct engine *e) {
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.phase[i] != PHASE_WALL) place(e, i, 0.5, 0.5, 0, 0);
}

static void fixed_tank(struct engine *e) {
  long i = first_fluid(e);
  park_all(e);
  place(e, i, 0.5, 0.01, 1, -2);
  expect_after_step(e, i, 1, 0, 1, "0.2 dx above the floor, moving down");
  place(e, i, 0.5, 0.01, 1, 2);
  expect_after_step(e, i, 1, 2, 0, "0.2 dx above the floor, moving up");
  place(e, i, 0.5, 0.03, 1, -2);
  expect_after_step(e, i, 1, -2, 0, "0.6 dx above the floor");
  place(e, i, 0.5, -0.005, 0.5, -1);
  expect_after_step(e, i, 0.5, 0, 1, "inside the floor's solid, moving deeper");
  place(e, i, 0.005, 0.5, -3, 1);
  expect_after_step(e, i, 0, 1, 1, "0.1 dx from the left wall, moving left");
  CHECK(e->wall_guard_hits >= 3, "wall_guard_hits %ld", e->wall_guard_hits);

  place(e, i, 0.5, 0.01, 0, 0);
  e->w.dv[0][i] = 2, e->w.dv[1][i] = -50;
  if (e->w.du[0]) e->w.du[0][i] = 0.1, e->w.du[1][i] = -0.2;
  guard_stage(e);
  CHECK(e->w.dv[0][i] == 2 && e->w.dv[1][i] == 0, "at rest: dv/dt = (%g, %g), want (2, 0)", e->w.dv[0][i], e->w.dv[1][i]);
  CHECK(e->w.du[0] && e->w.du[0][i] == 0.1 && e->w.du[1][i] == 0, "shifting velocity not clipped");
  place(e, i, 0.5, 0.01, 0, 1);
  e->w.dv[1][i] = -50;
  guard_stage(e);
  CHECK(e->w.dv[1][i] == -50, "moving away: dv/dt_y = %g, want -50 (kept)", e->w.dv[1][i]);
  e->prm.dt_step = 1e-3;   /* with a step: moving away at 1 m/s, at most 1000 m/s^2 back toward the floor */
  e->w.dv[1][i] = -50;
  guard_stage(e);
  CHECK(e->w.dv[1][i] == -50, "moving away, slow turn: dv/dt_y = %g, want -50 (kept)", e->w.dv[1][i]);
  e->w.dv[1][i] = -5000;
  guard_stage(e);
  CHECK(fabs(e->w.dv[1][i] + 1000) < 1e-9, "moving away, turning within the step: dv/dt_y = %g, want -1000",
        e->w.dv[1][i]);
  e->prm.dt_step = 0;
}

static void moving_tank(struct engine *e, const struct case_def *c) {
  long i = first_fluid(e);
  double floor_speed = 0.1 * 2 * acos(-1.0);   /* A omega cos(0) */
  motion_frame(&c->walls[0].motion, 0.0, &e->prm.frames[0]);
  park_all(e);
  place(e, i, 0.5, 0.01, 0, 0.3);
  expect_after_step(e, i, 0, floor_speed, 1, "moving floor overtaking the particle");
  place(e, i, 0.5, 0.01, 0, 1.0);
  expect_after_step(e, i, 0, 1.0, 0, "particle faster than the moving floor");
  place(e, i, 0.5, 0.01, 0, floor_speed);
  e->w.dv[1][i] = -3;   /* the floor's acceleration at t = 0 is 0: -3 is into it */
  guard_stage(e);
  CHECK(fabs(e->w.dv[1][i]) < TOL, "moving floor: dv/dt_y = %g, want 0", e->w.dv[1][i]);
}

/* A particle 0.1 dx under the body's bottom, 0.05 m left of its centre, moving up at 2 m/s: the
 * body (at rest, centre (0.5, 0.65)) takes its momentum m (0, 2) and the angular momentum
 * (-0.05 m) x (m (0, 2)) about its centre; in a stage the removed acceleration (0, 30) is a load
 * -m (0, 30) on it at the particle. Every rank places its own particle there: the body takes the
 * sum of their impulses. */
static void body_reaction(struct engine *e) {
  long i = first_fluid(e);
  park_all(e);
  double m = e->p.m[i], *y = e->bodies.run[0].y;
  place(e, i, 0.45, 0.595, 0.3, 2);
  expect_after_step(e, i, 0.3, 0, 1, "closing on the body's bottom");
  CHECK_CLOSE(y[RB_V + 1], e->n_ranks * 2 * m / 4, TOL, "the body's velocity takes the particles' momentum");
  CHECK_CLOSE(y[RB_W + 2], e->n_ranks * -0.05 * 2 * m / 0.5, TOL, "the body's spin takes their angular momentum");
  CHECK(y[RB_V] == 0, "no tangential impulse (free slip)");
  y[RB_V + 1] = y[RB_W + 2] = 0;
  place(e, i, 0.45, 0.595, 0, 0);
  e->w.dv[1][i] = 30;
  struct pass_ctx ctx = engine_pass_ctx(e);
  pass_wall_guard(&ctx);
  CHECK(e->w.dv[1][i] == 0 && ctx.loads->n == 1, "the stage's acceleration into the body removed, one load");
  CHECK(ctx.loads->at[0].wall == 1 && ctx.loads->at[0].source == LOAD_GUARD &&
        ctx.loads->at[0].force[1] == m * 30 && ctx.loads->at[0].force[0] == 0,
        "the load on the body: (%g, %g), want (0, %g)", ctx.loads->at[0].force[0], ctx.loads->at[0].force[1], m * 30);
  ctx.loads->n = 0;
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  char dir[256];
  snprintf(dir, sizeof dir, "%s/mpsph_wall_guard_XXXXXX", argc > 1 ? argv[1] : "/tmp");
  struct case_def c;
  struct engine e;
  if (engine_test_scratch(dir, sizeof dir) || engine_test_start(dir, fixed_case, &c, &e)) return 1;
  fixed_tank(&e);
  engine_close_output(&e);
  engine_free(&e);
  struct case_def cm;
  struct engine em;
  if (engine_test_start(dir, moving_case, &cm, &em)) return 1;
  moving_tank(&em, &cm);
  engine_close_output(&em);
  engine_free(&em);
  struct case_def cb;
  struct engine eb;
  if (engine_test_start(dir, body_case, &cb, &eb)) return 1;
  body_reaction(&eb);
  return engine_test_finish(&eb, dir, "test_wall_guard");
}
