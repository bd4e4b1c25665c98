/* pass_surface_tension.c — continuum surface force between the fluid phases (Brackbill et al.
 * 1992, J. Comput. Phys. 100:335) in SPH, for fluid i and fluid neighbours j (wall ghosts
 * excluded; all other phases count as one):
 *   grad chi_i = sum_{j other phase} grad_i W_ij V_j                (colour gradient, Morris 2000),
 *   n_i = grad chi_i / |grad chi_i|  where |grad chi_i| h >= 0.01, else n_i = 0,
 *   G_i = sum_{j: n_j != 0} (phi_ij n_j - n_i) (x) grad_i W_ij V_j,  phi_ij = +1 same phase, -1 other,
 *   B_i = sum_{j: n_j != 0} r_ji (x) grad_i W_ij V_j,
 *   kappa_i = trace(G_i B_i^-1)   (dim trace G / trace B, Adami et al. 2010, where det B < 0.1),
 *   du_i/dt += -sigma kappa_i n_i |grad chi_i| / rho_i.
 * n points toward the other phase and kappa = div n, so the force points to the centre of
 * curvature on both sides. The force per volume is the same on both sides of the interface
 * (the colour is not density-weighted as in Adami et al. 2010 and paper 004 Eq. 11): it is the
 * weighting that balances the pressure gradient -sum_j (p_j + p_i) grad_i W_ij V_j of this
 * scheme, which is not density-weighted either. See doc/theory.md section 4d. */
#include <math.h>
#include "physics/linalg.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"

#define COLOUR_GRAD_MIN 0.01     /* |grad chi| h below which a particle has no interface normal */
#define CURVATURE_MIN_DET 0.1    /* det of B below which the curvature takes Adami's scalar form */

/* The colour gradient of owned fluid particle i, grad chi_i = sum_{j other phase} grad_i W_ij V_j
 * [1/m], in `dim` dimensions (a literal where inlined). Returns the number of pairs within the
 * support. */
static inline __attribute__((always_inline)) long colour_gradient_dim(const struct pass_ctx *ctx, long i,
                                                                      const struct neighbours *nb, double *grad_chi,
                                                                      const int dim) {
  const struct parts *p = ctx->p;
  const int ph = p->phase[i];
  long pairs = 0;
  double xi[3];
  const double *x[3];
  pair_chunk_centre(p, i, x, xi);
  for (int d = 0; d < dim; d++) grad_chi[d] = 0;
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, ctx->w->vol, xi, dim, CHUNK_F, &c)) {
    pairs += c.n;
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      if (p->phase[j] == ph || part_has(p->phase[j], KIND_BOUNDARY)) continue;
      for (int d = 0; d < dim; d++) grad_chi[d] += c.fv[k] * c.dx[d][k];
    }
  }
  return pairs;
}

/* colour_gradient_dim in the particles' dimension. */
static long colour_gradient(const struct pass_ctx *ctx, long i, const struct neighbours *nb, double *grad_chi) {
  if (ctx->p->dim == 3) return colour_gradient_dim(ctx, i, nb, grad_chi, 3);
  return colour_gradient_dim(ctx, i, nb, grad_chi, 2);
}

/* Length of a vector of three components (those beyond the dimension 0). */
static double norm_of(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* trace(G B^-1) for symmetric B (row a of G solved against B: trace(A^T) with A^T = B^-1 G^T),
 * or dim trace(G) / trace(B) where det B < CURVATURE_MIN_DET; 0 without neighbours. */
static double renormalised_trace(int dim, const double *g, const double *b) {
  double tg = 0, tb = 0, x[3], tr = 0, det = 1;
  for (int a = 0; a < dim; a++) {
    tg += g[a * dim + a];
    tb += b[a * dim + a];
    det = linalg_solve(dim, b, g + a * dim, x);
    tr += x[a];
  }
  if (det >= CURVATURE_MIN_DET) return tr;
  return tb > 0 ? dim * tg / tb : 0.0;
}

/* Normal and |grad chi| of owned fluid particle i. */
static void interface_normal_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const int dim = ctx->p->dim;
  double grad_chi[3] = {0, 0, 0};   /* the axes beyond dim stay 0 */
  ctx->out.pairs += colour_gradient(ctx, i, nb, grad_chi);
  double g = norm_of(grad_chi);
  int on = g * ctx->prm->h >= COLOUR_GRAD_MIN;
  ctx->w->colour_grad[i] = on ? g : 0.0;
  for (int d = 0; d < dim; d++) ctx->w->interface_normal[d][i] = on ? grad_chi[d] / g : 0.0;
}

/* Wall ghosts carry no interface normal. */
static void clear_ghost(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  (void)nb;
  ctx->w->colour_grad[i] = 0;
  ctx->w->kappa_curvature[i] = 0;
  for (int d = 0; d < ctx->p->dim; d++) ctx->w->interface_normal[d][i] = 0;
}

void pass_interface_normals(struct pass_ctx *ctx) { pass_for_each_owned(ctx, interface_normal_of, clear_ghost); }

/* Curvature div n of owned fluid particle i with a normal [1/m]: with the gradient sums
 * G = sum_j (phi_ij n_j - n_i) (x) grad_i W_ij V_j and B = sum_j r_ji (x) grad_i W_ij V_j over the
 * neighbours that have a normal, div n = trace(G B^-1) (exact for a linear normal field, however
 * one-sided the neighbours), or dim trace(G) / trace(B) where det B < CURVATURE_MIN_DET.
 * Counts the pairs into *pairs. */
static double curvature_of(const struct pass_ctx *ctx, long i, const struct neighbours *nb, long *pairs) {
  const struct parts *p = ctx->p;
  double *const *nrm = ctx->w->interface_normal;
  const int dim = p->dim, ph = p->phase[i];
  double g[9] = {0}, b[9] = {0}, xi[3];   /* row-major dim x dim */
  const double *x[3];
  pair_chunk_centre(p, i, x, xi);
  struct neighbours it = *nb;
  struct pair_chunk ch;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, ctx->w->vol, xi, dim, CHUNK_F, &ch))
    for (int k = 0; k < ch.n; k++) {
      const long j = ch.j[k];
      if (part_has(p->phase[j], KIND_BOUNDARY)) continue;
      double dx[3], phi = p->phase[j] == ph ? 1.0 : -1.0, nj2 = 0;
      pair_chunk_dx(&ch, k, dim, dx);
      for (int d = 0; d < dim; d++) nj2 += nrm[d][j] * nrm[d][j];
      if (nj2 == 0) continue;
      (*pairs)++;
      const double fv = ch.fv[k];
      for (int a = 0; a < dim; a++)
        for (int c = 0; c < dim; c++) {
          g[a * dim + c] += (phi * nrm[a][j] - nrm[a][i]) * fv * dx[c];
          b[a * dim + c] -= dx[a] * fv * dx[c];
        }
    }
  return renormalised_trace(dim, g, b);
}

/* Curvature and CSF acceleration of owned fluid particle i. */
static void surface_tension_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  struct work *w = ctx->w;
  double kappa = w->colour_grad[i] > 0 ? curvature_of(ctx, i, nb, &ctx->out.pairs) : 0.0;
  double a = -ctx->c->surface_tension * kappa * w->colour_grad[i] / ctx->p->rho[i];
  w->kappa_curvature[i] = kappa;
  for (int d = 0; d < ctx->p->dim; d++) w->dv[d][i] += a * w->interface_normal[d][i];
}

void pass_surface_tension(struct pass_ctx *ctx) { pass_for_each_owned(ctx, surface_tension_of, NULL); }

double capillary_dt(const struct case_def *c, double h) {
  double rho_min = INFINITY;
  for (int ph = 0; ph < c->n_phases; ph++) rho_min = fmin(rho_min, c->phases[ph].rho0);
  return 0.25 * sqrt(rho_min * h * h * h / (2.0 * 3.14159265358979323846 * c->surface_tension));
}
