/* pass_ctx.h — what a pass works on: the case, the physics parameters, the particles, the work
 * arrays, the neighbour lists and the cell index, and the counts it reports back. The engine
 * builds one (engine_pass_ctx) and hands it to each pass; the physics layer sees nothing else of
 * the engine (no MPI state, no outputs, no timings). */
#ifndef MPSPH_PASS_CTX_H
#define MPSPH_PASS_CTX_H

#include <math.h>
#include <stdint.h>
#include "base/parts.h"
#include "case/case.h"
#include "parallel/nlist.h"
#include "parallel/space.h"
#include "physics/interface.h"
#include "physics/kernel.h"

/** Terms and passes a scene needs, decided once at start-up from the case. */
enum {
  FEAT_WALLS = 1,          /* wall ghost interpolation */
  FEAT_SHIFT = 2,          /* particle shifting velocity du (advection with u + du) */
  FEAT_DELTA_U = 4,        /* the delta-u terms of continuity and momentum (consistent shifting) */
  FEAT_DAMPER = 8,         /* acoustic damper on the liquid phases */
  FEAT_SURFACE = 16,       /* free-surface detection (region, normals) */
  FEAT_TIC = 32,           /* tensile instability control */
  FEAT_SHARPNESS = 64,     /* interface sharpness force */
  FEAT_CENTRAL = 128,      /* quadratic potential body force */
  FEAT_SURFACE_TENSION = 256,  /* CSF surface tension between the fluid phases */
  FEAT_SHEPARD = 512,      /* scheme delta-sph: same-phase Shepard density and the pressure from it */
  FEAT_SAME_PHASE_CONTINUITY = 1024,  /* scheme same-phase-continuity (paper 003): its own rhs pass,
                                         Shepard pressure of other-phase neighbours, midpoint
                                         predictor-corrector, density threshold */
  FEAT_GENERALIZED_DISSIPATION = 2048,  /* scheme generalized-dissipation (paper 004) */
  FEAT_RIEMANN = 4096,     /* scheme riemann: Riemann pair terms, density re-initialisation, dual time stepping */
  FEAT_TRANSPORT_VELOCITY = 8192,  /* scheme riemann with a light phase: its transport-velocity shift */
  FEAT_DIFFUSION = 16384,  /* density diffusion (delta > 0); in delta-plus and delta-sph also the
                              renormalised density gradient it reads */
  FEAT_VISCOSITY = 32768,  /* artificial (alpha > 0) or laminar (a phase's viscosity > 0) viscosity */
  FEAT_DAMPER_OWN_PHASE = 65536,  /* the damper's D over the own phase and the walls (div_own) */
  FEAT_BODIES = 131072     /* rigid bodies: the fluid's pair forces on their ghosts (body loads) */
};

/** What a body load holds: the pair forces of a stage, the wall guard's removed acceleration of a
 *  stage (a contact force), or the wall guard's velocity correction after a step (an impulse). */
enum body_load_source { LOAD_PAIRS = 0, LOAD_GUARD = 1, LOAD_GUARD_IMPULSE = 2 };

/** The reaction on one body of what it did to one fluid particle: minus the particle's mass times
 *  the part of its du/dt that body's ghost pairs (or the guard) make, or times the velocity the
 *  guard took from it (action and reaction). */
struct body_load {
  int64_t id;                      /* the fluid particle's id (the loads are summed in id order) */
  int wall;                        /* the body's wall index; for a solid load (struct solid_view) the
                                      solid particle's index g */
  int source;                      /* enum body_load_source: the order of one particle's loads */
  double x[3];                     /* the fluid particle's position: every pair force is along the
                                      pair's separation, so its torque is taken here [m] */
  double force[3];                 /* on the body [N] (2D: [N/m]); an impulse [N s] (2D: [N s/m]) */
};

/** The body loads of a stage (or of a step's wall guard), appended by the rhs pass and the wall
 *  guard in any order. */
struct body_loads {
  struct body_load *at;
  long n, cap;
};

/** Append to the loads the reaction on body wall w of the acceleration (or, for an impulse, the
 *  velocity change) dv that the body gave fluid particle i: -m_i dv at the particle's position. */
void body_load_append(struct body_loads *l, const struct parts *p, long i, int w, enum body_load_source source,
                      const double *dv);

/** What the pair passes read of the elastic solids (engine/solids.h): the particles with ids id0
 *  to id0 + n - 1 are the solids' (kind KIND_SOLID), g = id - id0 indexes v and a. */
struct solid_view {
  int64_t id0;
  long n;
  const double *v;                 /* velocity averaged over the last fluid sub-step (riemann) or
                                      step (delta-plus), dim per particle (the wall velocity the
                                      fluid sees) [m/s] */
  const double *a;                 /* the change of that average over the (sub-)step / its length [m/s^2] */
  const double *normal;            /* current unit surface normal, dim per particle (0 deep inside) [-] */
};

/** The one-sided dummy pressure [Pa] that particle g of the solid view s shows a fluid particle i
 *  of pressure p_i [Pa], density rho_i [kg/m^3] and body acceleration a_i (g + f_potential)
 *  [m/s^2] at dx = r_i - r_g [m] (paper 002 Eq. P-18 with the notes' A2, A3):
 *  p_i + rho_i max(0, (a_i - a~_g).(r_g - r_i)). */
static inline double solid_dummy_pressure(const struct solid_view *s, long g, double p_i, double rho_i,
                                          const double *a_i, const double *dx, const int dim) {
  const double *as = s->a + g * dim;
  double head = 0;
  for (int d = 0; d < dim; d++) head -= (a_i[d] - as[d]) * dx[d];
  return p_i + rho_i * fmax(0.0, head);
}

/** Work arrays of the scheme, sized to the particle capacity (those read at halo slots) or to
 *  the owned particles (the RK4 state and sums, the derivatives, the free-surface region and
 *  normals); optional ones stay NULL when the scene does not need them. The engine allocates
 *  them (engine_work_reserve); the passes fill them. */
struct work {
  long capacity, owned_capacity;
  double *vol;                     /* particle volume m/rho of every slot, this stage [m^dim] */
  double *grad_rho[3];             /* renormalised density gradient [kg/m^4] */
  double *div;                     /* velocity divergence <div u> over all neighbours [1/s] */
  double *div_own;                 /* FEAT_DAMPER_OWN_PHASE: <div u> over the neighbours of the own
                                      phase and the walls, the D of the damper [1/s] */
  double *drho, *dv[3];            /* right-hand sides of the current stage */
  double *x0[3], *v0[3], *rho0;    /* state at the start of the step */
  double *sum_x[3], *sum_v[3], *sum_rho;   /* RK4 weighted sums of the stage derivatives */
  double *du[3];                   /* FEAT_SHIFT: shifting velocity [m/s] */
  double *surface;                 /* FEAT_SURFACE: 1 for detected free-surface particles */
  double *region;                  /* FEAT_SURFACE: 1 in the free-surface region (band) */
  double *normal[3];               /* FEAT_SURFACE: outward unit normal */
  double *lambda;                  /* FEAT_SURFACE: smallest eigenvalue of the B matrix */
  double *rho_s;                   /* FEAT_SHEPARD: same-phase Shepard density [kg/m^3] */
  double *interface_normal[3];     /* FEAT_SURFACE_TENSION: unit normal of the colour gradient,
                                      toward the other phase; 0 off the interface band */
  double *colour_grad;             /* FEAT_SURFACE_TENSION: |grad chi| on the band, else 0 [1/m] */
  double *kappa_curvature;         /* FEAT_SURFACE_TENSION: div n, 0 off the band [1/m] */
  double *p_shepard;               /* FEAT_SAME_PHASE_CONTINUITY: Shepard pressure over the fluid of
                                      every phase, the particle included [Pa] */
  double *gd_gamma;                /* FEAT_GENERALIZED_DISSIPATION: Shepard sum incl. self, 1 on
                                      wall ghosts [-] */
  double *gd_grad_p[3];            /* FEAT_GENERALIZED_DISSIPATION: renormalised <grad p>^L [Pa/m] */
};

/** The parameters the physics reads, derived from the case by the engine: fixed at set-up and
 *  assembly, except the last group, which the time stepper sets before the passes that read it. */
struct physics_params {
  struct kernel kern;
  double h, vol0;                  /* smoothing length [m], dx^dim [m^dim] */
  double list_radius;              /* build radius of the neighbour lists at single resolution, and
                                      of the mirror points' lists: the cell edge [m] */
  /* multi-resolution (a phase with dx_ratio > 1, scheme riemann; at single resolution every phase's
     kernel is kern and support_max kern.support) */
  int multires;                    /* some phase has dx_ratio > 1 */
  struct kernel phase_kern[CASE_MAX_PHASES];   /* each phase's kernel, of smoothing length dx_ratio h */
  double phase_vol0[CASE_MAX_PHASES];          /* each phase's lattice volume (dx_ratio dx)^dim [m^dim] */
  double phase_list_radius[CASE_MAX_PHASES];   /* each phase's build radius (its support and the skin
                                                  of the lists at h), also of its pairs with a wall
                                                  ghost or a solid's particle [m] */
  double support_max;              /* the largest phase kernel's support: it sets the cells, the
                                      halo and the wall layers [m] */
  struct kernel chunk_kern[CASE_MAX_PHASES];   /* phase_kern with the cut-off support_max: what a
                                                  phase's pair chunks are filled with (so they keep
                                                  every pair; a pair of another kernel, or beyond its
                                                  own support, is evaluated again or dropped) */
  double c_max;                    /* largest phase sound speed [m/s] */
  unsigned features;               /* FEAT_* of the assembled pipeline */
  struct interface_weights iface[3];   /* eps/phi/kappa per pair relation (case interface mode) */
  double damper_coef[CASE_MAX_PHASES + 1];  /* alpha2 c0 h of phase k at [k + 1]; 0 for gases, walls [m^2/s] */
  double lattice_w_sum[CASE_MAX_PHASES];   /* scheme riemann: each phase's sum of its W over its
                                              undisturbed lattice, self included [1/m^dim] */
  double light_penalty[CASE_MAX_PHASES];   /* scheme riemann: physics.light_penalty for a light
                                              phase, 0 for the others [-] */
  unsigned body_walls;             /* bit w: wall w is a rigid body (FEAT_BODIES) */
  /* set by the time stepper */
  struct frame frames[CASE_MAX_WALLS];   /* the moving walls' frames at the stage's time */
  double rho_min[CASE_MAX_PHASES]; /* global minimum density per phase (first stage) [kg/m^3] */
  double tv_pressure;              /* scheme riemann: background pressure of the transport velocity
                                      this step [Pa] */
  double dt_step;                  /* the time step: this step's from its second stage on, the
                                      previous step's in the first (0 before the first step) [s] */
};

/** What a pass reports back; zero when it starts, added up by the engine after it. */
struct pass_out {
  long pairs;                      /* neighbour-pair evaluations */
  long renorm_fallbacks;           /* particles whose renormalisation matrix was singular */
  long n_surface;                  /* owned particles detected on the free surface */
};

/** The context of a pass. Pointers, so that the engine's arrays and parameters are seen as they
 *  are when the pass runs; a pass writes the owned slots of p and w (pass_volumes, pass_fluid_volumes,
 *  pass_boundary_volumes: the halo slots' volumes too), the lists (pass_neighbour_lists; the others their read-back scratch,
 *  nlist_enter_cell) and out, and never talks to another rank. */
struct pass_ctx {
  const struct case_def *c;
  const struct physics_params *prm;
  struct parts *p;                 /* owned slots, then the halo */
  struct work *w;
  struct nlist *nl;                /* neighbour lists of the owned fluid (built by pass_neighbour_lists) */
  const struct space *space;       /* cells: the index the lists and visit_near walk */
  const int *cells;                /* the owned cells pass_for_each_owned visits (indices into
                                      space->owned_cells); NULL: every owned cell */
  long n_cells;
  void (*progress)(void *arg);     /* called between cells by pass_for_each_owned (NULL: none): lets
                                      the halo messages the pass overlaps progress */
  void *progress_arg;
  struct body_loads *loads;        /* FEAT_BODIES: the rhs pass appends a load per fluid particle
                                      and body whose ghosts are among its neighbours */
  const struct solid_view *solids; /* the elastic solids; NULL without */
  struct body_loads *solid_loads;  /* with solids: the momentum pass appends a load per pair of an
                                      owned fluid particle and a solid particle */
  struct pass_out out;
};

/** A pass: one operation of the stage pipeline over the context's particles. */
typedef void (*pass_fn)(struct pass_ctx *ctx);

#endif
