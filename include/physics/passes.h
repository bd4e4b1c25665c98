/* passes.h — the passes over particles and neighbour pairs that build the right-hand sides; each
 * takes the context of physics/pass_ctx.h. */
#ifndef MPSPH_PASSES_H
#define MPSPH_PASSES_H

#include "physics/pass_ctx.h"

/** The separation r_i - r_j of slots i and j into dx [m]; returns its squared length [m^2]. */
static inline double pair_separation(const struct parts *p, int dim, long i, long j, double *dx) {
  double r2 = 0;
  for (int d = 0; d < dim; d++) {
    dx[d] = p->x[d][i] - p->x[d][j];
    r2 += dx[d] * dx[d];
  }
  return r2;
}

/** Body force per unit mass at particle i: gravity and the quadratic potential [m/s^2]. */
static inline void body_acceleration(const struct pass_ctx *ctx, long i, double *f) {
  const struct case_def *c = ctx->c;
  const struct parts *p = ctx->p;
  double w2 = c->potential_omega * c->potential_omega;
  for (int d = 0; d < p->dim; d++) f[d] = c->gravity[d] - w2 * (p->x[d][i] - c->potential_centre[d]);
}

/** Harmonic mean 2 a b/(a + b) of two viscosities [Pa s], the viscosity of a pair of phases
 *  (Hu & Adams 2006); 0 when either is 0. */
static inline double harmonic_mean(double a, double b) { return a + b > 0 ? 2.0 * a * b / (a + b) : 0.0; }

/** Dynamic viscosity of phase ph in the pair viscous terms of schemes same-phase-continuity and
 *  generalized-dissipation: the phase's own plus the artificial viscosity
 *  alpha h c0 rho0 / (2 (dim + 2)) [Pa s]. */
static inline double phase_viscosity_total(const struct pass_ctx *ctx, int ph) {
  const struct phase *f = &ctx->c->phases[ph];
  return f->viscosity + ctx->c->alpha * ctx->prm->h * f->c0 * f->rho0 / (2.0 * (ctx->p->dim + 2));
}

/** Work on owned particle i with its neighbour list (empty for the kinds without one). */
typedef void (*particle_fn)(struct pass_ctx *ctx, long i, const struct neighbours *nb);

/** Call fluid for every owned particle of a kind with a neighbour list (KIND_LISTED, base/kinds.h),
 *  wall for the others (wall ghosts; either may be NULL), over the context's cells (ctx->cells,
 *  or every owned cell in global cell order), cell by cell in slot order; ctx->progress, if set,
 *  between cells. Each call may write only particle i's slots, so that the order of the cells
 *  changes no result. */
void pass_for_each_owned(struct pass_ctx *ctx, particle_fn fluid, particle_fn wall);

/** Build the neighbour lists of the owned listed (fluid) particles within ctx->prm->list_radius, with
 *  multi-resolution within the pair's phases' phase_list_radius (once per step, at the first stage). */
void pass_neighbour_lists(struct pass_ctx *ctx);

/** Volumes m/rho of all slots (owned and halo) for the pair passes of this stage [m^dim]; runs
 *  after the halo update of the state (and, but with delta-sph, whose ghosts read it, after the
 *  wall ghost values; with walls the other schemes split it in the two passes below). */
void pass_volumes(struct pass_ctx *ctx);

/** pass_volumes of the fluid slots alone: what the wall ghosts' Shepard sums read, before the
 *  ghosts have their values. */
void pass_fluid_volumes(struct pass_ctx *ctx);

/** pass_volumes of the boundary slots alone: after the wall ghost values and their halo update,
 *  which complete the volumes pass_fluid_volumes began. */
void pass_boundary_volumes(struct pass_ctx *ctx);

/** Called for each slot j within the kernel support of a point, with wv = W V_j [-]. */
typedef void (*near_fn)(void *arg, const struct pass_ctx *ctx, long j, double wv);

/** Call fn for every fluid particle (and boundary particle, KIND_BOUNDARY: wall ghost, if
 *  with_walls) within the kernel support of xs, over the cells around xs's cell in global cell
 *  order, with wv = W m_j / rho_j; returns the number of calls. */
long visit_near(const struct pass_ctx *ctx, const double *xs, int with_walls, near_fn fn, void *arg);

/** The mirror point of wall ghost k now [m]: its position plus its body-frame offset (the
 *  mirror array), turned with the wall. */
void wall_mirror_point(const struct pass_ctx *ctx, long k, double *xs);

/** Once per step, before pass_wall_ghosts: the lists of the mirror points of the owned ghosts of
 *  fixed walls (nlist_point_add: the fluid within the cell edge), which pass_wall_ghosts reads at
 *  every stage instead of scanning the mirror point's stencil. */
void pass_wall_ghost_lists(struct pass_ctx *ctx);

/** Wall ghosts: Shepard interpolation of p, u, rho at the mirror point (over every phase, or
 *  with the density-weighted interface pressure over the phase with the largest Shepard weight
 *  there), hydrostatic and inertial pressure correction (from the mirror point, or with the
 *  density-weighted interface pressure and several phases from each neighbour with its own
 *  density) and free-/no-slip velocity (Marrone et al. 2011). Owned ghosts only; the ghosts of
 *  fixed walls read the lists of this step's pass_wall_ghost_lists. */
void pass_wall_ghosts(struct pass_ctx *ctx);

/** Scheme delta-sph, per stage: the same-phase Shepard density of the owned fluid (paper 001
 *  Eq. 13) and the pressure from it. */
void pass_shepard_density(struct pass_ctx *ctx);

/** The density the renormalised gradient and the delta-SPH diffusion act on: the Shepard density
 *  with scheme delta-sph, otherwise the state density. */
static inline const double *diffused_density(const struct pass_ctx *ctx) {
  return (ctx->prm->features & FEAT_SHEPARD) ? ctx->w->rho_s : ctx->p->rho;
}

/** The divergence the acoustic damper acts on: the own-phase one with that form, else <div u>. */
static inline const double *damper_divergence(const struct work *w) { return w->div_own ? w->div_own : w->div; }

/** zeta = alpha2 c0 h rho0 of phase ph: the acoustic damper's bulk viscosity, 0 where it is off
 *  [Pa s]. With rho0 (not rho_i) the damper's pair forces m_i/rho_i zeta (D_i + D_j) gW_ij V_j are
 *  zeta V_i V_j (D_i + D_j) grad_i W_ij, equal and opposite: the damper conserves momentum. */
static inline double damper_viscosity(const struct pass_ctx *ctx, int ph) {
  return ctx->prm->damper_coef[1 + ph] * ctx->c->phases[ph].rho0;
}

/** Scheme same-phase-continuity, per stage: the Shepard pressure of every owned fluid particle
 *  over the fluid of all phases, itself included (paper 003 Eq. 26, AMB-003-2 of the notes) [Pa]. */
void pass_shepard_pressure(struct pass_ctx *ctx);

/** Scheme same-phase-continuity, per stage: drho/dt with the velocity divergence over same-phase
 *  neighbours and walls and the delta diffusion over all neighbours, du/dt with the pressure
 *  gradient and viscosity over all neighbours, other-phase neighbours entering with their
 *  Shepard pressure and its density in the phase of i (paper 003 Eqs. 23-27). */
void pass_same_phase_rhs(struct pass_ctx *ctx);

/** Scheme same-phase-continuity: add to acc the wall repulsion of paper 003 Eq. 39 on gas
 *  particle i from wall ghost b, c0 |(u_i - u_b).n_b| W_ib h^d / |r_ib.n_b| along the ghost's unit
 *  normal n_b (toward its mirror point) while i approaches the wall, else nothing [m/s^2]. */
void spc_wall_repulsion(const struct pass_ctx *ctx, long i, long b, double *acc);

/** Per stage: particle volumes; renormalised density gradient over same-phase neighbours
 *  (paper 000 Eq. 7); velocity divergence over all neighbours; with shifting, the shifting
 *  velocity du of Eqs. 13-15. */
void pass_gradients(struct pass_ctx *ctx);

/** Free-surface detection (Marrone et al. 2010): smallest eigenvalue of B over all neighbours,
 *  normal, umbrella scan of the candidates. Sets surface, normal, lambda of owned fluid. */
void pass_free_surface(struct pass_ctx *ctx);

/** The free-surface region: detected particles and those within surface_band h of one. */
void pass_surface_band(struct pass_ctx *ctx);

/** Shifting velocity of owned fluid particle i from sum_j grad_i W_ij V_j (Eqs. 13-15). */
void shifting_velocity(const struct pass_ctx *ctx, long i, const double *sum_gradw, int n_neighbours);

/** Continuity (divergence, delta-SPH diffusion, delta-u terms) and momentum (pressure gradient
 *  with tensile control, viscosity, delta-u term, acoustic damper, sharpness force, body forces)
 *  right-hand sides of owned fluid particles (paper 000 Eqs. 5-10, 16-20). */
void pass_fluid_rhs(struct pass_ctx *ctx);

/** Surface tension, first pass: the colour gradient over the fluid neighbours of the other
 *  phases, its magnitude [1/m] and unit normal of owned fluid particles (both 0 where the
 *  gradient is below 0.01/h); 0 for wall ghosts. */
void pass_interface_normals(struct pass_ctx *ctx);

/** Surface tension, second pass (after pass_fluid_rhs, the normals halo-updated): curvature
 *  kappa = div n (renormalised divergence) [1/m] and the CSF acceleration
 *  -sigma kappa n |grad chi| / rho added to du/dt of owned fluid particles (Brackbill et al. 1992). */
void pass_surface_tension(struct pass_ctx *ctx);

/** Wall guard, after every force of the stage (src/physics/wall_guard.c): an owned fluid particle within
 *  physics.wall_guard x dx of a wall's boundary (or inside its solid) loses the part of du/dt
 *  (relative to the wall's acceleration) that points into the wall, beyond what stops it within a
 *  step when it is moving away (physics_params.dt_step), and the part of its shifting velocity
 *  that points into the wall. */
void pass_wall_guard(struct pass_ctx *ctx);

/** Scheme riemann: 1 if phase ph is a light phase: a gas (not `incompressible`) and a phase with a
 *  larger rho0 exists. */
int riemann_light_phase(const struct case_def *c, int ph);

/** Sum of W(|r|) over the nodes r of the lattice of spacing dx [m], r = 0 included [1/m^dim]. */
double lattice_kernel_sum(const struct kernel *k, double dx);

/** Scheme riemann, once per advection step: density re-initialisation of the owned fluid (paper
 *  002 Eqs. 10-11) and the pressure from it. */
void pass_density_reinit(struct pass_ctx *ctx);

/** Scheme riemann: du/dt of the owned fluid from the Riemann pressure, viscosity and body forces
 *  (paper 002 Eq. 6). */
void pass_riemann_momentum(struct pass_ctx *ctx);

/** Scheme riemann: drho/dt of the owned fluid with the Riemann interface velocity (Eqs. 6, 9). */
void pass_riemann_continuity(struct pass_ctx *ctx);

/** Scheme riemann: the transport-velocity acceleration -(2 p0_tv / rho_i) sum_j V_j grad_i W_ij of
 *  the owned light-phase particles into dv (0 for the heavy phase) [m/s^2] (Eq. 12). */
void pass_transport_acceleration(struct pass_ctx *ctx);

/** Scheme generalized-dissipation, first pass: the Shepard sum Gamma (with the particle itself)
 *  and the renormalised pressure gradient <grad p>^L over all neighbours, phases and wall ghosts
 *  of owned fluid (paper 004 Eqs. 9, 47-48; 0 where the matrix is near-singular); Gamma = 1 and
 *  no gradient for wall ghosts. */
void pass_gd_gradients(struct pass_ctx *ctx);

/** Scheme generalized-dissipation, second pass: continuity with the generalized density
 *  dissipation and its volume correction factor (paper 004 Eqs. 7, 36, 46 or 49 by
 *  physics.dissipation_form) and momentum with Grenier's pressure gradient, the Hu-Adams
 *  viscosity and the body forces (Eqs. 9, 10) of owned fluid. */
void pass_gd_rhs(struct pass_ctx *ctx);

/** The time step of paper 004 Eq. 23 [s]: cfl h / (c_max + u_max) (u_max the largest advection
 *  speed [m/s]; the paper's cfl is 0.25), 0.25 (h/a)^1/2 with a the larger of |g| and a_max
 *  (the largest acceleration [m/s^2]), 0.125 rho0 h^2 / mu per phase and, with surface tension,
 *  0.5 (rho0_min h^3 / (2 pi sigma))^1/2; *limit names the smallest. */
double gd_time_step(const struct pass_ctx *ctx, double a_max, double u_max, const char **limit);

/** The capillary time-step limit 0.25 (rho_min h^3 / (2 pi sigma))^(1/2), rho_min the smallest
 *  rho0 of the phases (Brackbill et al. 1992; Adami et al. 2010) [s]. */
double capillary_dt(const struct case_def *c, double h);

#endif
