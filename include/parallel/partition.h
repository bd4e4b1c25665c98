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

/** The most a part may hold of each constraint, as a multiple of the mean over the parts. */
static const double partition_tolerance[PARTITION_CONSTRAINTS] = {[WEIGHT_WORK] = 1.03, [WEIGHT_PARTICLES] = 1.10};

/** Partition the cells of g among n_parts with METIS_PartGraphKway on the graph of
 *  neighbouring cells that hold particles (a particle weight above 0), balancing both
 *  constraints of `weight` (only read on rank 0): the work within 3 %, the particles within
 *  10 % (so that no rank holds several times the average particles, as a rank of cheap wall
 *  ghosts would with the work alone). Every empty cell goes to the rank of the nearest occupied
 *  one. With the current owners `prev` (read on rank 0; NULL at start-up) the parts are
 *  numbered so that the ranks keep as many of their particles as they can.
 *  The result `owner` (one rank per cell) is broadcast to every rank of comm.
 *  Returns 0, or 1 with a message in err if some part received no cell, fewer cells hold
 *  particles than there are parts, or METIS failed. */
int partition_cells(const struct grid *g, const int64_t *weight, int n_parts, const int *prev, MPI_Comm comm,
                    int *owner, char *err, size_t err_len);

/** The imbalance max/mean - 1 over the parts of constraint k of `weight` for a given owner map. */
double partition_imbalance(const struct grid *g, const int64_t *weight, int k, const int *owner,
                           int n_parts);

#endif
