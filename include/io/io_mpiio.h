/* io_mpiio.h — the MPI-IO calls by which parallel HDF5 writes a file, watched through MPI's
 * profiling interface so that a failed write (a full disk, a quota, an I/O error) cannot make
 * the ranks diverge inside HDF5's collective calls. */
#ifndef MPSPH_IO_MPIIO_H
#define MPSPH_IO_MPIIO_H

#include <mpi.h>
#include <stddef.h>

/** Start watching this process's MPI-IO writes (MPI_File_write_at[_all], MPI_File_set_size,
 *  MPI_File_sync) into the file `path`, written by the ranks of comm. Until mpiio_watch_end, a failed or short write is recorded
 *  and reported to its caller (HDF5) as a success, so that HDF5 goes on through the same
 *  collective calls on every rank (its metadata flush and close); the caller then agrees with
 *  the other ranks on mpiio_watch_failed and discards the file. Outside a watch, calls pass
 *  through unchanged. Test hook, documented in doc/user-guide.md: with MPSPH_TEST_NO_SPACE=NAME
 *  in the environment and NAME in path, the last rank's writes fail as if the disk were full. */
void mpiio_watch_begin(const char *path, MPI_Comm comm);

/** 0 outside a watch, or if no watched write of this rank failed since mpiio_watch_begin; else
 *  3, with "cannot write <path>: <reason>" (the system's reason, e.g. "No space left on
 *  device") in err. */
int mpiio_watch_failed(char *err, size_t len);

/** Stop watching (after the file is closed). */
void mpiio_watch_end(void);

#endif
