/* parts.h — particle storage: structure of arrays, owned particles first, then the halo. */
#ifndef MPSPH_PARTS_H
#define MPSPH_PARTS_H

#include <stdint.h>

#define PHASE_WALL (-1)   /* phase value of fixed ghost (wall) particles */

/** Particle arrays. Indices [0, n_owned) are owned by this rank, sorted by (cell, id);
 *  [n_owned, n_owned + n_halo) are copies of neighbouring ranks' particles, sorted likewise.
 *  Vectors are stored per component: x[0..dim-1][i]. Unused components (z in 2D) are NULL. */
struct parts {
  int dim;
  long n_owned, n_halo, capacity;
  double *x[3];        /* position [m] */
  double *v[3];        /* velocity [m/s] */
  double *rho;         /* density [kg/m^3] */
  double *p;           /* pressure [Pa] */
  double *m;           /* mass [kg] */
  int *phase;          /* phase index, PHASE_WALL for ghosts */
  int64_t *id;         /* unique, stable id */
  int *cell;           /* global cell index */
  double *mirror[3];   /* ghosts: offset from the ghost to its interpolation point (the mirror across
                          the wall) in the wall's frame at t = 0 [m]; NULL without walls */
  int *wall;           /* ghosts: index of the wall in the case; -1 for fluid */
};

/** Allocate arrays for `capacity` particles in `dim` dimensions; with_walls adds the ghost arrays. */
void parts_init(struct parts *p, int dim, long capacity, int with_walls);

/** Grow the arrays to hold at least `capacity` particles, keeping the content. */
void parts_reserve(struct parts *p, long capacity);

/** Free all arrays. */
void parts_free(struct parts *p);

/** Copy particle src_index of src into slot dst_index of dst (all stored fields). */
void parts_copy_one(struct parts *dst, long dst_index, const struct parts *src, long src_index);

/** Bytes held by the particle arrays (all `capacity` slots). */
long parts_bytes(const struct parts *p);

#endif
