/* kernel.c — kernel normalisation constants. */
#include "physics/kernel.h"

#define GAUSS_EPS 3.0   /* cut-off radius in units of h */
#define PI 3.14159265358979323846

/* Integral over the ball of radius eps (in units of h) of exp(-q^2) - exp(-eps^2). */
static double gaussian_integral(int dim, double eps) {
  double c0 = exp(-eps * eps);
  if (dim == 2) return PI * (1.0 - c0 * (1.0 + eps * eps));
  return pow(PI, 1.5) * erf(eps) - 2.0 * PI * eps * c0 - c0 * 4.0 * PI * eps * eps * eps / 3.0;
}

void kernel_init(struct kernel *k, enum kernel_kind kind, int dim, double h) {
  k->kind = kind;
  k->dim = dim;
  k->h = h;
  k->inv_h2 = 1.0 / (h * h);
  double h_dim = dim == 2 ? h * h : h * h * h;
  if (kind == KERNEL_GAUSSIAN) {
    k->support = GAUSS_EPS * h;
    k->c0 = exp(-GAUSS_EPS * GAUSS_EPS);
    k->norm = 1.0 / (gaussian_integral(dim, GAUSS_EPS) * h_dim);
  } else {
    k->support = 2.0 * h;
    k->c0 = 0.0;
    k->norm = (dim == 2 ? 7.0 / (4.0 * PI) : 21.0 / (16.0 * PI)) / h_dim;
  }
  k->support2 = k->support * k->support;
}
