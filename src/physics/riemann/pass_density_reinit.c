/* pass_density_reinit.c — density re-initialisation of scheme riemann, once per advection step
 * (paper 002 Eqs. 10-11, notes seed-002 sections 1.5 and A12):
 * (light: a gas phase, i.e. not `incompressible`, lighter than another phase; heavy: every other)
 *   heavy phase i (free-surface type, every other phase ignored: i's own phase and the walls):
 *     rho_sum = rho0_i (W(0) + sum_{j of i's phase or wall} W_ij) / sigma0,
 *     rho_i   = rho_sum + max(0, rho*_i - rho_sum) rho0_i / rho*_i,
 *   light phase i (internal-flow type, every neighbour counted):
 *     rho_i   = rho0_i (W(0) + sum_j W_ij) / sigma0,
 * rho* the density from the continuity equation, sigma0 the same sum on the undisturbed lattice
 * (self term included), and p from the phase's EOS. A neighbour j counts as V0_j/V0_i lattice sites
 * of i's (notes A12; V0 the lattice volume, (dx_ratio dx)^dim, dx^dim for a wall ghost) and its W_ij
 * has the pair's kernel (riemann_pair_kernel); sigma0 is i's phase's sum with its own kernel on its
 * own lattice. At single resolution every V0_j/V0_i is 1 and every kernel the same. With one heavy phase
 * this is the paper's Eq. 10; with several (liquid-liquid) each one's interface with another liquid
 * is treated as its interface with the light phase is, so the rows of two liquids placed on offset
 * lattices do not read as compression (doc/theory.md section 10). */
#include <math.h>
#include "physics/eos.h"
#include "physics/passes.h"
#include "physics/riemann.h"

double lattice_kernel_sum(const struct kernel *k, double dx) {
  int n = (int)ceil(k->support / dx), dim = k->dim;
  double sum = 0;
  for (int a = -n; a <= n; a++)
    for (int b = -n; b <= n; b++)
      for (int c = dim == 3 ? -n : 0; c <= (dim == 3 ? n : 0); c++) {
        double r2 = dx * dx * (double)(a * a + b * b + c * c);
        if (r2 < k->support2) sum += kernel_w(k, r2);
      }
  return sum;
}

int riemann_light_phase(const struct case_def *c, int ph) {
  if (c->phases[ph].incompressible) return 0;
  for (int k = 0; k < c->n_phases; k++)
    if (c->phases[k].rho0 > c->phases[ph].rho0) return 1;
  return 0;
}

/* Re-initialised density and pressure of fluid particle i. */
static void reinit_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  struct parts *p = ctx->p;
  const int ph = p->phase[i], light = riemann_light_phase(ctx->c, ph);
  const struct phase *f = &ctx->c->phases[ph];
  const struct physics_params *prm = ctx->prm;
  double sum = kernel_w(&prm->phase_kern[ph], 0.0);
  long n = 0;
  struct neighbours it = *nb;
  for (long j; neighbours_next(&it, &j);) {
    const int phj = p->phase[j];
    if (!light && !part_has(phj, KIND_BOUNDARY) && phj != ph) continue;
    const struct kernel *k = riemann_pair_kernel(prm, ph, phj);
    double dx[3], r2 = pair_separation(p, p->dim, i, j, dx);
    if (r2 >= k->support2) continue;
    sum += (phj >= 0 ? prm->phase_vol0[phj] : prm->vol0) / prm->phase_vol0[ph] * kernel_w(k, r2);
    n++;
  }
  double rho_sum = f->rho0 * sum / prm->lattice_w_sum[ph], rho = p->rho[i];
  p->rho[i] = light ? rho_sum : rho_sum + fmax(0.0, rho - rho_sum) * f->rho0 / rho;
  p->p[i] = eos_pressure(f, p->rho[i]);
  ctx->out.pairs += n;
}

void pass_density_reinit(struct pass_ctx *ctx) { pass_for_each_owned(ctx, reinit_of, NULL); }
