/* engine_test.h — set-up and tear-down shared by the C tests that run an engine on MPI ranks:
 * a scratch folder made on rank 0 and known to all, an engine started from a case text, a
 * rank-independent pseudo-random field, and the end of such a test (free the engine, remove the
 * folder, agree on the verdict, finalise MPI). Include after check.h. */
#ifndef MPSPH_TEST_ENGINE_TEST_H
#define MPSPH_TEST_ENGINE_TEST_H

#include <mpi.h>
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>
#include "case/case_load.h"
#include "engine/engine.h"

/** Rank 0 creates the folder from the mkdtemp template dir (len bytes) and every rank receives
 *  its name. Returns 0, or 1 if it could not be made. Collective. */
static inline int engine_test_scratch(char *dir, int len) {
  int rank, ok = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) ok = mkdtemp(dir) != NULL;
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Bcast(dir, len, MPI_CHAR, 0, MPI_COMM_WORLD);
  return !ok;
}

/** Rank 0 writes case_text to dir/case.yaml; every rank loads it into *c and starts engine e
 *  with its output in dir/out. Returns 0, or 1 after a failed check. Collective. */
static inline int engine_test_start(const char *dir, const char *case_text, struct case_def *c,
                                    struct engine *e) {
  char path[300], out[300], err[512];
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  snprintf(path, sizeof path, "%s/case.yaml", dir);
  snprintf(out, sizeof out, "%s/out", dir);
  if (rank == 0) {
    FILE *f = fopen(path, "w");
    fputs(case_text, f);
    fclose(f);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  CHECK(case_load(path, 0, NULL, c, err, sizeof err) == 0, "case: %s", err);
  if (check_failures) return 1;
  CHECK(engine_init(e, c, out, NULL, MPI_COMM_WORLD) == 0, "engine_init");
  return check_failures != 0;
}

/** engine_test_scratch, then engine_test_start in that folder: returns 0, or 1 after a failed
 *  check (a folder that could not be made counts as one). Collective. */
static inline int engine_test_open(char *dir, int len, const char *case_text, struct case_def *c,
                                   struct engine *e) {
  int no_folder = engine_test_scratch(dir, len);
  CHECK(!no_folder, "scratch folder %s", dir);
  return no_folder || engine_test_start(dir, case_text, c, e);
}

/** Rebuild engine e (migration, sort, halo, cells; the state checks) for the state the test set
 *  by hand, which is the energy check's reference: a field set by hand is not a step of a run.
 *  Collective. */
static inline void engine_test_rebuild(struct engine *e) {
  engine_energy_reference(e);
  CHECK(engine_rebuild(e) == 0, "rebuild");
}

/** engine_test_rebuild, then evaluate the right-hand sides of the current state at RK stage 0.
 *  Collective. */
static inline void engine_test_evaluate(struct engine *e) {
  engine_test_rebuild(e);
  e->stage = 0;
  engine_evaluate(e, 0);
}

/** A deterministic pseudo-random number in [-0.5, 0.5) from a particle id and a salt, so that
 *  a field made from it is the same on any number of ranks. */
static inline double engine_test_noise(int64_t id, int salt) {
  uint64_t z = (uint64_t)id * 0x9E3779B97F4A7C15ull + (uint64_t)salt * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) / 9007199254740992.0 - 0.5;
}

/** Close and free engine e, remove the scratch folder dir, print the summary line of test name
 *  on rank 0 and finalise MPI. Returns the exit status for main(): non-zero on every rank if a
 *  check failed on any. Collective. */
static inline int engine_test_finish(struct engine *e, const char *dir, const char *name) {
  engine_close_output(e);
  engine_free(e);
  MPI_Barrier(MPI_COMM_WORLD);
  int rank, failed = check_failures, any;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd)) printf("could not remove %s\n", dir);
  }
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  int status = rank == 0 ? check_report(name) : 0;
  MPI_Finalize();
  return any ? 1 : status;
}

#endif
