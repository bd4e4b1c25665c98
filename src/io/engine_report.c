/* engine_report.c — the end-of-run summary: throughput, time per operation, memory; printed, and
 * written to OUTDIR/timings.csv for the benchmark driver (scripts/bench.py). */
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>
#include "engine/engine.h"
#include "io/outdir.h"
#include "base/mem.h"

/* Peak resident memory of this process [bytes]. */
static double peak_rss_bytes(void) {
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return (double)ru.ru_maxrss * 1024.0;
}

/* Current resident memory of this process [bytes] (/proc/self/statm; 0 where it is missing). */
static double current_rss_bytes(void) {
  long pages_total = 0, pages_resident = 0;
  FILE *f = fopen("/proc/self/statm", "r");
  if (!f) return 0;
  if (fscanf(f, "%ld %ld", &pages_total, &pages_resident) != 2) pages_resident = 0;
  fclose(f);
  return (double)pages_resident * (double)sysconf(_SC_PAGESIZE);
}

/* The number [kB] after `key` ("RssFile:", "Pss:") in a /proc file of this process, in bytes;
 * 0 where the file or the line is missing. */
static double proc_kb_line(const char *file, const char *key) {
  char line[256];
  size_t n = strlen(key);
  double kb = 0;
  FILE *f = fopen(file, "r");
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, key, n) == 0 && sscanf(line + n, "%lf", &kb) == 1) break;
  if (f) fclose(f);
  return kb * 1024.0;
}

/* File-backed resident memory of this process [bytes]: the pages of the executable and the shared
 * libraries (MPI, HDF5, ...), which every rank maps. */
static double current_file_rss_bytes(void) { return proc_kb_line("/proc/self/status", "RssFile:"); }

/* Proportional resident memory of this process [bytes]: each shared page divided by the number
 * of processes that map it. Summed over the ranks it is the memory the job holds, with the
 * library pages counted once. */
static double current_pss_bytes(void) { return proc_kb_line("/proc/self/smaps_rollup", "Pss:"); }

/* The owned particles of this rank by kind. */
static void local_counts(const struct engine *e, double *count) {
  for (int k = 0; k < KIND_COUNT; k++) count[k] = 0;
  for (long i = 0; i < e->p.n_owned; i++) count[kind_of(e->p.phase[i])]++;
}

void engine_global_counts(const struct engine *e, double *n_fluid, double *n_wall) {
  double local[KIND_COUNT], total[KIND_COUNT];
  local_counts(e, local);
  MPI_Allreduce(local, total, KIND_COUNT, MPI_DOUBLE, MPI_SUM, e->comm);
  *n_fluid = total[KIND_FLUID];
  *n_wall = total[KIND_WALL];
}

static double max_over_ranks(const struct engine *e, double x) {
  MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  return x;
}

/* The project's own arrays of this rank, by owner [bytes]. */
enum { MEM_PARTICLES, MEM_WORK, MEM_NLIST, MEM_CELLS, MEM_HALO, N_MEM };
static const char *const mem_names[N_MEM] = {"particles", "work", "neighbour_lists", "cells", "halo_buffers"};

static void project_bytes(struct engine *e, double *bytes) {
  bytes[MEM_PARTICLES] = (double)parts_bytes(&e->p);
  bytes[MEM_WORK] = (double)engine_work_bytes(e);
  bytes[MEM_NLIST] = (double)nlist_bytes(&e->nl);
  bytes[MEM_CELLS] = (double)space_bytes(&e->space);
  bytes[MEM_HALO] = (double)halo_bytes(&e->halo);
}

/* Figures gathered from each rank: memory (peak, end, file-backed, project, PSS [bytes]), then
 * its particles at the end (owned of each kind, halo). */
enum { RANK_PEAK, RANK_END, RANK_FILE, RANK_PROJECT, RANK_PSS, RANK_OWNED, RANK_HALO = RANK_OWNED + KIND_COUNT,
       PER_RANK };

/* Everything the summary reports, reduced over the ranks (memory gathered to rank 0). */
struct run_summary {
  const struct engine *e;
  long steps;
  double loop_seconds, n_fluid, n_wall;
  double op_max[ENGINE_MAX_OPS], op_mean[ENGINE_MAX_OPS], op_pairs[ENGINE_MAX_OPS];
  double solids_max, solids_mean;  /* in the solids' coupling [s] */
  double migrate_max, migrate_mean, output_max, steps_max, dropped_max, dropped_mean, cpu_max, cpu_mean;
  double *per_rank;                /* PER_RANK figures of each rank; rank 0 only */
  double mem_sum[N_MEM];           /* the project's arrays by owner, summed over the ranks [bytes] */
  double halo_particles;           /* halo copies summed over the ranks (from per_rank; rank 0 only) */
  double halo_particles_max;       /* on the rank with the most */
  double halo_neighbours_max;      /* neighbouring ranks (proxies) of the rank with the most */
  double halo_messages, halo_bytes;   /* sent since start, summed over the ranks */
  double repartition_max, repartition_mean;   /* re-partition time after start-up [s] */
};

/* Max and mean over ranks of x. */
static void max_mean(const struct engine *e, double x, double *max, double *mean) {
  *max = max_over_ranks(e, x);
  MPI_Allreduce(&x, mean, 1, MPI_DOUBLE, MPI_SUM, e->comm);
  *mean /= e->n_ranks;
}

static void summarise(struct engine *e, long steps, double loop_seconds, struct run_summary *s) {
  double rss[PER_RANK] = {[RANK_PEAK] = peak_rss_bytes(), [RANK_END] = current_rss_bytes(),
                          [RANK_FILE] = current_file_rss_bytes(), [RANK_PSS] = current_pss_bytes(),
                          [RANK_HALO] = (double)e->p.n_halo}, *all = NULL, mem[N_MEM];
  project_bytes(e, mem);
  for (int k = 0; k < N_MEM; k++) rss[RANK_PROJECT] += mem[k];
  local_counts(e, rss + RANK_OWNED);
  MPI_Reduce(mem, s->mem_sum, N_MEM, MPI_DOUBLE, MPI_SUM, 0, e->comm);
  s->halo_neighbours_max = max_over_ranks(e, (double)e->halo.n_proxies);
  double sent[2] = {(double)e->halo.n_messages, (double)e->halo.n_bytes}, sent_sum[2] = {0, 0};
  MPI_Reduce(sent, sent_sum, 2, MPI_DOUBLE, MPI_SUM, 0, e->comm);
  s->halo_messages = sent_sum[0];
  s->halo_bytes = sent_sum[1];
  max_mean(e, e->t_repartition, &s->repartition_max, &s->repartition_mean);
  s->e = e;
  s->steps = steps;
  s->loop_seconds = loop_seconds;
  engine_global_counts(e, &s->n_fluid, &s->n_wall);
  for (int k = 0; k < e->n_ops; k++) {
    double pairs = (double)e->ops[k].pairs;
    max_mean(e, e->ops[k].seconds, &s->op_max[k], &s->op_mean[k]);
    MPI_Allreduce(&pairs, &s->op_pairs[k], 1, MPI_DOUBLE, MPI_SUM, e->comm);
  }
  max_mean(e, e->t_migrate, &s->migrate_max, &s->migrate_mean);
  max_mean(e, e->t_solids, &s->solids_max, &s->solids_mean);
  max_mean(e, e->t_dropped_ops, &s->dropped_max, &s->dropped_mean);
  s->output_max = max_over_ranks(e, e->t_output);
  s->steps_max = max_over_ranks(e, e->t_steps);
  max_mean(e, e->t_steps_cpu, &s->cpu_max, &s->cpu_mean);
  if (e->rank == 0) all = mem_calloc(PER_RANK * (size_t)e->n_ranks, sizeof(double), "per-rank memory report");
  MPI_Gather(rss, PER_RANK, MPI_DOUBLE, all, PER_RANK, MPI_DOUBLE, 0, e->comm);
  s->per_rank = all;
  s->halo_particles = s->halo_particles_max = 0;
  for (int r = 0; all && r < e->n_ranks; r++) {
    s->halo_particles += all[PER_RANK * r + RANK_HALO];
    if (all[PER_RANK * r + RANK_HALO] > s->halo_particles_max) s->halo_particles_max = all[PER_RANK * r + RANK_HALO];
  }
}

/* Rank 0: the summary ctx (a struct run_summary) as CSV rows name,kind,value,seconds_max,
 * seconds_mean,pairs (an outdir_write_file filler). */
static void write_rows(FILE *f, const void *ctx) {
  const struct run_summary *s = ctx;
  const struct engine *e = s->e;
  fprintf(f, "name,kind,value,seconds_max,seconds_mean,pairs\n");
  fprintf(f, "ranks,run,%d,,,\nsteps,run,%ld,,,\n", e->n_ranks, s->steps);
  fprintf(f, "fluid_particles,run,%.0f,,,\nwall_particles,run,%.0f,,,\n", s->n_fluid, s->n_wall);
  fprintf(f, "loop,time,,%.6f,%.6f,\n", s->loop_seconds, s->loop_seconds);
  fprintf(f, "steps_without_final_output,time,,%.6f,,\n", s->steps_max);
  fprintf(f, "steps_without_final_output_cpu,cpu,,%.6f,%.6f,\n", s->cpu_max, s->cpu_mean);
  for (int k = 0; k < e->n_ops; k++)
    fprintf(f, "\"%s\",%s,,%.6f,%.6f,%.0f\n", e->ops[k].name, e->ops[k].pass ? "pass" : "halo",
            s->op_max[k], s->op_mean[k], s->op_pairs[k]);
  fprintf(f, "migration,time,%ld,%.6f,%.6f,\n", e->n_repartitions, s->migrate_max, s->migrate_mean);
  fprintf(f, "output,time,,%.6f,,\n", s->output_max);
  if (e->solids.n) fprintf(f, "solids,time,%ld,%.6f,%.6f,\n", e->solids.substeps_total, s->solids_max, s->solids_mean);
  fprintf(f, "dropped_operations,time,,%.6f,%.6f,\n", s->dropped_max, s->dropped_mean);
  fprintf(f, "halo_particles,run,%.0f,,,\n", s->halo_particles);
  fprintf(f, "halo_particles_max,run,%.0f,,,\n", s->halo_particles_max);
  fprintf(f, "halo_neighbours_max,run,%.0f,,,\n", s->halo_neighbours_max);
  fprintf(f, "halo_messages,run,%.0f,,,\nhalo_bytes,run,%.0f,,,\n", s->halo_messages, s->halo_bytes);
  fprintf(f, "repartition,time,%ld,%.6f,%.6f,\n", e->n_repartitions, s->repartition_max, s->repartition_mean);
  for (int r = 0; r < e->n_ranks; r++) {
    const double *m = s->per_rank + PER_RANK * r;
    fprintf(f, "rss_peak_rank%d,memory,%.0f,,,\nrss_end_rank%d,memory,%.0f,,,\n", r, m[RANK_PEAK], r, m[RANK_END]);
    fprintf(f, "rss_file_end_rank%d,memory,%.0f,,,\nproject_bytes_rank%d,memory,%.0f,,,\n", r, m[RANK_FILE], r,
            m[RANK_PROJECT]);
    fprintf(f, "pss_end_rank%d,memory,%.0f,,,\n", r, m[RANK_PSS]);
    for (int k = 0; k < KIND_COUNT; k++) {
      char key[32];
      snprintf(key, sizeof key, "%s", part_kinds[k].name);
      for (char *c = key; *c; c++) *c = *c == ' ' ? '_' : *c;
      fprintf(f, "owned_%s_rank%d,run,%.0f,,,\n", key, r, m[RANK_OWNED + k]);
    }
    fprintf(f, "halo_rank%d,run,%.0f,,,\n", r, m[RANK_HALO]);
  }
  for (int k = 0; k < N_MEM; k++) fprintf(f, "bytes_%s,memory,%.0f,,,\n", mem_names[k], s->mem_sum[k]);
}

/* Rank 0: write OUTDIR/timings.csv through a temporary name; a failure is only reported. */
static void write_timings(const struct engine *e, const struct run_summary *s) {
  if (e->outdir && outdir_write_file(e->outdir, "timings.csv", write_rows, s))
    fprintf(stderr, "mpsph: warning: cannot write %s/timings.csv\n", e->outdir);
}

static void print_summary(const struct engine *e, const struct run_summary *s) {
  double rate = s->steps > 0 && s->loop_seconds > 0 ? s->n_fluid * (double)s->steps / s->loop_seconds : 0;
  double rss_max = 0, rss_sum = 0, pss_sum = 0, own = 0, n = s->n_fluid + s->n_wall;
  for (int r = 0; r < e->n_ranks; r++) {
    const double *m = s->per_rank + PER_RANK * r;
    rss_max = rss_max > m[RANK_PEAK] ? rss_max : m[RANK_PEAK];
    rss_sum += m[RANK_PEAK];
    pss_sum += m[RANK_PSS];
    own += m[RANK_PROJECT];
  }
  printf("summary: %ld steps in %.2f s on %d ranks; %.0f fluid + %.0f wall particles\n", s->steps,
         s->loop_seconds, e->n_ranks, s->n_fluid, s->n_wall);
  printf("  throughput: %.4g fluid particle-steps/s in total, %.4g per rank\n", rate, rate / e->n_ranks);
  for (int k = 0; k < e->n_ops; k++) printf("  %6.2f s  %s\n", s->op_max[k], e->ops[k].name);
  printf("  %6.2f s  migration, sort, halo rebuild (%ld re-partitions)\n", s->migrate_max, e->n_repartitions);
  if (e->solids.n)
    printf("  %6.2f s  elastic solids: loads, %ld sub-steps (%.1f per fluid (sub-)step), particle copies\n",
           s->solids_max, e->solids.substeps_total,
           (double)e->solids.substeps_total / (double)(e->solids.advances ? e->solids.advances : 1));
  printf("  %6.2f s  output\n", e->t_output);
  printf("  peak memory: %.1f MB on the largest rank, %.0f bytes per particle (all ranks)\n",
         rss_max / 1e6, rss_sum / n);
  if (pss_sum > 0)
    printf("  memory at the end: %.0f bytes per particle (all ranks, shared pages counted once)\n",
           pss_sum / n);
  printf("  project arrays: %.0f bytes per particle (all ranks):", own / n);
  for (int k = 0; k < N_MEM; k++) printf(" %s %.0f", mem_names[k], s->mem_sum[k] / n);
  printf("\n");
  fflush(stdout);
}

void engine_report(struct engine *e, long steps, double loop_seconds) {
  struct run_summary s;
  long guard_hits = 0;
  summarise(e, steps, loop_seconds, &s);
  MPI_Reduce(&e->wall_guard_hits, &guard_hits, 1, MPI_LONG, MPI_SUM, 0, e->comm);
  if (e->rank == 0) {
    print_summary(e, &s);
    if (guard_hits)
      printf("  wall guard: %ld normal-velocity corrections of particles closing on a wall "
             "(stats.csv column wall_guard_hits)\n", guard_hits);
    if (engine_energy_on(e))
      printf("  energy check: largest growth of the mechanical energy %.3g M U_max^2/2 (stops "
             "above time.energy_growth %g)\n", e->energy_growth_peak, e->c->energy_growth);
    write_timings(e, &s);
  }
  free(s.per_rank);
}
