/* eos.h — Tait equation of state per phase: p = B((rho/rho0)^gamma - 1) + p_b, B = rho0 c0^2/gamma. */
#ifndef MPSPH_EOS_H
#define MPSPH_EOS_H

#include <math.h>
#include "case/case.h"

/** Pressure [Pa] of phase ph at density rho [kg/m^3]. */
static inline double eos_pressure(const struct phase *ph, double rho) {
  double b = ph->rho0 * ph->c0 * ph->c0 / ph->gamma;
  return b * (pow(rho / ph->rho0, ph->gamma) - 1.0) + ph->p_background;
}

/** Density [kg/m^3] of phase ph at pressure p [Pa] (inverse EOS). */
static inline double eos_density(const struct phase *ph, double p) {
  double b = ph->rho0 * ph->c0 * ph->c0 / ph->gamma;
  return ph->rho0 * pow(1.0 + (p - ph->p_background) / b, 1.0 / ph->gamma);
}

#endif
