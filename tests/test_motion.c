/* test_motion.c — prescribed wall motion: the analytic velocity and acceleration of a body point
 * against central differences of its position (2D, and 3D about a general axis), ramps, the
 * identity of an inactive motion, and the 3D rotation: an orthonormal matrix turning by the angle
 * about its axis, equal to the rotation about z with the axes permuted. A rigid body's equations
 * of motion (physics/rigid_body.h): Newton's law with fixed degrees of freedom, Euler's equations
 * in the case axes for a turned body against the world-frame formula, the quaternion's rate, the
 * frame of a spinning body, and the mass properties of the shapes (case/geometry.h). */
#include <math.h>
#include <string.h>
#include "check.h"
#include "case/geometry.h"
#include "case/motion.h"
#include "physics/rigid_body.h"

/* Position of body point x_ref at time t in dim dimensions. */
static void position_at(const struct wall_motion *m, int dim, double t, const double *x_ref, double *x) {
  struct frame f;
  motion_frame(m, t, &f);
  frame_position(&f, dim, x_ref, x);
}

/* Velocity and acceleration of x_ref's point at t against central differences of step k [s]. */
static void check_derivatives_dim(const struct wall_motion *m, int dim, double t, double k, const char *what) {
  const double x_ref[3] = {0.3, -0.2, 0.15};
  double xm[3], x0[3], xp[3], u[3], a[3];
  struct frame f;
  position_at(m, dim, t - k, x_ref, xm);
  position_at(m, dim, t + k, x_ref, xp);
  motion_frame(m, t, &f);
  frame_position(&f, dim, x_ref, x0);
  frame_velocity(&f, dim, x0, u);
  frame_acceleration(&f, dim, x0, a);
  for (int d = 0; d < dim; d++) {
    double fd_u = (xp[d] - xm[d]) / (2 * k), fd_a = (xp[d] - 2 * x0[d] + xm[d]) / (k * k);
    CHECK_CLOSE(u[d], fd_u, 1e-7, what);
    CHECK_CLOSE(a[d], fd_a, 2e-4, what);
  }
}

/* check_derivatives_dim in 2D with the step 1e-4 s. */
static void check_derivatives(const struct wall_motion *m, double t, const char *what) {
  check_derivatives_dim(m, 2, t, 1e-4, what);
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
  for (double t = 0.03; t < 1.0; t += 0.043) check_derivatives_dim(&m, 2, t, 1e-5, "table");
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

/* The columns R e_j of the frame's rotation (frame_turn of the unit vectors) are orthonormal and
 * right-handed; R leaves the axis k alone and turns a vector v normal to it by theta about k:
 * v . Rv = |v|^2 cos theta, (v x Rv) . k = |v|^2 sin theta. */
static void check_rotation(const struct frame *f, const char *what) {
  double R[3][3], k[3], v[3], turned[3], kk = 0;
  for (int j = 0; j < 3; j++) {
    double e[3] = {j == 0, j == 1, j == 2};
    frame_turn(f, 3, e, R[j]);   /* R[j] is column j */
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      CHECK_CLOSE(R[i][0] * R[j][0] + R[i][1] * R[j][1] + R[i][2] * R[j][2], i == j, 1e-15, what);
  double det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) - R[1][0] * (R[0][1] * R[2][2] - R[0][2] * R[2][1]) +
               R[2][0] * (R[0][1] * R[1][2] - R[0][2] * R[1][1]);
  CHECK_CLOSE(det, 1.0, 1e-15, what);
  frame_turn(f, 3, f->axis, k);
  for (int d = 0; d < 3; d++) CHECK_CLOSE(k[d], f->axis[d], 1e-15, what);
  for (int d = 0; d < 3; d++) kk += f->axis[d] * (d == 1);   /* v = e_y minus its part along k */
  for (int d = 0; d < 3; d++) v[d] = (d == 1) - kk * f->axis[d];
  frame_turn(f, 3, v, turned);
  double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2], dot = 0, sine = 0;
  for (int d = 0; d < 3; d++) {
    dot += v[d] * turned[d];
    sine += (v[(d + 1) % 3] * turned[(d + 2) % 3] - v[(d + 2) % 3] * turned[(d + 1) % 3]) * f->axis[d];
  }
  CHECK_CLOSE(dot, vv * cos(f->theta), 1e-15, what);
  CHECK_CLOSE(sine, vv * sin(f->theta), 1e-15, what);
}

/* v with its axes permuted cyclically, x -> y -> z -> x: z goes to x. */
static void permute(const double *v, double *out) {
  out[0] = v[2], out[1] = v[0], out[2] = v[1];
}

/* A 3D motion turning about the z axis (the in-plane formulas) and the same motion with the axes
 * permuted, turning about x (the rotation matrix): positions, inverse positions, turned offsets,
 * velocities and accelerations are the permuted ones. */
static void test_permuted_axes(const struct wall_motion *about_z) {
  static struct wall_motion about_x;
  about_x = *about_z;
  permute(about_z->centre, about_x.centre);
  permute(about_z->translation.amplitude, about_x.translation.amplitude);
  permute(about_z->axis, about_x.axis);
  const double x_ref[3] = {0.31, -0.17, 0.12};
  double px_ref[3];
  permute(x_ref, px_ref);
  for (double t = 0.05; t < 2.0; t += 0.31) {
    struct frame fz, fx;
    double out[5][3], got[5][3];
    motion_frame(about_z, t, &fz);
    motion_frame(&about_x, t, &fx);
    frame_position(&fz, 3, x_ref, got[0]);
    frame_reference(&fz, 3, x_ref, got[1]);
    frame_turn(&fz, 3, x_ref, got[2]);
    frame_velocity(&fz, 3, x_ref, got[3]);
    frame_acceleration(&fz, 3, x_ref, got[4]);
    frame_position(&fx, 3, px_ref, out[0]);
    frame_reference(&fx, 3, px_ref, out[1]);
    frame_turn(&fx, 3, px_ref, out[2]);
    frame_velocity(&fx, 3, px_ref, out[3]);
    frame_acceleration(&fx, 3, px_ref, out[4]);
    for (int q = 0; q < 5; q++) {
      double want[3];
      permute(got[q], want);
      for (int d = 0; d < 3; d++) CHECK_CLOSE(out[q][d], want[d], 1e-14, "about x = about z with the axes permuted");
    }
  }
}

/* The rotation about a general axis in 3D: the matrix, the derivatives against central
 * differences, the inverse, the axis's length left out, and the permuted-axes identity. */
static void test_axis_3d(void) {
  static struct wall_motion m;
  memset(&m, 0, sizeof(m));
  m.translation = (struct motion_law){.active = 1, .amplitude = {0.01, -0.004, 0.006}, .period = 0.9,
                                      .ramp = RAMP_SMOOTH, .ramp_time = 0.5};
  m.rotation = (struct motion_law){.active = 1, .amplitude = {0.3}, .period = 1.3, .ramp = RAMP_SMOOTH,
                                   .ramp_time = 0.7};
  m.centre[0] = 0.2, m.centre[1] = 0.1, m.centre[2] = -0.05;
  const double axes[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -2}, {1, -2, 0.5}};
  for (int i = 0; i < 4; i++) {
    memcpy(m.axis, axes[i], sizeof(m.axis));
    struct frame f;
    double x[3], back[3];
    const double x_ref[3] = {0.4, -0.3, 0.25};
    for (double t = 0.05; t < 2.0; t += 0.23) {
      motion_frame(&m, t, &f);
      check_rotation(&f, "rotation matrix");
      check_derivatives_dim(&m, 3, t, 1e-4, "3D rotation about an axis, smooth ramp");
      frame_position(&f, 3, x_ref, x);
      frame_reference(&f, 3, x, back);
      for (int d = 0; d < 3; d++) CHECK_CLOSE(back[d], x_ref[d], 1e-14, "3D frame_reference inverts frame_position");
    }
  }
  struct frame f, g;
  m.axis[0] = 0, m.axis[1] = 0, m.axis[2] = 3;   /* only the direction counts */
  motion_frame(&m, 0.9, &f);
  CHECK(f.axis[0] == 0 && f.axis[1] == 0 && f.axis[2] == 1, "axis [0, 0, 3] is z");
  m.axis[0] = 2, m.axis[2] = 0;
  motion_frame(&m, 0.9, &g);
  CHECK(g.axis[0] == 1 && g.axis[1] == 0 && g.axis[2] == 0, "axis [2, 0, 0] is x");
  m.axis[0] = 0, m.axis[2] = 1;
  test_permuted_axes(&m);
}

/* Newton in 2D with a fixed degree of freedom; Euler in 3D: a body with principal moments
 * (1, 2, 3) turned by 90 degrees about z has the world inertia diag(2, 1, 3), so at omega =
 * (1, 1, 0) without torque alpha = -I_w^-1 (omega x I_w omega) = (0, 0, 1/3); q' = (0, w) q / 2. */
static void test_rigid_rates(void) {
  struct body b = {.active = 1, .mass = 2.0, .inertia = {1, 2, 3}, .fixed = BODY_DOF_Y};
  double y[RB_STATE], rate[RB_STATE], acc[3], alpha[3], g[3] = {0, -9.81, 0};
  double force[3] = {4.0, 6.0, 0}, torque[3] = {0, 0, 1.5};
  rigid_initial(&b, y);
  rigid_rates(&b, 2, y, force, torque, g, rate, acc, alpha);
  CHECK_CLOSE(acc[0], 2.0, 0, "2D: F/M");
  CHECK(acc[1] == 0 && rate[RB_V + 1] == 0, "2D: a fixed y has no acceleration (%g)", acc[1]);
  CHECK_CLOSE(alpha[2], 0.5, 0, "2D: T/I_zz");
  b.fixed = 0;
  double zero[3] = {0, 0, 0}, h = sqrt(0.5);
  y[RB_Q] = h, y[RB_Q + 3] = h;                      /* 90 degrees about z */
  y[RB_W] = 1, y[RB_W + 1] = 1, y[RB_W + 2] = 0;
  rigid_rates(&b, 3, y, zero, zero, zero, rate, acc, alpha);
  CHECK_CLOSE(alpha[0], 0, 1e-15, "3D Euler, turned body: alpha_x");
  CHECK_CLOSE(alpha[1], 0, 1e-15, "3D Euler, turned body: alpha_y");
  CHECK_CLOSE(alpha[2], 1.0 / 3, 1e-15, "3D Euler, turned body: alpha_z");
  rigid_initial(&b, y);
  y[RB_W + 2] = 2;
  rigid_rates(&b, 3, y, zero, zero, zero, rate, acc, alpha);
  CHECK(rate[RB_Q] == 0 && rate[RB_Q + 1] == 0 && rate[RB_Q + 2] == 0 && rate[RB_Q + 3] == 1,
        "q' of the identity spinning at 2 rad/s about z: (%g, %g, %g, %g)", rate[RB_Q], rate[RB_Q + 1],
        rate[RB_Q + 2], rate[RB_Q + 3]);
}

/* A 3D body prescribing z and its three rotations from a wall motion (a heave and a rotation about
 * [1, 2, 2] through its centre of mass) and free along x and y: its frame moves every body point
 * as the motion's own frame does, with the same velocity and acceleration, while x keeps its
 * state. */
static void test_rigid_prescribe(void) {
  struct body b = {.active = 1, .mass = 1, .centre = {0.1, 0.2, 0.3}, .inertia = {1, 1, 1},
                   .prescribed = BODY_DOF_Z | BODY_DOF_RX | BODY_DOF_RY | BODY_DOF_RZ};
  struct wall_motion m = {.translation = {.active = 1, .amplitude = {0, 0, 0.05}, .period = 0.8},
                          .rotation = {.active = 1, .amplitude = {0.3}, .period = 1.1},
                          .centre = {0.1, 0.2, 0.3}, .axis = {1, 2, 2}};
  double y[RB_STATE], rate[RB_STATE], acc[3] = {0}, alpha[3] = {0};
  struct frame law, f;
  rigid_initial(&b, y);
  y[RB_X] = 0.4, y[RB_V] = -1;
  motion_frame(&m, 0.37, &law);
  rigid_prescribe(&b, 3, &law, y, rate, acc, alpha);
  rigid_frame(&b, 3, y, acc, alpha, &f);
  double x_ref[3] = {0.5, -0.1, 0.9}, x_law[3], x_body[3], u_law[3], u_body[3], a_law[3], a_body[3];
  frame_position(&law, 3, x_ref, x_law);
  frame_velocity(&law, 3, x_law, u_law);
  frame_acceleration(&law, 3, x_law, a_law);
  x_law[0] += 0.4 - 0.1;   /* the free x of the body moved it by 0.3 m */
  frame_position(&f, 3, x_ref, x_body);
  frame_velocity(&f, 3, x_body, u_body);
  frame_acceleration(&f, 3, x_body, a_body);
  for (int d = 0; d < 3; d++) {
    CHECK_CLOSE(x_body[d], x_law[d], 1e-15, "prescribed: the body point where the law puts it");
    CHECK_CLOSE(u_body[d], u_law[d] + (d == 0 ? -1 : 0), 1e-14, "prescribed: its velocity (and the free vx)");
    CHECK_CLOSE(a_body[d], a_law[d], 1e-14, "prescribed: its acceleration");
  }
  CHECK(y[RB_X] == 0.4 && y[RB_V] == -1 && rate[RB_V + 2] == law.a[2], "free x kept, z' from the law");
}

/* An impulse on a 3D body of mass 2 and principal moments (1, 2, 3) turned by 90 degrees about z
 * (world inertia diag(2, 1, 3)), rotation about x fixed and z prescribed: J = (1, 2, 3) gives
 * dV = (0.5, 1, 0), L = (2, 2, 3) gives d omega = I^-1 L = (1, 2, 1) with x held: (0, 2, 1). */
static void test_rigid_impulse(void) {
  struct body b = {.active = 1, .mass = 2, .inertia = {1, 2, 3}, .fixed = BODY_DOF_RX, .prescribed = BODY_DOF_Z};
  double y[RB_STATE], h = sqrt(0.5), J[3] = {1, 2, 3}, L[3] = {2, 2, 3};
  double dv[3] = {0.5, 1, 0}, dw[3] = {0, 2, 1};
  rigid_initial(&b, y);
  y[RB_Q] = h, y[RB_Q + 3] = h;
  rigid_impulse(&b, 3, J, L, y);
  for (int d = 0; d < 3; d++) {
    CHECK_CLOSE(y[RB_V + d], dv[d], 1e-15, "3D impulse: J / M in the free translations");
    CHECK_CLOSE(y[RB_W + d], dw[d], 1e-15, "3D impulse: I^-1 L in the free rotations (world inertia)");
  }
}

/* The frame of a 3D body turned 0.7 rad about [1, 2, 2]/3 and spinning at w: it turns a body point
 * about the centre of mass by that rotation, and its velocity and acceleration are v + w x r and
 * a + alpha x r + w x (w x r). */
static void test_rigid_frame(void) {
  struct body b = {.active = 1, .mass = 1, .centre = {0.1, 0.2, 0.3}, .inertia = {1, 1, 1}};
  double y[RB_STATE], acc[3] = {0.5, 0, -1}, alpha[3] = {0, 2, 0}, k[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  rigid_initial(&b, y);
  y[RB_X] = 1.1, y[RB_V + 1] = 3;
  y[RB_Q] = cos(0.35);
  for (int d = 0; d < 3; d++) y[RB_Q + 1 + d] = sin(0.35) * k[d];
  y[RB_W] = 1, y[RB_W + 2] = -2;
  struct frame f;
  rigid_frame(&b, 3, y, acc, alpha, &f);
  CHECK_CLOSE(f.theta, 0.7, 1e-15, "body frame: angle from the quaternion");
  for (int d = 0; d < 3; d++) CHECK_CLOSE(f.axis[d], k[d], 1e-15, "body frame: axis from the quaternion");
  double x[3] = {1.3, 0.2, 0.5}, u[3], a[3], r[3], w[3] = {1, 0, -2};
  for (int d = 0; d < 3; d++) r[d] = x[d] - y[RB_X + d];
  frame_velocity(&f, 3, x, u);
  frame_acceleration(&f, 3, x, a);
  double wr[3] = {w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2], w[0] * r[1] - w[1] * r[0]};
  double ar[3] = {alpha[1] * r[2], 0, -alpha[1] * r[0]};   /* alpha x r for alpha = (0, 2, 0) */
  double wwr[3] = {w[1] * wr[2] - w[2] * wr[1], w[2] * wr[0] - w[0] * wr[2], w[0] * wr[1] - w[1] * wr[0]};
  for (int d = 0; d < 3; d++) {
    CHECK_CLOSE(u[d], y[RB_V + d] + wr[d], 1e-14, "body frame: v + w x r");
    CHECK_CLOSE(a[d], acc[d] + ar[d] + wwr[d], 1e-14, "body frame: a + alpha x r + w x (w x r)");
  }
}

/* Centroid and inertia per unit mass: a box, an annulus, a ball, and a right triangle with legs
 * a, b at the origin (centroid (a/3, b/3), I_zz/M = (a^2 + b^2)/18); a rectangle as a polygon
 * equals the box. */
static void test_mass_properties(void) {
  struct shape box = {.kind = SHAPE_BOX, .min = {0, 0, 0}, .max = {2, 1, 0.5}};
  struct shape ring = {.kind = SHAPE_CIRCLE, .centre = {1, 2, 3}, .radius = 2, .inner_radius = 1};
  struct shape tri = {.kind = SHAPE_POLYGON, .n_vertices = 3, .vertex = {{0, 0}, {3, 0}, {0, 2}}};
  struct shape rect = {.kind = SHAPE_POLYGON, .n_vertices = 4, .vertex = {{0, 0}, {2, 0}, {2, 1}, {0, 1}}};
  double c[3], I[3], cb[3], Ib[3];
  shape_mass_properties(&box, 3, c, I);
  CHECK_CLOSE(I[0], (1 + 0.25) / 12, 1e-15, "box I_xx");
  CHECK_CLOSE(I[2], (4 + 1) / 12.0, 1e-15, "box I_zz");
  CHECK_CLOSE(c[1], 0.5, 0, "box centroid");
  shape_mass_properties(&ring, 2, c, I);
  CHECK_CLOSE(I[2], (4 + 1) / 2.0, 1e-15, "annulus I_zz");
  shape_mass_properties(&ring, 3, c, I);
  CHECK_CLOSE(I[0], 2.0 / 5 * (32 - 1) / (8 - 1), 1e-14, "spherical shell I");
  shape_mass_properties(&tri, 2, c, I);
  CHECK_CLOSE(c[0], 1, 1e-15, "triangle centroid x");
  CHECK_CLOSE(c[1], 2.0 / 3, 1e-15, "triangle centroid y");
  CHECK_CLOSE(I[2], (9 + 4) / 18.0, 1e-14, "triangle I_zz");
  box.max[2] = 0;
  shape_mass_properties(&box, 2, cb, Ib);
  shape_mass_properties(&rect, 2, c, I);
  CHECK_CLOSE(I[2], Ib[2], 1e-15, "rectangle as polygon = box");
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
  position_at(&m, 2, 0.0, ref, x);
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
  test_axis_3d();
  test_rigid_rates();
  test_rigid_prescribe();
  test_rigid_impulse();
  test_rigid_frame();
  test_mass_properties();
  return check_report("test_motion");
}
