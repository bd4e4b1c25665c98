/* motion.c — prescribed rigid wall motion: ramped sinusoids for the translation and the angle,
 * with their first and second time derivatives evaluated analytically. */
#include <math.h>
#include <string.h>
#include "motion.h"

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

/* The slope of table column col at row i: the derivative of the parabola through rows i-1, i,
 * i+1 (non-uniform three-point formula); zero at the first and last rows. */
static double table_slope(const struct wall_motion *m, int i, int col) {
  if (i == 0 || i == m->n_rows - 1) return 0;
  const double *a = m->table[i - 1], *b = m->table[i], *c = m->table[i + 1];
  double h0 = b[0] - a[0], h1 = c[0] - b[0];
  double s0 = (b[col] - a[col]) / h0, s1 = (c[col] - b[col]) / h1;
  return (h1 * s0 + h0 * s1) / (h0 + h1);
}

/* Column col of the table at time t and its first two derivatives into q[0..2]: the cubic
 * Hermite piece of the interval holding t; constant outside the table. */
static void table_eval(const struct wall_motion *m, double t, int col, double *q) {
  int n = m->n_rows, i = 0;
  q[1] = q[2] = 0;
  if (t <= m->table[0][0] || t >= m->table[n - 1][0]) {
    q[0] = m->table[t <= m->table[0][0] ? 0 : n - 1][col];
    return;
  }
  while (m->table[i + 1][0] <= t) i++;
  double h = m->table[i + 1][0] - m->table[i][0], s = (t - m->table[i][0]) / h;
  double y0 = m->table[i][col], y1 = m->table[i + 1][col];
  double m0 = table_slope(m, i, col) * h, m1 = table_slope(m, i + 1, col) * h;
  double s2 = s * s, s3 = s2 * s;
  q[0] = (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * m1;
  q[1] = ((6 * s2 - 6 * s) * (y0 - y1) + (3 * s2 - 4 * s + 1) * m0 + (3 * s2 - 2 * s) * m1) / h;
  q[2] = ((12 * s - 6) * (y0 - y1) + (6 * s - 4) * m0 + (6 * s - 2) * m1) / (h * h);
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

void frame_position(const struct frame *f, int dim, const double *x_ref, double *x) {
  double rx = x_ref[0] - f->centre[0], ry = x_ref[1] - f->centre[1];
  double c = cos(f->theta), s = sin(f->theta);
  x[0] = f->centre[0] + f->d[0] + c * rx - s * ry;
  x[1] = f->centre[1] + f->d[1] + s * rx + c * ry;
  if (dim == 3) x[2] = x_ref[2] + f->d[2];
}

void frame_reference(const struct frame *f, int dim, const double *x, double *x_ref) {
  double rx = x[0] - f->centre[0] - f->d[0], ry = x[1] - f->centre[1] - f->d[1];
  double c = cos(f->theta), s = sin(f->theta);
  x_ref[0] = f->centre[0] + c * rx + s * ry;
  x_ref[1] = f->centre[1] - s * rx + c * ry;
  if (dim == 3) x_ref[2] = x[2] - f->d[2];
}

/* The arm x - (c + d) of the point now at x, in the plane of rotation. */
static void arm(const struct frame *f, const double *x, double *r) {
  r[0] = x[0] - f->centre[0] - f->d[0];
  r[1] = x[1] - f->centre[1] - f->d[1];
}

void frame_velocity(const struct frame *f, int dim, const double *x, double *u) {
  double r[2];
  arm(f, x, r);
  u[0] = f->v[0] - f->omega * r[1];
  u[1] = f->v[1] + f->omega * r[0];
  if (dim == 3) u[2] = f->v[2];
}

void frame_acceleration(const struct frame *f, int dim, const double *x, double *a) {
  double r[2], w2 = f->omega * f->omega;
  arm(f, x, r);
  a[0] = f->a[0] - f->alpha * r[1] - w2 * r[0];
  a[1] = f->a[1] + f->alpha * r[0] - w2 * r[1];
  if (dim == 3) a[2] = f->a[2];
}
