/* pass_generalized_dissipation.c — scheme generalized-dissipation (paper 004, Zheng et al.): the
 * density-increment dissipation across phases with the volume correction factor, Grenier's
 * pressure gradient and the Hu-Adams viscosity, for owned fluid particle i and every neighbour j
 * (all phases and wall ghosts), with F_ij the kernel factor (grad_i W_ij = F_ij r_ij, F <= 0),
 * r_ij = r_i - r_j, V_j = m_j / rho_j (doc/theory.md section "generalized-dissipation"):
 *   Gamma_i = sum_j W_ij V_j + W(0) V_i                         (Eq. 9; 1 on wall ghosts)
 *   <grad p>^L_i = L_i sum_j (p_j - p_i) grad_i W_ij V_j,  L_i = [sum_j r_ji (x) grad_i W_ij V_j]^-1
 *                  (Eqs. 47-48 with rho~ = p / c^2; 0 where det L_i^-1 < 0.1)
 *   drho_i/dt = -rho_i sum_j u_ji . grad_i W_ij V_j + D_i                            (Eq. 7)
 *   D_i = -2 delta h sum_j VCF_ij / c_ij [p_ji + (<grad p>_i + <grad p>_j)/2 . r_ij] F_ij V_j
 *         (consistent form of Eq. 46, notes AMB-004-2), or as printed (Eq. 49):
 *   D_i = -delta sum_j VCF_ij / c_ij [p_ji - (<grad p>_j - <grad p>_i)/2 . r_ij] F_ij r^2 V_j,
 *         VCF_ij = 2 rho_i / (rho_i + rho_j) (Eq. 36), c_ij = max(c0_i, c0_j) (c0_i for a ghost,
 *         whose gradient is taken as <grad p>_i), p_ji = p_j - p_i;
 *   rho_i du_i/dt = -sum_j (p_i/Gamma_i + p_j/Gamma_j) F_ij r_ij V_j                  (Eq. 9)
 *                   + sum_j 4 mu_i mu_j/(mu_i + mu_j) F_ij r^2/(r^2 + (0.1 h)^2) u_ij V_j  (Eq. 10)
 *                   + rho_i (g - omega^2 (r_i - c)),
 *   mu_k = mu of phase k + alpha h c0_k rho0_k / (2 (dim + 2)) (artificial viscosity, not in 004). */
#include <math.h>
#include "physics/linalg.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"

#define GD_MIN_DET 0.1   /* det of L^-1 below which the gradient correction is dropped */

/* The sound speed of pair (i, j): the larger c0 of the two phases, c0_i beside a ghost [m/s]. */
static double pair_sound_speed(const struct pass_ctx *ctx, int phi, int phj) {
  double ci = ctx->c->phases[phi].c0;
  return part_has(phj, KIND_BOUNDARY) ? ci : fmax(ci, ctx->c->phases[phj].c0);
}

/* Gamma_i and the renormalised pressure gradient of owned fluid particle i. */
static void gd_gradients(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  const double *restrict vol = ctx->w->vol, *restrict pres = p->p;
  const int dim = p->dim;
  double gamma = kernel_w(&ctx->prm->kern, 0.0) * vol[i], mt[9] = {0}, g[3] = {0}, out[3], xi[3];
  const double *x[3];
  pair_chunk_centre(p, i, x, xi);
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, vol, xi, dim, CHUNK_F, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      const double fv = c.fv[k];
      double dx[3];
      pair_chunk_dx(&c, k, dim, dx);
      gamma += kernel_w(&ctx->prm->kern, c.r2[k]) * vol[j];
      for (int a = 0; a < dim; a++) {
        g[a] += (pres[j] - pres[i]) * fv * dx[a];
        for (int b = 0; b < dim; b++) mt[a * dim + b] -= fv * dx[a] * dx[b];
      }
      ctx->out.pairs++;
    }
  double det = linalg_solve(dim, mt, g, out);
  int fallback = !(fabs(det) >= GD_MIN_DET);
  for (int d = 0; d < dim; d++) ctx->w->gd_grad_p[d][i] = fallback ? 0.0 : out[d];
  ctx->w->gd_gamma[i] = gamma;
  ctx->out.renorm_fallbacks += fallback;
}

/* Wall ghosts: Gamma = 1 (paper 004, Eq. 9) and no gradient of their own. */
static void gd_ghost(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  (void)nb;
  ctx->w->gd_gamma[i] = 1.0;
  for (int d = 0; d < ctx->p->dim; d++) ctx->w->gd_grad_p[d][i] = 0.0;
}

void pass_gd_gradients(struct pass_ctx *ctx) { pass_for_each_owned(ctx, gd_gradients, gd_ghost); }

/* The dissipation pair term of (i, j) without the kernel factor F_ij V_j: the bracket of the
 * consistent (Eq. 46 corrected) or the printed (Eq. 49) form times its coefficient [kg/m^3/s
 * per unit F V]. dx = r_i - r_j, r2 = |dx|^2. */
static double dissipation_pair(const struct pass_ctx *ctx, long i, long j, const double *dx, double r2) {
  const struct parts *p = ctx->p;
  const int dim = p->dim, wall = part_has(p->phase[j], KIND_BOUNDARY);
  double vcf = 2.0 * p->rho[i] / (p->rho[i] + p->rho[j]);
  double k = vcf / pair_sound_speed(ctx, p->phase[i], p->phase[j]), corr = 0.0;
  for (int d = 0; d < dim; d++) {
    double gi = ctx->w->gd_grad_p[d][i], gj = wall ? gi : ctx->w->gd_grad_p[d][j];
    corr += (ctx->c->dissipation_form == DISSIPATION_PRINTED ? -(gj - gi) : gi + gj) * 0.5 * dx[d];
  }
  double bracket = p->p[j] - p->p[i] + corr;
  if (ctx->c->dissipation_form == DISSIPATION_PRINTED) return -ctx->c->delta * k * bracket * r2;
  return -2.0 * ctx->c->delta * ctx->prm->h * k * bracket;
}

/* Both right-hand sides of owned fluid particle i. */
static void gd_rhs(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  const double *restrict vol = ctx->w->vol, *restrict pres = p->p, *restrict gam = ctx->w->gd_gamma;
  const int dim = p->dim, ph = p->phase[i];
  double mu[CASE_MAX_PHASES];   /* mu of each phase, walls taking the phase of i */
  for (int k = 0; k < ctx->c->n_phases; k++) mu[k] = phase_viscosity_total(ctx, k);
  const double eta2 = 0.01 * ctx->prm->h * ctx->prm->h, mui = mu[ph], pgi = pres[i] / gam[i];
  double div = 0, diss = 0, force[3] = {0, 0, 0}, g[3], xi[3];
  const double *x[3];
  pair_chunk_centre(p, i, x, xi);
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, vol, xi, dim, CHUNK_F, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      const double r2 = c.r2[k], fv = c.fv[k];
      double dx[3], dvdx = 0;
      pair_chunk_dx(&c, k, dim, dx);
      double muj = part_has(p->phase[j], KIND_BOUNDARY) ? mui : mu[p->phase[j]];
      double mu_ij = 2.0 * harmonic_mean(mui, muj);
      double visc = mu_ij * fv * r2 / (r2 + eta2), pg = pgi + pres[j] / gam[j];
      for (int d = 0; d < dim; d++) {
        dvdx += (p->v[d][j] - p->v[d][i]) * dx[d];
        force[d] += -pg * fv * dx[d] - visc * (p->v[d][j] - p->v[d][i]);
      }
      div += fv * dvdx;
      diss += dissipation_pair(ctx, i, j, dx, r2) * fv;
      ctx->out.pairs++;
    }
  body_acceleration(ctx, i, g);
  ctx->w->drho[i] = -p->rho[i] * div + diss;
  for (int d = 0; d < dim; d++) ctx->w->dv[d][i] = force[d] / p->rho[i] + g[d];
}

void pass_gd_rhs(struct pass_ctx *ctx) { pass_for_each_owned(ctx, gd_rhs, NULL); }

/* Lower *dt to candidate if smaller, naming the limit. */
static void lower(double *dt, const char **limit, double candidate, const char *name) {
  if (candidate < *dt) {
    *dt = candidate;
    *limit = name;
  }
}

double gd_time_step(const struct pass_ctx *ctx, double a_max, double u_max, const char **limit) {
  const struct case_def *c = ctx->c;
  double dt = c->cfl * ctx->prm->h / (ctx->prm->c_max + u_max), g = 0;
  *limit = "acoustic";
  for (int d = 0; d < ctx->p->dim; d++) g += c->gravity[d] * c->gravity[d];
  double a = fmax(sqrt(g), a_max);
  if (a > 0) lower(&dt, limit, 0.25 * sqrt(ctx->prm->h / a), "acceleration");
  for (int ph = 0; ph < c->n_phases; ph++) {
    double mu = phase_viscosity_total(ctx, ph);
    if (mu > 0) lower(&dt, limit, 0.125 * c->phases[ph].rho0 * ctx->prm->h * ctx->prm->h / mu, "viscous");
  }
  if (ctx->prm->features & FEAT_SURFACE_TENSION)   /* twice the limit of paper 000's RK4 step (the exact 0.5 (...)^1/2) */
    lower(&dt, limit, 2.0 * capillary_dt(c, ctx->prm->h), "capillary");
  return dt;
}
