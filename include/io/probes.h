/* probes.h — the probes of the case read from the particles: pressure sensors (point or segment,
 * Shepard or first-order MLS), wave gauges (top of a phase along a vertical line) and per-phase
 * integrals; one probes.csv row per call. */
#ifndef MPSPH_PROBES_H
#define MPSPH_PROBES_H

#include <stdio.h>
#include "engine/engine.h"

/** Kernel-weighted moments around a point x for Shepard and first-order moving-least-squares
 *  (linear-corrected) interpolation: m = sum W V [1, r][1, r]^T, b = sum W V f [1, r], with
 *  r = x_j - x in any length unit used consistently (the caller divides by h). */
struct probe_sums {
  int dim;
  double m[4][4], b[4];
};

/** Start empty sums in dimension dim. */
void probe_sums_init(struct probe_sums *s, int dim);

/** Add neighbour j: offset r = x_j - x [length], weight wv = W_ij V_j [-], value f. */
void probe_sums_add(struct probe_sums *s, const double *r, double wv, double f);

/** Shepard interpolation sum W V f / sum W V (0 with no neighbour). */
double probe_sums_shepard(const struct probe_sums *s);

/** First-order MLS: the constant term a of the weighted least-squares fit f ~ a + g.r, exact for
 *  a linear field; falls back to Shepard when the moment matrix is near singular (the
 *  neighbours lie on a line, or fewer than dim + 1). */
double probe_sums_mls(const struct probe_sums *s);

/** Write the probes.csv header (step, time, the columns of every probe) to f (the caller
 *  flushes it). */
void probes_write_header(FILE *f, const struct case_def *c);

/** Evaluate every probe (collective) and, on rank 0, append the row of the current step and
 *  time to f: pressure [Pa], elevation [m] (nan when the phase is absent from the line) and,
 *  per integral, volume [m^dim], kinetic and potential energy [J, per metre in 2D] and centre
 *  of mass [m]. The caller flushes f. */
void probes_write_row(struct engine *e, FILE *f);

#endif
