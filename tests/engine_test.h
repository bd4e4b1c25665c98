/* engine_test.h — set-up and tear-down shared by the C tests that run an engine on MPI ranks:
 * a scratch folder made on rank 0 and known to all, and the end of such a test (free the
 * engine, remove the folder, agree on the verdict, finalise MPI). Include after check.h. */
#ifndef MPSPH_TEST_ENGINE_TEST_H
#define MPSPH_TEST_ENGINE_TEST_H

#include <mpi.h>
#include <stdlib.h>
#include <unistd.h>
#include "engine.h"

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
