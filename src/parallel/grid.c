/* grid.c — the global cell grid. */
#include <limits.h>
#include <math.h>
#include "parallel/grid.h"

int grid_init(struct grid *g, int dim, const double *min, const double *max, double min_edge) {
  g->dim = dim;
  g->n_cells = 1;
  for (int d = 0; d < 3; d++) {
    g->n[d] = 1;
    g->min[d] = d < dim ? min[d] : 0;
    g->max[d] = d < dim ? max[d] : 1;
    g->edge[d] = g->max[d] - g->min[d];
  }
  for (int d = 0; d < dim; d++) {
    double len = max[d] - min[d];
    long n = (long)floor(len / min_edge);
    g->n[d] = n < 1 ? 1 : n;
    g->edge[d] = len / (double)g->n[d];
    if ((double)g->n_cells * (double)g->n[d] > (double)INT_MAX) return 1;
    g->n_cells *= g->n[d];
  }
  return 0;
}

static long axis_index(const struct grid *g, int d, double x, int clamp) {
  long i = (long)floor((x - g->min[d]) / g->edge[d]);
  if (x == g->max[d]) i = g->n[d] - 1;
  if (clamp) return i < 0 ? 0 : (i >= g->n[d] ? g->n[d] - 1 : i);
  return (i < 0 || i >= g->n[d]) ? -1 : i;
}

static int cell_of(const struct grid *g, const double *x, int clamp) {
  long c = 0, stride = 1;
  for (int d = 0; d < g->dim; d++) {
    long i = axis_index(g, d, x[d], clamp);
    if (i < 0) return -1;
    c += i * stride;
    stride *= g->n[d];
  }
  return (int)c;
}

int grid_cell_of(const struct grid *g, const double *x) { return cell_of(g, x, 0); }

int grid_cell_clamped(const struct grid *g, const double *x) { return cell_of(g, x, 1); }

int grid_stencil(const struct grid *g, long c, int layers, long *out) {
  long ix = c % g->n[0], iy = (c / g->n[0]) % g->n[1], iz = c / (g->n[0] * g->n[1]);
  int lz = g->dim == 3 ? layers : 0, count = 0;
  for (long z = iz - lz; z <= iz + lz; z++) {
    if (z < 0 || z >= g->n[2]) continue;
    for (long y = iy - layers; y <= iy + layers; y++) {
      if (y < 0 || y >= g->n[1]) continue;
      for (long x = ix - layers; x <= ix + layers; x++) {
        if (x < 0 || x >= g->n[0]) continue;
        out[count++] = x + g->n[0] * (y + g->n[1] * z);
      }
    }
  }
  return count;
}

long grid_stencil_size(const struct grid *g, int layers) {
  long side = 2L * layers + 1, size = 1;
  for (int d = 0; d < g->dim; d++) size *= side;
  return size;
}
