/* pass_density_gradient.c — renormalised density gradient (paper 000 Eq. 7, Randles & Libersky):
 * <grad rho>_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j, L_i = [sum_j r_ji (x) grad_i W_ij V_j]^-1,
 * both sums over the phase of i only. A near-singular matrix falls back to L = I. */
#include <math.h>
#include "passes.h"

#define RENORM_MIN_DET 0.1   /* det of the matrix below which L falls back to the identity */

/* Solve M x = b for a dim x dim matrix (row-major); returns det(M). */
static double solve_small(int dim, const double *m, const double *b, double *x) {
  if (dim == 2) {
    double det = m[0] * m[3] - m[1] * m[2];
    x[0] = (m[3] * b[0] - m[1] * b[1]) / det;
    x[1] = (m[0] * b[1] - m[2] * b[0]) / det;
    return det;
  }
  double c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8], c02 = m[3] * m[7] - m[4] * m[6];
  double det = m[0] * c00 + m[1] * c01 + m[2] * c02;
  double inv[9] = {c00, m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
                   c01, m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
                   c02, m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]};
  for (int a = 0; a < 3; a++) x[a] = (inv[3 * a] * b[0] + inv[3 * a + 1] * b[1] + inv[3 * a + 2] * b[2]) / det;
  return det;
}

/* Gradient of particle i: accumulates the same-phase matrix and difference sum. Inlined with a
 * literal dim so that the loops over components unroll. */
static inline __attribute__((always_inline)) int gradient_of(struct engine *e, long i,
                                                             const struct neighbour_ranges *r,
                                                             long *pairs, const int dim) {
  struct parts *p = &e->p;
  const int ph = p->phase[i];
  const double *vol = e->w.vol;
  double mt[9] = {0}, g[3] = {0}, out[3];
  for (int k = 0; k < r->n; k++)
    for (long j = r->start[k]; j < r->start[k] + r->count[k]; j++) {
      if (p->phase[j] != ph || j == i) continue;
      double dx[3], r2 = 0;
      for (int d = 0; d < dim; d++) {
        dx[d] = p->x[d][i] - p->x[d][j];
        r2 += dx[d] * dx[d];
      }
      if (r2 >= e->kern.support2) continue;
      double fv = kernel_f(&e->kern, r2) * vol[j], drho = p->rho[j] - p->rho[i];
      for (int a = 0; a < dim; a++) {
        g[a] += drho * fv * dx[a];
        for (int b = 0; b < dim; b++) mt[a * dim + b] -= fv * dx[a] * dx[b];  /* (M)_ab = B_ba */
      }
      (*pairs)++;
    }
  double det = solve_small(dim, mt, g, out);
  int fallback = !(fabs(det) >= RENORM_MIN_DET);
  for (int d = 0; d < dim; d++) e->w.grad_rho[d][i] = fallback ? g[d] : out[d];
  return fallback;
}

/* Volumes m/rho of all slots (owned and halo) for this stage's pair passes. */
static void update_volumes(struct engine *e) {
  const struct parts *p = &e->p;
  for (long i = 0, n = p->n_owned + p->n_halo; i < n; i++) e->w.vol[i] = p->m[i] / p->rho[i];
}

void pass_density_gradient(struct engine *e) {
  struct parts *p = &e->p;
  const struct space *s = &e->space;
  long pairs = 0, fallbacks = 0;
  update_volumes(e);
  for (long k = 0; k < s->n_owned_cells; k++) {
    long c = s->owned_cells[k];
    if (!s->cell_count[c]) continue;
    struct neighbour_ranges r;
    neighbour_ranges(s, c, &r);
    for (long i = s->cell_start[c]; i < s->cell_start[c] + s->cell_count[c]; i++) {
      if (p->phase[i] == PHASE_WALL) {
        for (int d = 0; d < p->dim; d++) e->w.grad_rho[d][i] = 0;
        continue;
      }
      fallbacks += p->dim == 2 ? gradient_of(e, i, &r, &pairs, 2) : gradient_of(e, i, &r, &pairs, 3);
    }
  }
  e->pass_pairs += pairs;
  e->renorm_fallbacks += fallbacks;
}
