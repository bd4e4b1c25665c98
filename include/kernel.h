/* kernel.h — SPH smoothing kernels: Gaussian with 3h cut-off (paper 000 Eq. 8), Wendland C2. */
#ifndef MPSPH_KERNEL_H
#define MPSPH_KERNEL_H

#include <math.h>
#include "case.h"

/** A kernel of smoothing length h in `dim` dimensions, ready for evaluation. */
struct kernel {
  enum kernel_kind kind;
  int dim;
  double h;         /* smoothing length [m] */
  double support;   /* cut-off radius [m]: 3h (Gaussian) or 2h (Wendland C2) */
  double support2;  /* support^2 [m^2] */
  double inv_h2;    /* 1/h^2 [1/m^2] */
  double norm;      /* W = norm * shape(q) [1/m^dim] */
  double c0;        /* Gaussian: exp(-eps^2), subtracted so that W(support) = 0 */
};

/** Set up kernel `kind` in `dim` dimensions with smoothing length h [m]. */
void kernel_init(struct kernel *k, enum kernel_kind kind, int dim, double h);

/** W(r) for r^2 = r2 < support^2 [1/m^dim]. */
static inline double kernel_w(const struct kernel *k, double r2) {
  if (k->kind == KERNEL_GAUSSIAN) return k->norm * (exp(-r2 * k->inv_h2) - k->c0);
  double q = sqrt(r2 * k->inv_h2), a = 1.0 - 0.5 * q;
  return k->norm * a * a * a * a * (2.0 * q + 1.0);
}

/** F(r) = W'(r)/r for r^2 = r2 < support^2, so that grad_i W_ij = F (r_i - r_j) [1/m^(dim+2)]. */
static inline double kernel_f(const struct kernel *k, double r2) {
  if (k->kind == KERNEL_GAUSSIAN) return -2.0 * k->inv_h2 * k->norm * exp(-r2 * k->inv_h2);
  double q = sqrt(r2 * k->inv_h2), a = 1.0 - 0.5 * q;
  return -5.0 * k->inv_h2 * k->norm * a * a * a;
}

#endif
