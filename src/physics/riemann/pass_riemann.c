/* pass_riemann.c — the pair terms of scheme riemann (paper 002 Eqs. 6-9 and 12), for owned fluid
 * particle i over its neighbours j (both fluid phases and the wall ghosts):
 *   drho_i/dt = 2 rho_i sum_j V_j (v_i - v*_ij) . grad_i W_ij
 *   dv_i/dt   = -(2/rho_i) sum_j V_j p*_ij grad_i W_ij
 *               + (2/rho_i) sum_j V_j eta_ij v_ij F_ij + g + f_potential
 * with grad_i W_ij = F_ij (r_i - r_j), F = W'(r)/r, V_j = m_j/rho_j, eta_ij = 2 eta_i eta_j /
 * (eta_i + eta_j), p* from riemann_pressure() with U_L - U_R = (v_j - v_i).e_ij, e_ij = (r_i -
 * r_j)/r_ij, and the interface velocity of Eq. 9 with the sign of notes seed-002 A1,
 *   v*_ij = (Z_i v_i + Z_j v_j)/(Z_i + Z_j) - e_ij (p_i - p_j)/(Z_i + Z_j),   Z = rho c0,
 * so that (v_i - v*_ij).grad_i W_ij = F_ij [Z_j v_ij.(r_i - r_j) + r_ij (p_i - p_j)]/(Z_i + Z_j).
 * A wall ghost j (fixed walls) carries the one-sided dummy state of i (Eq. 20 with the corrections
 * A2, A3 of the notes): p_j = p_i + rho_i max(0, a_i.(r_j - r_i)), a_i = g + f_potential, the density
 * of i's EOS at p_j, i's sound speed and viscosity, and the velocity -v_i (no slip) or v_i with its
 * component along the ghost's mirror direction n reversed (free slip), with volume dx^dim. A
 * particle a of an elastic solid is a moving wall (notes 1.7): p_a = p_i + rho_i max(0, (a_i -
 * a~_a).(r_a - r_i)), v_a = 2 v~_a - v_i, v~_a and a~_a the solid's velocity averaged over the last
 * fluid sub-step and its change (struct solid_view), its own volume m_a/rho_a, and the pair force's
 * reaction -m_i dv_i(pair) a load on the solid (the Riemann axis stays the pair's, as for the walls).
 * Penalty (Eqs. 21-23 with the notes' A4, A5; light phases, physics.light_penalty k): a boundary
 * particle a (wall ghost or solid particle) with the unit normal n_a into the fluid (a ghost's mirror
 * direction, a solid's current normal) and beta = 2 (r_i - r_a).n_a / h <= 1 adds to du_i/dt
 *   -(2/rho_i) V_a Gamma n_a W'(r),  Gamma = k (h_S/h^chi) |p_i e_ia.n_a| (1 - beta)^2,
 * with no reaction; h_S = h, and h^chi the pair's (h at single resolution, 2h for a light phase at
 * dx_ratio 2). Multi-resolution: each pair has the kernel of riemann_pair_kernel.
 * Transport velocity (Eq. 12, light phases, notes A10): a_tv,i = -(2 p0_tv/rho_i) sum_j V_j grad_i W_ij. */
#include <math.h>
#include "physics/eos.h"
#include "physics/pair_chunk.h"
#include "physics/passes.h"
#include "physics/riemann.h"

/* The quantities of particle i that are constant over its neighbours. */
struct rcentre {
  long i;
  int phase;
  double penalty;   /* physics.light_penalty for a light-phase particle, else 0 */
  double x[3], v[3], a[3], rho, p, z, c, eta;
};

/* The dummy pressure [Pa] and velocity vj [m/s] of wall ghost j for particle i, dx = r_i - r_j. */
static inline double wall_dummy(const struct pass_ctx *ctx, const struct rcentre *ci, long j, const double *dx,
                                double *vj, const int dim) {
  const struct parts *p = ctx->p;
  double head = 0, n2 = 0, vn = 0;
  for (int d = 0; d < dim; d++) {
    head -= ci->a[d] * dx[d];
    n2 += p->mirror[d][j] * p->mirror[d][j];
    vn += ci->v[d] * p->mirror[d][j];
  }
  int no_slip = ctx->c->walls[p->wall[j]].slip == SLIP_NO;
  for (int d = 0; d < dim; d++) vj[d] = no_slip ? -ci->v[d] : ci->v[d] - 2.0 * vn * p->mirror[d][j] / n2;
  return ci->p + ci->rho * fmax(0.0, head);
}

/* The dummy pressure [Pa] and velocity vj [m/s] of solid particle j for particle i, dx = r_i - r_j;
 * its index g into the solid view in *g. */
static inline double solid_dummy(const struct pass_ctx *ctx, const struct rcentre *ci, long j, const double *dx,
                                 double *vj, long *g, const int dim) {
  const struct solid_view *s = ctx->solids;
  *g = (long)(ctx->p->id[j] - s->id0);
  const double *vs = s->v + *g * dim;
  for (int d = 0; d < dim; d++) vj[d] = 2.0 * vs[d] - ci->v[d];
  return solid_dummy_pressure(s, *g, ci->p, ci->rho, ci->a, dx, dim);
}

/* The unit normal n (into the fluid) of boundary particle j: a solid particle's (g >= 0, its index
 * in the solid view) current normal, a wall ghost's mirror direction; 0 when it has none (a solid
 * particle deep inside). */
static inline void boundary_normal(const struct pass_ctx *ctx, long j, long g, double *n, const int dim) {
  const struct parts *p = ctx->p;
  double n2 = 0;
  for (int d = 0; d < dim; d++) {
    n[d] = g >= 0 ? ctx->solids->normal[g * dim + d] : p->mirror[d][j];
    n2 += n[d] * n[d];
  }
  for (int d = 0; d < dim; d++) n[d] = n2 > 0 ? n[d] / sqrt(n2) : 0.0;
}

/* The penalty factor V_a Gamma_ia W'(r)/r (times n_a and -2/rho_i it is the acceleration) of boundary
 * particle j (g as for boundary_normal) for light particle i at dx = r_i - r_j, r = |dx|,
 * fv = V_a W'(r)/r with the pair's kernel of smoothing length h_pair; n_a into n. */
static inline double penalty_of(const struct pass_ctx *ctx, const struct rcentre *ci, long j, long g,
                                const double *dx, double r, double fv, double h_pair, double *n, const int dim) {
  double rn = 0;
  boundary_normal(ctx, j, g, n, dim);
  for (int d = 0; d < dim; d++) rn += dx[d] * n[d];
  double beta = 2.0 * rn / ctx->prm->h;
  if (beta > 1.0) return 0.0;
  return ci->penalty * (ctx->prm->h / h_pair) * fabs(ci->p * rn / r) * (1.0 - beta) * (1.0 - beta) * fv * r;
}

/* The factor F(r) V_j of a pair of kernel kp at r^2 = r2 whose chunk was filled with kown: the
 * chunk's fv when they are the same kernel, else F of kp times the neighbour's volume vol_j. */
static inline double pair_factor(const struct kernel *kp, const struct kernel *kown, double r2, double fv,
                                 double vol_j) {
  return kp == kown ? fv : kernel_f(kp, r2) * vol_j;
}

/* The Riemann sums of i: the momentum sums (pressure, viscous) when MOMENTUM, else the continuity
 * sum; with SOLIDS the solid particles among the neighbours are moving walls (and, with MOMENTUM,
 * take a load); with MULTIRES each pair has the kernel of riemann_pair_kernel; dim is a
 * compile-time constant of each specialisation. */
static inline __attribute__((always_inline)) void riemann_sums(const struct pass_ctx *ctx, const struct rcentre *ci,
                                                               const struct neighbours *nb, double *grad_p,
                                                               double *visc, double *drho, long *pairs,
                                                               const int dim, const int MOMENTUM,
                                                               const int SOLIDS, const int MULTIRES) {
  const struct physics_params *prm = ctx->prm;
  const struct parts *p = ctx->p;
  const struct phase *phases = ctx->c->phases;
  const double *restrict x[3] = {p->x[0], p->x[1], p->x[2]}, *restrict v[3] = {p->v[0], p->v[1], p->v[2]};
  const double *restrict rho = p->rho, *restrict pres = p->p, *restrict vol = ctx->w->vol;
  const int *restrict phase = p->phase;
  double gp[3] = {0, 0, 0}, vs[3] = {0, 0, 0}, dr = 0;
  long n = 0;
  struct neighbours it = *nb;
  struct pair_chunk c;
  const struct kernel *kchunk = &prm->chunk_kern[ci->phase], *kown = &prm->phase_kern[ci->phase];
  while (pair_chunk_next(&it, kchunk, x, vol, ci->x, dim, CHUNK_F, &c))
    for (int k = 0; k < c.n; k++) {
      const long j = c.j[k];
      const double r2 = c.r2[k];
      double dx[3], vj[3] = {0, 0, 0}, vdx = 0;
      const struct kernel *kp = MULTIRES ? riemann_pair_kernel(prm, ci->phase, phase[j]) : kown;
      if (r2 <= 0 || (MULTIRES && r2 >= kp->support2)) continue;
      pair_chunk_dx(&c, k, dim, dx);
      n++;
      const int wall = part_has(phase[j], KIND_BOUNDARY), solid = SOLIDS && phase[j] == PHASE_SOLID;
      double pj = pres[j], rhoj = rho[j], cj, etaj;
      long g = -1;
      if (wall) {
        pj = solid ? solid_dummy(ctx, ci, j, dx, vj, &g, dim) : wall_dummy(ctx, ci, j, dx, vj, dim);
        rhoj = eos_density(&phases[ci->phase], pj);
        cj = ci->c;
        etaj = ci->eta;
      } else {
        for (int d = 0; d < dim; d++) vj[d] = v[d][j];
        cj = phases[phase[j]].c0;
        etaj = phases[phase[j]].viscosity;
      }
      for (int d = 0; d < dim; d++) vdx += (ci->v[d] - vj[d]) * dx[d];
      /* the walls' volume is the lattice's, a solid particle's its own */
      const double fv = wall && !solid ? kernel_f(kp, r2) * prm->vol0 : pair_factor(kp, kown, r2, c.fv[k], vol[j]),
                   r = sqrt(r2), zj = rhoj * cj;
      if (MOMENTUM) {
        double pstar = riemann_pressure(ci->z, ci->p, zj, pj, -vdx / r, (ci->z + zj) / (ci->rho + rhoj));
        double eta = harmonic_mean(ci->eta, etaj), dv_pair[3] = {0, 0, 0};
        for (int d = 0; d < dim; d++) {
          gp[d] += pstar * fv * dx[d];
          vs[d] += eta * fv * (ci->v[d] - vj[d]);
          dv_pair[d] = 2.0 * (eta * fv * (ci->v[d] - vj[d]) - pstar * fv * dx[d]) / ci->rho;
        }
        if (solid) body_load_append(ctx->solid_loads, p, ci->i, (int)g, LOAD_PAIRS, dv_pair);
        if (wall && ci->penalty > 0) {
          double n[3], pen = penalty_of(ctx, ci, j, g, dx, r, fv, kp->h, n, dim);
          for (int d = 0; d < dim; d++) gp[d] += pen * n[d];   /* -(2/rho_i) pen n: as a pressure term */
        }
      } else {
        dr += fv * (zj * vdx + r * (ci->p - pj)) / (ci->z + zj);
      }
    }
  for (int d = 0; d < dim; d++) {
    grad_p[d] = gp[d];
    visc[d] = vs[d];
  }
  *drho = dr;
  *pairs += n;
}

/* The constants of particle i. */
static void centre_of(const struct pass_ctx *ctx, long i, struct rcentre *ci) {
  const struct parts *p = ctx->p;
  const struct phase *f = &ctx->c->phases[p->phase[i]];
  ci->i = i;
  ci->phase = p->phase[i];
  for (int d = 0; d < 3; d++) {
    ci->x[d] = d < p->dim ? p->x[d][i] : 0.0;
    ci->v[d] = d < p->dim ? p->v[d][i] : 0.0;
    ci->a[d] = 0.0;
  }
  body_acceleration(ctx, i, ci->a);
  ci->rho = p->rho[i];
  ci->p = p->p[i];
  ci->c = f->c0;
  ci->z = ci->rho * ci->c;
  ci->eta = f->viscosity;
  ci->penalty = ctx->prm->light_penalty[ci->phase];
}

typedef void (*sums_fn)(const struct pass_ctx *ctx, const struct rcentre *ci, const struct neighbours *nb,
                        double *grad_p, double *visc, double *drho, long *pairs);

/* One specialisation of riemann_sums: dimension D, momentum M, solids S, multi-resolution R. */
#define SUMS_SPECIALISED(D, M, S, R)                                                                          \
  static void sums_##D##M##S##R(const struct pass_ctx *ctx, const struct rcentre *ci, const struct neighbours *nb, \
                                double *grad_p, double *visc, double *drho, long *pairs) {                     \
    riemann_sums(ctx, ci, nb, grad_p, visc, drho, pairs, D, M, S, R);                                          \
  }
#define SUMS_OVER_R(D, M, S) SUMS_SPECIALISED(D, M, S, 0) SUMS_SPECIALISED(D, M, S, 1)
#define SUMS_OVER_S(D, M) SUMS_OVER_R(D, M, 0) SUMS_OVER_R(D, M, 1)
#define SUMS_OVER_M(D) SUMS_OVER_S(D, 0) SUMS_OVER_S(D, 1)
SUMS_OVER_M(2)
SUMS_OVER_M(3)

/* The specialisations by [dim == 3][momentum][solids][multi-resolution]. */
static const sums_fn SUMS[2][2][2][2] = {
    {{{sums_2000, sums_2001}, {sums_2010, sums_2011}}, {{sums_2100, sums_2101}, {sums_2110, sums_2111}}},
    {{{sums_3000, sums_3001}, {sums_3010, sums_3011}}, {{sums_3100, sums_3101}, {sums_3110, sums_3111}}}};

/* The sums of i in the specialisation for the dimension, the pass, the solids and the resolution. */
static void sums_of(struct pass_ctx *ctx, const struct rcentre *ci, const struct neighbours *nb, double *grad_p,
                    double *visc, double *drho, int momentum) {
  SUMS[ctx->p->dim == 3][momentum != 0][ctx->solids != NULL][ctx->prm->multires != 0](ctx, ci, nb, grad_p, visc,
                                                                                      drho, &ctx->out.pairs);
}

/* du/dt of fluid particle i. */
static void momentum_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  struct rcentre ci;
  double grad_p[3], visc[3], drho;
  centre_of(ctx, i, &ci);
  sums_of(ctx, &ci, nb, grad_p, visc, &drho, 1);
  for (int d = 0; d < ctx->p->dim; d++) ctx->w->dv[d][i] = 2.0 * (visc[d] - grad_p[d]) / ci.rho + ci.a[d];
}

/* drho/dt of fluid particle i. */
static void continuity_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  struct rcentre ci;
  double grad_p[3], visc[3], drho;
  centre_of(ctx, i, &ci);
  sums_of(ctx, &ci, nb, grad_p, visc, &drho, 0);
  ctx->w->drho[i] = 2.0 * ci.rho * drho;
}

void pass_riemann_momentum(struct pass_ctx *ctx) { pass_for_each_owned(ctx, momentum_of, NULL); }

void pass_riemann_continuity(struct pass_ctx *ctx) { pass_for_each_owned(ctx, continuity_of, NULL); }

/* Transport-velocity acceleration of fluid particle i into dv (0 for heavy phases). */
static void transport_of(struct pass_ctx *ctx, long i, const struct neighbours *nb) {
  const struct parts *p = ctx->p;
  const int dim = p->dim;
  double s[3] = {0, 0, 0}, xi[3];
  if (riemann_light_phase(ctx->c, p->phase[i])) {
    const struct physics_params *prm = ctx->prm;
    const int ph = p->phase[i];
    const struct kernel *kchunk = &prm->chunk_kern[ph], *kown = &prm->phase_kern[ph];
    const double *x[3];
    pair_chunk_centre(p, i, x, xi);
    struct neighbours it = *nb;
    struct pair_chunk c;
    while (pair_chunk_next(&it, kchunk, x, ctx->w->vol, xi, dim, CHUNK_F, &c))
      for (int k = 0; k < c.n; k++) {
        double fv = c.fv[k];
        if (prm->multires) {   /* the pair's kernel, when it is not the chunk's */
          const struct kernel *kp = riemann_pair_kernel(prm, ph, p->phase[c.j[k]]);
          if (c.r2[k] >= kp->support2) continue;
          fv = pair_factor(kp, kown, c.r2[k], fv, ctx->w->vol[c.j[k]]);
        }
        for (int d = 0; d < dim; d++) s[d] += fv * c.dx[d][k];
        ctx->out.pairs++;
      }
  }
  for (int d = 0; d < dim; d++) ctx->w->dv[d][i] = -2.0 * ctx->prm->tv_pressure * s[d] / p->rho[i];
}

void pass_transport_acceleration(struct pass_ctx *ctx) { pass_for_each_owned(ctx, transport_of, NULL); }
