/* space.h — this rank's view of the cells, on two levels (issue 22): a coarse top-level grid of
 * blocks of fine cells, partitioned among the ranks (every rank holds its owner map, one int
 * per top cell), and the fine cells (the neighbour-search cells, of about one kernel support)
 * held only inside the top cells this rank owns or reaches with its halo. Particles carry their
 * global fine cell; every neighbour sum runs over fine cells in global order, whatever the
 * partition. */
#ifndef MPSPH_SPACE_H
#define MPSPH_SPACE_H

#include "parallel/grid.h"
#include "base/parts.h"

/* The largest top grid (METIS runs on it on one rank). */
#define SPACE_TOP_CELLS_MAX (1L << 20)

struct space {
  struct grid grid;      /* the fine cells over the domain (cell edge >= kernel support) */
  struct grid top;       /* top cells: blocks of `block` fine cells per axis (the last of an
                            axis may be cut short by the domain) */
  long block;            /* fine cells per top cell and axis */
  long cells_per_top;    /* block^dim: fine-cell slots per local top cell */
  int rank, n_ranks;
  int halo_layers;       /* foreign fine cells within this many cells of an owned cell are copied in */
  int *top_owner;        /* [top.n_cells] rank owning each top cell */
  int *top_slot;         /* [top.n_cells] index of each local top cell among them, -1 elsewhere */
  long n_local_tops;     /* top cells owned or within the halo's reach */
  long *cell_start;      /* [n_local_tops * cells_per_top] first particle slot of each local fine cell */
  int *cell_count;       /* [n_local_tops * cells_per_top] its particles on this rank (0 when absent) */
  int *cell_fluid;       /* [n_local_tops * cells_per_top] of them fluid: the first ones (space_sort) */
  long n_local_cells;    /* local fine cells inside the domain */
  int *local_order;      /* [n_local_cells] their local indices in increasing global index */
  long n_owned_cells;
  int *owned_cells;      /* owned fine cells in increasing global index (they fit an int: grid.h) */
  int *by_reach;         /* [n_owned_cells] indices into owned_cells: first the n_interior cells whose
                            neighbours are all owned (their sums read no halo slot), then the others */
  long n_interior;
  int *order;            /* scratch: permutation for sorting (slots fit an int, as in nlist.h) */
  int *bucket;           /* scratch: counting-sort offsets per local fine cell */
  int *rank_of_local;    /* [n_local_tops * cells_per_top] position of a local fine cell in local_order */
  void *scratch;         /* scratch: one array's worth of particle data */
  long scratch_capacity;
};

/** Ranges of particle slots of the cells around one cell, in global cell order. */
struct neighbour_ranges {
  int n;
  long start[27];
  int count[27];
};

/** The top cell holding the fine cell at axis indices (ix, iy, iz). */
static inline long space_top_of_xyz(const struct space *s, long ix, long iy, long iz) {
  return ix / s->block + s->top.n[0] * (iy / s->block + s->top.n[1] * (iz / s->block));
}

/** The top cell holding global fine cell c. */
static inline long space_top_of(const struct space *s, long c) {
  const long *n = s->grid.n;
  return space_top_of_xyz(s, c % n[0], (c / n[0]) % n[1], c / (n[0] * n[1]));
}

/** The rank owning global fine cell c. */
static inline int space_cell_owner(const struct space *s, long c) {
  return s->top_owner[space_top_of(s, c)];
}

/** The local index of the fine cell at axis indices (ix, iy, iz), or -1 when its top cell is
 *  not local. */
static inline long space_local_xyz(const struct space *s, long ix, long iy, long iz) {
  long slot = s->top_slot[space_top_of_xyz(s, ix, iy, iz)], b = s->block;
  if (slot < 0) return -1;
  return slot * s->cells_per_top + ix % b + b * (iy % b + b * (iz % b));
}

/** The local index of global fine cell c, or -1 when its top cell is not local. */
static inline long space_local_cell(const struct space *s, long c) {
  const long *n = s->grid.n;
  return space_local_xyz(s, c % n[0], (c / n[0]) % n[1], c / (n[0] * n[1]));
}

/** First particle slot of local fine cell c (global index; the cell must be local). */
static inline long space_cell_first(const struct space *s, long c) {
  return s->cell_start[space_local_cell(s, c)];
}

/** Particles on this rank in global fine cell c (0 for a cell that is not local). */
static inline int space_cell_size(const struct space *s, long c) {
  long l = space_local_cell(s, c);
  return l < 0 ? 0 : s->cell_count[l];
}

/** The block edge [cells] of the top grid over fine grid g on n_ranks ranks: the largest that
 *  leaves per_rank top cells per rank (1 when the grid is too small for that), then grown until
 *  the top grid has at most SPACE_TOP_CELLS_MAX cells. */
long space_top_block(const struct grid *g, int n_ranks, long per_rank);

/** The top grid over fine grid g with blocks of b cells per axis. */
struct grid space_top_grid(const struct grid *g, long b);

/** The particle ranges of the 3^dim cells around cell c (those present on this rank). */
void neighbour_ranges(const struct space *s, long c, struct neighbour_ranges *r);

/** The ranges of the fluid of the cells around c (the first cell_fluid slots of each; the boundary
 *  particles follow, space_sort), in neighbour_ranges' order, without the cells whose box lies
 *  farther than radius [m] from point x [m]: the fluid within radius of x, of the particles in
 *  their cells' boxes (cells assigned at the current positions), is all kept. For a point that
 *  reads the fluid alone, without scanning the wall ghosts of the cells around it. */
void neighbour_ranges_fluid_within(const struct space *s, long c, const double *x, double radius,
                                   struct neighbour_ranges *r);

/** Bytes held by the space's arrays (top-cell owners, fine-cell index, sort scratch). */
long space_bytes(const struct space *s);

/** Set up the space over fine grid g for `rank` of `n_ranks`, with `halo_layers` cell layers:
 *  the top grid has the largest blocks that leave at least top_cells_per_rank top cells per rank
 *  (blocks of one fine cell when the grid is too small for that), and at most
 *  SPACE_TOP_CELLS_MAX top cells. No fine cell is held until space_set_owner. */
void space_init(struct space *s, const struct grid *g, int rank, int n_ranks, int halo_layers,
                long top_cells_per_rank);

/** Free the space's arrays. */
void space_free(struct space *s);

/** Adopt a new top cell -> rank map (copied), and rebuild the local top cells, the fine-cell
 *  index over them and the list of owned fine cells. */
void space_set_owner(struct space *s, const int *top_owner);

/** Compute the cell of particles [first, first+n). Returns the slot of the first particle
 *  outside the domain, or -1 when all are inside. */
long space_assign_cells(const struct space *s, struct parts *p, long first, long n);

/** Sort particles [first, first+n) (all in local cells) by cell, each cell's fluid before its
 *  boundary particles, then by id, by a counting sort on the local cells in global order. */
void space_sort(struct space *s, struct parts *p, long first, long n);

/** Keep the owned particles whose cell this rank owns, in their order, in the first owned slots
 *  (n_owned becomes their count); the others are dropped (sent away first). */
void space_keep_own(const struct space *s, struct parts *p);

/** Rebuild cell_start, cell_count and cell_fluid for owned and halo particles (both sorted by
 *  (cell, fluid before boundary, id)). */
void space_index(struct space *s, const struct parts *p);

#endif
