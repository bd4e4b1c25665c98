/* engine_io.c — output folder: config.yaml, snapshots + XDMF, stats.csv, probes.csv, and the
 * periodic checkpoint. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "case/case_load.h"
#include "engine/engine.h"
#include "io/engine_checkpoint.h"
#include "physics/eos.h"
#include "io/io_hdf5.h"
#include "base/mem.h"
#include "io/outdir.h"
#include "physics/passes.h"
#include "io/probes.h"

/* Write the text ctx to f (an outdir_write_file filler). */
static void put_text(FILE *f, const void *text) { fputs(text, f); }

/* Drop the rows of the CSV file at path whose step (first column) is above last_step, and a
 * last row cut short by a failed or interrupted write (no newline), keeping the header, through
 * a temporary file. Returns 0 or -1. */
static int trim_csv(const char *dir, const char *name, long last_step) {
  char *path = outdir_path(dir, "%s", name), *tmp = outdir_path(dir, "%s.tmp", name), *line = NULL;
  size_t cap = 0;
  ssize_t n;
  FILE *in = fopen(path, "r"), *out = in ? fopen(tmp, "w") : NULL;
  int ok = out != NULL;
  for (long row = 0; ok && (n = getline(&line, &cap, in)) > 0; row++)
    if (line[n - 1] == '\n' && (row == 0 || strtol(line, NULL, 10) <= last_step))
      ok = fputs(line, out) >= 0;
  free(line);
  if (in) fclose(in);
  if (out) ok &= fclose(out) == 0;
  ok = ok && rename(tmp, path) == 0;
  free(path);
  free(tmp);
  return ok ? 0 : -1;
}

/* Open table t (t->name in the output folder) for rows. A fresh run truncates it; a restart
 * keeps the rows up to its step and appends. *fresh = 1 when the file is new (the caller writes
 * the header). Returns 0, or -1 with errno set. */
static int open_csv(const struct engine *e, struct csv_table *t, int *fresh) {
  char *path = outdir_path(e->outdir, "%s", t->name);
  *fresh = !e->restarted || access(path, F_OK) != 0;
  t->f = *fresh ? fopen(path, "w") : trim_csv(e->outdir, t->name, e->step) ? NULL : fopen(path, "a");
  free(path);
  if (!t->f || fseek(t->f, 0, SEEK_END) != 0) return -1;
  t->complete = ftell(t->f);
  return 0;
}

/* Rank 0: mark table t failed with the system's reason `reason` (an errno; the first failure
 * counts) and say so, naming the file. Returns 3. */
static int table_failed(const struct engine *e, struct csv_table *t, int reason) {
  if (t->error) return 3;
  t->error = reason ? reason : EIO;
  fprintf(stderr, "mpsph: cannot write %s/%s: %s\n", e->outdir, t->name, strerror(t->error));
  return 3;
}

/* Rank 0: the row (or header) just printed into table t must now be in the file: flushed, or
 * else t is marked failed and cut back to its complete rows when closed. 0 or 3. */
static int end_row(const struct engine *e, struct csv_table *t) {
  if (t->error || ferror(t->f) || fflush(t->f) != 0) return table_failed(e, t, errno);
  t->complete = ftell(t->f);
  return 0;
}

/* Collective: rank 0's status (of its table or file writes), on every rank. */
static int rank0_status(const struct engine *e, int status) {
  MPI_Bcast(&status, 1, MPI_INT, 0, e->comm);
  return status;
}

static void stats_header(const struct engine *e) {
  const struct case_def *c = e->c;
  FILE *f = e->stats.f;
  fprintf(f, "step,time,dt");
  for (int ph = 0; ph < c->n_phases; ph++)
    fprintf(f, ",kinetic_energy_%s,mass_%s,volume_%s,max_density_deviation_%s", c->phases[ph].name,
            c->phases[ph].name, c->phases[ph].name, c->phases[ph].name);
  const char *axis = "xyz";
  for (int d = 0; d < c->dimension; d++) fprintf(f, ",momentum_%c", axis[d]);
  fprintf(f, ",wall_seconds,wall_guard_hits\n");
}

/* Rank 0: open stats.csv, probes.csv (if the case has probes), bodies.csv (if it has bodies) and
 * solids.csv (if it has solids),
 * headers on new files. Returns 0, 1 when a file cannot be opened, or 3 when a header cannot be
 * written, with a message. */
static int open_tables(struct engine *e) {
  int fresh_stats, fresh_probes = 0, fresh_bodies = 0, fresh_solids = 0;
  if (open_csv(e, &e->stats, &fresh_stats) ||
      (e->c->n_probes && open_csv(e, &e->probes, &fresh_probes)) ||
      (e->bodies.n && open_csv(e, &e->bodies_csv, &fresh_bodies)) ||
      (e->solids.n && open_csv(e, &e->solids_csv, &fresh_solids))) {
    fprintf(stderr, "mpsph: cannot open stats.csv, probes.csv, bodies.csv or solids.csv in '%s': %s\n", e->outdir,
            strerror(errno));
    return 1;
  }
  if (fresh_stats) stats_header(e);
  if (fresh_probes) probes_write_header(e->probes.f, e->c);
  if (fresh_bodies) bodies_csv_header(e, e->bodies_csv.f);
  if (fresh_solids) solids_csv_header(e, e->solids_csv.f);
  return end_row(e, &e->stats) || (e->probes.f && end_row(e, &e->probes)) ||
                 (e->bodies_csv.f && end_row(e, &e->bodies_csv)) || (e->solids_csv.f && end_row(e, &e->solids_csv))
             ? 3
             : 0;
}

int engine_open_output(struct engine *e) {
  e->case_yaml = case_to_yaml(e->c);
  e->stats.name = "stats.csv";
  e->probes.name = "probes.csv";
  e->bodies_csv.name = "bodies.csv";
  e->solids_csv.name = "solids.csv";
  int status = 0;
  if (e->rank == 0) {
    if (outdir_create(e->outdir) || outdir_write_file(e->outdir, "config.yaml", put_text, e->case_yaml)) {
      fprintf(stderr, "mpsph: cannot write to the output folder '%s': %s\n", e->outdir, strerror(errno));
      status = 1;
    } else {
      status = open_tables(e);
    }
  }
  return rank0_status(e, status);
}

/* Rank 0: close table t (if open); a table whose write failed is cut back to its complete
 * rows, so that no partial row stays to be glued to the next run's first. 0 or 3. */
static int close_table(const struct engine *e, struct csv_table *t) {
  if (!t->f) return 0;
  int status = end_row(e, t);
  if (fclose(t->f) != 0) status = table_failed(e, t, errno);
  char *path = outdir_path(e->outdir, "%s", t->name);
  if (t->error && truncate(path, t->complete) != 0)
    fprintf(stderr, "mpsph: cannot cut %s back to its complete rows: %s\n", path, strerror(errno));
  free(path);
  t->f = NULL;
  return status;
}

int engine_close_output(struct engine *e) {
  int status = close_table(e, &e->stats);
  if (close_table(e, &e->probes)) status = 3;
  if (close_table(e, &e->bodies_csv)) status = 3;
  if (close_table(e, &e->solids_csv)) status = 3;
  return rank0_status(e, status);
}

/* Rank 0: table t flushed and, with fsync, on disk; 0 or 3 with a message. */
static int sync_table(const struct engine *e, struct csv_table *t) {
  if (!t->f) return 0;
  if (end_row(e, t)) return 3;
  return fsync(fileno(t->f)) == 0 ? 0 : table_failed(e, t, errno);
}

int engine_checkpoint(struct engine *e) {
  int status = 0;
  if (e->rank == 0) status = sync_table(e, &e->stats) | sync_table(e, &e->probes) | sync_table(e, &e->bodies_csv) |
                           sync_table(e, &e->solids_csv);
  return rank0_status(e, status) ? 3 : engine_checkpoint_write(e);
}

/* Swap the owned particles' state with the RK start state of the step (x0, v0, rho0), pressure
 * from the EOS: calling it twice restores the state, except the pressures of the second call. */
static void swap_step_start(struct engine *e) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    double t;
    for (int d = 0; d < p->dim; d++) {
      t = p->x[d][i], p->x[d][i] = e->w.x0[d][i], e->w.x0[d][i] = t;
      t = p->v[d][i], p->v[d][i] = e->w.v0[d][i], e->w.v0[d][i] = t;
    }
    t = p->rho[i], p->rho[i] = e->w.rho0[i], e->w.rho0[i] = t;
    if (part_has(p->phase[i], KIND_INTEGRATED)) p->p[i] = eos_pressure(&e->c->phases[p->phase[i]], p->rho[i]);
  }
}

struct snapshot_info engine_snapshot_info(const struct engine *e, double time, long step) {
  return (struct snapshot_info){.time = time, .step = step, .dimension = e->c->dimension,
                                .case_yaml = e->case_yaml, .code_version = MPSPH_VERSION};
}

/* The snapshot at path of the state at the given time and step, with the solids' arrays
 * (hdf5_write_snapshot's status and message). */
static int snapshot_to(struct engine *e, const char *path, double time, long step, char *err, size_t len) {
  struct snapshot_info info = engine_snapshot_info(e, time, step);
  struct hdf5_array solid_arrays[CASE_MAX_SOLIDS * SOLID_SNAPSHOT_ARRAYS];
  info.n_arrays = solids_snapshot_arrays(e, solid_arrays);
  info.arrays = solid_arrays;
  return hdf5_write_snapshot(path, &info, &e->p, e->comm, err, len);
}

/* One snapshot file named `name` in the output folder at the given time and step. */
static int write_named(struct engine *e, const char *name, double time, long step) {
  char *path = outdir_path(e->outdir, "%s", name), err[512];
  int status = snapshot_to(e, path, time, step, err, sizeof(err));
  if (status && e->rank == 0) fprintf(stderr, "mpsph: %s\n", err);
  if (!status && e->rank == 0) printf("wrote %s (t = %.9g s, step %ld)\n", path, time, step);
  free(path);
  return status ? 3 : 0;
}

int engine_write_failure(struct engine *e) {
  int status = write_named(e, "unstable_failing.h5", e->time, e->step);
  swap_step_start(e);
  int good = write_named(e, "unstable_last_good.h5", e->step_start_time, e->step_start);
  swap_step_start(e);
  return status ? status : good;
}

static int write_snapshot(struct engine *e) {
  char *path = outdir_path(e->outdir, OUTDIR_SNAPSHOT_NAME, e->n_snapshots), err[512];
  double t0 = MPI_Wtime();
  int status = snapshot_to(e, path, e->time, e->step, err, sizeof(err));
  free(path);
  long n_total, n = e->p.n_owned;
  MPI_Allreduce(&n, &n_total, 1, MPI_LONG, MPI_SUM, e->comm);
  if (status) {
    if (e->rank == 0) fprintf(stderr, "mpsph: %s\n", err);
    return 3;
  }
  e->snap_times = mem_realloc(e->snap_times, (e->n_snapshots + 1) * sizeof(double), "snapshot series");
  e->snap_counts = mem_realloc(e->snap_counts, (e->n_snapshots + 1) * sizeof(long), "snapshot series");
  e->snap_times[e->n_snapshots] = e->time;
  e->snap_counts[e->n_snapshots++] = n_total;
  if (e->rank == 0 && xdmf_write_series(e->outdir, e->n_snapshots, e->snap_times, e->snap_counts,
                                        e->c->dimension, err, sizeof(err))) {
    fprintf(stderr, "mpsph: %s\n", err);
    status = 3;
  }
  status = rank0_status(e, status);
  e->t_output += MPI_Wtime() - t0;
  return status;
}

/* One stats.csv row: per-phase kinetic energy, mass, volume sum m/rho and max |rho/rho0 - 1|,
 * momentum, the wall guard's corrections since the start of the run. */
static void write_stats(struct engine *e) {
  const struct case_def *c = e->c;
  const struct parts *p = &e->p;
  int np = c->n_phases, dim = p->dim;
  double sum[3 * CASE_MAX_PHASES + 4] = {0}, dev[CASE_MAX_PHASES] = {0};
  for (long i = 0; i < p->n_owned; i++) {
    int ph = p->phase[i];
    if (!part_has(ph, KIND_INTEGRATED)) continue;
    double v2 = 0;
    for (int d = 0; d < dim; d++) {
      v2 += p->v[d][i] * p->v[d][i];
      sum[3 * np + d] += p->m[i] * p->v[d][i];
    }
    sum[3 * ph] += 0.5 * p->m[i] * v2;
    sum[3 * ph + 1] += p->m[i];
    sum[3 * ph + 2] += p->m[i] / p->rho[i];
    dev[ph] = fmax(dev[ph], fabs(p->rho[i] / c->phases[ph].rho0 - 1.0));
  }
  sum[3 * np + dim] = (double)e->wall_guard_hits;
  MPI_Reduce(e->rank ? sum : MPI_IN_PLACE, sum, 3 * np + dim + 1, MPI_DOUBLE, MPI_SUM, 0, e->comm);
  MPI_Reduce(e->rank ? dev : MPI_IN_PLACE, dev, np, MPI_DOUBLE, MPI_MAX, 0, e->comm);
  if (e->rank) return;
  FILE *f = e->stats.f;
  fprintf(f, "%ld,%.10g,%.6g", e->step, e->time, e->dt);
  for (int ph = 0; ph < np; ph++)
    fprintf(f, ",%.10g,%.15g,%.12g,%.6g", sum[3 * ph], sum[3 * ph + 1], sum[3 * ph + 2], dev[ph]);
  for (int d = 0; d < dim; d++) fprintf(f, ",%.10g", sum[3 * np + d]);
  fprintf(f, ",%.3f,%.0f\n", MPI_Wtime() - e->wall_start, sum[3 * np + dim]);
}

/* 1 if an output of period `interval` is due at the current time (advances *next). */
static int due(double time, double interval, double *next, int force) {
  if (!force && time < *next * (1 - 1e-12)) return 0;
  if (interval > 0)
    while (*next <= time * (1 + 1e-12)) *next += interval;
  return 1;
}

int engine_output(struct engine *e, int force) {
  const struct case_def *c = e->c;
  double snap_interval = c->output_interval > 0 ? c->output_interval : INFINITY;
  int snapshot = due(e->time, snap_interval, &e->next_output, force) && e->last_snapshot_step != e->step;
  int probes = c->n_probes && due(e->time, c->probes_interval, &e->next_probes, force) &&
               e->last_probes_step != e->step;
  if ((snapshot || probes) && (e->prm.features & FEAT_SHEPARD) && e->step > 0)
    engine_ghosts_now(e);   /* delta-sph: write the Shepard pressure its forces use */
  if (snapshot) {
    e->last_snapshot_step = e->step;
    if (write_snapshot(e)) return 3;
  }
  int rows = 0, status = 0;
  if (due(e->time, c->stats_interval, &e->next_stats, force) && e->last_stats_step != e->step) {
    e->last_stats_step = e->step;
    write_stats(e);
    if (e->rank == 0) status |= end_row(e, &e->stats);
    if (e->rank == 0 && e->bodies_csv.f) {
      bodies_csv_row(e, e->bodies_csv.f);
      status |= end_row(e, &e->bodies_csv);
    }
    if (e->rank == 0 && e->solids_csv.f) {
      solids_csv_row(e, e->solids_csv.f);
      status |= end_row(e, &e->solids_csv);
    }
    rows = 1;
  }
  if (probes) {
    e->last_probes_step = e->step;
    probes_write_row(e, e->probes.f);
    if (e->rank == 0) status |= end_row(e, &e->probes);
    rows = 1;
  }
  if (rows && rank0_status(e, status)) return 3;
  /* last, so that it holds the schedule advanced by this step's outputs; the end of the run
   * writes its own */
  if (!force && c->checkpoint_interval > 0 &&
      due(e->time, c->checkpoint_interval, &e->next_checkpoint, 0) && !engine_finished(e))
    return engine_checkpoint(e);
  return 0;
}
