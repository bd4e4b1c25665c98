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

void motion_frame(const struct wall_motion *m, double t, struct frame *f) {
  memset(f, 0, sizeof(*f));
  memcpy(f->centre, m->centre, sizeof(f->centre));
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
