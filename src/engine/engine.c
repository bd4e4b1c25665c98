/* engine.c — set-up of a rank's solver state, the rebuild after each step, load balance and the
 * time loop. */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "engine/engine.h"
#include "io/engine_checkpoint.h"
#include "case/init.h"
#include "io/outdir.h"
#include "parallel/partition.h"
#include "parallel/redistribute.h"
#include "physics/passes.h"
#include "engine/signal_stop.h"
#include "base/mem.h"

#define BALANCE_CHECK_EVERY 100 /* steps between load-balance checks (the timing window) */
#define REPARTITION_MIN_GAP 500 /* steps between imbalance-triggered re-partitions */
#define MIN_MEASURED_SECONDS 0.05  /* compute time below which timings are too noisy to use */

static void report(const struct engine *e, const char *msg) {
  if (e->rank == 0) fprintf(stderr, "mpsph: %s\n", msg);
}

/* Work units of owned particle i: its kind's (base/kinds.h). */
static int particle_work(const struct engine *e, long i) { return part_kinds[kind_of(e->p.phase[i])].work; }

/* Work units of this rank's owned particles. */
static double rank_work(const struct engine *e) {
  double work = 0;
  for (long i = 0; i < e->p.n_owned; i++) work += particle_work(e, i);
  return work;
}

/* This rank's measured seconds per work unit relative to the mean over ranks (1 when no time has
 * been measured yet, or when the case balances particle work alone), so that cell weights follow
 * the measured compute time. */
static double cost_factor(const struct engine *e) {
  if (e->c->balance == BALANCE_WORK) return 1.0;
  double work = rank_work(e);
  double rate = work > 0 ? e->t_compute / work : 0, sum;
  MPI_Allreduce(&rate, &sum, 1, MPI_DOUBLE, MPI_SUM, e->comm);
  return sum > 0 && rate > 0 ? rate / (sum / e->n_ranks) : 1.0;
}

void engine_weight_add(const struct engine *e, int64_t *weight, long cell, enum part_kind kind) {
  int64_t *w = weight + space_top_of(&e->space, cell) * PARTITION_CONSTRAINTS;
  w[WEIGHT_WORK] += part_kinds[kind].work;
  w[WEIGHT_PARTICLES] += 1;
}

void engine_weights_reduce(const struct engine *e, int64_t *weight) {
  int n = (int)(e->space.top.n_cells * PARTITION_CONSTRAINTS);
  MPI_Reduce(e->rank ? weight : MPI_IN_PLACE, weight, n, MPI_INT64_T, MPI_SUM, 0, e->comm);
}

/* The partition weights of the top cells from this rank's owned particles, their work scaled by
 * the rank's cost factor, summed onto rank 0. */
static int64_t *top_cell_weights(const struct engine *e) {
  long n = e->space.top.n_cells;
  int64_t *w = mem_calloc((size_t)n * PARTITION_CONSTRAINTS, sizeof(int64_t), "top cell weights");
  double factor = cost_factor(e);
  for (long i = 0; i < e->p.n_owned; i++) engine_weight_add(e, w, e->p.cell[i], kind_of(e->p.phase[i]));
  for (long c = 0; c < n; c++)
    w[c * PARTITION_CONSTRAINTS + WEIGHT_WORK] = (int64_t)llround((double)w[c * PARTITION_CONSTRAINTS + WEIGHT_WORK] * factor);
  engine_weights_reduce(e, w);
  return w;
}

/* Sort owned particles, rebuild the halo and the cell index. */
static void resort(struct engine *e) {
  space_sort(&e->space, &e->p, 0, e->p.n_owned);
  e->p.n_halo = 0;
  space_index(&e->space, &e->p);   /* the send lists of the halo are read from the owned cells */
  halo_rebuild(&e->halo, &e->space, &e->p);
  space_index(&e->space, &e->p);
  engine_work_reserve(e);
}

/* The cells of the mirror points of this rank's wall ghosts (the Shepard interpolation of
 * pass_wall_ghosts reads the cells around them); *n their number. */
static long *mirror_cells(struct engine *e, long *n) {
  const struct parts *p = &e->p;
  struct pass_ctx ctx = engine_pass_ctx(e);
  long *cells = mem_calloc(p->n_owned + 1, sizeof(long), "mirror point cells");
  *n = 0;
  for (long k = 0; k < p->n_owned; k++) {
    if (!part_has(p->phase[k], KIND_MIRRORED)) continue;
    double xs[3];
    wall_mirror_point(&ctx, k, xs);
    cells[(*n)++] = grid_cell_clamped(&e->space.grid, xs);
  }
  return cells;
}

/* The halo of the current partition: one cell layer around the owned cells, and one around the
 * cell of each owned ghost's mirror point; with a moving wall, whose ghosts move between two
 * builds, every cell within the space's halo_layers of an owned cell instead. */
static void build_halo(struct engine *e) {
  long n = 0, *reads = NULL;
  int band = engine_halo_band(e->c, e->space.halo_layers);
  if (band == 1 && e->c->n_walls) reads = mirror_cells(e, &n);
  halo_build(&e->halo, &e->space, band, reads, n, e->comm);
  free(reads);
}

/* Partition the top cells by weight and adopt the result (engine_adopt_partition). When the
 * partition fails and `optional` (a re-partition for balance), rank 0 warns and the current
 * partition, valid as it is, stays. Returns 0 or 1 (failed). Collective. */
static int adopt_partition(struct engine *e, const int64_t *weight, int keep, int optional) {
  char err[512];
  int *owner = mem_calloc(e->space.top.n_cells, sizeof(int), "top cell owners");
  int status = partition_cells(&e->space.top, weight, e->n_ranks, keep ? e->space.top_owner : NULL,
                              e->comm, owner, err, sizeof(err));
  if (!status) space_set_owner(&e->space, owner);
  else if (!optional) report(e, err);
  else if (e->rank == 0)
    fprintf(stderr, "mpsph: warning: the re-partition at step %ld is skipped and the current partition kept: %s\n",
            e->step, err);
  free(owner);
  return status;
}

int engine_adopt_partition(struct engine *e, const int64_t *weight, int keep) {
  return adopt_partition(e, weight, keep, 0);
}

int engine_repartition(struct engine *e, int optional) {
  double t0 = MPI_Wtime();
  int64_t *w = top_cell_weights(e);
  int status = adopt_partition(e, w, 1, optional);
  free(w);
  e->last_repartition_step = e->step;
  if (status) return optional ? 0 : 1;
  redistribute_parts(&e->space, &e->p, e->comm);
  build_halo(e);
  resort(e);
  e->n_repartitions++;
  e->t_repartition += MPI_Wtime() - t0;
  return 0;
}

void engine_report_particle(const struct engine *e, long i, const char *what) {
  const struct parts *p = &e->p;
  char pos[96];
  if (p->dim == 2) snprintf(pos, sizeof pos, "(%.9g, %.9g)", p->x[0][i], p->x[1][i]);
  else snprintf(pos, sizeof pos, "(%.9g, %.9g, %.9g)", p->x[0][i], p->x[1][i], p->x[2][i]);
  char stage[32] = "after the step";
  if (e->stage >= 0) snprintf(stage, sizeof stage, "RK stage %d", e->stage + 1);
  fprintf(stderr, "mpsph: unstable at step %ld, t = %.9g s, %s: particle %lld (phase %d) at %s "
          "with density %.6g kg/m^3, pressure %.6g Pa: %s\n", e->step, e->time, stage,
          (long long)p->id[i], p->phase[i], pos, p->rho[i], p->p[i], what);
}

int engine_rebuild(struct engine *e) {
  double t0 = MPI_Wtime();
  long bad = space_assign_cells(&e->space, &e->p, 0, e->p.n_owned);
  if (engine_check_state(e, bad)) return 2;
  int64_t lost = halo_migrate(&e->halo, &e->space, &e->p);
  if (lost >= 0) {
    if (e->rank == 0)
      fprintf(stderr, "mpsph: unstable at step %ld: particle %lld moved more than a cell in one step\n",
              e->step, (long long)lost);
    return 2;
  }
  resort(e);
  e->t_migrate += MPI_Wtime() - t0;
  return 0;
}

/* Imbalance (max/mean - 1) of a per-rank quantity. */
static double rank_imbalance(const struct engine *e, double local) {
  double max, sum;
  MPI_Allreduce(&local, &max, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, e->comm);
  return sum > 0 ? max / (sum / e->n_ranks) - 1.0 : 0.0;
}

/* Re-partition when forced by repartition_every, or when the compute time since the last check
 * (every BALANCE_CHECK_EVERY steps) is imbalanced beyond the case's threshold; while too little
 * time has been measured to be meaningful, or when the case balances work alone, the particle
 * work is used instead. */
static int balance(struct engine *e) {
  const struct case_def *c = e->c;
  if (e->n_ranks == 1) return 0;
  if (c->repartition_every > 0 && e->step % c->repartition_every == 0) return engine_repartition(e, 1);
  if (e->step % BALANCE_CHECK_EVERY) return 0;
  double parts_imb = rank_imbalance(e, rank_work(e)), time_imb = rank_imbalance(e, e->t_compute), t_sum;
  MPI_Allreduce(&e->t_compute, &t_sum, 1, MPI_DOUBLE, MPI_SUM, e->comm);
  double imb = t_sum > MIN_MEASURED_SECONDS && c->balance == BALANCE_TIME ? time_imb : parts_imb;
  int status = 0;
  if (e->step - e->last_repartition_step >= REPARTITION_MIN_GAP && imb > c->repartition_threshold) {
    if (e->rank == 0)
      printf("re-partition at step %ld: particle imbalance %.1f %%, time imbalance %.1f %%\n",
             e->step, 100 * parts_imb, 100 * time_imb);
    status = engine_repartition(e, 1);
  }
  e->t_compute = 0;
  return status;
}

/* Rank 0 locks the output folder for the run (outdir_lock). Returns 0, or 1 on every rank. */
static int lock_output(struct engine *e) {
  char err[PATH_MAX + 256];
  int status = e->rank == 0 ? outdir_lock(e->outdir, &e->lock_fd, err, sizeof err) : 0;
  if (status) report(e, err);
  MPI_Bcast(&status, 1, MPI_INT, 0, e->comm);
  return status;
}

/* The halo depth as the start-up line states it, into buf. */
static void halo_depth_text(const struct engine *e, char *buf, size_t len) {
  int layers = e->space.halo_layers;
  if (engine_halo_band(e->c, layers) == layers)
    snprintf(buf, len, "halo %d layer%s", layers, layers > 1 ? "s" : "");
  else snprintf(buf, len, "halo 1 layer, %d toward wall ghosts' mirror points", layers);
}

void engine_print_layout(const struct engine *e, double n_fluid, double n_wall) {
  char halo[96];
  halo_depth_text(e, halo, sizeof halo);
  if (e->rank == 0)
    printf("particles: %.0f fluid, %.0f wall; grid %ld x %ld x %ld cells, %s, %d ranks; "
           "top cells of %ld^%d\n", n_fluid, n_wall, e->space.grid.n[0], e->space.grid.n[1],
           e->space.grid.n[2], halo, e->n_ranks, e->space.block, e->c->dimension);
}

int engine_halo_layers(const struct case_def *c, const struct grid *g, double support) {
  double edge = g->edge[0];
  for (int d = 1; d < c->dimension; d++) edge = fmin(edge, g->edge[d]);
  double thickness = init_wall_layers(c, support) * c->dx;
  return c->n_walls ? 1 + (int)ceil(2 * thickness / edge) : 1;
}

int engine_halo_band(const struct case_def *c, int halo_layers) {
  return case_walls_move(c) ? halo_layers : 1;
}

int engine_cell_grid(const struct case_def *c, double support, struct grid *g) {
  return grid_init(g, c->dimension, c->domain_min, c->domain_max, support * ENGINE_CELL_SKIN);
}

/* Each phase's kernel, lattice volume and list radius, and the largest support (multi-resolution). */
static void setup_phase_kernels(struct engine *e) {
  const struct case_def *c = e->c;
  e->prm.multires = case_max_dx_ratio(c) > 1;
  e->prm.support_max = 0;
  for (int ph = 0; ph < c->n_phases; ph++) {
    kernel_init(&e->prm.phase_kern[ph], c->kernel, c->dimension, e->prm.h * c->phases[ph].dx_ratio);
    e->prm.phase_vol0[ph] = case_lattice_volume(c, case_phase_dx(c, ph));
    /* the skin of h's lists: the motion allowed within a step (engine_shift_max) is the same for every pair */
    e->prm.phase_list_radius[ph] = e->prm.phase_kern[ph].support + (ENGINE_CELL_SKIN - 1.0) * e->prm.kern.support;
    e->prm.support_max = fmax(e->prm.support_max, e->prm.phase_kern[ph].support);
  }
  for (int ph = 0; ph < c->n_phases; ph++) {
    e->prm.chunk_kern[ph] = e->prm.phase_kern[ph];
    e->prm.chunk_kern[ph].support = e->prm.support_max;
    e->prm.chunk_kern[ph].support2 = e->prm.support_max * e->prm.support_max;
  }
}

/* Kernel, grid, halo depth. Returns 0 or 1. */
static int setup_space(struct engine *e) {
  const struct case_def *c = e->c;
  e->prm.h = c->h_over_dx * c->dx;
  e->prm.vol0 = case_lattice_volume(c, c->dx);
  kernel_init(&e->prm.kern, c->kernel, c->dimension, e->prm.h);
  setup_phase_kernels(e);
  e->prm.list_radius = e->prm.support_max * ENGINE_CELL_SKIN;
  struct grid g;
  if (engine_cell_grid(c, e->prm.support_max, &g)) {
    report(e, "the domain has too many cells for this resolution (more than 2^31)");
    return 1;
  }
  int layers = engine_halo_layers(c, &g, e->prm.support_max);
  space_init(&e->space, &g, e->rank, e->n_ranks, layers, c->top_cells_per_rank);
  e->prm.c_max = 0;
  for (int ph = 0; ph < c->n_phases; ph++) e->prm.c_max = fmax(e->prm.c_max, c->phases[ph].c0);
  return 0;
}

/* After a restart: locate the particles read from the checkpoint in their cells, partition the
 * cells among the ranks and send the particles to their owners. Returns 0 or 1. */
static int distribute_particles(struct engine *e) {
  long outside = space_assign_cells(&e->space, &e->p, 0, e->p.n_owned);
  int any = outside >= 0;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, e->comm);
  if (any) {
    report(e, "a particle lies outside the domain at start-up");
    return 1;
  }
  double n_fluid, n_wall;
  engine_global_counts(e, &n_fluid, &n_wall);
  engine_print_layout(e, n_fluid, n_wall);
  return engine_repartition(e, 0);
}

int engine_init(struct engine *e, const struct case_def *c, const char *outdir,
                const char *restart, MPI_Comm comm) {
  memset(e, 0, sizeof(*e));
  e->c = c;
  e->comm = comm;
  e->outdir = outdir;
  e->restarted = restart != NULL;
  e->lock_fd = -1;
  MPI_Comm_rank(comm, &e->rank);
  MPI_Comm_size(comm, &e->n_ranks);
  e->wall_start = MPI_Wtime();
  e->last_snapshot_step = e->last_stats_step = e->last_probes_step = -1;
  e->next_checkpoint = c->checkpoint_interval;
  if (setup_space(e)) return 1;
  bodies_init(e);
  if (solids_init(e)) return 1;
  int status = restart ? engine_checkpoint_read(e, restart) : engine_generate(e);
  if (!status && !restart) status = solids_add_particles(e);
  if (!status && restart) status = solids_restarted(e, restart);
  if (status) return status;
  engine_assemble(e);
  if (restart && distribute_particles(e)) return 1;
  if (!restart) {
    build_halo(e);
    resort(e);
  }
  e->n_repartitions = 0;
  e->t_repartition = 0;
  engine_print_pipeline(e);
  /* not before: bad input found in the set-up creates no folder */
  if (lock_output(e)) return 1;
  status = engine_open_output(e);
  if (!status) engine_energy_reference(e);   /* the energy check's reference: the state it starts from */
  return status;
}

/* Free the free-surface work arrays (region, flags, eigenvalues, normals) and clear them. */
static void free_surface_arrays(struct work *w) {
  free(w->surface);
  free(w->region);
  free(w->lambda);
  w->surface = w->region = w->lambda = NULL;
  for (int d = 0; d < 3; d++) {
    free(w->normal[d]);
    w->normal[d] = NULL;
  }
}

/* free_surface: auto — after the first step, switch detection off if no particle was found on a
 * free surface at t = 0 (a closed tank full of fluid), and drop its passes and arrays. */
static void free_surface_auto(struct engine *e) {
  long n = e->n_surface;
  if (e->c->free_surface != FREE_SURFACE_AUTO || !(e->prm.features & FEAT_SURFACE)) return;
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG, MPI_SUM, e->comm);
  if (e->rank == 0)
    printf("free surface: %ld particles detected at t = 0: detection %s\n", n, n ? "kept" : "switched off");
  if (n) return;
  e->no_free_surface = 1;
  free_surface_arrays(&e->w);
  engine_assemble(e);
  engine_print_pipeline(e);
}

/* Print a progress line (rank 0, every output.progress_interval wall seconds); the ETA runs to
 * whichever of time.end and time.max_steps comes first. */
static void progress(struct engine *e) {
  double now = MPI_Wtime();
  if (e->rank || now < e->next_progress) return;
  double elapsed = now - e->wall_start, frac = e->time / e->c->t_end;
  if (e->c->max_steps) frac = fmax(frac, (double)e->step / e->c->max_steps);
  long n = e->p.n_owned;
  printf("step %ld  t = %.6g s  dt = %.3g s  %.3g particle-steps/s/rank  ETA %.0f s\n", e->step,
         e->time, e->dt, n * (double)e->step / elapsed, frac > 0 ? elapsed * (1 - frac) / frac : 0.0);
  fflush(stdout);
  e->next_progress = now + e->c->progress_interval;
}

int engine_finished(const struct engine *e) {
  return e->time >= e->c->t_end || (e->c->max_steps && e->step >= e->c->max_steps);
}

/* Rank 0: the run ends here because of a stop signal, or had nothing left to do. */
static void report_end(const struct engine *e, int signo, long steps) {
  if (e->rank) return;
  if (signo)
    printf("stopped by %s at step %ld, t = %.9g s: the checkpoint is %s/checkpoint.h5; continue "
           "with the same command and --restart\n", signal_stop_name(signo), e->step, e->time,
           e->outdir);
  else if (e->restarted && steps == 0)
    printf("nothing to run: the checkpoint is at t = %.9g s, step %ld, and the case ends at "
           "time.end = %g s, time.max_steps = %ld; raise them to continue\n", e->time, e->step,
           e->c->t_end, e->c->max_steps);
}

/* Advance one step with everything that follows it: migration, load balance, outputs. */
static int step_and_output(struct engine *e) {
  int status = engine_step(e);
  if (!status) engine_wall_guard(e);
  if (!status && e->step == 1) free_surface_auto(e);
  if (!status) status = engine_rebuild(e);
  if (!status) status = balance(e);
  if (!status) status = engine_output(e, 0);
  progress(e);
  return status;
}

/* CPU time of this process so far [s]: what the run costs on a machine shared with other jobs. */
static double process_cpu_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int engine_run(struct engine *e) {
  if (!e->restarted) engine_ghosts_now(e);   /* wall sensors and ghost pressures at t = 0 */
  int status = e->restarted ? 0 : engine_output(e, 1), signo = 0;
  long first_step = e->step;
  double loop_start = MPI_Wtime(), cpu_start = process_cpu_seconds();
  e->next_progress = loop_start + e->c->progress_interval;
  while (!status && !signo && !engine_finished(e)) {
    status = step_and_output(e);
    if (!status) signo = signal_stop_agreed(e->comm);
  }
  e->t_steps = MPI_Wtime() - loop_start;
  e->t_steps_cpu = process_cpu_seconds() - cpu_start;
  if (status == 2) {
    report(e, "run stopped: the state became unstable; writing the failing and the last good state");
    if (engine_write_failure(e)) status = 3;
  }
  if (signo && engine_finished(e)) signo = 0;   /* a signal during the last step: a normal end */
  if (!status && !signo) status = engine_output(e, 1);
  if (!status) status = engine_checkpoint(e);
  if (engine_close_output(e) && !status) status = 3;
  if (!status) report_end(e, signo, e->step - first_step);
  engine_report(e, e->step - first_step, MPI_Wtime() - loop_start);
  return status;
}

void engine_free(struct engine *e) {
  if (e->lock_fd >= 0) close(e->lock_fd);   /* the output folder's lock ends with the run */
  e->lock_fd = -1;
  engine_work_free(&e->w);
  nlist_free(&e->nl);
  halo_free(&e->halo);
  space_free(&e->space);
  parts_free(&e->p);
  free(e->case_yaml);
  free(e->snap_times);
  free(e->snap_counts);
  free(e->probe_buf);
  bodies_free(&e->bodies);
  solids_free(&e->solids);
}
