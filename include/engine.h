/* engine.h — the solver state of one rank and the time loop. */
#ifndef MPSPH_ENGINE_H
#define MPSPH_ENGINE_H

#include <mpi.h>
#include <stdio.h>
#include "case.h"
#include "kernel.h"
#include "parts.h"
#include "proxy.h"
#include "space.h"

#define ENGINE_MAX_OPS 16

struct engine;

/** One operation of the per-stage pipeline: a pass over particles/pairs, or a halo update. */
struct stage_op {
  const char *name;
  void (*pass)(struct engine *e);   /* NULL for a halo update */
  int halo_fields;                  /* for halo updates: a HALO_* set */
  double seconds;                   /* accumulated wall time */
  long pairs;                       /* accumulated neighbour-pair evaluations */
};

enum { HALO_STATE = 1, HALO_WALLS_AND_GRADIENT = 2 };

/** Work arrays of the scheme, sized to the particle capacity. */
struct work {
  long capacity;
  double *vol;                     /* particle volume m/rho of every slot, this stage [m^dim] */
  double *grad_rho[3];             /* renormalised density gradient [kg/m^4] */
  double *drho, *dv[3];            /* right-hand sides of the current stage */
  double *x0[3], *v0[3], *rho0;    /* state at the start of the step */
  double *sum_x[3], *sum_v[3], *sum_rho;   /* RK4 weighted sums of the stage derivatives */
};

struct engine {
  const struct case_def *c;
  MPI_Comm comm;
  int rank, n_ranks;
  struct kernel kern;
  struct space space;
  struct halo halo;
  struct parts p;
  struct work w;
  double h, vol0;                  /* smoothing length [m], dx^dim [m^dim] */
  double c_max;                    /* largest phase sound speed [m/s] */
  double time, dt;                 /* [s] */
  long step;
  int n_ops;
  struct stage_op ops[ENGINE_MAX_OPS];
  long pass_pairs;                 /* pair evaluations of the running pass */
  long renorm_fallbacks;           /* particles whose renormalisation matrix was singular */
  int renorm_reported;
  /* load balance */
  long n_repartitions, last_repartition_step;
  double t_compute;                /* this rank's pass time since the last balance check [s] */
  double t_migrate, t_output;      /* accumulated [s] */
  /* output */
  const char *outdir;
  char *case_yaml;
  int n_snapshots;
  double *snap_times;
  long *snap_counts;
  double next_output, next_stats, next_probes, wall_start, next_progress;
  long last_snapshot_step, last_stats_step, last_probes_step;   /* -1 before the first */
  FILE *stats, *probes;
};

/** Set up the engine for case c: generate particles, partition, distribute, open outputs.
 *  Returns 0, or the exit status (1 bad input, 3 I/O) with a message printed on rank 0. */
int engine_init(struct engine *e, const struct case_def *c, const char *outdir, MPI_Comm comm);

/** Run to t_end. Returns the exit status (0, 2 unstable, 3 I/O). */
int engine_run(struct engine *e);

/** Print (rank 0) the run summary: throughput, time per operation, peak memory. Collective. */
void engine_report(struct engine *e, double loop_seconds);

/** Free everything. */
void engine_free(struct engine *e);

/** Advance one RK4 step (all stages, dt from the first stage). Returns 0 or 2 if a check tripped. */
int engine_step(struct engine *e);

/** Migrate, sort, rebuild the halo and the cell index after positions changed.
 *  Returns 0 or 2 (a particle left the domain or jumped beyond the neighbouring ranks). */
int engine_rebuild(struct engine *e);

/** Re-partition the cells with METIS from the current particle weights and redistribute. */
int engine_repartition(struct engine *e);

/** Make the work arrays hold at least the current particle capacity. */
void engine_work_reserve(struct engine *e);

/** Evaluate the stage pipeline at the current state (skip_state_halo: the halo is fresh). */
void engine_evaluate(struct engine *e, int skip_state_halo);

/** Print (rank 0) and assemble the pipeline of the case's scheme. */
void engine_assemble(struct engine *e);

/** Snapshot, stats and probe output when due (force = write all now). Returns 0 or 3. */
int engine_output(struct engine *e, int force);

/** Open the output files (config.yaml, stats.csv, probes.csv). Returns 0 or 3. */
int engine_open_output(struct engine *e);

/** Close the output files and write the final XDMF index. */
void engine_close_output(struct engine *e);

#endif
