/* io_hdf5.h — collective parallel-HDF5 snapshots and checkpoints (one file per output time),
 * their reading back, and the XDMF index. */
#ifndef MPSPH_IO_HDF5_H
#define MPSPH_IO_HDF5_H

#include <mpi.h>
#include "base/parts.h"

/** A named array that every rank holds alike (an elastic solid's, replicated): written by rank 0
 *  as a dataset of n float64 in a group (/run of a checkpoint: read back whole by every rank into
 *  at, its length checked; /solids of a snapshot). */
struct hdf5_array {
  const char *name;
  double *at;
  long n;
};

/** What goes into a snapshot's /header besides the particles. Filled by hdf5_read_header too:
 *  then the two strings are allocated and freed with hdf5_info_free. */
struct snapshot_info {
  double time;               /* [s] */
  long step;
  int dimension;
  const char *case_yaml;     /* the fully resolved case, as YAML text */
  const char *code_version;
  long n_particles;          /* read only: /header/n_particles (written from the particles) */
  int n_arrays;              /* write only: arrays written as /solids/<name> (0: no group) */
  const struct hdf5_array *arrays;
};

/** A named number of a checkpoint's /run group (an attribute): exactly one of real (float64)
 *  and integer (int64) is set; it is written from and read into the variable it points to. */
struct hdf5_number {
  const char *name;
  double *real;
  long *integer;
};

/** What a checkpoint holds beyond the snapshot layout: the run state as named numbers and
 *  replicated arrays, and the snapshot series written so far (/run/snapshot_times [s],
 *  /run/snapshot_particles). */
struct checkpoint_extra {
  int n_numbers;
  const struct hdf5_number *numbers;
  int n_arrays;
  const struct hdf5_array *arrays;
  int n_snapshots;
  double *snapshot_times;    /* allocated by hdf5_read_run (caller frees) */
  long *snapshot_counts;     /* likewise */
};

/** Write the owned particles of every rank to `path` collectively (hyperslab offsets from
 *  MPI_Exscan), first to `path`.tmp, renamed to `path` when complete. Fluid and wall particles
 *  are both written (phase = the kind's marker, -1, for walls: base/kinds.h). Returns 0, or 3
 *  on I/O failure with a message in err (same return on every rank). */
int hdf5_write_snapshot(const char *path, const struct snapshot_info *info,
                        const struct parts *p, MPI_Comm comm, char *err, size_t err_len);

/** Write a checkpoint to `path` like hdf5_write_snapshot (same /header and /particles, so any
 *  snapshot reader opens it), plus the ghosts' /particles/mirror (N x dim) [m] and
 *  /particles/wall (int32, -1 for fluid) when p has walls, and the /run group of `extra`.
 *  Returns 0 or 3 with a message in err (same on every rank). */
int hdf5_write_checkpoint(const char *path, const struct snapshot_info *info,
                          const struct parts *p, const struct checkpoint_extra *extra,
                          MPI_Comm comm, char *err, size_t err_len);

/** Collective: read the /header attributes of a snapshot or checkpoint into info (strings
 *  allocated). Returns 0, or 3 with a message in err when the file is missing or unreadable. */
int hdf5_read_header(const char *path, struct snapshot_info *info, MPI_Comm comm, char *err,
                     size_t err_len);

/** Free the strings of an info filled by hdf5_read_header. */
void hdf5_info_free(struct snapshot_info *info);

/** Collective: 0 when `failed` is 0 on every rank; otherwise 1 on every rank, with msg replaced
 *  by the message (at most 767 characters) of the lowest rank where `failed` is not 0. */
int io_agree(int failed, MPI_Comm comm, char *msg, size_t len);

/** Collective: read the /run group of a checkpoint written by hdf5_write_checkpoint: every
 *  rank the numbers and the snapshot series of extra. Returns 0, or 3 with a message in err
 *  when the file does not hold them ("no group /run: not a checkpoint" for a snapshot). */
int hdf5_read_run(const char *path, struct checkpoint_extra *extra, MPI_Comm comm, char *err,
                  size_t err_len);

/** Collective: read the /particles of a checkpoint written by hdf5_write_checkpoint. Each rank
 *  receives a contiguous block of about n_particles / ranks rows into p (initialised by the
 *  caller with the dimension and walls the case implies; n_owned set, cells not assigned).
 *  Every dataset's row count is checked against /header/n_particles before p grows. Returns
 *  0, or 3 with a message in err when the file does not hold what p asks for. */
int hdf5_read_particles(const char *path, struct parts *p, MPI_Comm comm, char *err,
                        size_t err_len);

/** Rank-0 only: (re)write `dir`/snapshots.xdmf listing snapshots 0..n-1 (file names
 *  snap_NNNNN.h5, times, particle counts) as an XDMF temporal collection of Polyvertex grids
 *  with every contracted dataset as an attribute. Written to a temporary name, then renamed.
 *  Returns 0 or 3. */
int xdmf_write_series(const char *dir, int n_snapshots, const double *times,
                      const long *n_particles, int dimension, char *err, size_t err_len);

#endif
