/* pass_shepard_density.c — the density and pressure of the multi-fluid delta-SPH scheme (paper
 * 001 Eqs. 13 and 21, Grenier et al. 2009): a Shepard sum over the particle and its neighbours of
 * its own phase,
 *   rho^S_i = sum_{j in phase(i)} m_j W_ij / sum_{j in phase(i)} V_j W_ij   (j = i included),
 *   p_i = EOS of phase(i) at rho^S_i,
 * with V_j = m_j / rho_j the volumes of the integrated volumetric strain rate (the state density
 * rho = m/V). Restricting both sums to the phase keeps the density of one phase from leaking into
 * the other across an interface (notes seeds-000-001 section 2.4). */
#include "physics/eos.h"
#include "physics/passes.h"

/* Shepard density of owned fluid particle i and its pressure. */
static void shepard_density(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  const double *restrict vol = ctx->w->vol, *restrict m = p->m;
  const int *restrict phase = p->phase;
  const int ph = phase[i], dim = p->dim;
  const double w0 = kernel_w(&ctx->prm->kern, 0.0), support2 = ctx->prm->kern.support2;
  double mass_sum = m[i] * w0, vol_sum = vol[i] * w0;
  long pairs = 0;
  struct neighbours it = *nb;
  for (long j; neighbours_next(&it, &j);) {
    if (phase[j] != ph) continue;
    double dx[3], r2 = pair_separation(p, dim, i, j, dx);
    if (r2 >= support2) continue;
    double w = kernel_w(&ctx->prm->kern, r2);
    mass_sum += m[j] * w;
    vol_sum += vol[j] * w;
    pairs++;
  }
  ctx->w->rho_s[i] = mass_sum / vol_sum;
  ctx->p->p[i] = eos_pressure(&ctx->c->phases[ph], ctx->w->rho_s[i]);
  ctx->out.pairs += pairs;
}

void pass_shepard_density(struct pass_ctx *ctx) { pass_for_each_owned(ctx, shepard_density, NULL); }
