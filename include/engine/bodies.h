/* bodies.h — the rigid bodies of a run: their state, advanced with the fluid inside each
 * Runge-Kutta stage from the force and torque of the body loads (the rhs pass's pair forces on
 * their ghosts), summed over the ranks in the fluid particles' id order; their frames for the
 * ghosts; bodies.csv and their part of the checkpoint. */
#ifndef MPSPH_BODIES_H
#define MPSPH_BODIES_H

#include <mpi.h>
#include <stdio.h>
#include "engine/load_sum.h"
#include "io/io_hdf5.h"
#include "physics/pass_ctx.h"
#include "physics/rigid_body.h"

#define BODY_NUMBERS (RB_STATE + 6)   /* checkpoint numbers of a body: state and accelerations */

/** One rigid body of the run. */
struct body_run {
  int wall;                          /* its wall in the case */
  double y0[RB_STATE];               /* state at the start of the step */
  double y[RB_STATE];                /* state of the current stage */
  double sum[RB_STATE];              /* Runge-Kutta weighted sum of the stages' rates */
  double rate[RB_STATE];             /* rates at the last evaluation */
  double force[3], torque[3];        /* the fluid's on the body at the last evaluation [N], [N m]
                                        (about the centre of mass; 2D: per metre, torque[2]) */
  double acc[3], ang_acc[3];         /* accelerations at the last evaluation [m/s^2], [rad/s^2] */
  char names[BODY_NUMBERS][48];      /* the checkpoint's names of its numbers */
};

/** The bodies of a run and the loads of the current stage. */
struct bodies {
  int n;
  struct body_run run[CASE_MAX_WALLS];
  struct body_loads loads;           /* appended by the rhs pass on this rank */
  struct load_gather gather;         /* every rank's loads, in the sum order */
};

struct engine;

/** Set up the bodies of the case at their initial state (before a checkpoint is read); mark their
 *  walls in e->prm.body_walls. */
void bodies_init(struct engine *e);

/** The frames of the bodies (into f, indexed by wall) at their current state. */
void bodies_frames(const struct engine *e, struct frame *f);

/** After the stage's rhs: gather the loads of every rank, sum them per body in the fluid
 *  particles' id order (every rank the same sums, whatever the partition), and set each body's
 *  force, torque, accelerations and rates. Collective. */
void bodies_evaluate(struct engine *e);

/** After a step and its wall guard: gather the impulses the guard's velocity corrections put on
 *  the bodies (LOAD_GUARD_IMPULSE loads), sum them per body in the fluid particles' id order and
 *  change the bodies' velocities by them (rigid_impulse). Collective. */
void bodies_apply_impulses(struct engine *e);

/** At the start of a step: the current state is the step's start. */
void bodies_save(struct engine *e);

/** The Runge-Kutta update of stage s with weight ws: the next stage state y0 + step rate, or at
 *  the last stage the step's end y0 + step sum (the quaternion scaled back to unit length); the
 *  prescribed degrees of freedom are then set from their law at that state's time t_next [s]. */
void bodies_rk_update(struct engine *e, int s, double ws, double step, int last, double t_next);

/** The bodies.csv header and one row (step, time, then per body its state, force and torque). */
void bodies_csv_header(const struct engine *e, FILE *f);
void bodies_csv_row(const struct engine *e, FILE *f);

/** The checkpoint numbers of the bodies into v (named pointers to their state); returns the count. */
int bodies_numbers(struct engine *e, struct hdf5_number *v);

/** Free the loads. */
void bodies_free(struct bodies *b);

#endif
