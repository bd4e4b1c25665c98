/* test_motion.c — prescribed wall motion: the analytic velocity and acceleration of a body point
 * against central differences of its position, ramps, and the identity of an inactive motion. */
#include <string.h>
#include "check.h"
#include "motion.h"

/* Position of body point x_ref at time t. */
static void position_at(const struct wall_motion *m, double t, const double *x_ref, double *x) {
  struct frame f;
  motion_frame(m, t, &f);
  frame_position(&f, 2, x_ref, x);
}

/* Velocity and acceleration of x_ref's point at t against central differences (step k). */
static void check_derivatives(const struct wall_motion *m, double t, const char *what) {
  const double x_ref[2] = {0.3, -0.2}, k = 1e-4;
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
  return check_report("test_motion");
}
