/* pair_chunk.h — the pair loops' shared traversal of a neighbour list, one mask word (64
 * candidates) at a time: the word's neighbours are decoded into slots, their separations, squared
 * distances and kernel factors F(r) V_j computed in one loop without branches (which the compiler
 * vectorises: gathers of the neighbours' positions and volumes, the kernel's exp in SIMD lanes),
 * and the pairs within the support kept in list order. A pass then sums its terms over
 * chunk.n pairs, reading contiguous arrays; the pairs and their order are those of
 * neighbours_next, and each value is computed by the same operations, so the sums are the same to
 * the bit. */
#ifndef MPSPH_PAIR_CHUNK_H
#define MPSPH_PAIR_CHUNK_H

#include "parallel/nlist.h"
#include "physics/kernel.h"

#define PAIR_CHUNK 64   /* candidates per mask word */

/** The pairs within the support among one mask word's neighbours of particle i. */
struct pair_chunk {
  int n;                       /* pairs kept */
  long j[PAIR_CHUNK];          /* neighbour slot */
  double dx[3][PAIR_CHUNK];    /* x_i - x_j [m] */
  double r2[PAIR_CHUNK];       /* |x_i - x_j|^2 [m^2] */
  double fv[PAIR_CHUNK];       /* F(r) V_j (grad_i W_ij V_j = fv dx [1/m^2]), or W(r) V_j [-] */
};

/* Decode the next non-empty word of the list into slots; the number of them (0: list exhausted). */
static inline int pair_chunk_slots(struct neighbours *it, long *slot) {
  if (!neighbours_word(it)) return 0;
  const int *cand = it->candidates + (long)it->w * PAIR_CHUNK;
  int n = 0;
  for (uint64_t b = it->bits; b; b &= b - 1) slot[n++] = cand[__builtin_ctzll(b)];
  it->bits = 0;
  return n;
}

/** The separation x_i - x_j of the chunk's pair k, over dim axes, into dx [m]. */
static inline __attribute__((always_inline)) void pair_chunk_dx(const struct pair_chunk *c, int k, const int dim,
                                                                double *dx) {
  for (int d = 0; d < dim; d++) dx[d] = c->dx[d][k];
}

/** Which kernel function a chunk's factors hold. */
enum pair_chunk_kernel { CHUNK_F, CHUNK_W };

/* pair_chunk_fill in `dim` dimensions, a literal. */
static inline __attribute__((always_inline)) void pair_chunk_fill_dim(const long *slot, int m, const struct kernel *kern,
                                                                  const double *restrict const *x,
                                                                  const double *restrict vol, const double *xi,
                                                                  const int dim, const enum pair_chunk_kernel which,
                                                                  struct pair_chunk *c) {
  double dx[3][PAIR_CHUNK], r2[PAIR_CHUNK], fv[PAIR_CHUNK];
  const double support2 = kern->support2;
  for (int k = 0; k < m; k++) {
    double s = 0;
    for (int d = 0; d < dim; d++) {
      dx[d][k] = xi[d] - x[d][slot[k]];
      s += dx[d][k] * dx[d][k];
    }
    r2[k] = s;
  }
  const int gaussian = kern->kind == KERNEL_GAUSSIAN;
  if (which == CHUNK_F && gaussian)
    for (int k = 0; k < m; k++) fv[k] = kernel_f_gaussian(kern, r2[k]) * vol[slot[k]];
  else if (which == CHUNK_F)
    for (int k = 0; k < m; k++) fv[k] = kernel_f_wendland(kern, r2[k]) * vol[slot[k]];
  else if (gaussian)
    for (int k = 0; k < m; k++) fv[k] = kernel_w_gaussian(kern, r2[k]) * vol[slot[k]];
  else
    for (int k = 0; k < m; k++) fv[k] = kernel_w_wendland(kern, r2[k]) * vol[slot[k]];
  int n = 0;
  for (int k = 0; k < m; k++) {   /* keep the pairs within the support, in the slots' order */
    c->j[n] = slot[k];
    for (int d = 0; d < dim; d++) c->dx[d][n] = dx[d][k];
    c->r2[n] = r2[k];
    c->fv[n] = fv[k];
    n += r2[k] < support2;
  }
  c->n = n;
}

/** The chunk c of the m slots `slot` around the point xi [m] (`which` a literal where inlined, so
 *  the loops specialise; each dimension has its loops, unrolled over the axes): separations,
 *  squared distances and which (F or W) times vol[j] [m^dim], then the pairs within the support
 *  kept in the slots' order. */
static inline __attribute__((always_inline)) void pair_chunk_fill(const long *slot, int m, const struct kernel *kern,
                                                                  const double *restrict const *x,
                                                                  const double *restrict vol, const double *xi,
                                                                  const int dim, const enum pair_chunk_kernel which,
                                                                  struct pair_chunk *c) {
  if (dim == 3) pair_chunk_fill_dim(slot, m, kern, x, vol, xi, 3, which, c);
  else pair_chunk_fill_dim(slot, m, kern, x, vol, xi, 2, which, c);
}

/** The positions x of the particles p (the arrays of their axes) and the position xi of slot i [m]. */
static inline void pair_chunk_centre(const struct parts *p, long i, const double **x, double *xi) {
  for (int d = 0; d < 3; d++) {
    x[d] = p->x[d];
    xi[d] = d < p->dim ? p->x[d][i] : 0.0;
  }
}

/** The next chunk c of pairs of the particle at xi [m] from its list `it` (consumed), with
 *  fv = F V_j or W V_j (which): 0 when the list is exhausted; a chunk may hold no pair (every
 *  neighbour of its word beyond the support). */
static inline __attribute__((always_inline)) int pair_chunk_next(struct neighbours *it, const struct kernel *kern,
                                                                 const double *restrict const *x,
                                                                 const double *restrict vol, const double *xi,
                                                                 const int dim, const enum pair_chunk_kernel which,
                                                                 struct pair_chunk *c) {
  long slot[PAIR_CHUNK];
  const int m = pair_chunk_slots(it, slot);
  if (m) pair_chunk_fill(slot, m, kern, x, vol, xi, dim, which, c);
  return m > 0;
}

#endif
