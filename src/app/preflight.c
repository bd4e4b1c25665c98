/* preflight.c — the checks of `run` before any computation (output folder, memory) and the
 * `check` command. The particles are counted only when an upper bound on their number (the
 * lattice nodes that particle generation visits) does not settle whether they fit, and never
 * for a case far beyond the memory available, so that an absurd case is refused at once. */
#include "app/preflight.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "case/case_load.h"
#include "case/init.h"
#include "physics/kernel.h"
#include "app/mem_estimate.h"
#include "io/outdir.h"

#define COUNT_GUARD 10.0   /* a bound needing this many times the memory available: not counted */
#define COUNT_MAX_NODES 2e9   /* check: a bound on the nodes to visit above which it does not count
                                 (about 75 ns a node on one core: 2.5 minutes) */
#define ERR_LEN 1024
/* Open MPI's MPI-IO (sharedfp component lockedfile) writes "<file>.locktest.<rank>" into a buffer
 * of this many bytes at every MPI_File_open, with sprintf: a longer file path aborts the process. */
#define MPIIO_NAME_BUFFER 256
#define QUOTED(x) #x
#define DIGITS_OF(x) QUOTED(x)   /* the value of macro x as a string literal */
#define MPIIO_SUFFIX ".locktest."
#define LONGEST_OUTPUT_FILE "unstable_last_good.h5.tmp"   /* the longest name a run writes */

/* The particle count of a case for the memory estimate: exact, or the bound. */
struct sizing {
  double support;            /* kernel support [m] */
  double n;                  /* particles (fluid + wall) */
  double n_kind[KIND_COUNT]; /* of each kind */
  int counted;               /* n, n_kind and counts are exact; else bounds */
  struct init_counts counts;
};

/* Size case c for n_ranks ranks, per_node of them on each node, with `available` bytes each. The particles are counted when the
 * bound needs at most COUNT_GUARD times the memory available, and either always is set or the
 * bound does not fit. Returns 0, or 1 with particle generation's message. */
static int size_case(const struct case_def *c, int n_ranks, int per_node, double available, int always,
                     struct sizing *s, char *err, size_t len) {
  struct kernel k;
  kernel_init(&k, c->kernel, c->dimension, case_h_max(c));   /* the coarsest phase's */
  s->support = k.support;
  s->n = init_visit_count(c, k.support);
  s->n_kind[KIND_SOLID] = 0;   /* solids are small and not estimated (mem_estimate.c) */
  s->n_kind[KIND_WALL] = init_wall_visit_count(c, k.support);
  s->n_kind[KIND_FLUID] = s->n - s->n_kind[KIND_WALL];
  s->counted = 0;
  double bound_bytes = mem_estimate_rank(c, k.support, s->n_kind, n_ranks, per_node).total;
  if (bound_bytes > COUNT_GUARD * available || (bound_bytes <= available && !always)) return 0;
  if (always && s->n > COUNT_MAX_NODES) return 0;
  if (init_particles(c, k.support, NULL, &s->counts, err, len)) return 1;
  s->n_kind[KIND_FLUID] = (double)s->counts.n_fluid;
  s->n_kind[KIND_WALL] = (double)s->counts.n_wall;
  s->n = s->n_kind[KIND_FLUID] + s->n_kind[KIND_WALL];
  s->counted = 1;
  return 0;
}

/* "1234 particles (1000 fluid, 234 wall)" or "up to 1.2e+10 particles (...)". */
static void describe_count(const struct sizing *s, char *buf, size_t len) {
  if (s->counted)
    snprintf(buf, len, "%ld particles (%ld fluid, %ld wall)", s->counts.n_fluid + s->counts.n_wall,
             s->counts.n_fluid, s->counts.n_wall);
  else
    snprintf(buf, len, "up to %.3g particles (the lattice nodes of the fluid regions and wall "
             "layers; not counted)", s->n);
}

/* The memory of rank 0's node per rank on it, the minimum over all nodes [bytes]; -1 if unknown. */
static double available_per_rank(MPI_Comm comm, int *ranks_on_node) {
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, ranks_on_node);
  MPI_Comm_free(&node);
  double node_bytes = mem_node_available();
  double mine = node_bytes < 0 ? -1 : node_bytes / *ranks_on_node, least;
  MPI_Allreduce(&mine, &least, 1, MPI_DOUBLE, MPI_MIN, comm);
  return least;
}

static int bad_memory_variable(char *err, size_t len) {
  snprintf(err, len, "MPSPH_MEMORY_AVAILABLE: got '%s', expected a number of bytes > 0",
           getenv("MPSPH_MEMORY_AVAILABLE"));
  return 1;
}

/* Rank 0: 1 with the numbers in err if case c needs more than `available` bytes per rank. */
static int memory_verdict(const struct case_def *c, int n_ranks, double available, int per_node,
                          char *err, size_t len) {
  struct sizing s;
  char what[160];
  if (available < 0) return bad_memory_variable(err, len);
  if (size_case(c, n_ranks, per_node, available, 0, &s, err, len)) return 1;
  struct mem_estimate m = mem_estimate_rank(c, s.support, s.n_kind, n_ranks, per_node);
  if (m.total <= available) return 0;
  describe_count(&s, what, sizeof what);
  snprintf(err, len, "not enough memory: %s need about %.3g GB per rank on %d rank%s (%.3g GB of "
           "particles, %.0f MB per process, %.3g GB of cells), but %.3g GB are available per rank "
           "(the node's available memory over its %d rank%s): use more nodes or a coarser "
           "resolution.dx", what, m.total / 1e9, n_ranks, n_ranks == 1 ? "" : "s",
           m.particle_bytes / 1e9, m.process / 1e6, m.cells / 1e9, available / 1e9, per_node,
           per_node == 1 ? "" : "s");
  return 1;
}

/* Status of rank 0 to all ranks; its message printed by rank 0. */
static int verdict(int status, const char *err, int rank, MPI_Comm comm) {
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  if (status && rank == 0) fprintf(stderr, "mpsph: %s\n", err);
  return status;
}

/* The longest file path MPI-IO takes on n_ranks ranks (the rank's digits end the name). */
static int path_limit(int n_ranks) {
  int digits = 1;
  for (int r = n_ranks - 1; r >= 10; r /= 10) digits++;
  return MPIIO_NAME_BUFFER - 1 - (int)strlen(MPIIO_SUFFIX) - digits;
}

/* 1 with a message in err when the output folder's files, or the checkpoint to restart from
 * (NULL: none named), have paths longer than MPI-IO takes on n_ranks ranks, or that checkpoint
 * is not a regular file (MPI-IO would wait forever on a FIFO). */
static int paths_unusable(const char *outdir, const char *restart, int n_ranks, char *err, size_t len) {
  int limit = path_limit(n_ranks);
  size_t folder = strlen(outdir), longest = folder + 1 + strlen(LONGEST_OUTPUT_FILE);
  const char *why = "Open MPI's MPI-IO writes '<file>" MPIIO_SUFFIX "<rank>' into a buffer of "
                    DIGITS_OF(MPIIO_NAME_BUFFER) " bytes";
  if (longest > (size_t)limit)
    return snprintf(err, len, "-o: the output folder has %zu characters, at most %zu allowed on %d rank%s: "
                    "the path of its file %s would have %zu, above the %d of a file's path (%s); "
                    "use a shorter folder name (a relative path or a symbolic link)", folder,
                    (size_t)limit - 1 - strlen(LONGEST_OUTPUT_FILE), n_ranks, n_ranks == 1 ? "" : "s",
                    LONGEST_OUTPUT_FILE, longest, limit, why), 1;
  const char *kind = restart ? case_file_not_regular(restart) : NULL;
  if (kind)
    return snprintf(err, len, "--restart: cannot read '%s': it is %s, expected a checkpoint file",
                    restart, kind), 1;
  if (restart && strlen(restart) > (size_t)limit)
    return snprintf(err, len, "--restart: the checkpoint's path has %zu characters, at most %d allowed on "
                    "%d rank%s (%s); use a shorter path (a relative path or a symbolic link)",
                    strlen(restart), limit, n_ranks, n_ranks == 1 ? "" : "s", why), 1;
  return 0;
}

int preflight_run(const struct case_def *c, const char *outdir, const char *restart, MPI_Comm comm) {
  int rank, n_ranks, per_node, status = 0;
  char err[ERR_LEN];
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &n_ranks);
  if (rank == 0) status = paths_unusable(outdir, restart, n_ranks, err, sizeof err);
  if (rank == 0 && !status) status = outdir_probe(outdir, err, sizeof err);
  if (verdict(status, err, rank, comm)) return 1;
  double available = available_per_rank(comm, &per_node);
  if (rank == 0) status = memory_verdict(c, n_ranks, available, per_node, err, sizeof err);
  return verdict(status, err, rank, comm);
}

/* A memory size in MB below 1 GB, else in GB. */
static const char *bytes_text(double bytes, char *buf, size_t len) {
  if (bytes < 1e9) snprintf(buf, len, "%.1f MB", bytes / 1e6);
  else snprintf(buf, len, "%.3g GB", bytes / 1e9);
  return buf;
}

static void print_counts(const struct case_def *c, const struct sizing *s) {
  if (!s->counted) {
    printf("# particles: up to %.3g (the lattice nodes of the fluid regions and wall layers; not "
           "counted, it would take too long)", s->n);
  } else {
    printf("# particles: %ld fluid", s->counts.n_fluid);
    for (int ph = 0; ph < c->n_phases; ph++)
      printf(" (%s %ld)", c->phases[ph].name, s->counts.fluid[ph]);
    printf(", %ld wall (%d layers)", s->counts.n_wall, init_wall_layers(c, s->support));
  }
  if (case_max_dx_ratio(c) > 1)
    printf("; smoothing length %g m (%g m in the coarsest phase), its kernel support %g m\n", c->h_over_dx * c->dx,
           case_h_max(c), s->support);
  else
    printf("; smoothing length %g m, kernel support %g m\n", c->h_over_dx * c->dx, s->support);
}

static void print_memory(const struct case_def *c, const struct sizing *s, int n_ranks, int per_node,
                         double available) {
  struct mem_estimate m = mem_estimate_rank(c, s->support, s->n_kind, n_ranks, per_node);
  char need[32], parts[32], cells[32], rows[32], have[32];
  printf("# memory: about %s per rank on %d rank%s, %d per node (the rank needing the most: %.0f fluid, %.0f "
         "wall and %.0f halo particles, %s; %.0f MB per process, %s of cells, %s of start-up rows); "
         "%s available on this machine%s\n", bytes_text(m.total, need, sizeof need), n_ranks,
         n_ranks == 1 ? "" : "s", per_node, m.owned[KIND_FLUID], m.owned[KIND_WALL], m.halo,
         bytes_text(m.particle_bytes, parts, sizeof parts), m.process / 1e6,
         bytes_text(m.cells, cells, sizeof cells), bytes_text(m.startup, rows, sizeof rows),
         bytes_text(available, have, sizeof have), n_ranks == 1 && m.total > available ? ": more than it has" : "");
}

int preflight_check(const struct case_def *c, int n_ranks, int per_node) {
  struct sizing s;
  char err[ERR_LEN];
  double available = mem_node_available();
  long processors = sysconf(_SC_NPROCESSORS_ONLN);
  if (!per_node) per_node = processors > 0 && processors < n_ranks ? (int)processors : n_ranks;
  int status = available < 0 ? bad_memory_variable(err, sizeof err) : 0;
  if (!status) status = size_case(c, n_ranks, per_node, available, 1, &s, err, sizeof err);
  if (status) {
    fprintf(stderr, "mpsph: %s\n", err);
    return 1;
  }
  char *yaml = case_to_yaml(c);
  printf("%s", yaml);
  free(yaml);
  print_counts(c, &s);
  print_memory(c, &s, n_ranks, per_node, available);
  return 0;
}
