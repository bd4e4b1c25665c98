/* engine_step.c — the stage pipeline, the RK4 step (the predictor-corrector of paper 003 with scheme
 * same-phase-continuity) and the time-step limits (paper 000 Eq. 12). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "physics/eos.h"
#include "engine/engine.h"
#include "physics/passes.h"
#include "base/mem.h"
#include "engine/schemes.h"
#include "physics/wall_guard.h"

#define MOTION_SAFETY 0.75   /* fraction of the allowed motion per step used by the dt limit */

static double *grow(double *a, long n) {
  return mem_realloc(a, mem_bytes((size_t)n, sizeof(double), "work array"), "work array");
}

/* One work array: where its pointer lives, whether halo slots use it (else only the owned
 * particles do), and the feature it belongs to (0: every scene). */
struct work_slot {
  double **a;
  int halo;
  unsigned feature;
};

/* Every work array of w in dimension dim; returns the count. */
static int work_slots(struct work *w, int dim, struct work_slot *t) {
  int n = 0;
  for (int d = 0; d < dim; d++) {
    t[n++] = (struct work_slot){&w->grad_rho[d], 1, FEAT_DIFFUSION};
    t[n++] = (struct work_slot){&w->du[d], 1, FEAT_SHIFT};
    t[n++] = (struct work_slot){&w->normal[d], 0, FEAT_SURFACE};
    t[n++] = (struct work_slot){&w->dv[d], 0, 0};
    t[n++] = (struct work_slot){&w->x0[d], 0, 0};
    t[n++] = (struct work_slot){&w->v0[d], 0, 0};
    t[n++] = (struct work_slot){&w->sum_x[d], 0, 0};
    t[n++] = (struct work_slot){&w->sum_v[d], 0, 0};
  }
  t[n++] = (struct work_slot){&w->vol, 1, 0};
  t[n++] = (struct work_slot){&w->div, 1, 0};
  t[n++] = (struct work_slot){&w->div_own, 1, FEAT_DAMPER_OWN_PHASE};
  t[n++] = (struct work_slot){&w->surface, 1, FEAT_SURFACE};
  t[n++] = (struct work_slot){&w->region, 0, FEAT_SURFACE};
  t[n++] = (struct work_slot){&w->lambda, 0, FEAT_SURFACE};
  t[n++] = (struct work_slot){&w->drho, 0, 0};
  t[n++] = (struct work_slot){&w->rho0, 0, 0};
  t[n++] = (struct work_slot){&w->sum_rho, 0, 0};
  t[n++] = (struct work_slot){&w->rho_s, 1, FEAT_SHEPARD};
  for (int d = 0; d < dim; d++) t[n++] = (struct work_slot){&w->interface_normal[d], 1, FEAT_SURFACE_TENSION};
  t[n++] = (struct work_slot){&w->colour_grad, 0, FEAT_SURFACE_TENSION};
  t[n++] = (struct work_slot){&w->kappa_curvature, 0, FEAT_SURFACE_TENSION};
  t[n++] = (struct work_slot){&w->p_shepard, 1, FEAT_SAME_PHASE_CONTINUITY};
  t[n++] = (struct work_slot){&w->gd_gamma, 1, FEAT_GENERALIZED_DISSIPATION};
  for (int d = 0; d < dim; d++) t[n++] = (struct work_slot){&w->gd_grad_p[d], 1, FEAT_GENERALIZED_DISSIPATION};
  return n;
}

#define MAX_WORK_SLOTS 48

/* 1 if an optional array of a feature that is on has not been allocated yet. */
static int optional_missing(const struct engine *e) {
  const unsigned f = e->prm.features;
  return ((f & FEAT_SHIFT) && !e->w.du[0]) || ((f & FEAT_DIFFUSION) && !e->w.grad_rho[0]) ||
         ((f & FEAT_SURFACE) && !e->w.surface) || ((f & FEAT_SHEPARD) && !e->w.rho_s) ||
         ((f & FEAT_SURFACE_TENSION) && !e->w.colour_grad) ||
         ((f & FEAT_SAME_PHASE_CONTINUITY) && !e->w.p_shepard) ||
         ((f & FEAT_GENERALIZED_DISSIPATION) && !e->w.gd_gamma) ||
         ((f & FEAT_DAMPER_OWN_PHASE) && !e->w.div_own);
}

void engine_work_reserve(struct engine *e) {
  struct work *w = &e->w;
  struct work_slot t[MAX_WORK_SLOTS];
  long n_all = e->p.capacity, n_owned = w->owned_capacity;
  if (e->p.n_owned > n_owned) n_owned = e->p.n_owned + e->p.n_owned / 16 + 64;   /* room to migrate */
  if (n_all <= w->capacity && n_owned <= w->owned_capacity && !optional_missing(e)) return;
  for (int k = 0, n = work_slots(w, e->p.dim, t); k < n; k++)
    if (!t[k].feature || (e->prm.features & t[k].feature)) *t[k].a = grow(*t[k].a, t[k].halo ? n_all : n_owned);
  w->capacity = n_all;
  w->owned_capacity = n_owned;
}

long engine_work_bytes(struct engine *e) {
  struct work_slot t[MAX_WORK_SLOTS];
  long bytes = 0;
  for (int k = 0, n = work_slots(&e->w, e->p.dim, t); k < n; k++)
    if (*t[k].a) bytes += (t[k].halo ? e->w.capacity : e->w.owned_capacity) * (long)sizeof(double);
  return bytes;
}

void engine_work_free(struct work *w) {
  struct work_slot t[MAX_WORK_SLOTS];
  for (int k = 0, n = work_slots(w, 3, t); k < n; k++) {
    free(*t[k].a);
    *t[k].a = NULL;
  }
}

/* The arrays named by a halo field mask. */
static int halo_field_list(struct engine *e, int mask, double **f) {
  struct parts *p = &e->p;
  int n = 0;
  for (int d = 0; d < p->dim; d++) {
    if (mask & HF_POS) f[n++] = p->x[d];
    if (mask & HF_VEL) f[n++] = p->v[d];
    if (mask & HF_GRAD_RHO) f[n++] = e->w.grad_rho[d];
    if (mask & HF_SHIFT) f[n++] = e->w.du[d];
    if (mask & HF_INTERFACE_NORMAL) f[n++] = e->w.interface_normal[d];
    if (mask & HF_GD) f[n++] = e->w.gd_grad_p[d];
  }
  if (mask & HF_RHO) f[n++] = p->rho;
  if (mask & HF_P) f[n++] = p->p;
  if (mask & HF_MASS) f[n++] = p->m;
  if (mask & HF_DIV) f[n++] = e->w.div;
  if (mask & HF_DIV_OWN) f[n++] = e->w.div_own;
  if (mask & HF_SURFACE) f[n++] = e->w.surface;
  if (mask & HF_RHO_SHEPARD) f[n++] = e->w.rho_s;
  if (mask & HF_P_SHEPARD) f[n++] = e->w.p_shepard;
  if (mask & HF_GD) f[n++] = e->w.gd_gamma;
  return n;
}

/* engine_assemble makes at most 18 operations (ENGINE_MAX_OPS, engine.h), whatever the case; one
 * more is a programming error, stopped here before it overflows e->ops. */
static void add_op(struct engine *e, struct stage_op op) {
  if (e->n_ops == ENGINE_MAX_OPS) {
    fprintf(stderr, "mpsph: internal error: the stage pipeline has more than %d operations (adding '%s')\n",
            ENGINE_MAX_OPS, op.name);
    exit(3);
  }
  e->ops[e->n_ops++] = op;
}

void engine_add_op(struct engine *e, const char *name, pass_fn pass, int mask, int once) {
  add_op(e, (struct stage_op){.name = name, .pass = pass, .halo_fields = mask, .once_per_step = once});
}

void engine_add_cell_pass(struct engine *e, const char *name, pass_fn pass, int once) {
  add_op(e, (struct stage_op){.name = name, .pass = pass, .once_per_step = once, .cellwise = 1});
}

/* The owned fluid's neighbour lists, built at the first stage of a step. */
static void add_neighbour_lists(struct engine *e) {
  engine_add_op(e, "neighbour lists of the owned fluid (once per step)", pass_neighbour_lists, 0, 1);
}

void engine_add_volumes_and_lists(struct engine *e) {
  engine_add_op(e, "volumes m/rho of owned and halo particles", pass_volumes, 0, 0);
  add_neighbour_lists(e);
}

/* DESIGN.md data flow 3: what a scene does not use is not computed. */
unsigned engine_option_terms(const struct engine *e) {
  const struct case_def *c = e->c;
  unsigned f = 0;
  int liquid = 0, viscous = c->alpha > 0;
  for (int ph = 0; ph < c->n_phases; ph++) {
    liquid |= c->phases[ph].incompressible;
    viscous |= c->phases[ph].viscosity > 0;
  }
  if (c->delta > 0) f |= FEAT_DIFFUSION;
  if (viscous) f |= FEAT_VISCOSITY;
  if (c->n_walls) f |= FEAT_WALLS;
  if (c->shifting != SHIFTING_NONE) f |= FEAT_SHIFT;
  if (c->shifting == SHIFTING_CONSISTENT) f |= FEAT_DELTA_U;
  if (c->acoustic_damper > 0 && liquid) f |= FEAT_DAMPER;
  if ((f & FEAT_DAMPER) && c->damper_form == DAMPER_OWN_PHASE) f |= FEAT_DAMPER_OWN_PHASE;
  if (c->free_surface != FREE_SURFACE_OFF && !e->no_free_surface && (c->tensile_control || (f & FEAT_SHIFT)))
    f |= FEAT_SURFACE;
  if (c->tensile_control) f |= FEAT_TIC;
  if (c->interface_sharpness > 0 && c->n_phases > 1) f |= FEAT_SHARPNESS;
  if (c->potential_omega > 0) f |= FEAT_CENTRAL;
  if (c->surface_tension > 0 && c->n_phases > 1) f |= FEAT_SURFACE_TENSION;
  if (case_n_bodies(c)) f |= FEAT_BODIES;
  return f;
}

/* alpha2 c0 h of each liquid phase (index phase + 1; walls at 0), 0 for gases. */
static void damper_coefficients(struct engine *e) {
  e->prm.damper_coef[0] = 0;
  for (int ph = 0; ph < e->c->n_phases; ph++) {
    const struct phase *f = &e->c->phases[ph];
    int damped = (e->prm.features & FEAT_DAMPER) && f->incompressible;
    e->prm.damper_coef[ph + 1] = damped ? e->c->acoustic_damper * f->c0 * e->prm.h : 0;
  }
}

/* After a re-assembly: the operations that stay keep their accumulated time and pairs (matched by
 * name); the time of those dropped goes to e->t_dropped_ops. */
static void carry_op_totals(struct engine *e, const struct stage_op *old, int n_old) {
  for (int k = 0; k < n_old; k++) {
    int kept = 0;
    for (int j = 0; j < e->n_ops && !kept; j++)
      if (!strcmp(e->ops[j].name, old[k].name)) {
        e->ops[j].seconds += old[k].seconds;
        e->ops[j].pairs += old[k].pairs;
        kept = 1;
      }
    if (!kept) e->t_dropped_ops += old[k].seconds;
  }
}

void engine_assemble(struct engine *e) {
  struct stage_op old[ENGINE_MAX_OPS];
  int n_old = e->n_ops;
  memcpy(old, e->ops, sizeof old);
  const struct scheme *s = scheme_of(e->c->scheme);
  e->prm.features = s->terms(e) | s->feature;
  e->moving_walls = case_walls_move(e->c);
  damper_coefficients(e);
  interface_table(e->c->interface_mode, e->prm.iface);
  e->n_ops = 0;
  s->pipeline(e);
  carry_op_totals(e, old, n_old);
  engine_work_reserve(e);
}

void engine_assemble_stage(struct engine *e) {
  const struct scheme *s = scheme_of(e->c->scheme);
  unsigned f = e->prm.features;
  engine_add_op(e, "halo: positions, velocities, densities, pressures", NULL, HF_POS | HF_VEL | HF_RHO | HF_P, 0);
  if (s->pressure) s->pressure(e);
  /* the ghosts read this stage's fluid volumes; with a pressure pass, they are computed before it */
  int split_volumes = (f & FEAT_WALLS) && !s->pressure;
  if (split_volumes) engine_add_op(e, "volumes m/rho of the fluid (owned and halo)", pass_fluid_volumes, 0, 0);
  if (f & FEAT_WALLS) {
    engine_add_op(e, "wall ghosts: lists at the fixed walls' mirror points (once per step)", pass_wall_ghost_lists, 0, 1);
    engine_add_op(e, "wall ghosts: Shepard interpolation at mirror points", pass_wall_ghosts, 0, 0);
    engine_add_op(e, "halo: wall ghost values", NULL, HF_VEL | HF_RHO | HF_P | HF_MASS, 0);
  }
  if (split_volumes) {
    engine_add_op(e, "volumes m/rho of the wall ghosts (owned and halo)", pass_boundary_volumes, 0, 0);
    add_neighbour_lists(e);
  } else if (!s->pressure) {
    engine_add_volumes_and_lists(e);
  }
  if (f & FEAT_SURFACE) {
    engine_add_cell_pass(e, "free surface: eigenvalue + umbrella detection, normals (once per step)", pass_free_surface, 1);
    engine_add_op(e, "halo: free-surface flags (once per step)", NULL, HF_SURFACE, 1);
    engine_add_cell_pass(e, "free-surface region: band around the detected particles (once per step)", pass_surface_band, 1);
  }
  s->rhs(e);
  if (f & FEAT_SURFACE_TENSION) {
    engine_add_cell_pass(e, "surface tension: colour gradient, interface normals", pass_interface_normals, 0);
    engine_add_op(e, "halo: interface normals", NULL, HF_INTERFACE_NORMAL, 0);
    engine_add_cell_pass(e, "surface tension: curvature, CSF force", pass_surface_tension, 0);
  }
  if ((f & FEAT_WALLS) && e->c->wall_guard > 0)
    engine_add_op(e, "wall guard: no acceleration into a wall within the guard distance", pass_wall_guard, 0, 0);
}

/** Print the assembled pipeline and the active terms (rank 0). */
void engine_print_pipeline(const struct engine *e) {
  static const char *names[] = {"wall ghosts", "shifting", "delta-u terms", "acoustic damper",
                                "free-surface detection", "tensile instability control",
                                "interface sharpness", "quadratic potential", "surface tension",
                                "Shepard density", "same-phase continuity", "generalized dissipation"};
  if (e->rank) return;
  printf("terms:");
  for (int k = 0; k < (int)(sizeof names / sizeof names[0]); k++)
    if (e->prm.features & (1u << k)) printf(" [%s]", names[k]);
  if (e->prm.features & FEAT_RIEMANN) printf(" [Riemann SPH, density re-initialisation, dual time stepping]");
  if (e->prm.features & FEAT_TRANSPORT_VELOCITY) printf(" [transport velocity of the light phases]");
  if (e->prm.features & FEAT_DIFFUSION) printf(" [density diffusion]");
  if (e->prm.features & FEAT_VISCOSITY) printf(" [viscosity]");
  printf("\npipeline per %s (%d operations):\n", (e->prm.features & FEAT_RIEMANN) ? "advection step" : "RK stage", e->n_ops);
  for (int k = 0; k < e->n_ops; k++) printf("  %d. %s\n", k + 1, e->ops[k].name);
}

/* Account pass operation op, run with ctx for `seconds`: its counts and its time. */
static void finish_pass(struct engine *e, struct stage_op *op, const struct pass_ctx *ctx, double seconds) {
  op->pairs += ctx->out.pairs;
  e->renorm_fallbacks += ctx->out.renorm_fallbacks;
  e->n_surface += ctx->out.n_surface;
  op->seconds += seconds;
  e->t_compute += seconds;
}

void engine_run_op(struct engine *e, int k) {
  double *fields[32];
  struct stage_op *op = &e->ops[k];
  double t0 = MPI_Wtime();
  if (op->pass) {
    struct pass_ctx ctx = engine_pass_ctx(e);
    op->pass(&ctx);
    finish_pass(e, op, &ctx, MPI_Wtime() - t0);
  } else {
    halo_update(&e->halo, fields, halo_field_list(e, op->halo_fields, fields));
    op->seconds += MPI_Wtime() - t0;
  }
}

static void progress_halo(void *halo) { halo_update_progress(halo); }

/* Run halo operation k overlapped with the cell pass k + 1 that reads it: post the messages, run
 * the pass over the interior cells (whose sums read no halo slot) while they travel, wait, then
 * run it over the cells next to other ranks'. Every particle's sums are those of a plain run. */
static void run_overlapped(struct engine *e, int k) {
  double *fields[32];
  struct stage_op *halo = &e->ops[k], *op = &e->ops[k + 1];
  const struct space *s = &e->space;
  int n = halo_field_list(e, halo->halo_fields, fields);
  double t0 = MPI_Wtime();
  halo_update_begin(&e->halo, fields, n);
  double t1 = MPI_Wtime();
  struct pass_ctx ctx = engine_pass_ctx(e);
  ctx.cells = s->by_reach;
  ctx.n_cells = s->n_interior;
  ctx.progress = progress_halo;
  ctx.progress_arg = &e->halo;
  op->pass(&ctx);
  double t2 = MPI_Wtime();
  halo_update_end(&e->halo);
  double t3 = MPI_Wtime();
  ctx.cells = s->by_reach + s->n_interior;
  ctx.n_cells = s->n_owned_cells - s->n_interior;
  ctx.progress = NULL;
  op->pass(&ctx);
  halo->seconds += (t1 - t0) + (t3 - t2);
  finish_pass(e, op, &ctx, (t2 - t1) + (MPI_Wtime() - t3));
}

/* Whether operation k runs at the current stage. */
static int op_runs(const struct engine *e, int k) { return !e->ops[k].once_per_step || e->stage <= 0; }

void engine_evaluate(struct engine *e, int skip_state_halo) {
  e->prm.dt_step = e->dt;
  for (int k = skip_state_halo ? 1 : 0; k < e->n_ops; k++) {
    if (!op_runs(e, k)) continue;
    int overlap = e->n_ranks > 1 && !e->ops[k].pass && k + 1 < e->n_ops && e->ops[k + 1].cellwise &&
                  op_runs(e, k + 1);   /* one rank has no halo to wait for */
    if (overlap) run_overlapped(e, k++);
    else engine_run_op(e, k);
  }
}

struct pass_ctx engine_pass_ctx(struct engine *e) {
  return (struct pass_ctx){.c = e->c, .prm = &e->prm, .p = &e->p, .w = &e->w, .nl = &e->nl, .space = &e->space,
                           .loads = &e->bodies.loads, .solids = e->solids.n ? &e->solids.view : NULL,
                           .solid_loads = &e->solids.loads};
}

long engine_wall_guard(struct engine *e) {
  struct pass_ctx ctx = engine_pass_ctx(e);
  long hits = wall_guard_apply(&ctx);
  if (e->bodies.n) bodies_apply_impulses(e);
  e->wall_guard_hits += hits;
  return hits;
}

/* The counts of passes run outside the pipeline (engine_ghosts_now) are not kept: they are not
 * part of a stage. */
void engine_ghosts_now(struct engine *e) {
  int shepard = (e->prm.features & FEAT_SHEPARD) != 0, walls = (e->prm.features & FEAT_WALLS) != 0;
  if (!shepard && !walls) return;
  double *fields[32];
  struct pass_ctx ctx = engine_pass_ctx(e);
  halo_update(&e->halo, fields, halo_field_list(e, HF_POS | HF_VEL | HF_RHO | HF_P, fields));
  if (shepard) {   /* delta-sph: the stage's first operations, which set the pressure */
    pass_volumes(&ctx);
    pass_neighbour_lists(&ctx);
    pass_shepard_density(&ctx);
    halo_update(&e->halo, fields, halo_field_list(e, HF_RHO_SHEPARD | HF_P, fields));
  }
  if (walls) {
    if (!shepard) pass_fluid_volumes(&ctx);
    pass_wall_ghost_lists(&ctx);
    pass_wall_ghosts(&ctx);
    halo_update(&e->halo, fields, halo_field_list(e, HF_VEL | HF_RHO | HF_P | HF_MASS, fields));
  }
}

void engine_damper_divergence_now(struct engine *e) {
  unsigned f = e->prm.features;
  if (!(f & FEAT_DAMPER)) return;
  engine_ghosts_now(e);
  struct physics_params prm = e->prm;   /* the divergences alone: no density gradient, no shifting */
  prm.features &= ~(unsigned)(FEAT_DIFFUSION | FEAT_SHIFT);
  struct pass_ctx ctx = engine_pass_ctx(e);
  ctx.prm = &prm;
  pass_volumes(&ctx);
  pass_neighbour_lists(&ctx);
  pass_gradients(&ctx);
  double *fields[32];
  halo_update(&e->halo, fields, halo_field_list(e, (f & FEAT_DAMPER_OWN_PHASE) ? HF_DIV_OWN : HF_DIV, fields));
}

double engine_shift_max(const struct engine *e) { return 0.5 * (ENGINE_CELL_SKIN - 1.0) * e->prm.kern.support; }

/* |u_w|^2 of moving-wall ghost i at the current stage [m^2/s^2]. */
static double wall_speed2(const struct engine *e, long i) {
  double x[3] = {0, 0, 0}, u[3] = {0, 0, 0}, u2 = 0;
  for (int d = 0; d < e->p.dim; d++) x[d] = e->p.x[d][i];
  frame_velocity(&e->prm.frames[e->p.wall[i]], e->p.dim, x, u);
  for (int d = 0; d < e->p.dim; d++) u2 += u[d] * u[d];
  return u2;
}

/* Global maxima of the acceleration and of the advection speed |u + du| (and the moving walls' and
 * solids' speeds) [m/s^2, m/s], and the minimum density per phase, from the first stage. */
static void reduce_first_stage(struct engine *e, double *a_max, double *adv_max) {
  const struct parts *p = &e->p;
  int np = e->c->n_phases;
  double max2[2] = {0, 0};   /* |a|^2, |u + du|^2 */
  for (int ph = 0; ph < np; ph++) e->prm.rho_min[ph] = INFINITY;
  for (long i = 0; i < p->n_owned; i++) {
    int ph = p->phase[i];
    if (engine_moving_ghost(e, i)) max2[1] = fmax(max2[1], wall_speed2(e, i));
    if (!part_has(ph, KIND_INTEGRATED)) continue;
    double a2 = 0, w2 = 0;
    for (int d = 0; d < p->dim; d++) {
      double w = p->v[d][i] + (e->w.du[d] ? e->w.du[d][i] : 0.0);
      a2 += e->w.dv[d][i] * e->w.dv[d][i];
      w2 += w * w;
    }
    if (!(a2 <= max2[0])) max2[0] = a2;   /* NaN propagates */
    if (!(w2 <= max2[1])) max2[1] = w2;
    e->prm.rho_min[ph] = fmin(e->prm.rho_min[ph], p->rho[i]);
  }
  MPI_Allreduce(MPI_IN_PLACE, max2, 2, MPI_DOUBLE, MPI_MAX, e->comm);
  MPI_Allreduce(MPI_IN_PLACE, e->prm.rho_min, np, MPI_DOUBLE, MPI_MIN, e->comm);
  *a_max = sqrt(max2[0]);
  *adv_max = e->solids.n ? fmax(sqrt(max2[1]), solids_max_speed(e)) : sqrt(max2[1]);
}

/* The stable sound speed of Eq. 12 for every liquid/gas pair present:
 * c_stab = c0_l sqrt(gamma_g rho0_l / (gamma_l rho_min_g)) (Sun et al. 2021). */
static double stable_sound_speed(const struct pass_ctx *ctx) {
  const struct case_def *c = ctx->c;
  double c_stab = 0;
  for (int l = 0; l < c->n_phases; l++)
    for (int g = 0; g < c->n_phases; g++) {
      const struct phase *pl = &c->phases[l], *pg = &c->phases[g];
      if (!pl->incompressible || pg->incompressible || !isfinite(ctx->prm->rho_min[g])) continue;
      c_stab = fmax(c_stab, pl->c0 * sqrt(pg->gamma * pl->rho0 / (pl->gamma * ctx->prm->rho_min[g])));
    }
  return c_stab;
}

/* Lower *dt to candidate if smaller, naming the limit. */
static void limit_by(double *dt, const char **limit, double candidate, const char *name) {
  if (candidate < *dt) {
    *dt = candidate;
    *limit = name;
  }
}

/* The time-step limits of paper 000 Eq. 12: acoustic (with c_stab), acceleration, viscous,
 * damper; *limit names the smallest term. Scheme same-phase-continuity takes paper 003's
 * CFL h / c0 (section 3.3) without c_stab and without the acceleration and artificial-viscosity
 * limits; the physical viscous and capillary limits stay. */
double engine_delta_plus_dt(const struct pass_ctx *ctx, double a_max, double adv_max, const char **limit) {
  const struct case_def *c = ctx->c;
  (void)adv_max;   /* the motion limit is time_step's */
  const int paper003 = (ctx->prm->features & FEAT_SAME_PHASE_CONTINUITY) != 0;
  double c_eff = paper003 ? ctx->prm->c_max : fmax(ctx->prm->c_max, stable_sound_speed(ctx));
  double dt = c->cfl * ctx->prm->h / c_eff;
  *limit = c_eff > ctx->prm->c_max ? "acoustic (c_stab)" : "acoustic";
  if (a_max > 0 && !paper003) limit_by(&dt, limit, 0.25 * sqrt(ctx->prm->h / a_max), "acceleration");
  for (int ph = 0; ph < c->n_phases; ph++) {
    const struct phase *f = &c->phases[ph];
    if (c->alpha > 0 && !paper003) limit_by(&dt, limit, ctx->prm->h / (c->alpha * f->c0), "artificial viscosity");
    if (f->viscosity > 0) limit_by(&dt, limit, 0.125 * ctx->prm->h * ctx->prm->h * f->rho0 / f->viscosity, "viscous");
    if ((ctx->prm->features & FEAT_DAMPER) && f->incompressible)
      limit_by(&dt, limit, c->cfl * ctx->prm->h / (c->acoustic_damper * f->c0), "acoustic damper");
  }
  if (ctx->prm->features & FEAT_SURFACE_TENSION) limit_by(&dt, limit, capillary_dt(c, ctx->prm->h), "capillary");
  return dt;
}

/* Global time step: the scheme's limits (paper 000 Eq. 12, or paper 004 Eq. 23 for
 * generalized-dissipation) and the motion limit of the cell skin; *limit names the smallest
 * term. Not yet cut to time.end. */
static double time_step(struct engine *e, const char **limit) {
  double a_max, adv_max;
  reduce_first_stage(e, &a_max, &adv_max);
  struct pass_ctx ctx = engine_pass_ctx(e);
  double dt = scheme_of(e->c->scheme)->time_step(&ctx, a_max, adv_max, limit);
  if (adv_max > 0) limit_by(&dt, limit, MOTION_SAFETY * engine_shift_max(e) / adv_max, "motion (cell skin)");
  return dt;
}

static void save_state(struct engine *e) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    for (int d = 0; d < p->dim; d++) {
      e->w.x0[d][i] = p->x[d][i];
      e->w.v0[d][i] = p->v[d][i];
    }
    e->w.rho0[i] = p->rho[i];
  }
}

/* The frames of the moving walls at time t [s]: a prescribed motion's at t, a body's at its
 * current state. */
static void wall_frames(const struct engine *e, double t, struct frame *f) {
  for (int w = 0; w < e->c->n_walls; w++)
    if (e->c->walls[w].moving && !e->c->walls[w].body.active) motion_frame(&e->c->walls[w].motion, t, &f[w]);
  bodies_frames(e, f);
}

/* Carry the owned ghosts of moving walls rigidly from their place at the start of the step
 * (frames `start`) to time t [s]. */
static void move_ghosts(struct engine *e, const struct frame *start, double t) {
  struct parts *p = &e->p;
  struct frame now[CASE_MAX_WALLS];
  wall_frames(e, t, now);
  for (long i = 0; i < p->n_owned; i++) {
    if (!engine_moving_ghost(e, i)) continue;
    double x0[3] = {0, 0, 0}, ref[3], x[3];
    for (int d = 0; d < p->dim; d++) x0[d] = e->w.x0[d][i];
    frame_reference(&start[p->wall[i]], p->dim, x0, ref);
    frame_position(&now[p->wall[i]], p->dim, ref, x);
    for (int d = 0; d < p->dim; d++) p->x[d][i] = x[d];
  }
}

/* An explicit Runge-Kutta scheme of the form the update below runs: stage s + 1 evaluates
 * x0 + next[s] dt k_s (and the time offset[s + 1] dt), the step ends at
 * x0 + dt sum_s weight[s] k_s / divisor. */
struct rk_scheme {
  int stages;
  double weight[4], next[3], offset[4], divisor;
};

/* The classical RK4 (paper 000), and the predictor-corrector of paper 003 Eqs. 40-42:
 * phi^1/2 = phi^0 + dt/2 phi'^0, phi^1 = 2 (phi^0 + dt/2 phi'^1/2) - phi^0 = phi^0 + dt phi'^1/2
 * (the explicit midpoint rule, two rhs evaluations per step). */
static const struct rk_scheme RK4 = {4, {1, 2, 2, 1}, {0.5, 0.5, 1.0}, {0, 0.5, 0.5, 1.0}, 6.0};
static const struct rk_scheme MIDPOINT_PC = {2, {0, 1}, {0.5}, {0, 0.5}, 1.0};

/* The density threshold of paper 003 Eq. 28: a negative pressure is raised to 0 by setting the
 * density to that of zero pressure in the particle's phase. */
static void density_threshold(struct parts *p, long i, const struct phase *f) {
  if (p->p[i] >= 0) return;
  p->rho[i] = eos_density(f, 0.0);
  p->p[i] = 0.0;
}

/* Accumulate stage s's derivatives with the scheme's weight and move owned fluid to the next
 * stage state. Positions advance with u + du (du = 0 without shifting); moving walls go where
 * their motion puts them at the next stage's time. */
static void rk_update(struct engine *e, const struct rk_scheme *rk, int s, const struct frame *start) {
  struct parts *p = &e->p;
  struct work *w = &e->w;
  const int last = s == rk->stages - 1, threshold = (e->prm.features & FEAT_SAME_PHASE_CONTINUITY) != 0;
  double ws = rk->weight[s], step = !last ? rk->next[s] * e->dt : e->dt / rk->divisor;
  for (long i = 0; i < p->n_owned; i++) {
    if (!part_has(p->phase[i], KIND_INTEGRATED)) continue;
    for (int d = 0; d < p->dim; d++) {
      double dxdt = p->v[d][i] + (w->du[d] ? w->du[d][i] : 0.0);
      w->sum_x[d][i] = (s ? w->sum_x[d][i] : 0) + ws * dxdt;
      w->sum_v[d][i] = (s ? w->sum_v[d][i] : 0) + ws * w->dv[d][i];
      p->x[d][i] = w->x0[d][i] + step * (!last ? dxdt : w->sum_x[d][i]);
      p->v[d][i] = w->v0[d][i] + step * (!last ? w->dv[d][i] : w->sum_v[d][i]);
    }
    w->sum_rho[i] = (s ? w->sum_rho[i] : 0) + ws * w->drho[i];
    p->rho[i] = w->rho0[i] + step * (!last ? w->drho[i] : w->sum_rho[i]);
    p->p[i] = eos_pressure(&e->c->phases[p->phase[i]], p->rho[i]);
    if (threshold) density_threshold(p, i, &e->c->phases[p->phase[i]]);
  }
  double t_next = e->step_start_time + (!last ? rk->next[s] : 1.0) * e->dt;
  bodies_rk_update(e, s, ws, step, last, t_next);
  if (e->moving_walls) move_ghosts(e, start, t_next);
}

int engine_step(struct engine *e) { return scheme_of(e->c->scheme)->step(e); }

/* The elastic solids' part of stage s (doc/theory.md section 14): the loads of the stage with its
 * weight in the step's update, and after the last stage the solids' advance over the step, under
 * the loads so averaged. Returns 0 or 2. */
static int solids_stage(struct engine *e, const struct rk_scheme *rk, int s) {
  if (!e->solids.n) return 0;
  double t0 = MPI_Wtime();
  solids_take_loads(e, rk->weight[s] / rk->divisor, s == 0);
  int status = s == rk->stages - 1 ? solids_move(e, e->dt) : 0;
  e->t_solids += MPI_Wtime() - t0;
  return status;
}

int engine_step_rk(struct engine *e) {
  const struct rk_scheme *rk = (e->prm.features & FEAT_SAME_PHASE_CONTINUITY) ? &MIDPOINT_PC : &RK4;
  struct frame start[CASE_MAX_WALLS];
  engine_work_reserve(e);
  save_state(e);
  bodies_save(e);
  e->step_start_time = e->time;
  e->step_start = e->step;
  wall_frames(e, e->time, start);
  for (int s = 0; s < rk->stages; s++) {
    e->stage = s;
    e->stage_time = e->time + rk->offset[s] * e->dt;
    wall_frames(e, e->stage_time, e->prm.frames);
    engine_evaluate(e, s == 0);
    if (engine_check_derivatives(e)) return 2;
    if (e->bodies.n) bodies_evaluate(e);
    if (s == 0) {
      const char *limit;
      e->dt = time_step(e, &limit);
      if (engine_check_dt(e, limit)) return 2;
      e->dt = fmin(e->dt, e->c->t_end - e->time);
    }
    rk_update(e, rk, s, start);
    if (solids_stage(e, rk, s)) return 2;
  }
  wall_frames(e, e->time + e->dt, e->prm.frames);   /* the walls where the step ends (for the checks
                                                       and probes between steps) */
  e->stage = -1;   /* between steps */
  e->time += e->dt;
  e->step++;
  return 0;
}
