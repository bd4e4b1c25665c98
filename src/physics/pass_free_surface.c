/* pass_free_surface.c — free-surface detection of Marrone, Colagrossi, Le Touzé & Graziani 2010
 * (JCP 229:3652), the method cited by paper 000:
 *  1. lambda_i = smallest eigenvalue of B_i = sum_j r_ji (x) grad_i W_ij V_j over all neighbours
 *     (every phase and the wall ghosts, so that walls and interfaces are not free surfaces);
 *     lambda <= 0.2: free surface; lambda > 0.75: interior; otherwise a candidate;
 *  2. normal n_i = nu/|nu|, nu = -B_i^-1 sum_j grad_i W_ij V_j; a candidate is a free-surface
 *     particle unless a neighbour lies in the umbrella-shaped region around T = r_i + h n_i:
 *     |r_ji| >= sqrt(2) h and |r_j - T| < h, or |r_ji| < sqrt(2) h and
 *     |n.(r_j - T)| + |(r_j - T) - n (n.(r_j - T))| < h.
 * The free-surface region is the detected particles plus those within surface_band h of one. */
#include <math.h>
#include "physics/linalg.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"

#define LAMBDA_SURFACE 0.2
#define LAMBDA_INTERIOR 0.75
#define SINGULAR_DET 1e-3   /* det(B) below which the normal is -sum grad W itself */

/* B matrix and sum of kernel gradients of particle i over all neighbours, in `dim` dimensions (a
 * literal where inlined). */
static inline __attribute__((always_inline)) void moments_dim(const struct pass_ctx *ctx, long i,
                                                              const struct neighbours *nb, double *mt,
                                                              double *sum_gw, long *pairs, const int dim) {
  const double *restrict x[3] = {ctx->p->x[0], ctx->p->x[1], ctx->p->x[2]};
  double xi[3];
  for (int d = 0; d < dim; d++) xi[d] = x[d][i];
  for (int k = 0; k < 9; k++) mt[k] = 0;
  for (int d = 0; d < 3; d++) sum_gw[d] = 0;
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, ctx->w->vol, xi, dim, CHUNK_F, &c)) {
    for (int k = 0; k < c.n; k++)
      for (int a = 0; a < dim; a++) {
        sum_gw[a] += c.fv[k] * c.dx[a][k];
        for (int b = 0; b < dim; b++) mt[a * dim + b] -= c.fv[k] * c.dx[a][k] * c.dx[b][k];
      }
    *pairs += c.n;
  }
}

/* moments_dim in the particles' dimension. */
static void moments(const struct pass_ctx *ctx, long i, const struct neighbours *nb, double *mt,
                    double *sum_gw, long *pairs) {
  if (ctx->p->dim == 3) moments_dim(ctx, i, nb, mt, sum_gw, pairs, 3);
  else moments_dim(ctx, i, nb, mt, sum_gw, pairs, 2);
}

/* Outward unit normal -B^-1 sum grad W (or -sum grad W where B is singular); 0 if undefined. */
static void outward_normal(int dim, const double *mt, const double *sum_gw, double *n) {
  double nu[3] = {0, 0, 0}, len = 0;
  double det = linalg_solve(dim, mt, sum_gw, nu);
  for (int d = 0; d < dim; d++) nu[d] = fabs(det) > SINGULAR_DET ? -nu[d] : -sum_gw[d];
  for (int d = 0; d < dim; d++) len += nu[d] * nu[d];
  len = sqrt(len);
  for (int d = 0; d < dim; d++) n[d] = len > 0 ? nu[d] / len : 0;
}

/* 1 if some neighbour lies in the umbrella region above candidate i (so i is not on the surface). */
static int umbrella_covered(const struct pass_ctx *ctx, long i, const struct neighbours *nb,
                            const double *n) {
  const struct parts *p = ctx->p;
  const int dim = p->dim;
  const double h = ctx->prm->h;
  double t[3];
  for (int d = 0; d < dim; d++) t[d] = p->x[d][i] + h * n[d];
  struct neighbours it = *nb;
  for (long j; neighbours_next(&it, &j);) {
    double rij2 = 0, rt[3], rt2 = 0, rn = 0;
    for (int d = 0; d < dim; d++) {
      double dij = p->x[d][j] - p->x[d][i];
      rij2 += dij * dij;
      rt[d] = p->x[d][j] - t[d];
      rt2 += rt[d] * rt[d];
      rn += rt[d] * n[d];
    }
    if (rij2 >= ctx->prm->kern.support2) continue;
    if (rij2 >= 2 * h * h) {
      if (rt2 < h * h) return 1;
    } else if (fabs(rn) + sqrt(fmax(rt2 - rn * rn, 0.0)) < h) {
      return 1;
    }
  }
  return 0;
}

/* Classify owned fluid particle i. */
static void detect(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const int dim = ctx->p->dim;
  double mt[9], sum_gw[3], n[3];
  moments(ctx, i, nb, mt, sum_gw, &ctx->out.pairs);
  double lambda = linalg_min_eigenvalue(dim, mt);
  outward_normal(dim, mt, sum_gw, n);
  int surface = lambda <= LAMBDA_SURFACE;
  if (!surface && lambda <= LAMBDA_INTERIOR) surface = !umbrella_covered(ctx, i, nb, n);
  ctx->w->surface[i] = surface;
  ctx->w->lambda[i] = lambda;
  for (int d = 0; d < dim; d++) ctx->w->normal[d][i] = n[d];
  ctx->out.n_surface += surface;
}

/* A wall ghost is never on the free surface. */
static void clear_wall(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  (void)nb;
  ctx->w->surface[i] = 0;
  ctx->w->region[i] = 0;
  ctx->w->lambda[i] = 1;
}

void pass_free_surface(struct pass_ctx *ctx) { pass_for_each_owned(ctx, detect, clear_wall); }

/* 1 if fluid particle i lies within surface_band h of a detected particle (or is one). */
static void band_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  double band = fmin(ctx->c->surface_band * ctx->prm->h, ctx->prm->kern.support), band2 = band * band;
  int in = ctx->w->surface[i] > 0;
  struct neighbours it = *nb;
  for (long j; !in && neighbours_next(&it, &j);) {
    if (ctx->w->surface[j] <= 0) continue;
    double r2 = 0;
    for (int d = 0; d < p->dim; d++) r2 += (p->x[d][i] - p->x[d][j]) * (p->x[d][i] - p->x[d][j]);
    in = r2 < band2;
  }
  ctx->w->region[i] = in;
}

void pass_surface_band(struct pass_ctx *ctx) { pass_for_each_owned(ctx, band_of, NULL); }
