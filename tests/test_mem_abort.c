/* test_mem_abort.c — run by tests/mem_abort.sh on 2 ranks: with an HDF5 file open on every rank
 * through MPI-IO (as during a snapshot or a restart), rank 1 fails an allocation while rank 0
 * waits in a barrier. The job must end with status 3 and mem.h's message, not hang (exit() would
 * run HDF5's exit handler, which closes the file collectively and waits for rank 0 for ever).
 * Usage: test_mem_abort DIR */
#include <hdf5.h>
#include <mpi.h>
#include <stdint.h>
#include <stdio.h>
#include "base/mem.h"

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  char path[4096];
  snprintf(path, sizeof path, "%s/open.h5", argc > 1 ? argv[1] : ".");
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(fapl, MPI_COMM_WORLD, MPI_INFO_NULL);
  hid_t file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  if (file < 0) return fprintf(stderr, "cannot create %s\n", path), 1;
  if (rank == 1) mem_alloc(SIZE_MAX / 2, "test block on rank 1");
  MPI_Barrier(MPI_COMM_WORLD);
  printf("the failed allocation did not end the job\n");
  H5Fclose(file);
  H5Pclose(fapl);
  MPI_Finalize();
  return 0;
}
