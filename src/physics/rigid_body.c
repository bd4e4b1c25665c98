/* rigid_body.c — Newton's and Euler's equations of a rigid body on its flat state vector. */
#include <math.h>
#include <string.h>
#include "physics/rigid_body.h"

void rigid_initial(const struct body *b, double *state) {
  memset(state, 0, RB_STATE * sizeof *state);
  for (int d = 0; d < 3; d++) {
    state[RB_X + d] = b->centre[d];
    state[RB_V + d] = b->velocity[d];
    state[RB_W + d] = b->angular_velocity[d];
  }
  state[RB_Q] = 1.0;
}

/* The rotation matrix of the unit quaternion q = (w, x, y, z). */
static void quaternion_matrix(const double *q, double R[3][3]) {
  double w = q[0], x = q[1], y = q[2], z = q[3];
  R[0][0] = 1 - 2 * (y * y + z * z), R[0][1] = 2 * (x * y - w * z), R[0][2] = 2 * (x * z + w * y);
  R[1][0] = 2 * (x * y + w * z), R[1][1] = 1 - 2 * (x * x + z * z), R[1][2] = 2 * (y * z - w * x);
  R[2][0] = 2 * (x * z - w * y), R[2][1] = 2 * (y * z + w * x), R[2][2] = 1 - 2 * (x * x + y * y);
}

/* out = R v, or R^T v when transpose. */
static void turn(double R[3][3], int transpose, const double *v, double *out) {
  for (int i = 0; i < 3; i++)
    out[i] = transpose ? R[0][i] * v[0] + R[1][i] * v[1] + R[2][i] * v[2]
                       : R[i][0] * v[0] + R[i][1] * v[1] + R[i][2] * v[2];
}

/* Euler's equations in 3D: the angular acceleration [rad/s^2] of a body with principal moments
 * inertia (body axes = case axes at t = 0) turned by R, spinning at omega under torque: in the
 * body axes alpha_b = (torque_b - omega_b x I omega_b) / I. */
static void euler_acceleration(double R[3][3], const double *inertia, const double *omega, const double *torque,
                               double *alpha) {
  double wb[3], tb[3], ab[3];
  turn(R, 1, omega, wb);
  turn(R, 1, torque, tb);
  double Iw[3] = {inertia[0] * wb[0], inertia[1] * wb[1], inertia[2] * wb[2]};
  double gyro[3] = {wb[1] * Iw[2] - wb[2] * Iw[1], wb[2] * Iw[0] - wb[0] * Iw[2], wb[0] * Iw[1] - wb[1] * Iw[0]};
  for (int d = 0; d < 3; d++) ab[d] = (tb[d] - gyro[d]) / inertia[d];
  turn(R, 0, ab, alpha);
}

void rigid_rates(const struct body *b, int dim, const double *state, const double *force,
                 const double *torque, const double *gravity, double *rate, double *acc, double *ang_acc) {
  memset(rate, 0, RB_STATE * sizeof *rate);
  for (int d = 0; d < 3; d++) acc[d] = ang_acc[d] = 0;
  for (int d = 0; d < dim; d++) acc[d] = force[d] / b->mass + gravity[d];
  if (dim == 2) {
    ang_acc[2] = torque[2] / b->inertia[2];
  } else {
    double R[3][3];
    quaternion_matrix(&state[RB_Q], R);
    euler_acceleration(R, b->inertia, &state[RB_W], torque, ang_acc);
  }
  for (int d = 0; d < 3; d++) {
    if (b->fixed & (BODY_DOF_X << d)) acc[d] = 0;
    if (b->fixed & (BODY_DOF_RX << d)) ang_acc[d] = 0;
    rate[RB_X + d] = state[RB_V + d];
    rate[RB_V + d] = acc[d];
    rate[RB_W + d] = ang_acc[d];
  }
  rate[RB_THETA] = dim == 2 ? state[RB_W + 2] : 0.0;
  if (dim == 3) {   /* q' = (0, w) q / 2 = (-w.v, q0 w + w x v) / 2, v the vector part of q */
    const double *q = &state[RB_Q], *w = &state[RB_W];
    rate[RB_Q] = -0.5 * (w[0] * q[1] + w[1] * q[2] + w[2] * q[3]);
    rate[RB_Q + 1] = 0.5 * (q[0] * w[0] + w[1] * q[3] - w[2] * q[2]);
    rate[RB_Q + 2] = 0.5 * (q[0] * w[1] + w[2] * q[1] - w[0] * q[3]);
    rate[RB_Q + 3] = 0.5 * (q[0] * w[2] + w[0] * q[2] - w[1] * q[1]);
  }
}

void rigid_prescribe(const struct body *b, int dim, const struct frame *law, double *state, double *rate,
                     double *acc, double *ang_acc) {
  for (int d = 0; d < dim; d++) {
    if (!(b->prescribed & (BODY_DOF_X << d))) continue;
    state[RB_X + d] = b->centre[d] + law->d[d];
    state[RB_V + d] = law->v[d];
    acc[d] = law->a[d];
    if (rate) rate[RB_X + d] = law->v[d], rate[RB_V + d] = law->a[d];
  }
  if (!(b->prescribed & BODY_DOF_RZ)) return;
  const double *axis = dim == 2 ? (const double[3]){0, 0, 1} : law->axis;
  if (dim == 2) state[RB_THETA] = law->theta;
  else
    for (int k = 0; k < 4; k++) state[RB_Q + k] = k ? sin(0.5 * law->theta) * axis[k - 1] : cos(0.5 * law->theta);
  for (int d = 3 - (dim == 2 ? 1 : 3); d < 3; d++) {
    state[RB_W + d] = law->omega * axis[d];
    ang_acc[d] = law->alpha * axis[d];
    if (rate) rate[RB_W + d] = ang_acc[d];
  }
  if (rate && dim == 2) rate[RB_THETA] = law->omega;
}

void rigid_impulse(const struct body *b, int dim, const double *impulse, const double *angular, double *state) {
  const unsigned held = b->fixed | b->prescribed;
  double dw[3] = {0, 0, 0};
  if (dim == 2) {
    dw[2] = angular[2] / b->inertia[2];
  } else {   /* I^-1 L = R I_b^-1 R^T L */
    double R[3][3], lb[3];
    quaternion_matrix(&state[RB_Q], R);
    turn(R, 1, angular, lb);
    for (int d = 0; d < 3; d++) lb[d] /= b->inertia[d];
    turn(R, 0, lb, dw);
  }
  for (int d = 0; d < 3; d++) {
    if (d < dim && !(held & (BODY_DOF_X << d))) state[RB_V + d] += impulse[d] / b->mass;
    if (!(held & (BODY_DOF_RX << d))) state[RB_W + d] += dw[d];
  }
}

void rigid_normalise(int dim, double *state) {
  if (dim != 3) return;
  double *q = &state[RB_Q], len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 4; k++) q[k] /= len;
}

void rigid_frame(const struct body *b, int dim, const double *state, const double *acc,
                 const double *ang_acc, struct frame *f) {
  memset(f, 0, sizeof *f);
  for (int d = 0; d < 3; d++) {
    f->centre[d] = b->centre[d];
    f->d[d] = state[RB_X + d] - b->centre[d];
    f->v[d] = state[RB_V + d];
    f->a[d] = acc[d];
  }
  f->axis[2] = 1;
  if (dim == 2) {
    f->theta = state[RB_THETA];
    f->omega = state[RB_W + 2];
    f->alpha = ang_acc[2];
    return;
  }
  double q[RB_STATE];
  memcpy(q, state, sizeof q);
  rigid_normalise(3, q);
  double sin_half = sqrt(q[RB_Q + 1] * q[RB_Q + 1] + q[RB_Q + 2] * q[RB_Q + 2] + q[RB_Q + 3] * q[RB_Q + 3]);
  f->theta = 2 * atan2(sin_half, q[RB_Q]);
  if (sin_half > 0)
    for (int d = 0; d < 3; d++) f->axis[d] = q[RB_Q + 1 + d] / sin_half;
  f->free_spin = 1;
  for (int d = 0; d < 3; d++) {
    f->spin[d] = state[RB_W + d];
    f->spin_rate[d] = ang_acc[d];
  }
}
