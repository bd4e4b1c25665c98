/* init.h — initial particles: fluid regions filled on the lattice, wall ghost layers, ids,
 * hydrostatic pressure and masses. */
#ifndef MPSPH_INIT_H
#define MPSPH_INIT_H

#include <stddef.h>
#include "case/case.h"
#include "base/parts.h"

/** Particle counts of a case (global). */
struct init_counts {
  long fluid[CASE_MAX_PHASES];   /* per phase */
  long n_fluid, n_wall;
};

/** Number of ghost layers (wall thickness / dx) needed for a kernel support of `support` m. */
int init_wall_layers(const struct case_def *c, double support);

/** Generate this rank's share of the particles (node ordinal k goes to rank k % n_ranks; with
 *  p == NULL only count). Ids are the global ordinals, independent of the rank count.
 *  Returns 0, or 1 with a message naming the offending key (overlapping fluid regions, wall
 *  layers leaving the domain, no particle at all). */
int init_particles(const struct case_def *c, double support, int rank, int n_ranks,
                   struct parts *p, struct init_counts *counts, char *err, size_t err_len);

/** An upper bound on the lattice nodes init_particles visits (fluid regions and wall ghost
 *  candidates), hence on the particles it generates, computed without visiting them (infinity
 *  when beyond a double). */
double init_visit_count(const struct case_def *c, double support);

/** Initial gauge pressure [Pa] at x balancing the body forces: with uniform gravity the exact
 *  weight of the fluid regions above x; with a potential or a linear initial velocity field,
 *  integrated along the direction of the balancing acceleration. */
double init_hydrostatic_pressure(const struct case_def *c, const double *x);

#endif
