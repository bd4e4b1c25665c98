/* mem_estimate.h — the memory a run needs per rank, from the particle count, and the memory a
 * node has available. Rough by design: it is there to refuse runs that cannot fit. */
#ifndef MPSPH_MEM_ESTIMATE_H
#define MPSPH_MEM_ESTIMATE_H

#include "case/case.h"

/** The parts of the estimate for one rank [bytes]. */
struct mem_estimate {
  double particles;        /* the rank's share of the particles plus its halo [-] */
  double bytes_per_particle;
  double process;          /* baseline of a process: MPI, HDF5, code */
  double cells;            /* top-cell owners, their METIS graph (rank 0), the rank's cell index */
  double startup;          /* the rows of lattice nodes counted at start-up */
  double total;
};

/** Estimated peak memory of the largest rank of a run of case c (kernel support [m]) with
 *  n_particles fluid + wall particles on n_ranks ranks. */
struct mem_estimate mem_estimate_rank(const struct case_def *c, double support, double n_particles,
                                      int n_ranks);

/** Memory available on this node [bytes]: $MPSPH_MEMORY_AVAILABLE when set, else MemAvailable
 *  of /proc/meminfo, else the physical memory; -1 when $MPSPH_MEMORY_AVAILABLE is not a
 *  number > 0. */
double mem_node_available(void);

#endif
