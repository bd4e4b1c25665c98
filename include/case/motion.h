/* motion.h — prescribed rigid motion of a wall: a translation and a rotation about a fixed axis
 * through a centre (z in 2D; any axis in 3D: roll, pitch, yaw), each a sinusoid switched on by a
 * ramp, or a table of time, displacement and angle interpolated by cubic splines. Tank sloshing
 * cases move their walls with it. */
#ifndef MPSPH_MOTION_H
#define MPSPH_MOTION_H

/** How a law is switched on over its ramp time: at once, linearly, or smoothly (a quintic with
 *  zero first and second derivatives at both ends). */
enum ramp_kind { RAMP_NONE = 0, RAMP_LINEAR, RAMP_SMOOTH };

/** q(t) = r(t) amplitude sin(omega t + phase), r the ramp (0 -> 1 over ramp_time). For a
 *  translation the amplitude is a vector [m]; for a rotation amplitude[0] is the angle [rad]. */
struct motion_law {
  int active;
  double amplitude[3];
  double period;         /* [s]; the angular frequency is 2 pi / period */
  double phase;          /* [rad] */
  enum ramp_kind ramp;
  double ramp_time;      /* [s] */
};

#define MOTION_MAX_ROWS 256
#define MOTION_TABLE_COLUMNS 5   /* t [s], dx, dy, dz [m], theta [rad] */

/** The motion of a wall: x(t) = c + d(t) + R(theta(t)) (X - c) for a body point X at t = 0, R
 *  the rotation by theta about the axis through c (right-handed). With n_rows > 0 the table
 *  gives d and theta (the laws are then inactive): rows of MOTION_TABLE_COLUMNS values at
 *  strictly increasing times, dz = 0 in 2D. */
struct wall_motion {
  struct motion_law translation, rotation;
  double centre[3];      /* rotation centre at t = 0 [m] */
  double axis[3];        /* rotation axis, any length but 0 ([0, 0, 1] in 2D) */
  int n_rows;            /* rows of the table, 0 = no table */
  double table[MOTION_MAX_ROWS][MOTION_TABLE_COLUMNS];
};

/** The wall's frame at one time: displacement, velocity and acceleration of the centre, angle
 *  and its rates. */
struct frame {
  double d[3], v[3], a[3];             /* [m], [m/s], [m/s^2] */
  double theta, omega, alpha;          /* [rad], [rad/s], [rad/s^2] */
  double centre[3];                    /* rotation centre at t = 0 [m] */
  double axis[3];                      /* unit rotation axis (3D; 2D turns about z) */
  int free_spin;                       /* 3D rigid body: the rates are the vectors spin and
                                          spin_rate, not omega and alpha about the axis */
  double spin[3], spin_rate[3];        /* angular velocity [rad/s] and acceleration [rad/s^2] */
};

/** Evaluate the frame of motion m at time t [s]. A motion with no active law is the identity.
 *  A table is interpolated per column by the cubic spline through its rows with zero first
 *  derivative at the first and last rows (clamped): displacement, velocity and acceleration
 *  are continuous inside the table (C2); before the first row and after the last the wall rests
 *  at that row's displacement and angle, so only the acceleration jumps there. */
void motion_frame(const struct wall_motion *m, double t, struct frame *f);

/** The position at the frame's time of the body point x_ref (its position at t = 0) [m]. */
void frame_position(const struct frame *f, int dim, const double *x_ref, double *x);

/** The body point (its position at t = 0) of the point now at x: the inverse of frame_position. */
void frame_reference(const struct frame *f, int dim, const double *x, double *x_ref);

/** The body-frame vector v (a direction or offset at t = 0) turned with the wall: R(theta) v
 *  into out (which may be v). */
void frame_turn(const struct frame *f, int dim, const double *v, double *out);

/** Velocity [m/s] and acceleration [m/s^2] of the body point now at x: v + w x r and
 *  a + alpha x r + w x (w x r), r = x - (c + d), w = omega axis, alpha = alpha axis (with
 *  free_spin: w = spin, alpha = spin_rate). */
void frame_velocity(const struct frame *f, int dim, const double *x, double *u);
void frame_acceleration(const struct frame *f, int dim, const double *x, double *a);

#endif
