/* rigid_body.h — the equations of motion of a rigid body (Newton and Euler), on one flat state
 * vector that the engine's Runge-Kutta update advances like a particle's: centre of mass,
 * velocity, attitude (an angle about z in 2D, a unit quaternion in 3D) and angular velocity. */
#ifndef MPSPH_RIGID_BODY_H
#define MPSPH_RIGID_BODY_H

#include "case/case.h"

/** The components of the state vector: centre of mass x [m], its velocity v [m/s], attitude
 *  quaternion q = (w, x, y, z) turning the body from its place at t = 0 (3D; identity in 2D),
 *  angular velocity omega in the case axes [rad/s] (2D: about z, [2]), angle theta about z (2D)
 *  [rad]. */
enum { RB_X = 0, RB_V = 3, RB_Q = 6, RB_W = 10, RB_THETA = 13, RB_STATE = 14 };

/** The state of body b at t = 0: at its centre of mass, not turned, with its initial velocities. */
void rigid_initial(const struct body *b, double *state);

/** The rates of the state (d state/dt into rate) and the linear [m/s^2] and angular [rad/s^2]
 *  accelerations of body b in dimension dim under the fluid's force [N] and torque about the
 *  centre of mass [N m] (2D: per metre, torque[2]) and gravity [m/s^2]: Newton's law, Euler's
 *  equations in the case axes alpha = I^-1 (torque - omega x I omega), I = R I_b R^T; the
 *  quaternion's rate q' = (0, omega) q / 2. A fixed degree of freedom (struct body's fixed) has
 *  zero acceleration: it keeps its initial velocity. */
void rigid_rates(const struct body *b, int dim, const double *state, const double *force,
                 const double *torque, const double *gravity, double *rate, double *acc, double *ang_acc);

/** Impose on body b's state the degrees of freedom it prescribes (struct body's prescribed) from
 *  the frame law of its wall's motion at the state's time: position and velocity of the centre
 *  of mass (its place at t = 0 plus the law's displacement), 2D angle and angular velocity, 3D
 *  quaternion and angular velocity (all three rotations prescribed together: the law's angle
 *  about its axis), and their accelerations into acc [m/s^2] and ang_acc [rad/s^2]; with rate
 *  not NULL also their rates (over what rigid_rates wrote). */
void rigid_prescribe(const struct body *b, int dim, const struct frame *law, double *state, double *rate,
                     double *acc, double *ang_acc);

/** Change body b's state by an impulse [N s] and angular impulse about the centre of mass
 *  [N m s] (2D: per metre, angular[2]): V += J / M, omega += I^-1 L (I = R I_b R^T in 3D), in
 *  the degrees of freedom that are neither fixed nor prescribed. */
void rigid_impulse(const struct body *b, int dim, const double *impulse, const double *angular, double *state);

/** Scale the quaternion of a 3D state back to unit length (the Runge-Kutta update does not keep
 *  it); nothing in 2D. */
void rigid_normalise(int dim, double *state);

/** The frame (case/motion.h) of body b at state, with the accelerations of its last evaluation:
 *  displacement of the centre of mass from its place at t = 0, rotation about it (2D: theta
 *  about z; 3D: the quaternion's axis and angle, rates as the vectors spin and spin_rate). */
void rigid_frame(const struct body *b, int dim, const double *state, const double *acc,
                 const double *ang_acc, struct frame *f);

#endif
