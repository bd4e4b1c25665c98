/* passes.h — the passes over particles and neighbour pairs that build the right-hand sides. */
#ifndef MPSPH_PASSES_H
#define MPSPH_PASSES_H

#include "engine.h"

/** Ranges of particle slots of the cells around one cell, in global cell order. */
struct neighbour_ranges {
  int n;
  long start[27];
  int count[27];
};

/** The particle ranges of the 3^dim cells around cell c (those present on this rank). */
void neighbour_ranges(const struct space *s, long c, struct neighbour_ranges *r);

/** Wall ghosts: Shepard interpolation of p, u at the mirror point, hydrostatic pressure
 *  correction and free-/no-slip velocity (Marrone et al. 2011). Owned ghosts only. */
void pass_wall_ghosts(struct engine *e);

/** Renormalised density gradient over same-phase neighbours (paper 000 Eq. 7). */
void pass_density_gradient(struct engine *e);

/** Continuity (divergence + delta-SPH diffusion) and momentum (pressure gradient, viscosity,
 *  gravity) right-hand sides of owned fluid particles. */
void pass_fluid_rhs(struct engine *e);

#endif
