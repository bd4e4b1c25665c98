/* engine_report.c — the end-of-run summary: throughput, time per operation, memory. */
#include <sys/resource.h>
#include "engine.h"

/* Peak resident memory of this process [bytes]. */
static double peak_rss_bytes(void) {
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return (double)ru.ru_maxrss * 1024.0;
}

void engine_global_counts(const struct engine *e, double *n_fluid, double *n_wall) {
  double local[2] = {0, 0}, total[2];
  for (long i = 0; i < e->p.n_owned; i++) local[e->p.phase[i] == PHASE_WALL]++;
  MPI_Allreduce(local, total, 2, MPI_DOUBLE, MPI_SUM, e->comm);
  *n_fluid = total[0];
  *n_wall = total[1];
}

static double max_over_ranks(const struct engine *e, double x) {
  MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, e->comm);
  return x;
}

void engine_report(struct engine *e, long steps, double loop_seconds) {
  double n_fluid, n_wall, rss = peak_rss_bytes(), rss_sum, rss_max = max_over_ranks(e, rss);
  engine_global_counts(e, &n_fluid, &n_wall);
  MPI_Allreduce(&rss, &rss_sum, 1, MPI_DOUBLE, MPI_SUM, e->comm);
  double op_time[ENGINE_MAX_OPS], migrate = max_over_ranks(e, e->t_migrate);
  for (int k = 0; k < e->n_ops; k++) op_time[k] = max_over_ranks(e, e->ops[k].seconds);
  if (e->rank) return;
  double rate = steps > 0 && loop_seconds > 0 ? n_fluid * (double)steps / loop_seconds : 0;
  printf("summary: %ld steps in %.2f s on %d ranks; %.0f fluid + %.0f wall particles\n", steps,
         loop_seconds, e->n_ranks, n_fluid, n_wall);
  printf("  throughput: %.4g fluid particle-steps/s in total, %.4g per rank\n", rate, rate / e->n_ranks);
  for (int k = 0; k < e->n_ops; k++)
    printf("  %6.2f s  %s\n", op_time[k], e->ops[k].name);
  printf("  %6.2f s  migration, sort, halo rebuild (%ld re-partitions)\n", migrate, e->n_repartitions);
  printf("  %6.2f s  output\n", e->t_output);
  printf("  peak memory: %.1f MB on the largest rank, %.0f bytes per particle (all ranks)\n",
         rss_max / 1e6, rss_sum / (n_fluid + n_wall));
  fflush(stdout);
}
