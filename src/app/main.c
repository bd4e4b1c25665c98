/* main.c — command line: mpsph run | check | keys | --help | --version. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case/case_load.h"
#include "engine/engine.h"
#include "engine/schemes.h"
#include "base/mem.h"
#include "app/preflight.h"
#include "engine/signal_stop.h"
#include "io/outdir.h"

static const char *usage =
    "usage:\n"
    "  mpirun -n N mpsph run CASE.yaml [-o OUTDIR] [--set key.path=value ...] [--restart [FILE]]\n"
    "  mpsph check CASE.yaml [--set key.path=value ...] [--ranks N [--ranks-per-node K]]\n"
    "  mpsph keys\n"
    "  mpsph --help | --version\n"
    "\n"
    "run    runs the case; output goes to OUTDIR (default runs/<case name>)\n"
    "check  validates the case, prints the resolved case, the particle counts and the memory per\n"
    "       rank of a run on N ranks (default 1) with K of them on each node (default: N, at most\n"
    "       this machine's processors), without generating the particles\n"
    "keys   prints the reference of the case keys (a markdown table)\n"
    "--set  overrides any key of the case file, e.g. --set resolution.dx=0.005 --set time.end=0.5\n"
    "--restart  continues from FILE (default OUTDIR/checkpoint.h5), on any number of ranks\n"
    "SIGTERM, SIGINT or SIGUSR1 stop a run cleanly: it writes OUTDIR/checkpoint.h5 and exits 0\n"
    "exit status: 0 success, 1 bad input, 2 unstable run, 3 I/O failure\n";

struct args {
  const char *command, *case_path, *outdir;
  int restart;                /* --restart given */
  const char *restart_path;   /* its FILE, or NULL for OUTDIR/checkpoint.h5 */
  int n_sets;
  char **sets;                /* the --set values, room for every argument */
  long ranks;                 /* check --ranks N, else 0 */
  long ranks_per_node;        /* check --ranks-per-node K, else 0 */
};

#define MAX_RANKS 100000000L  /* check --ranks: the largest rank count it takes */

/* Option `name` (--ranks, --ranks-per-node) N: a whole number in [1, MAX_RANKS], once, into
 * *count. Returns 0, or 1 with a message in err. */
static int set_count(const char *name, long *count, const char *value, char *err, size_t len) {
  char *end;
  long n = strtol(value, &end, 10);
  if (*count) return snprintf(err, len, "%s: given twice, expected it once", name), 1;
  if (!*value || *end || n < 1 || n > MAX_RANKS)
    return snprintf(err, len, "%s: got '%s', expected a whole number of ranks from 1 to %ld", name,
                    value, MAX_RANKS), 1;
  *count = n;
  return 0;
}

/* The argument after option argv[k] (-o, --set), or NULL with a message in err when there is none. */
static const char *option_value(int argc, char **argv, int k, char *err, size_t len) {
  if (k + 1 < argc) return argv[k + 1];
  snprintf(err, len, "%s: needs a value after it, none given\n%s", argv[k], usage);
  return NULL;
}

/* -o DIR: one, not empty. Returns 0, or 1 with a message in err. */
static int set_outdir(struct args *a, const char *dir, char *err, size_t len) {
  if (!dir[0]) return snprintf(err, len, "-o: got an empty folder name, expected a path (-o . for the current folder)"), 1;
  if (a->outdir)
    return snprintf(err, len, "-o: given twice ('%s' and '%s'), expected one output folder", a->outdir, dir), 1;
  a->outdir = dir;
  return 0;
}

/* Parse argv. Returns 0, or 1 with a message in err. a->sets is allocated (free it). */
static int parse_args(int argc, char **argv, struct args *a, char *err, size_t len) {
  memset(a, 0, sizeof(*a));
  a->sets = mem_calloc((size_t)argc, sizeof *a->sets, "the --set list");
  if (argc < 2) return snprintf(err, len, "no command given\n%s", usage), 1;
  a->command = argv[1];
  for (int k = 2; k < argc; k++) {
    if (!strcmp(argv[k], "-o") || !strcmp(argv[k], "--set") || !strcmp(argv[k], "--ranks") ||
        !strcmp(argv[k], "--ranks-per-node")) {
      const char *value = option_value(argc, argv, k++, err, len);
      if (!value) return 1;
      if (!strcmp(argv[k - 1], "--set")) a->sets[a->n_sets++] = argv[k];
      else if (!strcmp(argv[k - 1], "--ranks")) {
        if (set_count("--ranks", &a->ranks, value, err, len)) return 1;
      } else if (!strcmp(argv[k - 1], "--ranks-per-node")) {
        if (set_count("--ranks-per-node", &a->ranks_per_node, value, err, len)) return 1;
      } else if (set_outdir(a, value, err, len)) return 1;
    } else if (!strcmp(argv[k], "--restart")) {
      if (a->restart) return snprintf(err, len, "--restart: given twice, expected it once"), 1;
      a->restart = 1;   /* FILE follows when the case file is already named */
      if (a->case_path && k + 1 < argc && argv[k + 1][0] != '-') a->restart_path = argv[++k];
      if (a->restart_path && !a->restart_path[0])
        return snprintf(err, len, "--restart: got an empty file name, expected a checkpoint file"), 1;
    }
    else if (argv[k][0] != '-' && !a->case_path) a->case_path = argv[k];
    else return snprintf(err, len, "unexpected argument '%s'\n%s", argv[k], usage), 1;
  }
  if (strcmp(a->command, "run") && strcmp(a->command, "check"))
    return snprintf(err, len, "unknown command '%s'\n%s", a->command, usage), 1;
  if (!a->case_path) return snprintf(err, len, "%s needs a case file\n%s", a->command, usage), 1;
  if ((a->restart || a->outdir) && strcmp(a->command, "run"))
    return snprintf(err, len, "%s: only with run\n%s", a->restart ? "--restart" : "-o", usage), 1;
  if ((a->ranks || a->ranks_per_node) && strcmp(a->command, "check"))
    return snprintf(err, len, "%s: only with check (run takes its ranks from mpirun)\n%s",
                    a->ranks ? "--ranks" : "--ranks-per-node", usage), 1;
  if (a->ranks_per_node > (a->ranks ? a->ranks : 1))
    return snprintf(err, len, "--ranks-per-node: got %ld, expected at most the %ld rank%s of --ranks",
                    a->ranks_per_node, a->ranks ? a->ranks : 1, a->ranks > 1 ? "s" : ""), 1;
  return 0;
}

/* What this build and the chosen scheme can run; anything else is refused with a reason. */
static int supported(const struct case_def *c, char *err, size_t len) {
  const char *src = c->source_file;
#ifdef MPSPH_SINGLE_PHASE
  if (c->n_phases > 1)
    return snprintf(err, len, "%s: phases: this build (SINGLE_PHASE=1) runs single-phase cases only", src), 1;
#endif
  if (c->scheme != SCHEME_SAME_PHASE_CONTINUITY && c->spc_model != SPC_PRESENT)
    return snprintf(err, len, "%s: physics.spc_model: conventional only with scheme same-phase-continuity", src), 1;
  if (c->dissipation_form != DISSIPATION_CONSISTENT && c->scheme != SCHEME_GENERALIZED_DISSIPATION)
    return snprintf(err, len, "%s: physics.dissipation_form: only scheme generalized-dissipation has one", src), 1;
  const struct scheme *s = scheme_of(c->scheme);
  return s->refuse ? s->refuse(c, err, len) : 0;
}

/* Set up and run case c into outdir (from the checkpoint restart unless NULL). The stop handler is
 * installed here, after the case is loaded and checked: before, SIGINT and SIGTERM end the process
 * (nothing is written yet); from here they end the run with a checkpoint. */
static int start_run(const struct case_def *c, const char *outdir, const char *restart) {
  signal_stop_install();
  struct engine e;
  int status = engine_init(&e, c, outdir, restart, MPI_COMM_WORLD);
  if (!status) status = engine_run(&e);
  engine_free(&e);
  return status;
}

/* The run command: the checks of preflight_run, then the run into -o (default runs/<name>). */
static int run_case(const struct case_def *c, const struct args *a) {
  char *defdir = outdir_path("runs", "%s", c->name), *checkpoint = NULL;
  const char *outdir = a->outdir ? a->outdir : defdir;
  int status = preflight_run(c, outdir, a->restart_path, MPI_COMM_WORLD);
  if (!status && a->restart && !a->restart_path) checkpoint = outdir_path(outdir, OUTDIR_CHECKPOINT_NAME);
  if (!status) status = start_run(c, outdir, a->restart_path ? a->restart_path : checkpoint);
  free(checkpoint);
  free(defdir);
  return status;
}

int main(int argc, char **argv) {
  if (argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) return printf("%s", usage), 0;
  if (argc == 2 && !strcmp(argv[1], "--version")) return printf("mpsph %s\n", MPSPH_VERSION), 0;
  if (argc == 2 && !strcmp(argv[1], "keys")) return case_keys_markdown(stdout), 0;
  mem_setup();
  MPI_Init(&argc, &argv);
  setvbuf(stdout, NULL, _IOLBF, 0);   /* progress shows up in batch logs as it is printed */
  int rank, status;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  struct args a;
  static struct case_def c;
  char err[2048];
  status = parse_args(argc, argv, &a, err, sizeof(err));
  if (!status) status = case_load(a.case_path, a.n_sets, a.sets, &c, err, sizeof(err));
  if (!status) status = supported(&c, err, sizeof(err));
  if (status && rank == 0) fprintf(stderr, "mpsph: %s\n", err);
  if (!status) status = !strcmp(a.command, "check") ? (rank == 0 ? preflight_check(&c, a.ranks ? (int)a.ranks : 1, (int)a.ranks_per_node) : 0) : run_case(&c, &a);
  free(a.sets);
  MPI_Finalize();
  return status;
}
