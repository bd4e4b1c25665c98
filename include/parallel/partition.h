/* partition.h — METIS partition of the cell graph, computed on rank 0 and broadcast. */
#ifndef MPSPH_PARTITION_H
#define MPSPH_PARTITION_H

#include <mpi.h>
#include <stdint.h>
#include "parallel/grid.h"

/** Partition the cells of g among n_parts with METIS_PartGraphKway on the graph of
 *  neighbouring cells, vertex weights `weight` (one per cell, only read on rank 0).
 *  The result `owner` (one rank per cell) is broadcast to every rank of comm.
 *  Returns 0, or 1 with a message in err if some part received no cell or METIS failed. */
int partition_cells(const struct grid *g, const int64_t *weight, int n_parts, MPI_Comm comm,
                    int *owner, char *err, size_t err_len);

/** Sum of weights per part and the imbalance max/mean - 1 of a given owner map. */
double partition_imbalance(const struct grid *g, const int64_t *weight, const int *owner,
                           int n_parts);

#endif
