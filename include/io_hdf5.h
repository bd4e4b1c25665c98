/* io_hdf5.h — collective parallel-HDF5 snapshots (one file per output time) and XDMF index. */
#ifndef MPSPH_IO_HDF5_H
#define MPSPH_IO_HDF5_H

#include <mpi.h>
#include "parts.h"

/** What goes into a snapshot's /header besides the particles. */
struct snapshot_info {
  double time;               /* [s] */
  long step;
  int dimension;
  const char *case_yaml;     /* the fully resolved case, as YAML text */
  const char *code_version;
};

/** Write the owned particles of every rank to `path` collectively (hyperslab offsets from
 *  MPI_Exscan), first to `path`.tmp, renamed to `path` when complete. Fluid and wall particles
 *  are both written (phase = PHASE_WALL for walls). Returns 0, or 3 on I/O failure with a
 *  message in err (same return on every rank). */
int hdf5_write_snapshot(const char *path, const struct snapshot_info *info,
                        const struct parts *p, MPI_Comm comm, char *err, size_t err_len);

/** Rank-0 only: (re)write `dir`/snapshots.xdmf listing snapshots 0..n-1 (file names
 *  snap_NNNNN.h5, times, particle counts) as an XDMF temporal collection of Polyvertex grids
 *  with every contracted dataset as an attribute. Written to a temporary name, then renamed.
 *  Returns 0 or 3. */
int xdmf_write_series(const char *dir, int n_snapshots, const double *times,
                      const long *n_particles, int dimension, char *err, size_t err_len);

#endif
