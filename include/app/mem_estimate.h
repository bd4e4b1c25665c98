/* mem_estimate.h — the memory a run needs per rank, from the particle count, and the memory a
 * node has available. Rough by design: it is there to refuse runs that cannot fit. */
#ifndef MPSPH_MEM_ESTIMATE_H
#define MPSPH_MEM_ESTIMATE_H

#include "base/kinds.h"
#include "case/case.h"

/** The parts of the estimate for the rank that needs the most memory [bytes]. */
struct mem_estimate {
  double owned[KIND_COUNT];   /* its owned particles of each kind [-] */
  double halo;                /* its halo particles [-] */
  double particle_bytes;      /* the arrays of these particles */
  double process;             /* baseline of a process: MPI, HDF5, code */
  double cells;               /* top-cell owners, their METIS graph (rank 0), the rank's cell index */
  double startup;             /* the rows of lattice nodes counted at start-up */
  double total;
};

/** Estimated peak memory of the largest rank of a run of case c (kernel support [m], the coarsest phase's) with
 *  n_kind[k] particles of kind k on n_ranks ranks, per_node of them on each node. */
struct mem_estimate mem_estimate_rank(const struct case_def *c, double support, const double *n_kind,
                                      int n_ranks, int per_node);

/** Memory available on this node [bytes]: $MPSPH_MEMORY_AVAILABLE when set, else MemAvailable
 *  of /proc/meminfo, else the physical memory; -1 when $MPSPH_MEMORY_AVAILABLE is not a
 *  number > 0. */
double mem_node_available(void);

#endif
