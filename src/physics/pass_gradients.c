/* pass_gradients.c — the first pair pass of every stage:
 *  - with density diffusion, the renormalised density gradient (paper 000 Eq. 7, Randles &
 *    Libersky), same phase only:
 *    <grad rho>_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j, L_i = [sum_j r_ji (x) grad_i W_ij V_j]^-1;
 *    a near-singular matrix falls back to L = I;
 *  - velocity divergence over all neighbours: <div u>_i = sum_j w_ij u_ji . grad_i W_ij V_j, w_ij = 1
 *    except with the density-weighted interface pressure for j of another phase,
 *    w_ij = 2 rho_j / (rho_i + rho_j), the continuity that matches its pair pressure 2 p_ij in the
 *    energy balance (doc/theory.md section 3);
 *  - with the own-phase damper, the same divergence over the neighbours of the own phase and the
 *    walls only, the D of the damper (equal to <div u> with one phase);
 *  - with shifting, sum_j grad_i W_ij V_j over all neighbours, turned into du (shifting.c). */
#include <math.h>
#include "physics/linalg.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"

#define RENORM_MIN_DET 0.1   /* det of the matrix below which L falls back to the identity */

/* Sums of particle i; inlined with literal dim, shift, multi (0: one phase, 1: several, 2: several
 * phases or one, with the own-phase damper's divergence) and renorm (the density gradient, read
 * only by the density diffusion) so that the loops specialise. The arrays
 * are read through restrict pointers and the sums kept in locals. Returns 1 if the
 * renormalisation fell back to the identity. */
static inline __attribute__((always_inline)) int gradients_of(struct pass_ctx *ctx, long i,
                                                              const struct neighbours *nb,
                                                              long *pairs, const int dim,
                                                              const int shift, const int multi,
                                                              const int renorm) {
  const struct parts *p = ctx->p;
  const double *restrict x[3] = {p->x[0], p->x[1], p->x[2]}, *restrict v[3] = {p->v[0], p->v[1], p->v[2]};
  const double *restrict vol = ctx->w->vol, *restrict rho = diffused_density(ctx);
  const int *restrict phase = p->phase;
  const int ph = phase[i];
  const double rhoi = rho[i], *restrict rho_state = p->rho;
  const int weighted = multi && ctx->c->interface_pressure == IFACE_P_DENSITY_WEIGHTED;
  double *restrict div_own = ctx->w->div_own;   /* NULL unless the own-phase damper is on */
  const int own = multi == 2;                    /* then div_own is summed */
  double xi[3], vi[3], mt[9] = {0}, g[3] = {0}, sum_gw[3] = {0}, div = 0, div_ph = 0, out[3];
  for (int d = 0; d < dim; d++) {
    xi[d] = x[d][i];
    vi[d] = v[d][i];
  }
  int n_nb = 0;
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, vol, xi, dim, CHUNK_F, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      const double fv = c.fv[k];
      double dx[3], dvdx = 0;
      for (int d = 0; d < dim; d++) {
        dx[d] = c.dx[d][k];
        dvdx += (v[d][j] - vi[d]) * dx[d];
      }
      if (weighted && phase[j] != ph && !part_has(phase[j], KIND_BOUNDARY))
        div += fv * dvdx * 2.0 * rho_state[j] / (rho_state[i] + rho_state[j]);
      else
        div += fv * dvdx;
      if (own && (phase[j] == ph || part_has(phase[j], KIND_BOUNDARY))) div_ph += fv * dvdx;
      n_nb++;
      if (shift)
        for (int d = 0; d < dim; d++) sum_gw[d] += fv * dx[d];
      if (!renorm || (multi ? phase[j] != ph : part_has(phase[j], KIND_BOUNDARY))) continue;
      double drho = rho[j] - rhoi;
      for (int a = 0; a < dim; a++) {
        g[a] += drho * fv * dx[a];
        for (int b = 0; b < dim; b++) mt[a * dim + b] -= fv * dx[a] * dx[b];  /* (M)_ab = B_ba */
      }
    }
  *pairs += n_nb;
  int fallback = 0;
  if (renorm) {
    double det = linalg_solve(dim, mt, g, out);
    fallback = !(fabs(det) >= RENORM_MIN_DET);
    for (int d = 0; d < dim; d++) ctx->w->grad_rho[d][i] = fallback ? g[d] : out[d];
  }
  ctx->w->div[i] = div;
  if (own) div_own[i] = div_ph;
  if (shift) shifting_velocity(ctx, i, sum_gw, n_nb);
  return fallback;
}

/* The volumes m/rho of the owned and halo slots of the kinds `kinds` (KIND_* set bits, 0: all). */
static void volumes_of(struct pass_ctx *ctx, unsigned kinds) {
  const struct parts *p = ctx->p;
  for (long i = 0, n = p->n_owned + p->n_halo; i < n; i++)
    if (!kinds || ((kinds >> kind_of(p->phase[i])) & 1u)) ctx->w->vol[i] = p->m[i] / p->rho[i];
}

void pass_volumes(struct pass_ctx *ctx) { volumes_of(ctx, 0); }

void pass_fluid_volumes(struct pass_ctx *ctx) { volumes_of(ctx, 1u << KIND_FLUID); }

void pass_boundary_volumes(struct pass_ctx *ctx) { volumes_of(ctx, KINDS_WITH(KIND_BOUNDARY)); }

/* Zero the gradient-pass results of a wall ghost. */
static void clear_ghost(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  (void)nb;
  for (int d = 0; d < ctx->p->dim; d++) {
    if (ctx->w->grad_rho[d]) ctx->w->grad_rho[d][i] = 0;
    if (ctx->w->du[d]) ctx->w->du[d][i] = 0;
  }
  ctx->w->div[i] = 0;
  if (ctx->w->div_own) ctx->w->div_own[i] = 0;
}

#define GRADIENTS_OF(D, S, M) \
  (renorm ? gradients_of(ctx, i, nb, pairs, D, S, M, 1) : gradients_of(ctx, i, nb, pairs, D, S, M, 0))
#ifdef MPSPH_SINGLE_PHASE   /* benchmark build: the multiphase specialisations compiled out */
#define PHASED(D, S) (own ? GRADIENTS_OF(D, S, 2) : GRADIENTS_OF(D, S, 0))
#else
#define PHASED(D, S) (own ? GRADIENTS_OF(D, S, 2) : multi ? GRADIENTS_OF(D, S, 1) : GRADIENTS_OF(D, S, 0))
#endif

/* The specialisation of gradients_of for the dimension, shifting, the number of phases, the
 * own-phase damper and the density gradient. */
static void gradients(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  long *pairs = &ctx->out.pairs;
  int shift = (ctx->prm->features & FEAT_SHIFT) != 0, multi = ctx->c->n_phases > 1, fallback;
  const int renorm = (ctx->prm->features & FEAT_DIFFUSION) != 0, own = ctx->w->div_own != NULL;
  (void)multi;
  if (ctx->p->dim == 2) fallback = shift ? PHASED(2, 1) : PHASED(2, 0);
  else fallback = shift ? PHASED(3, 1) : PHASED(3, 0);
  ctx->out.renorm_fallbacks += fallback;
}

void pass_gradients(struct pass_ctx *ctx) { pass_for_each_owned(ctx, gradients, clear_ghost); }
