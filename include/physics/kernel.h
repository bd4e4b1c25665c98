/* kernel.h — SPH smoothing kernels: Gaussian with 3h cut-off (paper 000 Eq. 8), Wendland C2. */
#ifndef MPSPH_KERNEL_H
#define MPSPH_KERNEL_H

#include <math.h>
#include <stdint.h>
#include "case/case.h"

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

/** 2^(j/32), j = 0..31, correctly rounded (computed with 60-digit decimal arithmetic). */
static const double kernel_exp2_table[32] = {
    0x1.0000000000000p+0, 0x1.059b0d3158574p+0, 0x1.0b5586cf9890fp+0, 0x1.11301d0125b51p+0,
    0x1.172b83c7d517bp+0, 0x1.1d4873168b9aap+0, 0x1.2387a6e756238p+0, 0x1.29e9df51fdee1p+0,
    0x1.306fe0a31b715p+0, 0x1.371a7373aa9cbp+0, 0x1.3dea64c123422p+0, 0x1.44e086061892dp+0,
    0x1.4bfdad5362a27p+0, 0x1.5342b569d4f82p+0, 0x1.5ab07dd485429p+0, 0x1.6247eb03a5585p+0,
    0x1.6a09e667f3bcdp+0, 0x1.71f75e8ec5f74p+0, 0x1.7a11473eb0187p+0, 0x1.82589994cce13p+0,
    0x1.8ace5422aa0dbp+0, 0x1.93737b0cdc5e5p+0, 0x1.9c49182a3f090p+0, 0x1.a5503b23e255dp+0,
    0x1.ae89f995ad3adp+0, 0x1.b7f76f2fb5e47p+0, 0x1.c199bdd85529cp+0, 0x1.cb720dcef9069p+0,
    0x1.d5818dcfba487p+0, 0x1.dfc97337b9b5fp+0, 0x1.ea4afa2a490dap+0, 0x1.f50765b6e4540p+0};

/** exp(x) for -700 < x <= 0, inline so that the pair loops need no library call:
 *  x = (32 m + j) ln2/32 + r with |r| <= ln2/64 (ln2/32 split in two parts so that the product
 *  with the integer is exact), exp(x) = 2^m 2^(j/32) exp(r), exp(r) by its Taylor polynomial of
 *  degree 6 (truncation below 4e-18 relative) in Estrin form for a short dependency chain.
 *  Within 3 ulp of libm's exp; test_kernel checks it. */
static inline double kernel_exp(double x) {
  const double n_ln2 = 46.16624130844683, ln2_n_hi = 0.021660849393811077,
               ln2_n_lo = -1.312785960212839e-12, shifter = 6755399441055744.0;   /* 1.5 * 2^52 */
  double kd = x * n_ln2 + shifter;
  union { double d; int64_t i; } bits = {.d = kd};
  int64_t k = bits.i - (int64_t)0x4338000000000000;   /* nearest integer of 32 x / ln2 */
  kd -= shifter;
  double r = (x - kd * ln2_n_hi) - kd * ln2_n_lo, r2 = r * r;
  double poly = (1.0 + r) + r2 * ((0.5 + r * (1.0 / 6)) + r2 * ((1.0 / 24 + r * (1.0 / 120)) + r2 * (1.0 / 720)));
  union { double d; int64_t i; } scale = {.i = ((k >> 5) + 1023) << 52};
  return poly * kernel_exp2_table[k & 31] * scale.d;
}

/** W(r) of the Gaussian for r^2 = r2 < support^2 [1/m^dim]. */
static inline double kernel_w_gaussian(const struct kernel *k, double r2) {
  return k->norm * (kernel_exp(-r2 * k->inv_h2) - k->c0);
}

/** W(r) of the Wendland C2 kernel for r^2 = r2 < support^2 [1/m^dim]. */
static inline double kernel_w_wendland(const struct kernel *k, double r2) {
  double q = sqrt(r2 * k->inv_h2), a = 1.0 - 0.5 * q;
  return k->norm * a * a * a * a * (2.0 * q + 1.0);
}

/** W(r) of kernel k's kind for r^2 = r2 < support^2 [1/m^dim]. */
static inline double kernel_w(const struct kernel *k, double r2) {
  return k->kind == KERNEL_GAUSSIAN ? kernel_w_gaussian(k, r2) : kernel_w_wendland(k, r2);
}

/** F(r) = W'(r)/r of the Gaussian for r^2 = r2 < support^2, so that grad_i W_ij = F (r_i - r_j)
 *  [1/m^(dim+2)]. */
static inline double kernel_f_gaussian(const struct kernel *k, double r2) {
  return -2.0 * k->inv_h2 * k->norm * kernel_exp(-r2 * k->inv_h2);
}

/** kernel_f of the Wendland C2 kernel. */
static inline double kernel_f_wendland(const struct kernel *k, double r2) {
  double q = sqrt(r2 * k->inv_h2), a = 1.0 - 0.5 * q;
  return -5.0 * k->inv_h2 * k->norm * a * a * a;
}

/** F(r) of kernel k's kind. */
static inline double kernel_f(const struct kernel *k, double r2) {
  return k->kind == KERNEL_GAUSSIAN ? kernel_f_gaussian(k, r2) : kernel_f_wendland(k, r2);
}

#endif
