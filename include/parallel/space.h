/* space.h — this rank's view of the cell grid: who owns which cell, and where each cell's
 * particles (owned or halo) sit in the particle arrays. */
#ifndef MPSPH_SPACE_H
#define MPSPH_SPACE_H

#include "parallel/grid.h"
#include "base/parts.h"

struct space {
  struct grid grid;
  int rank, n_ranks;
  int halo_layers;       /* foreign cells within this many cells of an owned cell are copied in */
  int *owner;            /* rank owning each global cell */
  long *cell_start;      /* first particle slot of each cell present on this rank */
  int *cell_count;       /* particles of each cell on this rank (0 for absent cells) */
  long n_owned_cells;
  int *owned_cells;      /* owned cells in increasing index (cell indices fit an int: grid.h) */
  int *order;            /* scratch: permutation for sorting (slots fit an int, as in nlist.h) */
  int *bucket;           /* scratch: counting-sort offsets per cell */
  void *scratch;         /* scratch: one array's worth of particle data */
  long scratch_capacity;
};

/** Ranges of particle slots of the cells around one cell, in global cell order. */
struct neighbour_ranges {
  int n;
  long start[27];
  int count[27];
};

/** The particle ranges of the 3^dim cells around cell c (those present on this rank). */
void neighbour_ranges(const struct space *s, long c, struct neighbour_ranges *r);

/** Bytes held by the space's arrays (per-cell index and ownership, sort scratch). */
long space_bytes(const struct space *s);

/** Set up the space over grid g for `rank` of `n_ranks`, with `halo_layers` cell layers. */
void space_init(struct space *s, const struct grid *g, int rank, int n_ranks, int halo_layers);

/** Free the space's arrays. */
void space_free(struct space *s);

/** Adopt a new cell -> rank map (copied) and rebuild the list of owned cells. */
void space_set_owner(struct space *s, const int *owner);

/** Compute the cell of particles [first, first+n). Returns the slot of the first particle
 *  outside the domain, or -1 when all are inside. */
long space_assign_cells(const struct space *s, struct parts *p, long first, long n);

/** Sort particles [first, first+n) by (cell, id) with a counting sort on cells. */
void space_sort(struct space *s, struct parts *p, long first, long n);

/** Rebuild cell_start/cell_count for owned and halo particles (both sorted by (cell, id)). */
void space_index(struct space *s, const struct parts *p);

#endif
