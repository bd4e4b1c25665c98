/* nlist.h — per-step neighbour lists of the owned fluid particles (Verlet lists without a skin
 * of their own: the cell skin bounds how far particles may move within a step). */
#ifndef MPSPH_NLIST_H
#define MPSPH_NLIST_H

#include "parts.h"
#include "space.h"

/** Neighbour slots of every owned fluid particle, in the order of the cell scan (global cell
 *  order, then slot order), so that sums over a list add in the same order on any rank count. */
struct nlist {
  long n_slots;          /* owned slots covered (lists of wall ghosts are empty) */
  long *offset;          /* [n_slots + 1]: the list of slot i is j[offset[i] .. offset[i+1]) */
  int *j;                /* neighbour slots (owned or halo) */
  long capacity, offset_capacity;
  double radius2;        /* build radius^2 [m^2] */
};

/** The neighbours of one particle: n slots from a list. */
struct neighbours {
  const int *j;
  int n;
};

/** Build the lists of the owned fluid particles of p: every other slot within `radius` [m]
 *  at the current positions. Grows the arrays (geometrically) only when they are too small. */
void nlist_build(struct nlist *l, const struct space *s, const struct parts *p, double radius);

/** The neighbours of owned slot i. */
static inline struct neighbours nlist_of(const struct nlist *l, long i) {
  return (struct neighbours){l->j + l->offset[i], (int)(l->offset[i + 1] - l->offset[i])};
}

/** Free the arrays. */
void nlist_free(struct nlist *l);

/** Bytes held by the lists. */
long nlist_bytes(const struct nlist *l);

#endif
