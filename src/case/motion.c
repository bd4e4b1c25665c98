/* motion.c — prescribed rigid wall motion: ramped sinusoids for the translation and the angle,
 * or a table interpolated by clamped cubic splines, with their first and second time
 * derivatives evaluated analytically; the rotation about z in the plane (2D), or about any axis
 * by its rotation matrix (3D). */
#include <math.h>
#include <string.h>
#include "case/motion.h"

#define PI 3.14159265358979323846

/* The ramp r(t) and its derivatives r', r''. The smooth ramp is the quintic 10s^3 - 15s^4 + 6s^5
 * of s = t / t_ramp, whose first and second derivatives vanish at both ends: the wall's velocity
 * and acceleration are continuous (the linear ramp's velocity jumps at t_ramp). */
static void ramp_of(enum ramp_kind kind, double t_ramp, double t, double *r) {
  r[0] = 1, r[1] = 0, r[2] = 0;
  if (kind == RAMP_NONE || t >= t_ramp) return;
  if (t <= 0) {
    r[0] = 0;
    return;
  }
  double s = t / t_ramp;
  if (kind == RAMP_LINEAR) {
    r[0] = s;
    r[1] = 1 / t_ramp;
    return;
  }
  r[0] = s * s * s * (10 - 15 * s + 6 * s * s);
  r[1] = 30 * s * s * (1 - s) * (1 - s) / t_ramp;
  r[2] = 60 * s * (1 - s) * (1 - 2 * s) / (t_ramp * t_ramp);
}

/* q(t)/amplitude and its two derivatives: s = r sin(w t + phi). */
static void law_shape(const struct motion_law *l, double t, double *s) {
  double w = 2 * PI / l->period, r[3], arg = w * t + l->phase;
  ramp_of(l->ramp, l->ramp_time, t, r);
  double sn = sin(arg), cs = cos(arg);
  s[0] = r[0] * sn;
  s[1] = r[1] * sn + r[0] * w * cs;
  s[2] = r[2] * sn + 2 * r[1] * w * cs - r[0] * w * w * sn;
}

/* The second derivatives M[0..n-1] at the rows of the clamped cubic spline of table column col
 * (zero first derivative at the first and last rows): the tridiagonal system
 * h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (s_i - s_{i-1}), s_i the secant
 * slopes, solved by the Thomas algorithm. */
static void spline_moments(const struct wall_motion *m, int col, double *M) {
  int n = m->n_rows;
  double c[MOTION_MAX_ROWS], prev_h = 0, prev_s = 0;   /* c: the eliminated super-diagonal */
  for (int i = 0; i < n; i++) {
    double h = i < n - 1 ? m->table[i + 1][0] - m->table[i][0] : 0;
    double s = i < n - 1 ? (m->table[i + 1][col] - m->table[i][col]) / h : 0;
    double diag = 2 * (prev_h + h), rhs = 6 * (s - prev_s);
    if (i > 0) {
      diag -= prev_h * c[i - 1];
      rhs -= prev_h * M[i - 1];
    }
    c[i] = h / diag;
    M[i] = rhs / diag;
    prev_h = h, prev_s = s;
  }
  for (int i = n - 2; i >= 0; i--) M[i] -= c[i] * M[i + 1];
}

/* Column col of the table at time t and its first two derivatives into q[0..2]: the clamped
 * cubic spline through the rows; constant outside the table. */
static void table_eval(const struct wall_motion *m, double t, int col, double *q) {
  int n = m->n_rows, i = 0;
  double M[MOTION_MAX_ROWS];
  q[1] = q[2] = 0;
  if (t <= m->table[0][0] || t >= m->table[n - 1][0]) {
    q[0] = m->table[t <= m->table[0][0] ? 0 : n - 1][col];
    return;
  }
  while (m->table[i + 1][0] <= t) i++;
  spline_moments(m, col, M);
  double h = m->table[i + 1][0] - m->table[i][0], a = m->table[i + 1][0] - t, b = t - m->table[i][0];
  double ca = m->table[i][col] / h - M[i] * h / 6, cb = m->table[i + 1][col] / h - M[i + 1] * h / 6;
  q[0] = (M[i] * a * a * a + M[i + 1] * b * b * b) / (6 * h) + ca * a + cb * b;
  q[1] = (M[i + 1] * b * b - M[i] * a * a) / (2 * h) - ca + cb;
  q[2] = (M[i] * a + M[i + 1] * b) / h;
}

/* The frame of a tabulated motion at time t. */
static void table_frame(const struct wall_motion *m, double t, struct frame *f) {
  double q[3];
  for (int d = 0; d < 3; d++) {
    table_eval(m, t, 1 + d, q);
    f->d[d] = q[0], f->v[d] = q[1], f->a[d] = q[2];
  }
  table_eval(m, t, 4, q);
  f->theta = q[0], f->omega = q[1], f->alpha = q[2];
}

void motion_frame(const struct wall_motion *m, double t, struct frame *f) {
  memset(f, 0, sizeof(*f));
  memcpy(f->centre, m->centre, sizeof(f->centre));
  double len = sqrt(m->axis[0] * m->axis[0] + m->axis[1] * m->axis[1] + m->axis[2] * m->axis[2]);
  for (int d = 0; d < 3; d++) f->axis[d] = m->axis[d] / len;
  if (m->n_rows > 0) {
    table_frame(m, t, f);
    return;
  }
  double s[3];
  if (m->translation.active) {
    law_shape(&m->translation, t, s);
    for (int d = 0; d < 3; d++) {
      f->d[d] = m->translation.amplitude[d] * s[0];
      f->v[d] = m->translation.amplitude[d] * s[1];
      f->a[d] = m->translation.amplitude[d] * s[2];
    }
  }
  if (m->rotation.active) {
    law_shape(&m->rotation, t, s);
    f->theta = m->rotation.amplitude[0] * s[0];
    f->omega = m->rotation.amplitude[0] * s[1];
    f->alpha = m->rotation.amplitude[0] * s[2];
  }
}

/* 1 if the frame turns about z: always in 2D, and in 3D about the axis [0, 0, 1]. These keep the
 * in-plane formulas (z untouched), so that their results do not depend on the general path; any
 * other axis of a 3D frame takes the rotation matrix. */
static int about_z(const struct frame *f, int dim) {
  return dim == 2 || (f->axis[0] == 0 && f->axis[1] == 0 && f->axis[2] > 0);
}

/* R(theta) about the unit axis k (Rodrigues): R = cos I + sin [k]x + (1 - cos) k k^T, [k]x the
 * matrix of k x .; out = R v, or R^T v (the inverse) when transpose. */
static void rotate(const struct frame *f, int transpose, const double *v, double *out) {
  const double *k = f->axis;
  double c = cos(f->theta), s = sin(f->theta), R[3][3], w[3] = {v[0], v[1], v[2]};   /* v may be out */
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) R[i][j] = (i == j ? c : 0) + (1 - c) * k[i] * k[j];
  R[0][1] -= s * k[2], R[1][2] -= s * k[0], R[2][0] -= s * k[1];
  R[1][0] += s * k[2], R[2][1] += s * k[0], R[0][2] += s * k[1];
  for (int i = 0; i < 3; i++) out[i] = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) out[i] += (transpose ? R[j][i] : R[i][j]) * w[j];
}

void frame_position(const struct frame *f, int dim, const double *x_ref, double *x) {
  double rx = x_ref[0] - f->centre[0], ry = x_ref[1] - f->centre[1];
  if (!about_z(f, dim)) {
    double r[3] = {rx, ry, x_ref[2] - f->centre[2]}, turned[3];
    rotate(f, 0, r, turned);
    for (int d = 0; d < 3; d++) x[d] = f->centre[d] + f->d[d] + turned[d];
    return;
  }
  double c = cos(f->theta), s = sin(f->theta);
  x[0] = f->centre[0] + f->d[0] + c * rx - s * ry;
  x[1] = f->centre[1] + f->d[1] + s * rx + c * ry;
  if (dim == 3) x[2] = x_ref[2] + f->d[2];
}

/* The arm x - (c + d) of the point now at x (its first dim components; the third is 0 in 2D). */
static void arm(const struct frame *f, int dim, const double *x, double *r) {
  r[2] = 0;
  for (int d = 0; d < dim; d++) r[d] = x[d] - f->centre[d] - f->d[d];
}

void frame_reference(const struct frame *f, int dim, const double *x, double *x_ref) {
  double r[3];
  arm(f, dim, x, r);
  if (!about_z(f, dim)) {
    double back[3];
    rotate(f, 1, r, back);
    for (int d = 0; d < 3; d++) x_ref[d] = f->centre[d] + back[d];
    return;
  }
  double c = cos(f->theta), s = sin(f->theta);
  x_ref[0] = f->centre[0] + c * r[0] + s * r[1];
  x_ref[1] = f->centre[1] - s * r[0] + c * r[1];
  if (dim == 3) x_ref[2] = x[2] - f->d[2];
}

void frame_turn(const struct frame *f, int dim, const double *v, double *out) {
  if (!about_z(f, dim)) {
    rotate(f, 0, v, out);
    return;
  }
  double c = cos(f->theta), s = sin(f->theta), vx = v[0];
  out[0] = c * vx - s * v[1];
  out[1] = s * vx + c * v[1];
  if (dim == 3) out[2] = v[2];
}

/* out = k x r. */
static void cross(const double *k, const double *r, double *out) {
  out[0] = k[1] * r[2] - k[2] * r[1];
  out[1] = k[2] * r[0] - k[0] * r[2];
  out[2] = k[0] * r[1] - k[1] * r[0];
}

/* out = k x r for the frame's axis k. */
static void axis_cross(const struct frame *f, const double *r, double *out) { cross(f->axis, r, out); }

/* A free-spinning frame's velocity v + w x r and acceleration a + alpha x r + w x (w x r) at the
 * arm r (either output may be NULL). */
static void spin_kinematics(const struct frame *f, const double *r, double *u, double *a) {
  double wr[3], wwr[3], ar[3];
  cross(f->spin, r, wr);
  cross(f->spin, wr, wwr);
  cross(f->spin_rate, r, ar);
  for (int d = 0; d < 3; d++) {
    if (u) u[d] = f->v[d] + wr[d];
    if (a) a[d] = f->a[d] + ar[d] + wwr[d];
  }
}

void frame_velocity(const struct frame *f, int dim, const double *x, double *u) {
  double r[3];
  arm(f, dim, x, r);
  if (f->free_spin) {
    spin_kinematics(f, r, u, NULL);
    return;
  }
  if (!about_z(f, dim)) {   /* v + omega k x r */
    double kr[3];
    axis_cross(f, r, kr);
    for (int d = 0; d < 3; d++) u[d] = f->v[d] + f->omega * kr[d];
    return;
  }
  u[0] = f->v[0] - f->omega * r[1];
  u[1] = f->v[1] + f->omega * r[0];
  if (dim == 3) u[2] = f->v[2];
}

void frame_acceleration(const struct frame *f, int dim, const double *x, double *a) {
  double r[3], w2 = f->omega * f->omega;
  arm(f, dim, x, r);
  if (f->free_spin) {
    spin_kinematics(f, r, NULL, a);
    return;
  }
  if (!about_z(f, dim)) {   /* a + alpha k x r + omega^2 (k (k . r) - r) */
    double kr[3], along = f->axis[0] * r[0] + f->axis[1] * r[1] + f->axis[2] * r[2];
    axis_cross(f, r, kr);
    for (int d = 0; d < 3; d++) a[d] = f->a[d] + f->alpha * kr[d] + w2 * (f->axis[d] * along - r[d]);
    return;
  }
  a[0] = f->a[0] - f->alpha * r[1] - w2 * r[0];
  a[1] = f->a[1] + f->alpha * r[0] - w2 * r[1];
  if (dim == 3) a[2] = f->a[2];
}
