/* engine_checkpoint.c — checkpoint.h5 written from and read into the engine, and the check
 * that a restart continues the same case. What is stored, and why nothing else is needed, is
 * in doc/user-guide.md section 4.4. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "case/case_load.h"
#include "io/checkpoint_check.h"
#include "io/engine_checkpoint.h"
#include "io/io_hdf5.h"
#include "base/mem.h"
#include "io/outdir.h"

#define MAX_NUMBERS (12 + CASE_MAX_WALLS * BODY_NUMBERS)
#define MAX_ARRAYS (CASE_MAX_SOLIDS * SOLID_ARRAYS)

/* The /run numbers: engine fields and the extras, as named pointers (for writing and reading). */
static int run_numbers(struct engine *e, struct run_extras *x, struct hdf5_number *v) {
  int n = 0;
  v[n++] = (struct hdf5_number){"dt", &e->dt, NULL};
  v[n++] = (struct hdf5_number){"next_output", &e->next_output, NULL};
  v[n++] = (struct hdf5_number){"next_stats", &e->next_stats, NULL};
  v[n++] = (struct hdf5_number){"next_probes", &e->next_probes, NULL};
  v[n++] = (struct hdf5_number){"next_checkpoint", &e->next_checkpoint, NULL};
  v[n++] = (struct hdf5_number){"last_snapshot_step", NULL, &e->last_snapshot_step};
  v[n++] = (struct hdf5_number){"last_stats_step", NULL, &e->last_stats_step};
  v[n++] = (struct hdf5_number){"last_probes_step", NULL, &e->last_probes_step};
  v[n++] = (struct hdf5_number){"wall_seconds", &x->wall_seconds, NULL};
  v[n++] = (struct hdf5_number){"no_free_surface", NULL, &x->no_free_surface};
  v[n++] = (struct hdf5_number){"finished", NULL, &x->finished};
  v[n++] = (struct hdf5_number){"wall_guard_hits", NULL, &x->wall_guard_hits};
  return n + bodies_numbers(e, v + n);
}

int engine_checkpoint_write(struct engine *e) {
  char *path = outdir_path(e->outdir, OUTDIR_CHECKPOINT_NAME), err[512];
  struct run_extras x = {MPI_Wtime() - e->wall_start, e->no_free_surface, engine_finished(e), 0};
  MPI_Bcast(&x.wall_seconds, 1, MPI_DOUBLE, 0, e->comm);   /* attributes: one value for all */
  MPI_Allreduce(&e->wall_guard_hits, &x.wall_guard_hits, 1, MPI_LONG, MPI_SUM, e->comm);
  struct hdf5_number v[MAX_NUMBERS];
  struct hdf5_array a[MAX_ARRAYS];
  struct checkpoint_extra extra = {run_numbers(e, &x, v), v, solids_arrays(e, a), a, e->n_snapshots, e->snap_times,
                                   e->snap_counts};
  struct snapshot_info info = engine_snapshot_info(e, e->time, e->step);
  double t0 = MPI_Wtime();
  int status = hdf5_write_checkpoint(path, &info, &e->p, &extra, e->comm, err, sizeof err);
  e->t_output += MPI_Wtime() - t0;
  if (e->rank == 0 && status) fprintf(stderr, "mpsph: %s\n", err);
  if (e->rank == 0 && !status) printf("wrote %s (t = %.9g s, step %ld)\n", path, e->time, e->step);
  free(path);
  return status ? 3 : 0;
}

/* Print why the restart is refused (rank 0); returns 1. */
static int refuse(const struct engine *e, const char *path, const char *why) {
  if (e->rank == 0) fprintf(stderr, "mpsph: cannot restart from %s: %s\n", path, why);
  return 1;
}

/* What a restart may change: the end of the run, the outputs, the partitioning. */
static void allow_restart_changes(struct case_def *old, const struct case_def *now) {
  old->t_end = now->t_end;
  old->max_steps = now->max_steps;
  old->output_interval = now->output_interval;
  old->stats_interval = now->stats_interval;
  old->probes_interval = now->probes_interval;
  old->progress_interval = now->progress_interval;
  old->checkpoint_interval = now->checkpoint_interval;
  old->repartition_threshold = now->repartition_threshold;
  old->repartition_every = now->repartition_every;
  old->balance = now->balance;
}

/* The first line where texts a and b differ, and the top-level key above it, into msg. */
static void first_difference(const char *a, const char *b, char *msg, size_t len) {
  const char *section = a, *la = a, *lb = b;
  while (*la && *lb) {
    size_t na = strcspn(la, "\n"), nb = strcspn(lb, "\n");
    if (na != nb || strncmp(la, lb, na)) break;
    if (*la != ' ') section = la;
    la += na + (la[na] == '\n');
    lb += nb + (lb[nb] == '\n');
  }
  if (*la != ' ') section = la;
  snprintf(msg, len, "under '%.*s' the checkpoint has '%.*s' and the case '%.*s'",
           (int)strcspn(section, ":\n"), section, (int)strcspn(la, "\n"), la,
           (int)strcspn(lb, "\n"), lb);
}

/* Load the checkpoint's case into old and compare it with e->c apart from what a restart may
 * change. Returns 0, or 1 with the reason in why. */
static int case_differs(const struct engine *e, const char *path, const char *yaml,
                        struct case_def *old, char *why, size_t len) {
  char err[1024];
  if (case_load_string(yaml, strlen(yaml), path, 0, NULL, old, err, sizeof err)) {
    snprintf(why, len, "its case does not load with this version: %s", err);
    return 1;
  }
  struct case_def *cmp = mem_alloc(sizeof *cmp, "case of the checkpoint");
  *cmp = *old;
  allow_restart_changes(cmp, e->c);
  char *was = case_to_yaml(cmp), *now = case_to_yaml(e->c);
  int differs = strcmp(was, now) != 0;
  if (differs) {
    char where[600];
    first_difference(was, now, where, sizeof where);
    snprintf(why, len, "the case differs from the checkpoint's (only time.end, time.max_steps, "
             "output.* and parallel.* may change): %s", where);
  }
  free(was);
  free(now);
  free(cmp);
  return differs;
}

/* The next output time of a schedule whose interval changed at the restart: the first multiple
 * of the new interval after t (never for a zero snapshot interval). */
static double rescheduled(double next, double old_interval, double interval, double t) {
  if (interval == old_interval) return next;
  return interval > 0 ? interval * (floor(t / interval) + 1) : INFINITY;
}

/* Output schedules for the intervals of the case being restarted. */
static void reschedule(struct engine *e, const struct case_def *old) {
  const struct case_def *c = e->c;
  e->next_output = rescheduled(e->next_output, old->output_interval, c->output_interval, e->time);
  e->next_stats = rescheduled(e->next_stats, old->stats_interval, c->stats_interval, e->time);
  e->next_probes = rescheduled(e->next_probes, old->probes_interval, c->probes_interval, e->time);
  e->next_checkpoint = rescheduled(e->next_checkpoint, old->checkpoint_interval,
                                   c->checkpoint_interval, e->time);
}

/* Read the checkpoint into e and x, each part checked (checkpoint_check.h) before anything
 * is read by it: the /run group, then the header (the particle count), then the particles and
 * everything together. Returns 0, or 1 with the reason in err. */
static int read_checked(struct engine *e, const char *path, const struct snapshot_info *info,
                        const struct case_def *old, struct run_extras *x, char *err, size_t len) {
  struct hdf5_number v[MAX_NUMBERS];
  struct hdf5_array a[MAX_ARRAYS];
  struct checkpoint_extra extra = {run_numbers(e, x, v), v, solids_arrays(e, a), a, 0, NULL, NULL};
  parts_init(&e->p, e->c->dimension, 1, e->c->n_walls > 0);
  int status = hdf5_read_run(path, &extra, e->comm, err, len);
  e->snap_times = extra.snapshot_times;     /* owned by e from here, read or not */
  e->snap_counts = extra.snapshot_counts;
  e->n_snapshots = extra.n_snapshots;
  e->time = info->time;
  e->step = info->step;
  return status || checkpoint_check_header(e, old, info, err, len) ||
         hdf5_read_particles(path, &e->p, e->comm, err, len) ||
         checkpoint_check(e, old, info, x, err, len);
}

/* Read the checkpoint into e (refused unless every field passes its check) and restore the
 * run state. Returns 0 or 1. */
static int restore(struct engine *e, const char *path, const struct snapshot_info *info,
                   const struct case_def *old) {
  char err[1024];
  struct run_extras x;
  if (read_checked(e, path, info, old, &x, err, sizeof err)) return refuse(e, path, err);
  e->no_free_surface = (int)x.no_free_surface;
  e->wall_start = MPI_Wtime() - x.wall_seconds;
  e->wall_guard_hits = e->rank ? 0 : x.wall_guard_hits;   /* summed over the ranks in stats.csv */
  reschedule(e, old);
  if (e->rank == 0)
    printf("restart from %s: t = %.9g s, step %ld, %ld particles%s\n", path, e->time, e->step,
           info->n_particles, x.finished ? " (the run had finished)" : "");
  return 0;
}

int engine_checkpoint_read(struct engine *e, const char *path) {
  char why[2048];
  struct snapshot_info info;
  if (hdf5_read_header(path, &info, e->comm, why, sizeof why)) return refuse(e, path, why);
  struct case_def *old = mem_alloc(sizeof *old, "case of the checkpoint");
  int status = case_differs(e, path, info.case_yaml, old, why, sizeof why) ? refuse(e, path, why)
                                                                           : restore(e, path, &info, old);
  if (!status && e->rank == 0 && strcmp(info.code_version, MPSPH_VERSION))
    fprintf(stderr, "mpsph: warning: %s was written by mpsph %s, this is %s: the continuation "
            "may differ from an uninterrupted run\n", path, info.code_version, MPSPH_VERSION);
  hdf5_info_free(&info);
  free(old);
  return status;
}
