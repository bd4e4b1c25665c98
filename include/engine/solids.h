/* solids.h — the elastic solids of a run (schemes riemann and delta-plus; notes seed-002 §1.7,
 * §1.10, §1.13).
 * Each solid is replicated on every rank (physics/elastic_solid.h) and advanced alike on all of
 * them; its particles also sit among the fluid's (kind KIND_SOLID, ids after the fluid and wall
 * particles), owned by the rank of their cell and in the halos like any particle, so that the
 * fluid's pair loops see them as moving walls. The pair forces the fluid's momentum pass recorded
 * (loads) are gathered from every rank and summed per solid particle in the fluid particles' id
 * order (the same sums on every rank, whatever the partition): with riemann after each acoustic
 * sub-step, with delta-plus after each RK stage, weighted as the stage's derivatives are. They are
 * held over the solid's sub-steps of that fluid sub-step (riemann) or step (delta-plus), and then
 * the particles' copies take the new state. */
#ifndef MPSPH_SOLIDS_H
#define MPSPH_SOLIDS_H

#include <stdio.h>
#include "engine/load_sum.h"
#include "io/io_hdf5.h"
#include "physics/elastic_solid.h"
#include "physics/pass_ctx.h"

#define SOLID_ARRAYS 9   /* checkpoint arrays of a solid: x, v, acc, F, dF, v_avg, acc_avg, the
                            last advance's length, the fluid's force */
#define SOLID_SNAPSHOT_ARRAYS 4   /* snapshot arrays of a solid: reference position, displacement,
                                     Cauchy stress, von Mises stress */

/** One solid of the run. */
struct solid_run {
  struct elastic_solid s;
  long first;                 /* index g of its particle 0 (its id is view.id0 + first) */
  int probe;                  /* its particle nearest to the case's probe point */
  double force[3];            /* the fluid's on the solid at the last coupling [N] (2D: [N/m]) */
  double *x_start;            /* positions at the start of the advection step [m] */
  char names[SOLID_ARRAYS][32];   /* the checkpoint's names of its arrays */
  char snapshot_names[SOLID_SNAPSHOT_ARRAYS][40];   /* the snapshots' */
  double *displacement;       /* x - x0 (dim per particle) [m], filled for a snapshot */
  double *stress;             /* Cauchy stress J^-1 P F^T (dim x dim per particle, in-plane in 2D) [Pa] */
  double *von_mises;          /* von Mises stress of the full 3D stress (plane strain in 2D) [Pa] */
};

/** The solids of a run. */
struct solids {
  int n;
  struct solid_run run[CASE_MAX_SOLIDS];
  struct solid_view view;     /* what the pair passes read (its arrays: v_avg, acc_avg) */
  double *v_avg, *acc_avg, *normal;   /* every solid's, concatenated (dim per particle) */
  struct body_loads loads;    /* appended by the momentum pass on this rank */
  struct load_gather gather;
  long substeps;              /* solid sub-steps of the last solids_move (largest over solids) */
  long substeps_total, advances;   /* sums of substeps and the count of solids_move calls */
};

struct engine;

/** Set up the solids of the case on every rank at their reference state. Returns 0, or 1 with a
 *  message on rank 0 (a solid the elastic module refuses). Collective only in its agreement. */
int solids_init(struct engine *e);

/** After the fluid and wall particles are generated: number the solids' particles after them and
 *  add those whose cell this rank owns to its particles. Collective. Returns 0, or 1 with a
 *  message (a solid particle outside the domain). */
int solids_add_particles(struct engine *e);

/** Gather the loads the pair passes appended on every rank, sum them per solid particle (in the
 *  order of load_sum.h) and add weight times them to the loads the solids hold (acc_ext, and each
 *  solid's total force), which are first set to 0 when `first`. Collective. */
void solids_take_loads(struct engine *e, double weight, int first);

/** Advance every solid over dt [s] under gravity and the loads it holds, and give the solid
 *  particles' copies (owned and halo) the new position, velocity v_avg, density rho0/J and
 *  pressure -tr(sigma)/dim. Returns 0, or 2 on every rank (with a message on rank 0) if a solid's
 *  state is not finite. Collective. */
int solids_move(struct engine *e, double dt);

/** After an acoustic sub-step of dt [s] (scheme riemann): solids_take_loads with weight 1, then
 *  solids_move over dt. Returns as solids_move. Collective. */
int solids_advance(struct engine *e, double dt);

/** The checkpoint arrays of the solids into v (named pointers to their state: what a continuation
 *  needs to take the same sub-steps); returns the count. */
int solids_arrays(struct engine *e, struct hdf5_array *v);

/** The snapshot arrays of the solids into v (their reference positions, and displacements and
 *  stresses computed here from the current state); returns the count. */
int solids_snapshot_arrays(struct engine *e, struct hdf5_array *v);

/** After a restart read the solids' arrays and the particles: the first solid id, the current
 *  normals and the averaged state the pair passes read. Returns 0, or 1 with a message on rank 0
 *  when an array read holds a value that is not finite, or the solid particles read are not the
 *  case's (their count, their ids), the same on every rank. Collective. */
int solids_restarted(struct engine *e, const char *path);

/** The largest speed of a solid particle [m/s] (the same on every rank). */
double solids_max_speed(const struct engine *e);

/** At the start of an advection step: the solids' positions from which solids_motion measures. */
void solids_step_start(struct engine *e);

/** Raise m[0] (speed [m/s]), m[1] (acceleration [m/s^2]) and m[2] (displacement since
 *  solids_step_start [m]) to the solids' largest (the same on every rank). */
void solids_motion(const struct engine *e, double *m);

/** The solids.csv header and one row: step, time, then per solid the probe particle's
 *  displacement, the fluid's force on the solid and the solid's kinetic plus strain energy. */
void solids_csv_header(const struct engine *e, FILE *f);
void solids_csv_row(const struct engine *e, FILE *f);

/** Free everything. */
void solids_free(struct solids *S);

#endif
