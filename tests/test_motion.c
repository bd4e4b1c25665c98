/* test_motion.c — prescribed wall motion: the analytic velocity and acceleration of a body point
 * against central differences of its position, ramps, and the identity of an inactive motion. */
#include <math.h>
#include <string.h>
#include "check.h"
#include "case/motion.h"

/* Position of body point x_ref at time t. */
static void position_at(const struct wall_motion *m, double t, const double *x_ref, double *x) {
  struct frame f;
  motion_frame(m, t, &f);
  frame_position(&f, 2, x_ref, x);
}

/* Velocity and acceleration of x_ref's point at t against central differences of step k [s]. */
static void check_derivatives_step(const struct wall_motion *m, double t, double k, const char *what) {
  const double x_ref[2] = {0.3, -0.2};
  double xm[2], x0[2], xp[2], u[2], a[2];
  struct frame f;
  position_at(m, t - k, x_ref, xm);
  position_at(m, t + k, x_ref, xp);
  motion_frame(m, t, &f);
  frame_position(&f, 2, x_ref, x0);
  frame_velocity(&f, 2, x0, u);
  frame_acceleration(&f, 2, x0, a);
  for (int d = 0; d < 2; d++) {
    double fd_u = (xp[d] - xm[d]) / (2 * k), fd_a = (xp[d] - 2 * x0[d] + xm[d]) / (k * k);
    CHECK_CLOSE(u[d], fd_u, 1e-7, what);
    CHECK_CLOSE(a[d], fd_a, 2e-4, what);
  }
}

/* check_derivatives_step with the step 1e-4 s. */
static void check_derivatives(const struct wall_motion *m, double t, const char *what) {
  check_derivatives_step(m, t, 1e-4, what);
}

/* A table motion: passes through its rows, C2 (velocity and acceleration continuous across a
 * row), derivatives against finite differences, rest outside the table. */
static void test_table(void) {
  static struct wall_motion m;
  const double rows[5][5] = {{0, 0, 0, 0, 0}, {0.2, 0.01, -0.003, 0, 0.02}, {0.5, -0.02, 0.004, 0, -0.01},
                             {0.6, 0.005, 0.001, 0, 0.03}, {1.0, 0, 0, 0, 0}};
  memset(&m, 0, sizeof(m));
  m.n_rows = 5;
  memcpy(m.table, rows, sizeof(rows));
  m.centre[0] = 0.4, m.centre[1] = 0.1;
  struct frame f, g;
  for (int i = 0; i < 5; i++) {
    motion_frame(&m, rows[i][0], &f);
    CHECK(fabs(f.d[0] - rows[i][1]) + fabs(f.d[1] - rows[i][2]) + fabs(f.theta - rows[i][4]) < 1e-16,
          "table row %d: d %.17g %.17g theta %.17g", i, f.d[0], f.d[1], f.theta);
  }
  /* the spline's pieces of 0.1 s have a third derivative up to ~300 m/s^3 (it jumps at the
   * rows), so a step of 1e-5 s keeps the differences' error below 1e-8 */
  for (double t = 0.03; t < 1.0; t += 0.043) check_derivatives_step(&m, t, 1e-5, "table");
  for (int i = 1; i < 4; i++) {   /* velocity and acceleration are continuous across the rows */
    motion_frame(&m, rows[i][0] - 1e-9, &f);
    motion_frame(&m, rows[i][0] + 1e-9, &g);
    CHECK_CLOSE(f.v[0], g.v[0], 1e-6, "table velocity continuous at a row");
    CHECK_CLOSE(f.omega, g.omega, 1e-6, "table rate continuous at a row");
    CHECK_CLOSE(f.a[1], g.a[1], 1e-5, "table acceleration continuous at a row");
    CHECK_CLOSE(f.alpha, g.alpha, 1e-5, "table angular acceleration continuous at a row");
  }
  motion_frame(&m, 1.5, &f);
  CHECK(f.d[0] == 0 && f.v[0] == 0 && f.a[0] == 0 && f.omega == 0, "rest after the last row");
  motion_frame(&m, 0.0, &f);
  CHECK(f.v[0] == 0 && f.v[1] == 0 && f.omega == 0, "a table starts at rest (zero end slopes)");
  motion_frame(&m, 1e-9, &f);
  CHECK(fabs(f.v[0]) < 1e-6 && fabs(f.omega) < 1e-6, "the clamped spline leaves the first row at rest: v %g",
        f.v[0]);
}

int main(void) {
  struct wall_motion m;
  memset(&m, 0, sizeof(m));
  struct frame f;
  double x[2], ref[2] = {1.5, 2.5};
  motion_frame(&m, 3.0, &f);
  frame_position(&f, 2, ref, x);
  CHECK(x[0] == ref[0] && x[1] == ref[1], "inactive motion moved a point to (%g, %g)", x[0], x[1]);

  m.translation = (struct motion_law){.active = 1, .amplitude = {0.01, 0.002}, .period = 0.83,
                                      .phase = -1.5707963267948966};   /* x = -A cos(w t) */
  position_at(&m, 0.0, ref, x);
  CHECK_CLOSE(x[0], ref[0] - 0.01, 1e-15, "x(0) = -A for -A cos(wt)");
  for (double t = 0.05; t < 2; t += 0.37) check_derivatives(&m, t, "translation");

  m.rotation = (struct motion_law){.active = 1, .amplitude = {0.05}, .period = 1.707, .ramp = RAMP_SMOOTH,
                                   .ramp_time = 1.0};
  m.centre[0] = 0.2, m.centre[1] = 0.1;
  for (double t = 0.05; t < 2.5; t += 0.29) check_derivatives(&m, t, "translation + rotation, smooth ramp");
  m.translation.ramp = RAMP_LINEAR, m.translation.ramp_time = 5.0;
  for (double t = 0.05; t < 4.9; t += 0.61) check_derivatives(&m, t, "linear ramp");
  double back[2];
  motion_frame(&m, 1.7, &f);
  frame_position(&f, 2, ref, x);
  frame_reference(&f, 2, x, back);
  for (int d = 0; d < 2; d++) CHECK_CLOSE(back[d], ref[d], 1e-14, "frame_reference inverts frame_position");
  motion_frame(&m, 0.0, &f);
  CHECK(f.theta == 0 && f.omega == 0, "a smooth ramp starts at rest: theta %g, rate %g", f.theta, f.omega);
  test_table();
  return check_report("test_motion");
}
