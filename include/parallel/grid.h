/* grid.h — the global uniform cell grid over the case domain (cell edge >= kernel support). */
#ifndef MPSPH_GRID_H
#define MPSPH_GRID_H

/** Cells are numbered c = ix + nx*(iy + ny*iz), the global order of all neighbour sums. */
struct grid {
  int dim;
  long n[3];          /* cells per axis (1 for unused axes) */
  long n_cells;
  double min[3], max[3];
  double edge[3];     /* cell edge per axis [m] */
};

/** Cover [min, max] with cells of edge >= min_edge [m]. Returns 0, or 1 if the grid would be
 *  too large to index. */
int grid_init(struct grid *g, int dim, const double *min, const double *max, double min_edge);

/** Cell containing x, or -1 if x lies outside the domain. */
int grid_cell_of(const struct grid *g, const double *x);

/** Cell containing x, clamped to the grid (for interpolation points on the domain edge). */
int grid_cell_clamped(const struct grid *g, const double *x);

/** Cells within `layers` cells of c (c included) in increasing global index; returns the count.
 *  `out` must hold (2*layers+1)^dim entries. */
int grid_stencil(const struct grid *g, long c, int layers, long *out);

/** (2*layers+1)^dim: the most cells grid_stencil can return, the size its `out` needs. */
long grid_stencil_size(const struct grid *g, int layers);

#endif
