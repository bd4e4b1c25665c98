/* partition.h — METIS partition of the cell graph, computed on rank 0 and broadcast. */
#ifndef MPSPH_PARTITION_H
#define MPSPH_PARTITION_H

#include <mpi.h>
#include <stdint.h>
#include "parallel/grid.h"

/** The balance constraints of the partition: per cell, its work (load-balance units of its
 *  particles, base/kinds.h) and its particles (memory). A weight array holds
 *  PARTITION_CONSTRAINTS values per cell, in this order. */
enum { WEIGHT_WORK, WEIGHT_PARTICLES, PARTITION_CONSTRAINTS };

/** Partition the cells of g among n_parts with METIS_PartGraphKway on the graph of
 *  neighbouring cells, balancing both constraints of `weight` (only read on rank 0): the work
 *  within 3 %, the particles within 10 % (so that no rank holds several times the average
 *  particles, as a rank of cheap wall ghosts would with the work alone).
 *  The result `owner` (one rank per cell) is broadcast to every rank of comm.
 *  Returns 0, or 1 with a message in err if some part received no cell or METIS failed. */
int partition_cells(const struct grid *g, const int64_t *weight, int n_parts, MPI_Comm comm,
                    int *owner, char *err, size_t err_len);

/** The imbalance max/mean - 1 over the parts of constraint k of `weight` for a given owner map. */
double partition_imbalance(const struct grid *g, const int64_t *weight, int k, const int *owner,
                           int n_parts);

#endif
