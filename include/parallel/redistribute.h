/* redistribute.h — move every owned particle to the owner of its cell (after a re-partition or
 * the reading of a checkpoint), with one all-to-all exchange counted in particles. */
#ifndef MPSPH_REDISTRIBUTE_H
#define MPSPH_REDISTRIBUTE_H

#include <mpi.h>
#include "base/parts.h"
#include "parallel/space.h"

/** Send each owned particle [0, n_owned) to the owner of its cell; on return the owned set is exactly
 *  the particles of this rank's cells (unsorted) and n_halo = 0. Cells must be assigned. */
void redistribute_parts(const struct space *s, struct parts *p, MPI_Comm comm);

#endif
