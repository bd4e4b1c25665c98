/* pass_fluid_rhs.c — right-hand sides of owned fluid particles, paper 000 Eqs. 5-10, 16-20:
 *   drho_i/dt = -rho_i <div u>_i + delta h c0 D_i
 *               + sum_j [(phi_ij rho_j - eps_ij rho_i) du_j + (eps_ii + phi_ii) rho_i du_i] . gW_ij
 *   rho_i du_i/dt = -sum_j (p_j + s_i p_i) gW_ij + K_i sum_{j in phase(i) or wall} pi_ij gW_ij
 *                   + sum_{j in phase(i)} [rho_i u_i (du_i . gW_ij) + rho_j u_j (du_j . gW_ij)]
 *                   + 2(dim+2) sum_{j other fluid} mu_ij pi_ij gW_ij   (interface viscosity: harmonic)
 *                   - chi sum_{j other fluid} (|p_i| + |p_j|) gW_ij
 *                   + rho0 alpha2 c0 h sum_j (D~_j + D_i) gW_ij   (acoustic damper on liquids, symmetric
 *                        form; D~_j = D_j in the phase of i, 0 in other phases and walls; own-phase
 *                        form: j in phase(i) or wall only, with D over those neighbours only)
 *                   + rho0 alpha2 c0 h sum_{j in phase(i)} (D_j - D_i) gW_ij   (difference form)
 *                   + rho_i (g - omega^2 (r_i - c))
 * with gW_ij = grad_i W_ij V_j = F_ij (r_i - r_j) V_j, D_i = sum_{j in phase(i)} psi_ij (-F_ij) V_j,
 * psi_ij = 2(rho_j - rho_i) - (<grad rho>_i + <grad rho>_j).r_ji, pi_ij = u_ji.r_ji/(r^2 + 0.01 h^2),
 * K_i = alpha h c0 rho0 + 2(dim+2) mu, mu_ij = 2 mu_i mu_j/(mu_i + mu_j), s_i = -1 (tensile control: p_i < 0 outside the free-surface
 * region) else +1, D = <div u>. eps/phi: interface.c.
 * The terms a case does not use are compiled out of its loop (see dispatch()). With rigid bodies,
 * the same sums over the ghosts of each body alone (pressure pairs symmetric) give the body loads.
 * A particle a of an elastic solid is a moving wall (doc/theory.md section 14): p_a the one-sided
 * dummy pressure of solid_dummy_pressure (paper 002 Eq. P-18), its velocity v~_a and volume m_a/rho_a
 * as they are, and the pair's pressure (p_a + p_i, symmetric) and viscous force on i, times -m_i, a
 * load on a. */
#include <math.h>
#include "physics/interface.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"

/* Per-particle quantities of i that are constant over its neighbours. */
struct centre {
  long i;
  int phase;
  double p_sign;                        /* +1, or -1 under tensile control */
  double a[3];                          /* g + f_potential at i [m/s^2] */
};

/* Sums over the neighbours of fluid particle i. */
struct fluid_sums {
  double diff, drho_du, grad_p[3], visc[3], visc_other[3], mom_du[3], damper[3], sharp[3];
};

/* The pressure of other-phase neighbour j as particle i sees it with the density-weighted
 * interface pressure p_ij = (rho_j p_i + rho_i p_j)/(rho_i + rho_j) (Hu & Adams 2006): the pair
 * term p_j' + p_i equals 2 p_ij, so p_j' = 2 p_ij - p_i [Pa]. */
static inline double other_phase_pressure(double pi, double rhoi, double pj, double rhoj) {
  return ((rhoj - rhoi) * pi + 2.0 * rhoi * pj) / (rhoi + rhoj);
}

/* K_i = alpha h c0 rho0 + 2(dim+2) mu of phase ph: the viscous pair terms' factor [Pa s]. */
static double viscous_coefficient(const struct pass_ctx *ctx, int ph) {
  const struct phase *f = &ctx->c->phases[ph];
  return ctx->c->alpha * ctx->prm->h * f->c0 * f->rho0 + 2.0 * (ctx->p->dim + 2) * f->viscosity;
}

/* The load on solid particle g (its index in the solid view) of its pair with fluid particle i
 * (ci): the reaction of the pair's force on i, its pressure term with psum = p_g + p_i, its viscous
 * term with pi_ij (0 without viscosity) and its damper term with d_damp (D_i with the symmetric
 * damper, else 0); fv dx = grad_i W_ig V_g. */
static void solid_load(const struct pass_ctx *ctx, const struct centre *ci, long g, double psum, double pi_ij,
                       double d_damp, double fv, const double *dx) {
  const struct parts *p = ctx->p;
  const double k_visc = viscous_coefficient(ctx, ci->phase), rho_i = p->rho[ci->i];
  const double zeta = damper_viscosity(ctx, ci->phase);
  double dv[3] = {0, 0, 0};
  for (int d = 0; d < p->dim; d++) dv[d] = (k_visc * pi_ij - psum + zeta * d_damp) * fv * dx[d] / rho_i;
  body_load_append(ctx->solid_loads, p, ci->i, (int)g, LOAD_PAIRS, dv);
}

/* The terms of a case's loop: du (delta-u), damp (acoustic damper: 1 symmetric, 2 difference
 * form), phases (0: one fluid phase, so no pair is of the other-phase relation; 1: several
 * phases; 2: several phases with the sharpness force), diss (bit 1: viscosity, bit 2: density
 * diffusion). */
struct terms {
  int du, damp, phases, diss;
};

/* Loop over the neighbours of i (with BODY_WALL >= 0 over the ghosts of that wall only; with SOLIDS
 * the solid particles among them are moving walls and take a load); the terms DU, DAMP, PHASES,
 * DISS (struct terms), SOLIDS and the dimension are compile-time constants in each specialisation,
 * so that a term that is off has its pair terms compiled out. The sums are accumulated in locals
 * and the arrays read through restrict pointers, so that nothing goes through memory inside the
 * loop. */
static inline __attribute__((always_inline)) void fluid_sums(const struct pass_ctx *ctx,
                                                             const struct centre *ci,
                                                             const struct neighbours *nb,
                                                             struct fluid_sums *out, long *pairs,
                                                             const int dim, const int DU,
                                                             const int DAMP, const int PHASES,
                                                             const int DISS, const int BODY_WALL,
                                                             const int SOLIDS) {
  const struct parts *p = ctx->p;
  const struct work *w = ctx->w;
  const double *restrict x[3] = {p->x[0], p->x[1], p->x[2]}, *restrict v[3] = {p->v[0], p->v[1], p->v[2]};
  const double *restrict du[3] = {w->du[0], w->du[1], w->du[2]};
  const double *restrict grad_rho[3] = {w->grad_rho[0], w->grad_rho[1], w->grad_rho[2]};
  const double *restrict rho = p->rho, *restrict pres = p->p, *restrict vol = w->vol;
  const double *restrict div = damper_divergence(w);   /* the damper's D */
  const int damp_other = !w->div_own;   /* the damper's sum includes other-phase pairs */
  const double *restrict rho_d = diffused_density(ctx);   /* the density the diffusion acts on */
  const int *restrict phase = p->phase;
  const long i = ci->i;
  const int ph = ci->phase;
  const double pi = pres[i], rhoi = rho[i], eta2 = 0.01 * ctx->prm->h * ctx->prm->h;
  const double p_sign = ci->p_sign;
  const int visc = DISS & 1, diff = DISS & 2;
  const int weighted = PHASES && ctx->c->interface_pressure == IFACE_P_DENSITY_WEIGHTED;
  const int visc_other = PHASES && visc && ctx->c->interface_viscosity == IFACE_VISC_HARMONIC;
  const double rho0i = ctx->c->phases[ph].rho0, mui = ctx->c->phases[ph].viscosity;
  const struct solid_view *solids = ctx->solids;
  double xi[3], vi[3], dui[3] = {0, 0, 0}, gri[3];
  for (int d = 0; d < dim; d++) {
    xi[d] = x[d][i];
    vi[d] = v[d][i];
    gri[d] = diff ? grad_rho[d][i] : 0.0;
    if (DU) dui[d] = du[d][i];
  }
  struct fluid_sums s = {0};
  long n_pairs = 0;
  struct neighbours it = *nb;
  struct pair_chunk c;
  while (pair_chunk_next(&it, &ctx->prm->kern, x, vol, xi, dim, CHUNK_F, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      if (BODY_WALL >= 0 && !(part_has(phase[j], KIND_BOUNDARY) && p->wall[j] == BODY_WALL)) continue;
      const double fv = c.fv[k], r2 = c.r2[k];
      double dx[3], dvdx = 0;
      for (int d = 0; d < dim; d++) {
        dx[d] = c.dx[d][k];
        dvdx += (v[d][j] - vi[d]) * dx[d];
      }
      n_pairs++;
      const int rel = part_has(phase[j], KIND_BOUNDARY) ? PAIR_WALL
                      : (!PHASES || phase[j] == ph)      ? PAIR_SAME
                                                         : PAIR_OTHER;
      const long g = SOLIDS && rel == PAIR_WALL && phase[j] == PHASE_SOLID ? (long)(p->id[j] - solids->id0) : -1;
      const int solid = g >= 0;
      /* other phase: a fluid particle of another phase, or a ghost standing for one (rho0 of
       * another phase), so that fluid and ghost neighbours of a phase act alike */
      const int other = weighted && !solid && (rel == PAIR_OTHER || (rel == PAIR_WALL && rho[j] != rho0i));
      double pj = solid   ? solid_dummy_pressure(solids, g, pi, rhoi, ci->a, dx, dim)
                  : other ? other_phase_pressure(pi, rhoi, pres[j], rho[j])
                          : pres[j];
      double psum = pj + p_sign * pi;
      for (int d = 0; d < dim; d++) s.grad_p[d] += psum * fv * dx[d];
      if (DU) {
        const struct interface_weights *iw = &ctx->prm->iface[rel];
        double cii, cj, dui_g = 0, duj_g = 0;
        interface_continuity_coefficients(iw, rhoi, rho[j], &cii, &cj);
        for (int d = 0; d < dim; d++) {
          dui_g += dui[d] * dx[d] * fv;
          duj_g += du[d][j] * dx[d] * fv;
        }
        s.drho_du += cj * duj_g + cii * dui_g;
        if (iw->kappa != 0)
          for (int d = 0; d < dim; d++)
            s.mom_du[d] += iw->kappa * (rhoi * vi[d] * dui_g + rho[j] * v[d][j] * duj_g);
      }
      if (DAMP == 1 && (damp_other || rel != PAIR_OTHER)) {   /* symmetric forms, D~ = 0 outside the phase */
        double dsum = (rel == PAIR_SAME ? div[j] : 0.0) + div[i];
        for (int d = 0; d < dim; d++) s.damper[d] += dsum * fv * dx[d];
      }
      if (PHASES == 2 && rel == PAIR_OTHER)
        for (int d = 0; d < dim; d++) s.sharp[d] -= (fabs(pi) + fabs(pres[j])) * fv * dx[d];
      if (PHASES && rel == PAIR_OTHER) {
        if (visc_other) {   /* mu_ij pi_ij is symmetric in i and j, so the pair's forces cancel */
          const double mu_ij = harmonic_mean(mui, ctx->c->phases[phase[j]].viscosity), pi_ij = -dvdx / (r2 + eta2);
          for (int d = 0; d < dim; d++) s.visc_other[d] += mu_ij * pi_ij * fv * dx[d];
        }
        continue;
      }
      const double pi_ij = visc ? -dvdx / (r2 + eta2) : 0.0;   /* u_ji . r_ji / (r^2 + 0.01 h^2), r_ji = -dx */
      if (visc)
        for (int d = 0; d < dim; d++) s.visc[d] += pi_ij * fv * dx[d];
      if (solid) solid_load(ctx, ci, g, pj + pi, pi_ij, DAMP == 1 ? div[i] : 0.0, fv, dx);
      if (rel == PAIR_WALL) continue;
      if (DAMP == 2)
        for (int d = 0; d < dim; d++) s.damper[d] += (div[j] - div[i]) * fv * dx[d];
      if (!diff) continue;
      double gsum = 0;
      for (int d = 0; d < dim; d++) gsum -= (gri[d] + grad_rho[d][j]) * dx[d];
      s.diff -= (2.0 * (rho_d[j] - rho_d[i]) - gsum) * fv;
    }
  *out = s;
  *pairs += n_pairs;
}

#define FLUID_SUMS(D, U, A, P, S) fluid_sums(ctx, ci, nb, s, pairs, D, U, A, P, S, -1, 0)
#define DAMPED(D, U, P, S) \
  (damp == 0 ? FLUID_SUMS(D, U, 0, P, S) : damp == 1 ? FLUID_SUMS(D, U, 1, P, S) : FLUID_SUMS(D, U, 2, P, S))
#ifdef MPSPH_SINGLE_PHASE   /* benchmark build: the multiphase specialisations compiled out */
#define PHASED(D, U, S) DAMPED(D, U, 0, S)
#else
#define PHASED(D, U, S) (phases == 0 ? DAMPED(D, U, 0, S) : phases == 1 ? DAMPED(D, U, 1, S) : DAMPED(D, U, 2, S))
#endif

/* The specialisations of fluid_sums for one DISS, in a function of their own (not inlined into
 * one dispatcher with the other DISS values: there gcc compiled the loops of the ones with a term
 * off about 70 % slower per pair than their instruction counts, measured with callgrind, imply). */
#define DISPATCH_DISS(S) \
  static __attribute__((noinline)) void dispatch_##S(const struct pass_ctx *ctx, const struct centre *ci, \
                                                     const struct neighbours *nb, struct fluid_sums *s, \
                                                     long *pairs, int du, int damp, int phases) { \
    (void)phases; \
    if (ctx->p->dim == 2) du ? PHASED(2, 1, S) : PHASED(2, 0, S); \
    else du ? PHASED(3, 1, S) : PHASED(3, 0, S); \
  }
DISPATCH_DISS(0)
DISPATCH_DISS(1)
DISPATCH_DISS(2)
DISPATCH_DISS(3)

/* The terms of the loop of particle i (its phase decides whether the damper acts). */
static struct terms terms_of(const struct pass_ctx *ctx, const struct centre *ci) {
  unsigned f = ctx->prm->features;
  struct terms t;
  t.du = (f & FEAT_DELTA_U) != 0;
  t.phases = ctx->c->n_phases == 1 ? 0 : (f & FEAT_SHARPNESS) ? 2 : 1;
  t.damp = !(f & FEAT_DAMPER) ? 0 : ctx->c->damper_form == DAMPER_DIFFERENCE ? 2 : 1;
  if (!ctx->c->phases[ci->phase].incompressible) t.damp = 0;
  t.diss = ((f & FEAT_VISCOSITY) ? 1 : 0) | ((f & FEAT_DIFFUSION) ? 2 : 0);
  return t;
}

/* fluid_sums in a scene with elastic solids: one generic (not specialised) loop, so that the
 * specialised loops of the scenes without solids carry no solid pair. */
static __attribute__((noinline)) void solid_scene_sums(const struct pass_ctx *ctx, const struct centre *ci,
                                                       const struct neighbours *nb, const struct terms *t,
                                                       struct fluid_sums *s, long *pairs) {
  fluid_sums(ctx, ci, nb, s, pairs, ctx->p->dim, t->du, t->damp, t->phases, t->diss, -1, 1);
}

/* Call the specialisation of fluid_sums for the terms t (the generic loop with solids). */
static void dispatch(const struct pass_ctx *ctx, const struct centre *ci, const struct neighbours *nb,
                     const struct terms *t, struct fluid_sums *s, long *pairs) {
  if (ctx->solids) {
    solid_scene_sums(ctx, ci, nb, t, s, pairs);
    return;
  }
  static void (*const by_diss[4])(const struct pass_ctx *, const struct centre *, const struct neighbours *,
                                  struct fluid_sums *, long *, int, int, int) = {dispatch_0, dispatch_1,
                                                                                 dispatch_2, dispatch_3};
  by_diss[t->diss](ctx, ci, nb, s, pairs, t->du, t->damp, t->phases);
}

/* du/dt of particle i from its momentum sums s, the body forces aside [m/s^2]. */
static void pair_acceleration(const struct pass_ctx *ctx, const struct centre *ci, const struct fluid_sums *s,
                              double *acc) {
  const int dim = ctx->p->dim;
  double k_visc = viscous_coefficient(ctx, ci->phase);
  double k_visc_other = 2.0 * (dim + 2);   /* times mu_ij, inside visc_other */
  double zeta = damper_viscosity(ctx, ci->phase), rho_i = ctx->p->rho[ci->i];
  for (int d = 0; d < dim; d++)
    acc[d] = (-s->grad_p[d] + k_visc * s->visc[d] + k_visc_other * s->visc_other[d] + s->mom_du[d] +
              ctx->c->interface_sharpness * s->sharp[d] + zeta * s->damper[d]) / rho_i;
}

/* Combine the sums into drho/dt and du/dt of particle i. */
static void finish(struct pass_ctx *ctx, const struct centre *ci, const struct fluid_sums *s) {
  const struct parts *p = ctx->p;
  const struct phase *f = &ctx->c->phases[ci->phase];
  const long i = ci->i;
  double acc[3];
  /* delta-sph integrates m/V: its diffusion is -(V/rho^S) times the volume diffusion (paper 001
   * Eq. 21 with the factor 2 restored), i.e. the density diffusion scaled by rho_i / rho^S_i */
  double diffusion = ctx->c->delta * ctx->prm->h * f->c0 * s->diff;
  if (ctx->prm->features & FEAT_SHEPARD) diffusion *= p->rho[i] / ctx->w->rho_s[i];
  ctx->w->drho[i] = -p->rho[i] * ctx->w->div[i] + diffusion + s->drho_du;
  pair_acceleration(ctx, ci, s, acc);
  for (int d = 0; d < p->dim; d++) ctx->w->dv[d][i] = acc[d] + ci->a[d];
}

/* The body loads of fluid particle i: for each body, its sums over that body's ghosts alone (the
 * same pair terms as its du/dt, but with the symmetric pressure pairs p_k + p_i whatever tensile
 * control does to i: the load approximates the surface integral of p, doc/theory.md section 5b),
 * times -m_i; none for a body without ghosts among its neighbours. One generic (not specialised)
 * loop: it runs only in scenes with bodies. */
static __attribute__((noinline)) void add_body_loads(struct pass_ctx *ctx, const struct centre *ci,
                                                     const struct neighbours *nb, const struct terms *t) {
  struct centre symmetric = *ci;
  symmetric.p_sign = 1.0;
  for (int w = 0; w < ctx->c->n_walls; w++) {
    if (!(ctx->prm->body_walls >> w & 1)) continue;
    struct fluid_sums s;
    long n_pairs = 0;
    double acc[3];
    fluid_sums(ctx, &symmetric, nb, &s, &n_pairs, ctx->p->dim, t->du, t->damp, t->phases, t->diss, w, 0);
    if (n_pairs == 0) continue;
    pair_acceleration(ctx, &symmetric, &s, acc);
    body_load_append(ctx->loads, ctx->p, ci->i, w, LOAD_PAIRS, acc);
  }
}

/* Phase, tensile-control sign and body acceleration of particle i. */
static void centre_of(const struct pass_ctx *ctx, long i, struct centre *ci) {
  ci->i = i;
  ci->phase = ctx->p->phase[i];
  int in_region = ctx->w->region && ctx->w->region[i] > 0;
  ci->p_sign = (ctx->prm->features & FEAT_TIC) && ctx->p->p[i] < 0 && !in_region ? -1.0 : 1.0;
  for (int d = 0; d < 3; d++) ci->a[d] = 0.0;
  body_acceleration(ctx, i, ci->a);
}

/* Both right-hand sides of fluid particle i. */
static void fluid_rhs(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  struct centre ci;
  struct fluid_sums sum;
  centre_of(ctx, i, &ci);
  struct terms t = terms_of(ctx, &ci);
  dispatch(ctx, &ci, nb, &t, &sum, &ctx->out.pairs);
  finish(ctx, &ci, &sum);
  if (ctx->prm->features & FEAT_BODIES) add_body_loads(ctx, &ci, nb, &t);
}

void pass_fluid_rhs(struct pass_ctx *ctx) { pass_for_each_owned(ctx, fluid_rhs, NULL); }
