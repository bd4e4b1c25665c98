/* nlist.h — per-step neighbour lists of the owned particles of the kinds that have one (KIND_LISTED
 * in base/kinds.h: the fluid) and of points that stay fixed within a step (the mirror points of
 * the fixed walls' ghosts), Verlet lists without a skin of their own (the cell skin bounds how
 * far particles may move within a step), stored as one bit per candidate of the cell stencil. */
#ifndef MPSPH_NLIST_H
#define MPSPH_NLIST_H

#include <stdint.h>
#include "base/parts.h"
#include "parallel/space.h"

#define NLIST_MAX_PHASES 8   /* fluid phases of the lists by phase (at least case.h's CASE_MAX_PHASES) */

/** The candidates of a particle are the slots of the cells around its cell (space.h
 *  neighbour_ranges), concatenated in global cell order then slot order; its list is a bit mask
 *  over them, bit b set when candidate b lies within the build radius. All listed particles of a
 *  cell have masks of the same length, stored one after the other in slot order (the other kinds,
 *  wall ghosts, have none), so a mask costs
 *  ceil(candidates / 64) words instead of 4 bytes per neighbour, and reading it back yields the
 *  neighbours in the same fixed global order on any rank count. */
struct nlist_cell {
  long first_word;       /* first word of the masks of the cell's particles */
  int words;             /* words per mask */
};

struct nlist {
  struct nlist_cell *cells;   /* [n_owned_cells]: where owned cell k's masks are */
  uint64_t *bits;        /* the masks */
  int *candidates;       /* scratch: the candidate slots of the cell being read (nlist_enter_cell) */
  long capacity, cell_capacity, candidate_capacity;   /* words, cells, slots */
  double radius2;        /* build radius^2 [m^2] */
  int by_phase;          /* multi-resolution: build radii by phase (nlist_build) */
  double phase_radius2[NLIST_MAX_PHASES];  /* with by_phase: the build radius^2 of each fluid phase [m^2] */
  /* the lists at points (nlist_point_add): header and mask, one after the other in the order added */
  uint64_t *point_bits;
  long point_capacity, point_words;   /* words held, words in use */
};

/** Words of a mask over the candidates of the stencil ranges r. */
static inline int nlist_words(const struct neighbour_ranges *r) {
  long candidates = 0;
  for (int q = 0; q < r->n; q++) candidates += r->count[q];
  return (int)((candidates + 63) / 64);
}

/** The neighbours of one particle, read back from its mask with neighbours_next (which
 *  consumes the bits: copy it to read the list again). */
struct neighbours {
  const uint64_t *mask;
  const int *candidates;   /* slot of each candidate */
  int words, w;            /* words of the mask, the word being read */
  uint64_t bits;           /* the bits of word w not read yet */
};

/** Move nb to the next word with bits not read yet (the current one if it has some); 0 when
 *  the list is exhausted. */
static inline int neighbours_word(struct neighbours *nb) {
  while (!nb->bits) {
    if (++nb->w >= nb->words) return 0;
    nb->bits = nb->mask[nb->w];
  }
  return 1;
}

/** The next neighbour slot into *j; 0 when the list is exhausted. */
static inline int neighbours_next(struct neighbours *nb, long *j) {
  if (!neighbours_word(nb)) return 0;
  *j = nb->candidates[nb->w * 64 + __builtin_ctzll(nb->bits)];
  nb->bits &= nb->bits - 1;
  return 1;
}

/** Build the masks of the owned listed particles of p (the other kinds get none): every other slot
 *  within `radius` [m] at the current positions. With phase_radius (multi-resolution: the build
 *  radius of each of the n_phases <= NLIST_MAX_PHASES fluid phases [m], `radius` then unused), a
 *  particle of phase a lists a fluid slot of phase b within the larger of the two phases' radii and
 *  a slot of another kind (a wall ghost, a solid's particle) within its own. Grows the arrays
 *  (geometrically) only when they are too small. */
void nlist_build(struct nlist *l, const struct space *s, const struct parts *p, double radius,
                 const double *phase_radius, int n_phases);

/** Make the candidates of a cell whose stencil ranges are r the ones nlist_of reads back (once per
 *  cell, before the lists of its particles). */
void nlist_enter_cell(struct nlist *l, const struct neighbour_ranges *r);

/** The neighbours of the f-th listed particle (counted from 0 in slot order) of owned cell number
 *  k (s->owned_cells[k]), as of the last build; nlist_enter_cell must have been called with the
 *  cell's ranges, whose candidates stay valid until the next call. */
static inline struct neighbours nlist_of(const struct nlist *l, long k, long f) {
  const int words = l->cells[k].words;
  const uint64_t *mask = l->bits + l->cells[k].first_word + f * words;
  return (struct neighbours){mask, l->candidates, words, 0, words ? mask[0] : 0};
}

/** The header of a list at a point whose mask keeps `words` words from word `first` on. */
static inline uint64_t nlist_point_header(int first, int words) { return (uint64_t)first << 32 | (uint32_t)words; }

/** The words the list at `point` keeps after its header, and the first of them in *first. */
static inline int nlist_point_words(const uint64_t *point, int *first) {
  *first = (int)(point[0] >> 32);
  return (int)(uint32_t)point[0];
}

/** The list after the one at `point` (the lists follow each other in the order added). */
static inline const uint64_t *nlist_point_next(const uint64_t *point) { return point + 1 + (uint32_t)point[0]; }

/** Forget the lists at points; the next ones are built within `radius` [m]. */
void nlist_points_clear(struct nlist *l, double radius);

/** Append the list of point x [m] (the mirror point of a fixed wall's ghost): a mask over the
 *  candidates of the ranges r (the fluid around x, neighbour_ranges_fluid_within: the points
 *  interpolate the fluid), bit b set when candidate b lies within the build radius of x at the
 *  current positions: a header word (nlist_point_header: the first word of
 *  the mask kept and how many are kept, the zero words before and after left out; 0 when no bit
 *  is set), then those words. Like the particles'
 *  lists, it stays valid for the step when x is fixed (the cell skin bounds how far the
 *  candidates move). */
void nlist_point_add(struct nlist *l, const struct parts *p, const double *x, const struct neighbour_ranges *r);

/** An empty list (the kinds without lists). */
static inline struct neighbours nlist_none(void) { return (struct neighbours){0}; }

/** Free the arrays. */
void nlist_free(struct nlist *l);

/** Bytes held by the lists (masks, cell offsets, read-back scratch). */
long nlist_bytes(const struct nlist *l);

#endif
