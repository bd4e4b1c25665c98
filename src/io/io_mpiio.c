/* io_mpiio.c — the MPI-IO write calls of parallel HDF5, intercepted through MPI's profiling
 * interface: this file defines MPI_File_write_at, MPI_File_write_at_all, MPI_File_set_size and
 * MPI_File_sync, which call the MPI library's PMPI_ versions; the executable's definitions take
 * precedence over the library's for HDF5's calls, as for any MPI profiling tool.
 *
 * Why: when a write fails on some ranks only (with collective buffering, only the aggregator
 * ranks write), HDF5 returns from the failed collective on those ranks and they enter a
 * different collective call than the others: the job hangs for ever in H5Fclose, and a failed
 * H5Fclose leaves a half-closed file that crashes MPI_Finalize. While a file is watched, the
 * first failure of each rank is recorded here and HDF5 is told the write succeeded, so every
 * rank makes the same calls up to and through H5Fclose; then the ranks agree on the recorded
 * failures (io_hdf5.c) and the file is discarded. */
#include "io/io_mpiio.h"
#include "base/mem.h"
#include "io/outdir.h"

#include <errno.h>
#include <mpi.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The watched file and this rank's failures in it. */
static struct {
  int on;              /* between mpiio_watch_begin and mpiio_watch_end */
  int inject;          /* the test hook MPSPH_TEST_NO_SPACE applies to this file on this rank */
  char *path;          /* the final file's path (from mem.h) */
  MPI_Comm comm;       /* the ranks that write the file */
  int failed;          /* a watched call failed */
  int sys_errno;       /* the system's reason of the first failure that gave one, or 0 */
  int mpi_code;        /* else the MPI error code of the first failure (MPI_SUCCESS: short write) */
} watch;

/* The errno an MPI-IO error class stands for, or 0 when it names none. */
static int class_errno(int code) {
  int cls;
  MPI_Error_class(code, &cls);
  return cls == MPI_ERR_NO_SPACE ? ENOSPC : cls == MPI_ERR_QUOTA ? EDQUOT
       : cls == MPI_ERR_READ_ONLY ? EROFS : cls == MPI_ERR_ACCESS ? EACCES : 0;
}

/* Record a failed call: its MPI error code (MPI_SUCCESS for a short write) and the errno its
 * system calls left. The reason kept is the errno of the code's error class, else that errno,
 * from the first failure that gives one: a short write (ENOSPC met half-way) often leaves none,
 * but the next write meets ENOSPC at once. */
static void record(int code, int sys_errno) {
  int e = watch.inject ? ENOSPC : code != MPI_SUCCESS ? class_errno(code) : 0;
  if (!e) e = sys_errno;
  if (!watch.failed) watch.mpi_code = code;
  if (!watch.sys_errno) watch.sys_errno = e;
  watch.failed = 1;
}

/* Bytes in `count` items of `type`. */
static MPI_Count bytes_of(MPI_Datatype type, int count) {
  MPI_Count size = 0;
  MPI_Type_size_x(type, &size);
  return size * count;
}

/* 1 if a call that should have written `count` items of `type` wrote fewer (status says). */
static int short_write(const MPI_Status *status, MPI_Datatype type, int count) {
  MPI_Count written = 0;
  if (status == MPI_STATUS_IGNORE || MPI_Get_elements_x(status, MPI_BYTE, &written) != MPI_SUCCESS)
    return 0;
  return written < bytes_of(type, count);
}

/* The result of a watched call: code from the library (errno as its system calls left it), the
 * status of a write of count items of type (status NULL for calls without). Records a failure
 * and reports success, with the status of a complete write. Outside a watch: code. */
static int outcome(int code, int sys_errno, MPI_Status *status, MPI_Datatype type, int count) {
  if (!watch.on) return code;
  int short_count = code == MPI_SUCCESS && status && short_write(status, type, count);
  if (code != MPI_SUCCESS || short_count || watch.inject) record(code, sys_errno);
  if (status && status != MPI_STATUS_IGNORE && (code != MPI_SUCCESS || short_count))
    MPI_Status_set_elements_x(status, MPI_BYTE, bytes_of(type, count));
  return MPI_SUCCESS;
}

/* The intercepted calls: each calls the library's (PMPI_) version and passes its result
 * through `outcome`. An independent write (HDF5 writes some metadata from one rank): */
int MPI_File_write_at(MPI_File fh, MPI_Offset offset, const void *buf, int count,
                      MPI_Datatype type, MPI_Status *status) {
  errno = 0;
  int code = PMPI_File_write_at(fh, offset, buf, count, type, status);
  return outcome(code, errno, status, type, count);
}

/* A collective write (the datasets; the metadata with collective metadata writes). */
int MPI_File_write_at_all(MPI_File fh, MPI_Offset offset, const void *buf, int count,
                          MPI_Datatype type, MPI_Status *status) {
  errno = 0;
  int code = PMPI_File_write_at_all(fh, offset, buf, count, type, status);
  return outcome(code, errno, status, type, count);
}

/* Collective: the file extended or cut to size (HDF5: at create and at close). */
int MPI_File_set_size(MPI_File fh, MPI_Offset size) {
  errno = 0;
  int code = PMPI_File_set_size(fh, size);
  return outcome(code, errno, NULL, MPI_BYTE, 0);
}

/* Collective: the file's data on the storage device (HDF5: H5Fflush). Within a watch, only
 * when no rank has recorded a failure: Open MPI's ompio returns from MPI_File_sync at once,
 * without its barrier, on a rank whose failed write left a request pending, and the other
 * ranks then wait in that barrier for ever. The file of a failed write is discarded anyway. */
int MPI_File_sync(MPI_File fh) {
  int any = watch.failed;
  if (watch.on) MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, watch.comm);
  if (any) return MPI_SUCCESS;
  errno = 0;
  int code = PMPI_File_sync(fh);
  return outcome(code, errno, NULL, MPI_BYTE, 0);
}

/* Whether the test hook MPSPH_TEST_NO_SPACE names path, on the last rank. */
static int hook_applies(const char *path) {
  const char *name = getenv("MPSPH_TEST_NO_SPACE");
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return name && name[0] && strstr(path, name) && rank == size - 1;
}

void mpiio_watch_begin(const char *path, MPI_Comm comm) {
  memset(&watch, 0, sizeof watch);
  watch.path = mem_strndup(path, SIZE_MAX, "the path of the file being written");
  watch.comm = comm;
  watch.inject = hook_applies(path);
  watch.on = 1;
}

/* The reason of the recorded failure: the system's, else MPI's text; a short write without
 * either on a file system with no space left is ENOSPC. */
static void failure_reason(char *reason, int len) {
  int e = watch.sys_errno;
  if (!e && watch.mpi_code == MPI_SUCCESS && outdir_free_bytes(watch.path) == 0) e = ENOSPC;
  if (e) snprintf(reason, (size_t)len, "%s", strerror(e));
  else if (watch.mpi_code != MPI_SUCCESS) MPI_Error_string(watch.mpi_code, reason, &len);
  else snprintf(reason, (size_t)len, "fewer bytes written than asked");
}

int mpiio_watch_failed(char *err, size_t len) {
  char reason[MPI_MAX_ERROR_STRING];
  if (!watch.on || !watch.failed) return 0;
  failure_reason(reason, (int)sizeof reason);
  if (err && len) snprintf(err, len, "cannot write %s: %s", watch.path, reason);
  return 3;
}

void mpiio_watch_end(void) {
  watch.on = 0;
  free(watch.path);
  watch.path = NULL;
}
