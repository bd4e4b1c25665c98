/* nlist.h — per-step neighbour lists of the owned fluid particles (Verlet lists without a skin
 * of their own: the cell skin bounds how far particles may move within a step), stored as one
 * bit per candidate of the cell stencil. */
#ifndef MPSPH_NLIST_H
#define MPSPH_NLIST_H

#include <stdint.h>
#include "parts.h"
#include "space.h"

/** The candidates of a particle are the slots of the cells around its cell (space.h
 *  neighbour_ranges), concatenated in global cell order then slot order; its list is a bit mask
 *  over them, bit b set when candidate b lies within the build radius. All fluid particles of a
 *  cell have masks of the same length, stored one after the other in slot order (wall ghosts
 *  have none), so a mask costs
 *  ceil(candidates / 64) words instead of 4 bytes per neighbour, and reading it back yields the
 *  neighbours in the same fixed global order on any rank count. */
struct nlist_cell {
  long first_word;       /* first word of the masks of the cell's particles */
  int words;             /* words per mask */
};

struct nlist {
  struct nlist_cell *cells;   /* [n_owned_cells]: where owned cell k's masks are */
  uint64_t *bits;        /* the masks */
  int *decoded;          /* scratch: the neighbour slots of one particle, read back from its mask */
  long capacity, cell_capacity, decoded_capacity;   /* words, cells, slots */
  double radius2;        /* build radius^2 [m^2] */
};

/** The neighbours of one particle: n slots (owned or halo). */
struct neighbours {
  const int *j;
  int n;
};

/** Build the masks of the owned fluid particles of p (wall ghosts get none): every other slot
 *  within `radius` [m] at the current positions. Grows the arrays (geometrically) only when
 *  they are too small. */
void nlist_build(struct nlist *l, const struct space *s, const struct parts *p, double radius);

/** The neighbours of the f-th fluid particle (counted from 0 in slot order) of owned cell number
 *  k (s->owned_cells[k]) whose stencil ranges are r, as of the last build. The slots are valid
 *  until the next call. */
struct neighbours nlist_of(struct nlist *l, long k, const struct neighbour_ranges *r, long f);

/** Free the arrays. */
void nlist_free(struct nlist *l);

/** Bytes held by the lists (masks, cell offsets, read-back scratch). */
long nlist_bytes(const struct nlist *l);

#endif
