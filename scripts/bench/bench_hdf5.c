/* bench_hdf5.c — snapshot write bandwidth of the project's collective HDF5 writer
 * (hdf5_write_snapshot) against a raw sequential write() of the same bytes to the same folder.
 * Both are followed by fsync of the file and a barrier, and both are timed from a barrier to
 * the end of the fsync on every rank. Each rank writes n/ranks particles (2D snapshot layout:
 * position, velocity, density, pressure, mass, phase, id).
 * Usage: mpirun -n R bench_hdf5 DIR N_PARTICLES REPEATS
 * Prints "hdf5 <bytes> <seconds>" and "raw <bytes> <seconds>" per repeat (rank 0). */
#include <fcntl.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "io/io_hdf5.h"

/* Bytes of one particle in the 2D snapshot: x, v (2 each), rho, p, m as double, phase int32, id int64. */
#define SNAP_BYTES_2D (7 * 8 + 4 + 8)

/* n owned 2D particles with ids starting at first. */
static void fill(struct parts *p, long n, long first) {
  parts_init(p, 2, n, 0);
  p->n_owned = n;
  for (long i = 0; i < n; i++) {
    for (int d = 0; d < 2; d++) p->x[d][i] = 1e-3 * (double)(first + i) + d, p->v[d][i] = 0.5 * d;
    p->rho[i] = 1000.0 + 1e-6 * (double)i, p->p[i] = 10.0 * (double)i, p->m[i] = 0.1;
    p->phase[i] = (int)(i % 2), p->id[i] = first + i;
  }
}

/* fsync the file at path (every rank opens it; 0 on success). */
static int sync_path(const char *path) {
  int fd = open(path, O_RDONLY);
  if (fd < 0) return -1;
  int st = fsync(fd);
  close(fd);
  return st;
}

/* Seconds for one collective snapshot write of p to dir/bench.h5, fsync included. */
static double time_hdf5(const char *dir, const struct parts *p, MPI_Comm comm) {
  char path[4096], err[512];
  snprintf(path, sizeof path, "%s/bench.h5", dir);
  struct snapshot_info info = {.time = 0, .step = 0, .dimension = 2, .case_yaml = "bench", .code_version = "bench"};
  MPI_Barrier(comm);
  double t0 = MPI_Wtime();
  if (hdf5_write_snapshot(path, &info, p, comm, err, sizeof err)) {
    fprintf(stderr, "bench_hdf5: %s\n", err);
    MPI_Abort(comm, 3);
  }
  sync_path(path);
  MPI_Barrier(comm);
  double t = MPI_Wtime() - t0;
  unlink(path);
  return t;
}

/* Seconds for every rank to pwrite its share of `bytes` into dir/bench.raw at its offset, fsync
 * included. */
static double time_raw(const char *dir, long bytes, long offset, MPI_Comm comm) {
  char path[4096];
  snprintf(path, sizeof path, "%s/bench.raw", dir);
  char *buf = malloc((size_t)bytes + 1);
  memset(buf, 7, (size_t)bytes + 1);
  MPI_Barrier(comm);
  double t0 = MPI_Wtime();
  int fd = open(path, O_WRONLY | O_CREAT, 0644);
  long done = 0;
  while (fd >= 0 && done < bytes) {
    ssize_t w = pwrite(fd, buf + done, (size_t)(bytes - done), offset + done);
    if (w <= 0) break;
    done += w;
  }
  if (fd >= 0) fsync(fd), close(fd);
  MPI_Barrier(comm);
  double t = MPI_Wtime() - t0;
  free(buf);
  MPI_Barrier(comm);
  if (offset == 0) unlink(path);
  return t;
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc != 4) {
    if (!rank) fprintf(stderr, "usage: bench_hdf5 DIR N_PARTICLES REPEATS\n");
    MPI_Finalize();
    return 1;
  }
  long n_total = atol(argv[2]), n = n_total / size + (rank < n_total % size), first = 0;
  MPI_Exscan(&n, &first, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (!rank) first = 0;
  struct parts p;
  fill(&p, n, first);
  for (int r = 0; r < atoi(argv[3]); r++) {
    double th = time_hdf5(argv[1], &p, MPI_COMM_WORLD);
    double tr = time_raw(argv[1], n * SNAP_BYTES_2D, first * SNAP_BYTES_2D, MPI_COMM_WORLD);
    if (!rank) printf("hdf5 %ld %.6f\nraw %ld %.6f\n", n_total * SNAP_BYTES_2D, th, n_total * SNAP_BYTES_2D, tr);
  }
  parts_free(&p);
  MPI_Finalize();
  return 0;
}
