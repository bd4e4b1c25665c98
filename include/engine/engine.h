/* engine.h — the solver state of one rank and the time loop. */
#ifndef MPSPH_ENGINE_H
#define MPSPH_ENGINE_H

#include <mpi.h>
#include <stdio.h>
#include "case/case.h"
#include "engine/bodies.h"
#include "engine/solids.h"
#include "io/io_hdf5.h"
#include "physics/pass_ctx.h"
#include "parallel/nlist.h"
#include "parallel/partition.h"
#include "base/parts.h"
#include "parallel/proxy.h"
#include "parallel/space.h"

/* The longest pipeline engine_assemble builds: 1 halo + 4 Shepard (delta-sph) + 3 wall ghosts + 3
 * free surface + 3 gradients/halo/rhs + 3 surface tension + 1 wall guard = 18 (without the Shepard
 * pass, the volumes and lists around the wall ghosts take 3 of its 4 places); the dual stepper's
 * table is shorter (a static assertion in engine_step_dual.c). */
#define ENGINE_MAX_OPS 18
#define ENGINE_CELL_SKIN 1.15   /* cell edge / kernel support: room for motion within a step; the
                                   neighbour lists use the same radius (with multi-resolution the
                                   cells follow the coarsest support, each pair's list radius its
                                   support plus the skin at h) */

struct engine;

/** A CSV table of the output folder (stats.csv, probes.csv), appended row by row by rank 0. */
struct csv_table {
  FILE *f;                 /* NULL on the other ranks */
  const char *name;        /* file name in the output folder */
  long complete;           /* bytes of its complete rows: a failed row is cut back to here */
  int error;               /* errno of the first failed write, 0 while none */
};

/** One operation of the per-stage pipeline: a pass over particles/pairs, or a halo update. */
struct stage_op {
  const char *name;
  pass_fn pass;                     /* NULL for a halo update */
  int halo_fields;                  /* for halo updates: a mask of HF_* fields */
  int once_per_step;                /* run at the first stage only */
  int cellwise;                     /* a pass over the owned cells (pass_for_each_owned) that honours
                                       the context's cell list: it may overlap a halo update before it */
  double seconds;                   /* accumulated wall time */
  long pairs;                       /* accumulated neighbour-pair evaluations */
};

/** Halo field sets (bit mask). */
enum { HF_POS = 1, HF_VEL = 2, HF_RHO = 4, HF_P = 8, HF_MASS = 16, HF_GRAD_RHO = 32, HF_SHIFT = 64,
       HF_DIV = 128, HF_SURFACE = 256, HF_INTERFACE_NORMAL = 512, HF_RHO_SHEPARD = 1024,
       HF_P_SHEPARD = 2048,
       HF_GD = 4096 /* scheme generalized-dissipation: Shepard sum Gamma and <grad p>^L */,
       HF_DIV_OWN = 8192 /* the damper's own-phase divergence */ };

struct engine {
  const struct case_def *c;
  MPI_Comm comm;
  int rank, n_ranks;
  struct space space;
  struct halo halo;
  struct parts p;
  struct work w;
  struct nlist nl;                 /* neighbour lists of the owned fluid, rebuilt every step */
  struct physics_params prm;       /* what the passes read (physics/pass_ctx.h) */
  int stage;                       /* current RK stage 0..3 */
  double time, dt;                 /* [s] */
  double stage_time;               /* time of the state the current stage evaluates (prm.frames) [s] */
  int moving_walls;                /* the case has moving walls (a prescribed motion, or bodies) */
  struct bodies bodies;            /* the rigid bodies (engine/bodies.h) */
  struct solids solids;            /* the elastic solids (engine/solids.h) */
  long step;
  double step_start_time;          /* time and step at the start of the current step */
  long step_start;
  int n_ops;
  struct stage_op ops[ENGINE_MAX_OPS];
  long n_surface;                  /* owned particles detected on the free surface, summed over the
                                      detections so far (free_surface_auto reads it after the
                                      first step, when one has run) */
  int no_free_surface;             /* free_surface auto found none at t = 0 */
  long renorm_fallbacks;           /* particles whose renormalisation matrix was singular, summed
                                      over the passes so far */
  /* load balance */
  long n_repartitions, last_repartition_step;
  double t_compute;                /* this rank's pass time since the last balance check [s] */
  double t_migrate, t_output;      /* accumulated [s] */
  double t_solids;                 /* in the solids' coupling (loads, sub-steps, copies), accumulated [s] */
  double t_repartition;            /* in re-partitions after start-up, accumulated [s] */
  double t_dropped_ops;            /* time of operations dropped from the pipeline by a re-assembly [s] */
  double t_steps;                  /* wall time of the step loop without the final output [s] */
  double t_steps_cpu;              /* CPU time of this process in the same loop [s] */
  /* output */
  const char *outdir;
  char *case_yaml;
  int n_snapshots;
  double *snap_times;
  long *snap_counts;
  double next_output, next_stats, next_probes, next_checkpoint, wall_start, next_progress;
  long last_snapshot_step, last_stats_step, last_probes_step;   /* -1 before the first */
  struct csv_table stats, probes, bodies_csv, solids_csv;
  int lock_fd;                     /* rank 0: the output folder's lock (outdir_lock), else -1 */
  double *probe_buf;               /* the probes' samples of one row, sized at the first row */
  long probe_buf_len;
  int restarted;                   /* continues from a checkpoint */
  long wall_guard_hits;            /* normal-velocity corrections by the wall guard on this rank */
  /* energy check (energy_check.c) */
  double energy_unit;              /* the fixed-point unit of the energy sums [J] */
  double energy_limit;             /* bound of one particle's energy in the sum [units] */
  int64_t energy_start;            /* mechanical energy at the start of the run [units] */
  double energy_scale;             /* M U_max^2 / 2 [units] */
  double energy_growth_peak;       /* largest growth (E - E_start) / energy_scale so far [-] */
  /* scheme riemann (engine_step_dual.c) */
  double dt_acoustic;              /* the last acoustic sub-step [s] */
  long n_acoustic;                 /* acoustic sub-steps of the last advection step */
  int dual_ops[ENGINE_MAX_OPS];    /* index in ops of each of its operations, -1 when absent */
};

/** Set up the engine for case c: lock the output folder for the run (refused with 1 when
 *  another run holds it), generate particles (or, with `restart` non-NULL, read them and
 *  the run state from that checkpoint), partition, distribute, open outputs.
 *  Returns 0, or the exit status (1 bad input, 3 I/O) with a message printed on rank 0. */
int engine_init(struct engine *e, const struct case_def *c, const char *outdir,
                const char *restart, MPI_Comm comm);

/** Run to t_end (or max_steps), or until a stop signal; write the final outputs and the
 *  checkpoint. Returns the exit status (0, also after a stop signal; 2 unstable, 3 I/O). */
int engine_run(struct engine *e);

/** 1 when the run has reached time.end or time.max_steps. */
int engine_finished(const struct engine *e);

/** Global fluid and wall particle counts. Collective. */
void engine_global_counts(const struct engine *e, double *n_fluid, double *n_wall);

/** Print (rank 0) the summary of the `steps` steps run in loop_seconds [s]: throughput, time
 *  per operation, peak memory; and write it, with every rank's memory, to OUTDIR/timings.csv
 *  (through a temporary name) for the benchmark driver. Collective. */
void engine_report(struct engine *e, long steps, double loop_seconds);

/** Print (stderr) the step, time, stage, id, phase and position of particle i and what tripped. */
void engine_report_particle(const struct engine *e, long i, const char *what);

/** Free everything and release the output folder's lock. */
void engine_free(struct engine *e);

/** Advance one step of the case's scheme (its `step` in the scheme table, engine/schemes.h: an RK
 *  step, all stages, dt from the first stage, or with scheme riemann one advection step,
 *  engine_step_dual). Returns 0 or 2 if a check tripped. */
int engine_step(struct engine *e);

/** Scheme riemann: one advection step of the dual-criteria time stepping (paper 002 section 2.5):
 *  density re-initialisation, transport-velocity shift of the light phases, then position-Verlet
 *  acoustic sub-steps up to the advection step e->dt. Returns 0 or 2 if a check tripped. */
int engine_step_dual(struct engine *e);

/** Scheme riemann: the operations of its pipeline (run by engine_step_dual). */
void engine_assemble_dual(struct engine *e);

/** Scheme riemann: the advection step 0.25 h / U (U the largest fluid speed, at least
 *  physics.u_max; h^2/(4 nu) with viscosity) cut so that the particles' motion in it, with the
 *  largest transport-velocity shift of acceleration a_tv [m/s^2], stays within the cell skin
 *  [s]. Collective. */
double dual_advection_dt(struct engine *e, double a_tv);

/** Scheme riemann: the acoustic sub-step time.cfl h / (c_max + |v|_max) [s]. Collective. */
double dual_acoustic_dt(struct engine *e);

/** Run operation k of the pipeline (a pass or a halo update), timed; a pass's counts (pairs, renorm
 *  fallbacks, free-surface particles) are added to the operation's and the engine's totals. */
void engine_run_op(struct engine *e, int k);

/** The context the passes of engine e run with: its case, parameters, particles, work arrays,
 *  neighbour lists and cells, and zero counts. */
struct pass_ctx engine_pass_ctx(struct engine *e);

/** After a step: wall_guard_apply (physics/wall_guard.h) on this rank's particles; the corrections
 *  made are added to e->wall_guard_hits and returned. Local: no communication. */
long engine_wall_guard(struct engine *e);

/** After an RK stage: stop (2 on every rank) if an owned fluid particle has a non-finite
 *  derivative (drho/dt, du/dt, shifting velocity), else 0. Collective. */
int engine_check_derivatives(struct engine *e);

/** After the time step e->dt [s] is computed (limit: the name of its smallest term): 2 if it is
 *  below time.dt_min or not finite, naming the particle with the largest acceleration; else 0.
 *  Collective only when it trips, which it does on every rank alike. */
int engine_check_dt(struct engine *e, const char *limit);

/** After a step, on the new state: stop (2 on every rank) if a particle left the domain
 *  (left_domain: its index on this rank, or -1), lies deeper than half a dx inside a wall's
 *  solid, or has a density outside its phase's density_band, or engine_check_energy trips;
 *  else 0. Collective. */
int engine_check_state(struct engine *e, long left_domain);

/** The owned fluid particle with the largest |vec| over all ranks (vec: per-particle components,
 *  e.g. the velocity or the acceleration): its index on the rank that holds it, -1 on the others;
 *  the largest |vec| in *norm on every rank. Collective (one MAXLOC reduction). */
long engine_largest_vector(const struct engine *e, double *const vec[3], double *norm);

/** Whether the energy check runs: time.energy_growth > 0 and no wall moves. */
int engine_energy_on(const struct engine *e);

/** At the start of the run (also after a restart): the mechanical energy the check compares with
 *  (energy_check.c). Collective; nothing when the check is off. */
void engine_energy_reference(struct engine *e);

/** After a step, on the new state: stop (2 on every rank) if the mechanical energy of the fluid
 *  has grown by more than time.energy_growth M U_max^2 / 2 since engine_energy_reference, naming
 *  the fastest particle; else 0. One reduction when on, none when off. Collective. */
int engine_check_energy(struct engine *e);

/** Migrate, sort, rebuild the halo and the cell index after positions changed.
 *  Returns 0 or 2 (a particle left the domain or jumped beyond the neighbouring ranks). */
int engine_rebuild(struct engine *e);

/** Re-partition the cells with METIS from the current particle weights and redistribute.
 *  Returns 0, or 1 when the partition fails (a rank would get no cell, METIS failed) with a
 *  message on rank 0; when `optional` (a re-partition for balance) such a failure only warns,
 *  keeps the current partition and returns 0. Collective. */
int engine_repartition(struct engine *e, int optional);

/** Rank 0 prints the start-up line: the global particle counts, the cell grid, the halo depth,
 *  the ranks and the top cells' block size. */
void engine_print_layout(const struct engine *e, double n_fluid, double n_wall);

/** The cell grid of case c for a kernel support of `support` m (cell edge at least
 *  ENGINE_CELL_SKIN supports). Returns 0, or 1 when it would have more than 2^31 cells. */
int engine_cell_grid(const struct case_def *c, double support, struct grid *g);

/** The halo's reach [cells] of case c on cell grid g: 1 without walls; with walls
 *  1 + ceil(2 wall thickness / smallest cell edge), since a ghost's mirror point lies up to twice
 *  the wall thickness away and its interpolation reaches one support further. The halo is this
 *  deep only around the mirror points' cells (everywhere with a moving wall), 1 elsewhere. */
int engine_halo_layers(const struct case_def *c, const struct grid *g, double support);

/** The depth [cells] of the halo band around every owned cell, for a halo reach of halo_layers
 *  (engine_halo_layers): 1, or halo_layers with a moving wall (its ghosts' mirror points move
 *  between two partitions); beyond the band, with fixed walls, the halo holds only the cells
 *  around the owned ghosts' mirror points. */
int engine_halo_band(const struct case_def *c, int halo_layers);

/** Add a particle of kind `kind` in fine cell `cell` to the partition weights of its top cell
 *  (PARTITION_CONSTRAINTS values per top cell, parallel/partition.h). */
void engine_weight_add(const struct engine *e, int64_t *weight, long cell, enum part_kind kind);
/** Sum the partition weights of all ranks onto rank 0. */
void engine_weights_reduce(const struct engine *e, int64_t *weight);
/** Partition the top cells with METIS by `weight` (one per top cell, read on rank 0) and adopt
 *  the result in the space; with `keep`, the ranks keep as much of the space's current
 *  partition as they can (a re-partition), without it the first partition. Returns 0, or 1 with
 *  a message on rank 0. Collective. */
int engine_adopt_partition(struct engine *e, const int64_t *weight, int keep);

/** Generate the initial particles (src/engine/startup.c): count the lattice rows in parallel,
 *  partition the top cells by the counted work, generate on each rank only its own particles
 *  with the ids of a serial generation; print the counts line. Returns 0, or 1 with a message on
 *  rank 0 (bad input). Collective. */
int engine_generate(struct engine *e);

/** The largest distance a particle may move within one step: half the skin of the lists at h
 *  (with multi-resolution every pair's list has that skin; the cells are wider), so that the
 *  cells and neighbour lists built at the start of the step hold every pair in its kernel
 *  support at every stage [m]. */
double engine_shift_max(const struct engine *e);

/** 1 if slot i is of a kind that moves with its wall (KIND_ON_WALL) and that wall is moving. */
static inline int engine_moving_ghost(const struct engine *e, long i) {
  return part_has(e->p.phase[i], KIND_ON_WALL) && e->c->walls[e->p.wall[i]].moving;
}

/** Make the work arrays hold at least the current particle capacity (the owned-only ones: the
 *  owned particles, with room for some to migrate in). */
void engine_work_reserve(struct engine *e);

/** Bytes held by the work arrays. */
long engine_work_bytes(struct engine *e);

/** Free the work arrays (every one, also the optional ones) and set them to NULL. */
void engine_work_free(struct work *w);

/** Evaluate the stage pipeline at the current state (skip_state_halo: the halo is fresh). */
void engine_evaluate(struct engine *e, int skip_state_halo);

/** Wall ghost values (pressure, velocity, density, mass) from the current fluid state, outside
 *  the timed stage pipeline: for the outputs at the start of a run, before any stage has set
 *  them; with delta-sph also the Shepard density and pressure first (what the next stage
 *  recomputes), for every snapshot and probe row. Collective. */
void engine_ghosts_now(struct engine *e);

/** With the acoustic damper, the damper's divergence D of every owned and halo fluid particle
 *  (work array div_own, or div with the symmetric and difference forms) at the current state,
 *  wall ghosts first: what the pressure probes need to read the damper's stress. Outside the
 *  timed pipeline; the next stage recomputes everything it touches. Collective. */
void engine_damper_divergence_now(struct engine *e);

/** Assemble the pipeline of passes and halo updates the case needs; allocate its arrays. On a
 *  re-assembly the operations that stay keep their accumulated time and pairs. */
void engine_assemble(struct engine *e);

/** Print the active terms and the pipeline (rank 0). */
void engine_print_pipeline(const struct engine *e);

/** Snapshot, stats and probe output when due (force = write them now), then the checkpoint
 *  when output.checkpoint_interval is due (never when forced). Returns 0 or 3 (every rank). */
int engine_output(struct engine *e, int force);

/** Collective: make the rows of stats.csv and probes.csv durable (fsync), then write
 *  checkpoint.h5, whose restart keeps those rows. Returns 0 or 3 with a message (every rank). */
int engine_checkpoint(struct engine *e);

/** The /header of a snapshot or checkpoint at the given time [s] and step. */
struct snapshot_info engine_snapshot_info(const struct engine *e, double time, long step);

/** Open the output files (config.yaml, stats.csv, probes.csv). After a restart, stats.csv and
 *  probes.csv keep their rows up to the checkpoint's step and are appended to. Returns 0, or 1
 *  (with a message) when the output folder cannot be written: a bad -o is bad input. */
int engine_open_output(struct engine *e);

/** After an instability: write the failing state (unstable_failing.h5) and the state at the start
 *  of the step (unstable_last_good.h5). Collective. Returns 0 or 3. */
int engine_write_failure(struct engine *e);

/** Collective: close stats.csv and probes.csv; a table whose write failed is cut back to its
 *  complete rows. Returns 0, or 3 (every rank) when a write or the close failed. */
int engine_close_output(struct engine *e);

#endif
