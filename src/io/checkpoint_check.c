/* checkpoint_check.c — every field of a checkpoint checked before a restart uses it. Each rule
 * is stated once, as a row of a table (header, /run numbers, snapshot series, particle rows)
 * built from the checkpoint's case, and checked by one function; the ids' uniqueness over all
 * ranks is checked by a census in which each rank counts one block of ids. */
#include "io/checkpoint_check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "case/init.h"
#include "base/mem.h"
#include "io/outdir.h"

#define OPEN_MIN 1u      /* the value must lie above min, not at it */
#define OPEN_MAX 2u      /* ... below max */
#define INTEGER 4u       /* an integer field */
#define ROUNDED 8u       /* finite bounds computed by the run: they hold up to ROUND_TOL relative */
#define ROUND_TOL 1e-9
#define MAX_RULES 16     /* rules of one table: 15 for a 3-D particle with walls */

/* A stored value and the range it must lie in (NaN lies in none). */
struct rule {
  const char *field;   /* attribute or dataset */
  int column;          /* column of an N x dim dataset, or -1 */
  double value, min, max;
  unsigned flags;
  const char *why;     /* what the bounds are, or NULL */
};

/* A rule of a real value in the range from min to max (open ends as flags say). */
static struct rule real_rule(const char *field, double value, double min, double max,
                             unsigned flags, const char *why) {
  return (struct rule){field, -1, value, min, max, flags, why};
}

/* A rule of an integer value from min to max. */
static struct rule integer_rule(const char *field, double value, double min, double max,
                                const char *why) {
  return (struct rule){field, -1, value, min, max, INTEGER, why};
}

/* A rule of a value that must be finite. */
static struct rule finite_rule(const char *field, double value) {
  return real_rule(field, value, -INFINITY, INFINITY, OPEN_MIN | OPEN_MAX, NULL);
}

/* The same rule, for column `column` of its dataset. */
static struct rule in_column(struct rule r, int column) {
  r.column = column;
  return r;
}

/* How far a bound of the given flags may be missed: rounding, for a finite ROUNDED bound. */
static double slack(double bound, unsigned flags) {
  return (flags & ROUNDED) && isfinite(bound) ? ROUND_TOL * fabs(bound) : 0;
}

/* 1 if r's value lies in its range. */
static int holds(const struct rule *r) {
  double lo = r->min - slack(r->min, r->flags), hi = r->max + slack(r->max, r->flags);
  int above = r->flags & OPEN_MIN ? r->value > lo : r->value >= lo;
  int below = r->flags & OPEN_MAX ? r->value < hi : r->value <= hi;
  return above && below;
}

/* A number of a message: integers in full, reals to 12 digits. */
static void put_number(char *buf, size_t len, double v, unsigned flags) {
  if ((flags & INTEGER) && isfinite(v)) snprintf(buf, len, "%.0f", v);
  else snprintf(buf, len, "%.12g", v);
}

/* What r allows, in words ("a finite number > 0", "an integer from 0 to 3"), into buf. */
static void allowed(const struct rule *r, char *buf, size_t len) {
  char lo[40], hi[40];
  unsigned f = r->flags;
  put_number(lo, sizeof lo, r->min, f);
  put_number(hi, sizeof hi, r->max, f);
  int low = isfinite(r->min), high = isfinite(r->max);
  int finite = (!high && (f & OPEN_MAX)) || (!low && (f & OPEN_MIN));
  const char *kind = f & INTEGER ? "an integer" : finite ? "a finite number" : "a number";
  if (r->min == r->max) snprintf(buf, len, "%s", lo);
  else if (low && high && (f & INTEGER)) snprintf(buf, len, "an integer from %s to %s", lo, hi);
  else if (low && high)
    snprintf(buf, len, "a number in %c%s, %s%c", f & OPEN_MIN ? '(' : '[', lo, hi,
             f & OPEN_MAX ? ')' : ']');
  else if (low) snprintf(buf, len, "%s %s %s", kind, f & OPEN_MIN ? ">" : ">=", lo);
  else if (high) snprintf(buf, len, "%s %s %s", kind, f & OPEN_MAX ? "<" : "<=", hi);
  else snprintf(buf, len, "%s", kind);
}

/* "FIELD[: row R[ (id I)][, column C]]: got VALUE, expected RANGE[ (WHY)]" into why. */
static void describe(const struct rule *r, long row, const int64_t *id, char *why, size_t len) {
  char where[96] = "", value[40], range[160];
  if (row >= 0 && id) snprintf(where, sizeof where, ": row %ld (id %lld)", row, (long long)*id);
  else if (row >= 0) snprintf(where, sizeof where, ": row %ld", row);
  size_t n = strlen(where);
  if (r->column >= 0) snprintf(where + n, sizeof where - n, ", column %d", r->column);
  put_number(value, sizeof value, r->value, r->flags);
  allowed(r, range, sizeof range);
  snprintf(why, len, "%s%s: got %s, expected %s%s%s%s", r->field, where, value, range,
           r->why ? " (" : "", r->why ? r->why : "", r->why ? ")" : "");
}

/* Check the rules r[0..n) of one row (row -1: not of a dataset; id: the particle's, or NULL):
 * 0, or 1 with the first rule that does not hold described in why. */
static int check_rules(const struct rule *r, int n, long row, const int64_t *id, char *why,
                       size_t len) {
  for (int k = 0; k < n; k++)
    if (!holds(&r[k])) {
      describe(&r[k], row, id, why, len);
      return 1;
    }
  return 0;
}

/* ---- the tables ---- */

/* The /header rules, against the checkpoint's case c (with the kernel of e). */
static int header_rules(const struct engine *e, const struct case_def *c,
                        const struct snapshot_info *info, struct rule *r) {
  int n = 0;
  r[n++] = real_rule("/header/time", info->time, 0, INFINITY, OPEN_MIN | OPEN_MAX, NULL);
  r[n++] = integer_rule("/header/step", (double)info->step, 1, INFINITY,
                        "a checkpoint is written after a step");
  r[n++] = integer_rule("/header/dimension", info->dimension, c->dimension, c->dimension,
                        "the dimension of its case");
  r[n++] = integer_rule("/header/n_particles", (double)info->n_particles, 1,
                        floor(init_visit_count(c, e->prm.support_max)) + (double)e->solids.view.n,
                        "at most the lattice nodes its case fills with fluid and ghosts, and its solids' particles");
  return n;
}

/* The next due time of an output schedule of period `interval`: after the checkpoint's time t,
 * at most one period later. */
static struct rule schedule_rule(const char *field, double next, double t, double interval,
                                 const char *why) {
  return real_rule(field, next, t, t + interval, ROUNDED, why);
}

/* The rules of the /run numbers, at the checkpoint's time and step in e, against its case c. */
static int run_rules(const struct engine *e, const struct case_def *c, const struct run_extras *x,
                     struct rule *r) {
  double t = e->time, s = (double)e->step;
  int n = 0, probes = c->n_probes > 0;
  int finished = t >= c->t_end || (c->max_steps && e->step >= c->max_steps);
  r[n++] = real_rule("/run/dt", e->dt, 0, t, OPEN_MIN, "the last step: at most the time");
  r[n++] = c->output_interval > 0
               ? schedule_rule("/run/next_output", e->next_output, t, c->output_interval,
                               "from the time to one output.interval later")
               : real_rule("/run/next_output", e->next_output, INFINITY, INFINITY, 0,
                           "never: output.interval is 0");
  r[n++] = schedule_rule("/run/next_stats", e->next_stats, t, c->stats_interval,
                         "from the time to one output.stats_interval later");
  r[n++] = probes ? schedule_rule("/run/next_probes", e->next_probes, t, c->probes_interval,
                                  "from the time to one output.probes_interval later")
                  : real_rule("/run/next_probes", e->next_probes, 0, INFINITY, 0,
                              "unused: the case has no probes");
  r[n++] = c->checkpoint_interval > 0
               ? schedule_rule("/run/next_checkpoint", e->next_checkpoint, t,
                               c->checkpoint_interval,
                               "from the time to one output.checkpoint_interval later")
               : real_rule("/run/next_checkpoint", e->next_checkpoint, 0, INFINITY, 0,
                           "unused: output.checkpoint_interval is 0");
  r[n++] = integer_rule("/run/last_snapshot_step", (double)e->last_snapshot_step, 0, s,
                        "a step up to the checkpoint's");
  r[n++] = integer_rule("/run/last_stats_step", (double)e->last_stats_step, 0, s,
                        "a step up to the checkpoint's");
  r[n++] = integer_rule("/run/last_probes_step", (double)e->last_probes_step, probes ? 0 : -1,
                        probes ? s : -1,
                        probes ? "a step up to the checkpoint's" : "none: the case has no probes");
  r[n++] = real_rule("/run/wall_seconds", x->wall_seconds, 0, INFINITY, OPEN_MAX, NULL);
  r[n++] = integer_rule("/run/no_free_surface", (double)x->no_free_surface, 0,
                        c->free_surface == FREE_SURFACE_AUTO, "1 only with free_surface: auto");
  r[n++] = integer_rule("/run/finished", (double)x->finished, finished, finished,
                        "as time.end and time.max_steps of its case give at its time and step");
  r[n++] = integer_rule("/run/wall_guard_hits", (double)x->wall_guard_hits, 0, INFINITY, NULL);
  return n;
}

/* The rules of row k of the snapshot series in e (the time and particle count of snapshot k),
 * for a checkpoint of n_particles particles. */
static int series_rules(const struct engine *e, long n_particles, int k, struct rule *r) {
  int n = 0, last = k == e->n_snapshots - 1;
  double t = e->snap_times[k];
  if (last && e->last_snapshot_step == e->step)
    r[n++] = real_rule("/run/snapshot_times", t, e->time, e->time, 0,
                       "the last snapshot was written at the checkpoint's step, so at its time");
  else if (k == 0)
    r[n++] = real_rule("/run/snapshot_times", t, 0, 0, 0, "snapshot 0 is the state at t = 0");
  else
    r[n++] = real_rule("/run/snapshot_times", t, e->snap_times[k - 1], e->time,
                       OPEN_MIN | (last ? OPEN_MAX : 0),
                       "after the previous snapshot, and before the checkpoint's time unless "
                       "/run/last_snapshot_step is its step");
  r[n++] = integer_rule("/run/snapshot_particles", (double)e->snap_counts[k],
                        (double)n_particles, (double)n_particles,
                        "every snapshot holds every particle");
  return n;
}

/* What the particle rows of a checkpoint are checked against. */
struct particle_bounds {
  const struct case_def *c;   /* the checkpoint's case */
  long n_particles;
  double mirror_reach;        /* a ghost lies within the wall thickness of its wall, so its
                                 mirror offset within twice that [m] */
  int lowest_phase;           /* the lowest phase value of a row: the lowest marker of the kinds
                                 the case can hold (0: fluid only) */
  char phase_why[160];        /* what the phase values mean, for the message */
};

/* The kinds besides fluid that p can hold (those of a wall only with the wall arrays, the solids'
 * only in a case with solids): their
 * lowest marker and the words of the phase rule ("an index into phases, or -1 for a wall
 * ghost") into b. */
static void held_kinds(const struct parts *p, struct particle_bounds *b) {
  size_t len = sizeof b->phase_why, at = (size_t)snprintf(b->phase_why, len, "an index into phases");
  b->lowest_phase = 0;
  for (int k = 0; k < KIND_COUNT; k++) {
    if (k == KIND_FLUID || (!p->wall && (part_kinds[k].properties & KIND_ON_WALL)) ||
        (k == KIND_SOLID && !b->c->n_solids))
      continue;
    if (kind_marker(k) < b->lowest_phase) b->lowest_phase = kind_marker(k);
    if (at < len)
      at += (size_t)snprintf(b->phase_why + at, len - at, ", or %d for a %s", kind_marker(k), part_kinds[k].name);
  }
  if (b->lowest_phase == 0) snprintf(b->phase_why + at, len - at, ": the case has no walls");
}

/* The rules of particle i of p. */
static int particle_rules(const struct parts *p, long i, const struct particle_bounds *b,
                          struct rule *r) {
  const struct case_def *c = b->c;
  const int ph = p->phase[i], held = ph >= b->lowest_phase;   /* kind_of(ph) is in the table */
  int n = 0, walls = p->wall != NULL, on_wall = held && part_has(ph, KIND_ON_WALL);
  int mirrored = held && part_has(ph, KIND_MIRRORED);
  r[n++] = integer_rule("/particles/id", (double)p->id[i], 0, (double)(b->n_particles - 1),
                        "the ids are 0 to n_particles - 1, each once");
  r[n++] = integer_rule("/particles/phase", ph, b->lowest_phase, c->n_phases - 1, b->phase_why);
  if (walls)
    r[n++] = on_wall ? integer_rule("/particles/wall", p->wall[i], 0, c->n_walls - 1,
                                    "a wall ghost's index into walls")
                     : integer_rule("/particles/wall", p->wall[i], -1, -1, "-1 for a fluid particle");
  for (int d = 0; d < p->dim; d++)
    r[n++] = in_column(real_rule("/particles/position", p->x[d][i], c->domain_min[d],
                                 c->domain_max[d], 0, "inside the domain"), d);
  for (int d = 0; d < p->dim; d++)
    r[n++] = in_column(finite_rule("/particles/velocity", p->v[d][i]), d);
  for (int d = 0; walls && d < p->dim; d++)
    r[n++] = in_column(mirrored ? real_rule("/particles/mirror", p->mirror[d][i], -b->mirror_reach,
                                            b->mirror_reach, ROUNDED,
                                            "a ghost's mirror point is within twice the wall "
                                            "thickness")
                                : finite_rule("/particles/mirror", p->mirror[d][i]), d);
  r[n++] = real_rule("/particles/density", p->rho[i], 0, INFINITY, OPEN_MIN | OPEN_MAX, NULL);
  r[n++] = finite_rule("/particles/pressure", p->p[i]);
  r[n++] = real_rule("/particles/mass", p->m[i], 0, INFINITY, OPEN_MIN | OPEN_MAX, NULL);
  return n;
}

/* ---- the checks ---- */

int checkpoint_check_header(const struct engine *e, const struct case_def *c,
                            const struct snapshot_info *info, char *why, size_t len) {
  struct rule r[MAX_RULES];
  return check_rules(r, header_rules(e, c, info, r), -1, NULL, why, len);
}

/* The snapshot series in e: at least snapshot 0, and each row by series_rules; 0 or 1. */
static int check_series(const struct engine *e, long n_particles, char *why, size_t len) {
  struct rule r[MAX_RULES];
  r[0] = integer_rule("/run/snapshot_times: number of rows", e->n_snapshots, 1,
                      (double)e->step + 1, "snapshot 0 at t = 0, then at most one a step");
  if (check_rules(r, 1, -1, NULL, why, len)) return 1;
  for (int k = 0; k < e->n_snapshots; k++)
    if (check_rules(r, series_rules(e, n_particles, k, r), k, NULL, why, len)) return 1;
  return 0;
}

/* Whether the restart would overwrite path, the next snapshot of the series: 0 unless it exists
 * and was written at or before the checkpoint's step (or cannot be read to tell); then 1 with
 * the reason in why. */
static int overwrite_reason(const char *path, const struct engine *e, char *why, size_t len) {
  char err[512];
  struct snapshot_info info;
  if (access(path, F_OK)) return 0;
  if (hdf5_read_header(path, &info, MPI_COMM_SELF, err, sizeof err)) {
    snprintf(why, len, "/run/snapshot_times: got %d rows, so the restart writes %s next, which "
             "exists and cannot be read (%s): remove it if it is not needed", e->n_snapshots,
             path, err);
    return 1;
  }
  long step = info.step;
  hdf5_info_free(&info);
  if (step > e->step) return 0;   /* written after the checkpoint: replaced, as documented */
  snprintf(why, len, "/run/snapshot_times: got %d rows, expected at least %d: %s (step %ld) was "
           "written at or before the checkpoint's step %ld, and the restart would overwrite it",
           e->n_snapshots, e->n_snapshots + 1, path, step, e->step);
  return 1;
}

/* Rank 0: 0 unless OUTDIR/snap_N.h5, which the restart writes next (N the length of the series),
 * exists and was written at or before the checkpoint's step (or cannot be read to tell): then
 * the series lost snapshots that the restart would overwrite, and 1 with the reason. */
static int overwrites_snapshot(const struct engine *e, char *why, size_t len) {
  char *path = outdir_path(e->outdir, OUTDIR_SNAPSHOT_NAME, e->n_snapshots);
  int status = overwrite_reason(path, e, why, len);
  free(path);
  return status;
}

/* This rank's particles (global rows from first_row): 0, or 1 with the first rule a row
 * breaks. */
static int check_particles(const struct parts *p, const struct particle_bounds *b,
                           long first_row, char *why, size_t len) {
  struct rule r[MAX_RULES];
  for (long i = 0; i < p->n_owned; i++)
    if (check_rules(r, particle_rules(p, i, b, r), first_row + i, &p->id[i], why, len)) return 1;
  return 0;
}

/* ---- the id census ---- */

/* The census: rank r counts the ids [r * block, (r + 1) * block); each rank sends it the ids
 * (with their global rows) in that block, as pairs. Counts and offsets are in pairs. */
struct census {
  long block;
  int *send_n, *send_at, *recv_n, *recv_at;
  long n_recv;
};

/* Counts and offsets of the pairs this rank sends and receives; collective. */
static void census_plan(struct census *s, const struct parts *p, int size, MPI_Comm comm) {
  s->send_n = mem_calloc((size_t)size, sizeof(int), "id census counts");
  s->recv_n = mem_calloc((size_t)size, sizeof(int), "id census counts");
  s->send_at = mem_calloc((size_t)size, sizeof(int), "id census offsets");
  s->recv_at = mem_calloc((size_t)size, sizeof(int), "id census offsets");
  for (long i = 0; i < p->n_owned; i++) s->send_n[p->id[i] / s->block]++;
  MPI_Alltoall(s->send_n, 1, MPI_INT, s->recv_n, 1, MPI_INT, comm);
  s->n_recv = s->recv_n[0];
  for (int r = 1; r < size; r++) {
    s->send_at[r] = s->send_at[r - 1] + s->send_n[r - 1];
    s->recv_at[r] = s->recv_at[r - 1] + s->recv_n[r - 1];
    s->n_recv += s->recv_n[r];
  }
}

/* Send every (id, row) pair to the rank counting its id; returns the pairs received. */
static int64_t *census_exchange(struct census *s, const struct parts *p, long first_row,
                                int size, MPI_Comm comm) {
  int64_t *out = mem_calloc(2 * (size_t)p->n_owned, sizeof(int64_t), "id census pairs sent");
  int64_t *in = mem_calloc(2 * (size_t)s->n_recv, sizeof(int64_t), "id census pairs received");
  int *next = mem_calloc((size_t)size, sizeof(int), "id census offsets");
  memcpy(next, s->send_at, (size_t)size * sizeof(int));
  for (long i = 0; i < p->n_owned; i++) {
    int k = next[p->id[i] / s->block]++;
    out[2 * k] = p->id[i];
    out[2 * k + 1] = first_row + i;
  }
  MPI_Datatype pair;
  MPI_Type_contiguous(2, MPI_INT64_T, &pair);
  MPI_Type_commit(&pair);
  MPI_Alltoallv(out, s->send_n, s->send_at, pair, in, s->recv_n, s->recv_at, pair, comm);
  MPI_Type_free(&pair);
  free(next);
  free(out);
  return in;
}

/* Among n pairs (id, row) of ids in [lo, lo + block): 0 if no id repeats, else 1 with both
 * rows of the first repeat in why. */
static int find_repeat(const int64_t *pairs, long n, long lo, long block, char *why, size_t len) {
  int64_t *row_of = mem_calloc((size_t)block, sizeof(int64_t), "id census rows");
  for (long k = 0; k < block; k++) row_of[k] = -1;
  int repeat = 0;
  for (long k = 0; k < n && !repeat; k++) {
    int64_t id = pairs[2 * k], row = pairs[2 * k + 1], *seen = &row_of[id - lo];
    repeat = *seen >= 0;
    if (repeat)
      snprintf(why, len, "/particles/id: rows %lld and %lld: got %lld in both, expected each id "
               "once", (long long)(*seen < row ? *seen : row),
               (long long)(*seen < row ? row : *seen), (long long)id);
    *seen = row;
  }
  free(row_of);
  return repeat;
}

/* Collective, every id known to lie in [0, n_particles): 0 if no id appears twice over the
 * ranks, else 1 with the rows on the rank that counted it. Memory: about 3 pairs per particle
 * of the rank. */
static int ids_repeat(const struct parts *p, long n_particles, long first_row, MPI_Comm comm,
                      char *why, size_t len) {
  int rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  struct census s = {.block = (n_particles + size - 1) / size};
  census_plan(&s, p, size, comm);
  int64_t *pairs = census_exchange(&s, p, first_row, size, comm);
  int repeat = find_repeat(pairs, s.n_recv, rank * s.block, s.block, why, len);
  free(pairs);
  free(s.send_n);
  free(s.recv_n);
  free(s.send_at);
  free(s.recv_at);
  return repeat;
}

int checkpoint_check(const struct engine *e, const struct case_def *c,
                     const struct snapshot_info *info, const struct run_extras *x, char *why,
                     size_t len) {
  struct rule r[MAX_RULES];
  long mine = e->p.n_owned, first_row = 0, n_particles = info->n_particles;
  struct particle_bounds bounds = {c, n_particles,
                                   2 * init_wall_layers(c, e->prm.support_max) * c->dx, 0, ""};
  held_kinds(&e->p, &bounds);
  MPI_Exscan(&mine, &first_row, 1, MPI_LONG, MPI_SUM, e->comm);
  if (e->rank == 0) first_row = 0;   /* MPI_Exscan leaves rank 0's result undefined */
  int bad = check_rules(r, run_rules(e, c, x, r), -1, NULL, why, len) ||
            check_series(e, n_particles, why, len) ||
            (e->rank == 0 && overwrites_snapshot(e, why, len)) ||
            check_particles(&e->p, &bounds, first_row, why, len);
  if (io_agree(bad, e->comm, why, len)) return 1;
  return io_agree(ids_repeat(&e->p, n_particles, first_row, e->comm, why, len), e->comm, why, len);
}
