/* pass_fluid_rhs.c — right-hand sides of owned fluid particles (paper 000 Eqs. 5, 6, 9, 10 with
 * the delta-u terms off):
 *   drho_i/dt = -rho_i sum_j (u_j - u_i).grad_i W_ij V_j + delta h c0 sum_{j in phase(i)} psi_ij (-F_ij) V_j
 *   psi_ij    = 2 (rho_j - rho_i) - (<grad rho>_i + <grad rho>_j).r_ji
 *   du_i/dt   = [-sum_j (p_j + p_i) grad_i W_ij V_j + K sum_{j in phase(i) or wall} pi_ij grad_i W_ij V_j] / rho_i + g
 *   pi_ij     = u_ji.r_ji / |r_ji|^2,  K = alpha h c0 rho0 + 2(dim+2) mu.
 * grad_i W_ij = F_ij (r_i - r_j) with F = W'(r)/r. */
#include "passes.h"

/* Per-particle constants of the phase of i. */
struct phase_coef {
  double diffusion;   /* delta h c0 [m^2/s] */
  double viscosity;   /* K [Pa s] */
};

static struct phase_coef coefficients(const struct engine *e, int ph) {
  const struct phase *f = &e->c->phases[ph];
  struct phase_coef k;
  k.diffusion = e->c->delta * e->h * f->c0;
  k.viscosity = e->c->alpha * e->h * f->c0 * f->rho0 + 2.0 * (e->p.dim + 2) * f->viscosity;
  return k;
}

/* Sums over the neighbours of fluid particle i. */
struct fluid_sums {
  double div, diff, grad_p[3], visc[3];
};

/* Inlined with a literal dim so that the loops over components unroll. */
static inline __attribute__((always_inline)) void fluid_sums(const struct engine *e, long i,
                                                             const struct neighbour_ranges *r,
                                                             struct fluid_sums *s, long *pairs,
                                                             const int dim) {
  const struct parts *p = &e->p;
  const int ph = p->phase[i];
  const double *vol = e->w.vol;
  *s = (struct fluid_sums){0};
  for (int k = 0; k < r->n; k++)
    for (long j = r->start[k]; j < r->start[k] + r->count[k]; j++) {
      double dx[3], dv[3], r2 = 0, dvdx = 0;
      for (int d = 0; d < dim; d++) {
        dx[d] = p->x[d][i] - p->x[d][j];
        dv[d] = p->v[d][j] - p->v[d][i];
        r2 += dx[d] * dx[d];
        dvdx += dv[d] * dx[d];
      }
      if (r2 >= e->kern.support2 || j == i) continue;
      (*pairs)++;
      double fv = kernel_f(&e->kern, r2) * vol[j];
      double psum = p->p[j] + p->p[i];
      s->div += fv * dvdx;
      for (int d = 0; d < dim; d++) s->grad_p[d] += psum * fv * dx[d];
      int same = p->phase[j] == ph;
      if (!same && p->phase[j] != PHASE_WALL) continue;
      double pi_ij = -dvdx / r2;   /* u_ji . r_ji / r^2 with r_ji = -dx */
      for (int d = 0; d < dim; d++) s->visc[d] += pi_ij * fv * dx[d];
      if (!same) continue;
      double gsum = 0;
      for (int d = 0; d < dim; d++) gsum -= (e->w.grad_rho[d][i] + e->w.grad_rho[d][j]) * dx[d];
      s->diff -= (2.0 * (p->rho[j] - p->rho[i]) - gsum) * fv;
    }
}

void pass_fluid_rhs(struct engine *e) {
  struct parts *p = &e->p;
  const struct space *s = &e->space;
  long pairs = 0;
  for (long k = 0; k < s->n_owned_cells; k++) {
    long c = s->owned_cells[k];
    if (!s->cell_count[c]) continue;
    struct neighbour_ranges r;
    neighbour_ranges(s, c, &r);
    for (long i = s->cell_start[c]; i < s->cell_start[c] + s->cell_count[c]; i++) {
      if (p->phase[i] == PHASE_WALL) continue;
      struct fluid_sums sum;
      struct phase_coef coef = coefficients(e, p->phase[i]);
      if (p->dim == 2) fluid_sums(e, i, &r, &sum, &pairs, 2);
      else fluid_sums(e, i, &r, &sum, &pairs, 3);
      e->w.drho[i] = -p->rho[i] * sum.div + coef.diffusion * sum.diff;
      for (int d = 0; d < p->dim; d++)
        e->w.dv[d][i] = (-sum.grad_p[d] + coef.viscosity * sum.visc[d]) / p->rho[i] + e->c->gravity[d];
    }
  }
  e->pass_pairs += pairs;
}
