/* pass_same_phase.c — the right-hand sides of scheme same-phase-continuity (He et al., paper 003
 * Eqs. 23-27; doc/theory.md section "Same-phase continuity"):
 *   drho_i/dt = -rho_i sum_{j in chi_i} (u_j - u_i).gW_ij + delta h c0_i sum_j psi*_ij.gW_ij
 *   du_i/dt   = -(1/rho_i) sum_j (p_i + p*_j) gW_ij + (2(d+2)/rho_i) sum_j mu_ij pi_ij gW_ij + f_i
 * with gW_ij = grad_i W_ij V_j, chi_i the fluid of i's phase, of every phase with a larger rho0
 * (a deviation from Eq. 23: a lighter phase reads a heavier one's velocities, doc/theory.md section
 * 11) and the wall ghosts, the other sums over every neighbour;
 * psi*_ij.gW_ij = 2 (rho*_j - rho_i) r_ji.gW_ij / r^2; for a neighbour of another phase p*_j is
 * its Shepard pressure p~_j (Eq. 26) and rho*_j the density of i's phase at
 * p*_j (Eq. 27, the inverse EOS of i's phase); for a ghost p*_j = p_j and rho*_j likewise (Eq. 38);
 * for i's own phase p*_j = p_j, rho*_j = rho_j. pi_ij = u_ji.r_ji/(r^2 + 0.01 h^2) and mu_ij is the
 * harmonic mean of the phases' mu = alpha h c0 rho0 / (2(d+2)) + viscosity (Eqs. 21-22).
 * A gas particle approaching a wall ghost b is pushed back by paper 003 Eq. 39:
 *   a_i += -c0 [(u_i - u_b).n_b] W_ib h^d n_b / |r_ib.n_b|   when (u_i - u_b).n_b < 0,
 * n_b the unit normal from the ghost toward its mirror point (into the fluid).
 * physics.spc_model: conventional is paper 003's baseline (section 2.3, Eqs. 17-22): the divergence
 * over every neighbour and p*_j = p_j for every j (rho*_j = rho'_j of Eq. 20), no Shepard pass. */
#include <math.h>
#include "physics/eos.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"

/* Shepard pressure of owned fluid particle i over the fluid of every phase (walls excluded). */
static void shepard_pressure(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  const double *restrict vol = ctx->w->vol, *restrict pres = p->p;
  const double w0 = kernel_w(&ctx->prm->kern, 0.0);
  double p_sum = pres[i] * vol[i] * w0, vol_sum = vol[i] * w0, xi[3];
  const double *x[3];
  pair_chunk_centre(p, i, x, xi);
  long pairs = 0;
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, vol, xi, p->dim, CHUNK_W, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      if (part_has(p->phase[j], KIND_BOUNDARY)) continue;
      p_sum += pres[j] * c.fv[k];
      vol_sum += c.fv[k];
      pairs++;
    }
  ctx->w->p_shepard[i] = p_sum / vol_sum;
  ctx->out.pairs += pairs;
}

void pass_shepard_pressure(struct pass_ctx *ctx) { pass_for_each_owned(ctx, shepard_pressure, NULL); }

/* Sums over the neighbours of fluid particle i. */
struct spc_sums {
  double div, diff, grad_p[3], visc[3], repulsion[3];
};

void spc_wall_repulsion(const struct pass_ctx *ctx, long i, long b, double *acc) {
  const struct parts *p = ctx->p;
  const int dim = p->dim;
  double xs[3], n[3], nn = 0, un = 0, rn = 0, r2 = 0;
  wall_mirror_point(ctx, b, xs);
  for (int d = 0; d < dim; d++) {
    n[d] = xs[d] - p->x[d][b];
    nn += n[d] * n[d];
  }
  for (int d = 0; d < dim; d++) {
    n[d] /= sqrt(nn);
    un += (p->v[d][i] - p->v[d][b]) * n[d];
    rn += (p->x[d][i] - p->x[d][b]) * n[d];
    r2 += (p->x[d][i] - p->x[d][b]) * (p->x[d][i] - p->x[d][b]);
  }
  if (un >= 0 || r2 >= ctx->prm->kern.support2) return;
  double f = -ctx->c->phases[p->phase[i]].c0 * un * kernel_w(&ctx->prm->kern, r2) * pow(ctx->prm->h, dim) / fabs(rn);
  for (int d = 0; d < dim; d++) acc[d] += f * n[d];
}

/* The pair sums of fluid particle i over its neighbours. */
static void spc_sums(const struct pass_ctx *ctx, long i, const struct neighbours *nb, struct spc_sums *s,
                     long *pairs) {
  const struct parts *p = ctx->p;
  const double *restrict rho = p->rho, *restrict pres = p->p, *restrict vol = ctx->w->vol;
  const double *restrict p_tilde = ctx->w->p_shepard;
  const int conventional = ctx->c->spc_model == SPC_CONVENTIONAL;
  const int gas = !ctx->c->phases[p->phase[i]].incompressible;
  const int dim = p->dim, ph = p->phase[i];
  const struct phase *fi = &ctx->c->phases[ph];
  const double pi = pres[i], rhoi = rho[i], eta2 = 0.01 * ctx->prm->h * ctx->prm->h;
  double mu[CASE_MAX_PHASES];
  int heavier[CASE_MAX_PHASES];   /* phases whose velocities i's divergence reads besides its own */
  for (int k = 0; k < ctx->c->n_phases; k++) {
    mu[k] = phase_viscosity_total(ctx, k);
    heavier[k] = ctx->c->phases[k].rho0 > fi->rho0;
  }
  *s = (struct spc_sums){0};
  double xi[3];
  const double *x[3];
  pair_chunk_centre(p, i, x, xi);
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, vol, xi, dim, CHUNK_F, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      const double r2 = c.r2[k], fv = c.fv[k];   /* gW_ij = fv (r_i - r_j) */
      double dx[3], dvdx = 0;
      pair_chunk_dx(&c, k, dim, dx);
      (*pairs)++;
      for (int d = 0; d < dim; d++) dvdx += (p->v[d][j] - p->v[d][i]) * dx[d];
      const int wall = part_has(p->phase[j], KIND_BOUNDARY), same = p->phase[j] == ph;
      const double p_star = same || wall || conventional ? pres[j] : p_tilde[j];
      const double rho_star = same ? rho[j] : eos_density(fi, p_star);
      const double mu_ij = harmonic_mean(mu[ph], wall ? mu[ph] : mu[p->phase[j]]);
      const double pi_ij = -dvdx / (r2 + eta2);   /* u_ji.r_ji / (r^2 + 0.01 h^2) */
      if (same || wall || conventional || (!wall && heavier[p->phase[j]])) s->div += dvdx * fv;
      if (wall && gas) spc_wall_repulsion(ctx, i, j, s->repulsion);
      s->diff -= 2.0 * (rho_star - rhoi) * fv;    /* psi*_ij.gW_ij: r_ji.r_ij / r^2 = -1 */
      for (int d = 0; d < dim; d++) {
        s->grad_p[d] += (pi + p_star) * fv * dx[d];
        s->visc[d] += mu_ij * pi_ij * fv * dx[d];
      }
    }
}

/* Both right-hand sides of owned fluid particle i. */
static void same_phase_rhs(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  const struct phase *f = &ctx->c->phases[p->phase[i]];
  struct spc_sums s;
  double g[3];
  spc_sums(ctx, i, nb, &s, &ctx->out.pairs);
  body_acceleration(ctx, i, g);
  ctx->w->drho[i] = -p->rho[i] * s.div + ctx->c->delta * ctx->prm->h * f->c0 * s.diff;
  for (int d = 0; d < p->dim; d++)
    ctx->w->dv[d][i] = (-s.grad_p[d] + 2.0 * (p->dim + 2) * s.visc[d]) / p->rho[i] + s.repulsion[d] + g[d];
}

void pass_same_phase_rhs(struct pass_ctx *ctx) { pass_for_each_owned(ctx, same_phase_rhs, NULL); }
