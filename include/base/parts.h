/* parts.h — particle storage: structure of arrays, owned particles first, then the halo. */
#ifndef MPSPH_PARTS_H
#define MPSPH_PARTS_H

#include <stddef.h>
#include <stdint.h>
#include "base/kinds.h"

/** Particle arrays. Indices [0, n_owned) are owned by this rank, sorted by cell, each
 *  cell's fluid before its boundary particles, then by id;
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
  int *phase;          /* phase index of a fluid particle, else its kind's marker (base/kinds.h) */
  int64_t *id;         /* unique, stable id */
  int *cell;           /* global cell index */
  double *mirror[3];   /* ghosts: offset from the ghost to its interpolation point (the mirror across
                          the wall) in the wall's frame at t = 0 [m]; NULL without walls */
  int *wall;           /* ghosts: index of the wall in the case; -1 for fluid */
};

/* ---- the particle field table: one entry per array (or array per component) of struct parts ---- */

enum part_type { PART_DOUBLE, PART_INT, PART_INT64, N_PART_TYPES };

/* The operations that carry a field beyond those that carry every field of the table (allocation
 * and growth, parts_free, parts_bytes, parts_copy_one and the sort's permutation). */
enum {
  PART_HALO = 1,        /* halo rebuild: parts_pack/parts_unpack in halo_rebuild */
  PART_MIGRATE = 2,     /* migration: halo_migrate and redistribute_parts */
  PART_SNAPSHOT = 4,    /* a /particles dataset of snapshots (and of checkpoints) */
  PART_CHECKPOINT = 8   /* a /particles dataset of checkpoints (only; snapshot fields are in both) */
};

/** One particle field: what it is, where its storage is, which operations carry it. */
struct part_field {
  const char *name;     /* HDF5 dataset under /particles; the field's name where it has none */
  enum part_type type;  /* element type */
  int vector;           /* 1: dim components, a pointer array (PART_DOUBLE only: the HDF5 rows
                           assume it); 0: one component, a pointer */
  size_t offset;        /* offsetof the pointer (or pointer array) in struct parts */
  int walls_only;       /* 1: allocated only with walls (parts_init's with_walls) */
  unsigned ops;         /* PART_* operations that carry it */
};

#define PARTS_MAX_FIELDS 16   /* entries of parts_fields, at most (bounds the writers' lists) */

/** The table of the particle fields of struct parts, in the order of the packed columns and of the
 *  datasets written. */
extern const struct part_field parts_fields[];
extern const int parts_n_fields;

/** Whether p holds field f (walls-only fields exist only with walls). */
int parts_has_field(const struct parts *p, const struct part_field *f);

/** The number of components of f in p: dim for vectors, 1 for scalars. */
int parts_field_ncomp(const struct parts *p, const struct part_field *f);

/** Bytes per element of f. */
size_t parts_field_size(const struct part_field *f);

/** Component k of field f of p (the array itself; NULL if not allocated). */
void *parts_field_array(const struct parts *p, const struct part_field *f, int k);

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
