/* preflight.h — what `run` checks before any computation, and the `check` command. */
#ifndef MPSPH_PREFLIGHT_H
#define MPSPH_PREFLIGHT_H

#include <mpi.h>
#include "case/case.h"

/** Before a run of case c on the ranks of comm: the paths of the files in the folder outdir and
 *  the checkpoint restart (NULL: none named; it must be a regular file) are short enough for MPI-IO (Open MPI writes
 *  "<path>.locktest.<rank>" into a buffer of 256 bytes at every MPI_File_open: 244 characters on
 *  up to 10 ranks, 243 on up to 100, ...), the output folder
 *  can be written (probed on rank 0, leaving nothing behind), and the particles fit in the memory
 *  available to each rank (mem_estimate.h; counted on rank 0 only when a bound does not settle
 *  it). Returns 0, or 1 on every rank with the reason printed by rank 0. Collective. */
int preflight_run(const struct case_def *c, const char *outdir, const char *restart, MPI_Comm comm);

/** The check command: print the resolved case, the particle counts and the memory estimate per
 *  rank for a run on n_ranks ranks, per_node of them on each node (0: n_ranks, at most this
 *  machine's processors) (mem_estimate.h), allocating no particle. A case whose bound
 *  needs more than COUNT_GUARD times this machine's memory per rank, or has more than
 *  COUNT_MAX_NODES lattice nodes to visit (minutes of counting), is not counted; its bound is
 *  printed instead. Returns 0, or 1 when particle generation refuses the case. */
int preflight_check(const struct case_def *c, int n_ranks, int per_node);

#endif
