/* riemann.h — the linearised (acoustic) Riemann solver of scheme riemann (paper 002 Eqs. 7-9,
 * Zhang, Hu & Adams 2017) with the dissipation limiter, written with acoustic impedances
 * Z = rho c so that phases of different sound speeds couple; with one sound speed for every phase
 * (the paper's choice) it is the printed density-weighted form. */
#ifndef MPSPH_RIEMANN_H
#define MPSPH_RIEMANN_H

#include <math.h>
#include "physics/pass_ctx.h"

/** The limiter coefficient of Eq. 8: beta = min(RIEMANN_LIMITER max(U_L - U_R, 0), c). */
#define RIEMANN_LIMITER 3.0

/** Interface pressure p* [Pa] of the pair problem between left (impedance zl = rho_l c_l [kg/m^2 s],
 *  pressure pl [Pa]) and right (zr, pr) with the approach speed du = U_L - U_R [m/s] along the
 *  pair axis and the pair's mean sound speed c = (zl + zr)/(rho_l + rho_r) [m/s] (Eq. 8):
 *    p* = (zl pr + zr pl + zl zr du min(RIEMANN_LIMITER max(du, 0)/c, 1)) / (zl + zr).
 *  For c_l = c_r = c: (rho_l pr + rho_r pl + rho_l rho_r beta du)/(rho_l + rho_r). Symmetric
 *  under left <-> right (du is). */
static inline double riemann_pressure(double zl, double pl, double zr, double pr, double du, double c) {
  double limited = fmin(RIEMANN_LIMITER * fmax(du, 0.0) / c, 1.0);
  return (zl * pr + zr * pl + zl * zr * du * limited) / (zl + zr);
}

/** Multi-resolution (paper 002 section 3.5): the kernel of the pair of fluid particle i of phase
 *  ph_i and slot j of phase phase_j, the one of the larger smoothing length (h^chi = max(h_i, h_j),
 *  the same both ways, so the pair forces stay antisymmetric); a wall ghost or solid particle
 *  (phase_j < 0) takes i's. */
static inline const struct kernel *riemann_pair_kernel(const struct physics_params *prm, int ph_i, int phase_j) {
  const struct kernel *ki = &prm->phase_kern[ph_i];
  return phase_j >= 0 && prm->phase_kern[phase_j].h > ki->h ? &prm->phase_kern[phase_j] : ki;
}

#endif
