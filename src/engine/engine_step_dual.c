/* engine_step_dual.c — dual-criteria time stepping of scheme riemann (paper 002 section 2.5,
 * Eqs. 24-28; notes seed-002 section 1.10; the time steps take h, the heavy phases' also with
 * multi-resolution), with the elastic solids advanced
 * after each acoustic sub-step (engine/solids.h). One engine step is one
 * advection step dt_ad: the cells and neighbour lists (built by engine_rebuild after the previous
 * step), the density re-initialisation and the transport-velocity shift of the light phases belong
 * to it; inside it, acoustic sub-steps dt_ac of position Verlet,
 *   rho += dt_ac/2 drho/dt;  p = EOS(rho);  r += dt_ac/2 v;      then du/dt at this state
 *   v += dt_ac du/dt;  r += dt_ac/2 v;                            then drho/dt at this state
 *   rho += dt_ac/2 drho/dt,
 * every phase updated before any force is computed (Jacobi order, notes 1.10). The drho/dt of the
 * first half is the one of the previous sub-step's second half (notes A13); at the start of an
 * advection step it is computed afresh from the re-initialised state, so that a step depends only
 * on the particle state (checkpoints restart bitwise);
 * the halo refreshed before every force evaluation. */
#include <math.h>
#include <string.h>
#include "physics/eos.h"
#include "engine/engine.h"
#include "physics/passes.h"

#define DUAL_ADVECTION_CFL 0.25   /* Eq. 24 */
#define DUAL_MOTION_SAFETY 0.75   /* fraction of the cell skin's motion allowance used by dt_ad */
#define TRANSPORT_COEFFICIENT 10.0   /* p0_tv = 10 rho0_light U^2 (Eq. 12) */

/* The operations, in the order of the pipeline. */
enum { OP_STATE_HALO, OP_VOLUMES, OP_LISTS, OP_REINIT, OP_REINIT_HALO,
       OP_TRANSPORT, OP_MOMENTUM, OP_NORMALS, OP_NORMALS_HALO, OP_SURFACE_TENSION, OP_CONTINUITY, N_DUAL_OPS };
_Static_assert(N_DUAL_OPS <= ENGINE_MAX_OPS, "the dual pipeline must fit in engine.ops");

static const struct {
  const char *name;
  pass_fn pass;
  int halo_fields;
  unsigned feature;   /* present only with this feature (0: always) */
} dual_table[N_DUAL_OPS] = {
    {"halo: positions, velocities, densities, pressures", NULL, HF_POS | HF_VEL | HF_RHO | HF_P, 0},
    {"volumes m/rho of owned and halo particles", pass_volumes, 0, 0},
    {"neighbour lists of the owned fluid (once per advection step)", pass_neighbour_lists, 0, 0},
    {"density re-initialisation, heavy and light phases (once per advection step)", pass_density_reinit, 0, 0},
    {"halo: re-initialised densities, pressures", NULL, HF_RHO | HF_P, 0},
    {"transport-velocity acceleration of the light phases (once per advection step)",
     pass_transport_acceleration, 0, FEAT_TRANSPORT_VELOCITY},
    {"Riemann momentum (first half of each acoustic sub-step)", pass_riemann_momentum, 0, 0},
    {"surface tension: colour gradient, interface normals (each acoustic sub-step)", pass_interface_normals, 0,
     FEAT_SURFACE_TENSION},
    {"halo: interface normals", NULL, HF_INTERFACE_NORMAL, FEAT_SURFACE_TENSION},
    {"surface tension: curvature, CSF force added to the momentum", pass_surface_tension, 0, FEAT_SURFACE_TENSION},
    {"Riemann continuity (second half of each acoustic sub-step)", pass_riemann_continuity, 0, 0},
};

void engine_assemble_dual(struct engine *e) {
  for (int k = 0; k < N_DUAL_OPS; k++) {
    e->dual_ops[k] = -1;
    if (dual_table[k].feature && !(e->prm.features & dual_table[k].feature)) continue;
    e->dual_ops[k] = e->n_ops;
    e->ops[e->n_ops++] = (struct stage_op){.name = dual_table[k].name, .pass = dual_table[k].pass,
                                           .halo_fields = dual_table[k].halo_fields};
  }
  for (int ph = 0; ph < e->c->n_phases; ph++) {
    e->prm.lattice_w_sum[ph] = lattice_kernel_sum(&e->prm.phase_kern[ph], case_phase_dx(e->c, ph));
    e->prm.light_penalty[ph] = riemann_light_phase(e->c, ph) ? e->c->light_penalty : 0.0;
  }
}

/* Run operation id of the table if the pipeline has it. */
static void run(struct engine *e, int id) {
  if (e->dual_ops[id] >= 0) engine_run_op(e, e->dual_ops[id]);
}

/* Halo and volumes of the current state: what the pair passes read (the wall ghosts' dummy
 * states are made in the pair loops). */
static void refresh(struct engine *e) {
  for (int id = OP_STATE_HALO; id <= OP_VOLUMES; id++) run(e, id);
}

/* Global maxima over the owned fluid (of the light phases only with light_only) of |v| [m/s], of
 * |dv| (the work acceleration) [m/s^2] and of the displacement |r - r0| since the start of the
 * advection step [m], into m[0..2]. */
static void fluid_maxima(struct engine *e, int light_only, double *m) {
  const struct parts *p = &e->p;
  m[0] = m[1] = m[2] = 0;
  for (long i = 0; i < p->n_owned; i++) {
    if (!part_has(p->phase[i], KIND_INTEGRATED) || (light_only && !riemann_light_phase(e->c, p->phase[i])))
      continue;
    double q[3] = {0, 0, 0};
    for (int d = 0; d < p->dim; d++) {
      double s = p->x[d][i] - e->w.x0[d][i];
      q[0] += p->v[d][i] * p->v[d][i];
      q[1] += e->w.dv[d][i] * e->w.dv[d][i];
      q[2] += s * s;
    }
    for (int k = 0; k < 3; k++)
      if (!(q[k] <= m[k])) m[k] = q[k];   /* NaN propagates */
  }
  MPI_Allreduce(MPI_IN_PLACE, m, 3, MPI_DOUBLE, MPI_MAX, e->comm);
  for (int k = 0; k < 3; k++) m[k] = sqrt(m[k]);
}

/* The motion allowance of an advection step: a fraction of half the cell skin [m]. */
static double motion_budget(const struct engine *e) { return DUAL_MOTION_SAFETY * engine_shift_max(e); }

double dual_advection_dt(struct engine *e, double a_tv) {
  const struct case_def *c = e->c;
  double m[3];
  fluid_maxima(e, 0, m);
  double v_max = fmax(m[0], solids_max_speed(e)), dt = DUAL_ADVECTION_CFL * e->prm.h / fmax(c->u_max, v_max);
  for (int ph = 0; ph < c->n_phases; ph++)
    if (c->phases[ph].viscosity > 0)
      dt = fmin(dt, DUAL_ADVECTION_CFL * e->prm.h * e->prm.h * c->phases[ph].rho0 / c->phases[ph].viscosity);
  /* motion v dt + a_tv dt^2 / 2 within the allowance B: dt = 2B / (v + sqrt(v^2 + 2 a_tv B)) */
  double b = motion_budget(e), root = v_max + sqrt(v_max * v_max + 2.0 * a_tv * b);
  if (root > 0) dt = fmin(dt, 2.0 * b / root);
  return dt;
}

/* The acoustic sub-step [s] from the maxima m of fluid_maxima, and the capillary limit with
 * surface tension. */
static double acoustic_dt(const struct engine *e, const double *m) {
  double dt = e->c->cfl * e->prm.h / (e->prm.c_max + m[0]);
  return (e->prm.features & FEAT_SURFACE_TENSION) ? fmin(dt, capillary_dt(e->c, e->prm.h)) : dt;
}

double dual_acoustic_dt(struct engine *e) {
  double m[3];
  fluid_maxima(e, 0, m);
  return acoustic_dt(e, m);
}

/* The transport-velocity background pressure 10 rho0 U^2 of the light phase (the largest light
 * rho0), U the largest light-phase speed, at least physics.u_max (notes A11) [Pa]; its largest
 * acceleration into *a_tv [m/s^2] (dv holds the accelerations). */
static void transport_velocity(struct engine *e, double *a_tv) {
  double rho0 = 0, m[3];
  for (int ph = 0; ph < e->c->n_phases; ph++)
    if (riemann_light_phase(e->c, ph)) rho0 = fmax(rho0, e->c->phases[ph].rho0);
  fluid_maxima(e, 1, m);
  double u = fmax(m[0], e->c->u_max);
  e->prm.tv_pressure = TRANSPORT_COEFFICIENT * rho0 * u * u;
  run(e, OP_VOLUMES);   /* of the re-initialised densities */
  run(e, OP_TRANSPORT);
  fluid_maxima(e, 0, m);
  *a_tv = m[1];
}

/* Positions r += scale dv (transport shift) or r += scale v of the owned fluid. */
static void move(struct engine *e, double scale, int by_acceleration) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < p->dim && part_has(p->phase[i], KIND_INTEGRATED); d++)
      p->x[d][i] += scale * (by_acceleration ? e->w.dv[d][i] : p->v[d][i]);
}

/* rho += scale drho/dt and p = EOS(rho) of the owned fluid. */
static void compress(struct engine *e, double scale) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++) {
    if (!part_has(p->phase[i], KIND_INTEGRATED)) continue;
    p->rho[i] += scale * e->w.drho[i];
    p->p[i] = eos_pressure(&e->c->phases[p->phase[i]], p->rho[i]);
  }
}

/* v += dt dv/dt of the owned fluid. */
static void accelerate(struct engine *e, double dt) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < p->dim && part_has(p->phase[i], KIND_INTEGRATED); d++) p->v[d][i] += dt * e->w.dv[d][i];
}

/* The time-step check of engine_check_dt on step dt [s] of the named limit. Returns 0 or 2. */
static int check_step(struct engine *e, double dt, const char *limit) {
  double advection = e->dt;
  e->dt = dt;
  int status = engine_check_dt(e, limit);
  e->dt = advection;
  return status;
}

/* pass_wall_guard outside the pipeline: no acceleration (or shift) into a wall. */
static void guard_accelerations(struct engine *e) {
  struct pass_ctx ctx = engine_pass_ctx(e);
  pass_wall_guard(&ctx);
}

/* One acoustic sub-step of dt [s]; the wall guard (doc/theory.md §5) acts on the acceleration
 * and on the new velocity of each sub-step. Returns 0 or 2. */
static int acoustic_substep(struct engine *e, double dt) {
  int guard = (e->prm.features & FEAT_WALLS) && e->c->wall_guard > 0;
  compress(e, 0.5 * dt);
  move(e, 0.5 * dt, 0);
  refresh(e);
  for (int id = OP_MOMENTUM; id <= OP_SURFACE_TENSION; id++) run(e, id);
  if (engine_check_derivatives(e)) return 2;
  if (guard) guard_accelerations(e);
  accelerate(e, dt);
  if (guard) engine_wall_guard(e);
  move(e, 0.5 * dt, 0);
  refresh(e);
  run(e, OP_CONTINUITY);
  if (engine_check_derivatives(e)) return 2;
  compress(e, 0.5 * dt);
  if (!e->solids.n) return 0;
  double t0 = MPI_Wtime();
  int status = solids_advance(e, dt);
  e->t_solids += MPI_Wtime() - t0;
  return status;
}

/* The start of an advection step: lists, re-initialisation, transport shift, dt_ad, drho/dt.
 * Returns 0 or 2. */
static int advection_start(struct engine *e) {
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned; i++)   /* for the motion check */
    for (int d = 0; d < p->dim; d++) e->w.x0[d][i] = p->x[d][i];
  for (long i = 0; i < p->n_owned; i++)
    for (int d = 0; d < p->dim; d++) e->w.dv[d][i] = 0;
  for (int id = OP_STATE_HALO; id <= OP_REINIT_HALO; id++) run(e, id);
  double a_tv = 0;
  solids_step_start(e);
  if (e->prm.features & FEAT_TRANSPORT_VELOCITY) transport_velocity(e, &a_tv);
  e->dt = dual_advection_dt(e, a_tv);
  if (check_step(e, e->dt, "advection")) return 2;
  e->dt = fmin(e->dt, e->c->t_end - e->time);
  if (a_tv > 0 && (e->prm.features & FEAT_WALLS) && e->c->wall_guard > 0) guard_accelerations(e);   /* no shift into a wall */
  if (a_tv > 0) move(e, 0.5 * e->dt * e->dt, 1);
  refresh(e);
  run(e, OP_CONTINUITY);
  return engine_check_derivatives(e);
}

int engine_step_dual(struct engine *e) {
  engine_work_reserve(e);
  e->step_start_time = e->stage_time = e->time;
  e->step_start = e->step;
  e->stage = 0;
  if (advection_start(e)) return 2;
  double tau = 0;
  int last = 0;
  for (e->n_acoustic = 0; !last; e->n_acoustic++) {
    double m[3];
    fluid_maxima(e, 0, m);
    double dt = acoustic_dt(e, m);
    if (check_step(e, dt, "acoustic")) return 2;
    last = e->dt - tau <= dt * (1.0 + 1e-12);   /* no sub-step of a rounding error at the end */
    double step = last ? e->dt - tau : dt;
    if (e->solids.n) solids_motion(e, m);   /* the solids' particles are in the lists too */
    if (e->n_acoustic && m[2] + step * (m[0] + m[1] * step) > motion_budget(e) * (1.0 + 1e-9)) {
      e->dt = tau;   /* the next sub-step could leave the cell skin: end the advection step here */
      break;
    }
    e->dt_acoustic = step;
    if (acoustic_substep(e, e->dt_acoustic)) return 2;
    tau += e->dt_acoustic;
    e->stage_time = e->time + tau;
  }
  e->stage = -1;
  e->time += e->dt;
  e->step++;
  return 0;
}
