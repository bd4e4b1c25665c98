/* case.h — the resolved description of a simulation case (from case.yaml + --set overrides). */
#ifndef MPSPH_CASE_H
#define MPSPH_CASE_H

#include <stddef.h>
#include "case/motion.h"

#define CASE_MAX_NAME 64
#define CASE_MAX_PHASES 8
#define CASE_MAX_REGIONS 32
#define CASE_MAX_WALLS 16
#define CASE_MAX_PROBES 64
#define CASE_MAX_SOLIDS 4
#define CASE_MAX_VERTICES 64

/* The schemes, one line each: X(value of enum scheme_kind, its spelling in case files). The
 * engine's scheme table (SCHEMES, src/engine/schemes.c) holds an entry per line. */
#define SCHEME_LIST(X)                                          \
  X(SCHEME_DELTA_PLUS, "delta-plus")                            \
  X(SCHEME_DELTA_SPH, "delta-sph")                              \
  X(SCHEME_SAME_PHASE_CONTINUITY, "same-phase-continuity")      \
  X(SCHEME_GENERALIZED_DISSIPATION, "generalized-dissipation")  \
  X(SCHEME_RIEMANN, "riemann")

#define SCHEME_ENUM_VALUE(value, spelling) value,
enum scheme_kind { SCHEME_LIST(SCHEME_ENUM_VALUE) SCHEME_COUNT };
#undef SCHEME_ENUM_VALUE
enum kernel_kind { KERNEL_GAUSSIAN = 0, KERNEL_WENDLAND_C2 };
enum shape_kind { SHAPE_BOX = 0, SHAPE_CIRCLE, SHAPE_POLYGON };
enum slip_kind { SLIP_FREE = 0, SLIP_NO };
enum fluid_side { FLUID_INSIDE = 0, FLUID_OUTSIDE };
enum shifting_kind { SHIFTING_NONE = 0, SHIFTING_CONSISTENT, SHIFTING_POSITION };
enum probe_kind { PROBE_PRESSURE = 0, PROBE_ELEVATION, PROBE_INTEGRAL };
enum probe_interpolation { INTERP_SHEPARD = 0, INTERP_MLS };
enum free_surface_mode { FREE_SURFACE_AUTO = 0, FREE_SURFACE_ON, FREE_SURFACE_OFF };
enum damper_form { DAMPER_DIFFERENCE = 0, DAMPER_SYMMETRIC, DAMPER_OWN_PHASE };
enum init_pressure { INIT_PRESSURE_HYDROSTATIC = 0, INIT_PRESSURE_ZERO };
enum interface_pressure { IFACE_P_SUM = 0, IFACE_P_DENSITY_WEIGHTED };
enum interface_viscosity { IFACE_VISC_NONE = 0, IFACE_VISC_HARMONIC };
enum spc_model { SPC_PRESENT = 0, SPC_CONVENTIONAL };   /* paper 003 section 3 / section 2.3 */
enum dissipation_form { DISSIPATION_CONSISTENT = 0, DISSIPATION_PRINTED };
enum balance_kind { BALANCE_TIME = 0, BALANCE_WORK };   /* what a re-partition balances */
enum solid_model { SOLID_SVK = 0, SOLID_NEO_HOOKEAN };  /* as enum elastic_model (physics/elastic_solid.h) */
enum solid_correction { SOLID_LINEAR = 0, SOLID_QUADRATIC };   /* as enum elastic_correction */

/** A geometric shape: box {min,max}, circle {centre,radius[,inner_radius]} (disc in 2D, ball in
 *  3D; an annulus or shell with inner_radius > 0) or polygon (2D only, vertices in order). [m] */
struct shape {
  enum shape_kind kind;
  double min[3], max[3];                 /* box */
  /* box of a fluid: its lower (SURFACE_FLOOR) or upper (SURFACE_CEILING) face along the last axis
   * is the cosine surface level + amplitude sum_d cos(2 pi x_d / wavelength), d the other axes */
  enum surface_kind { SURFACE_NONE = 0, SURFACE_FLOOR, SURFACE_CEILING } surface;
  double surface_level, surface_amplitude, surface_wavelength;
  double centre[3], radius, inner_radius;   /* circle (inner_radius 0: full disc) */
  int n_vertices;                        /* polygon */
  double vertex[CASE_MAX_VERTICES][2];
};

/** One fluid phase: Tait equation of state p = B((rho/rho0)^gamma - 1) + p_background. */
struct phase {
  char name[CASE_MAX_NAME];
  double rho0;          /* reference density [kg/m^3] */
  double c0;            /* numerical sound speed [m/s] */
  double gamma;         /* polytropic exponent [-] */
  double p_background;  /* background pressure [Pa] */
  double viscosity;     /* dynamic viscosity [Pa s]; 0 = artificial viscosity only */
  int incompressible;   /* liquid (receives the acoustic damper) */
  double density_band[2];   /* [min, max] of rho/rho0; leaving it stops the run as unstable [-] */
  int dx_ratio;         /* particle spacing and smoothing length in units of dx and h: 1, or 2 for a
                           light phase at the coarser level of multi-resolution (scheme riemann) */
};

/** A potential-flow mode of a horizontal interface at y = interface (2D): added to the initial
 *  velocity, u = amplitude e^(-k|y - interface|) (sgn(y - interface) sin kx, cos kx), k = 2 pi /
 *  wavelength: the linear eigenmode of a small interface perturbation, started from a flat
 *  interface (Rayleigh-Taylor growth, gravity waves). */
struct velocity_mode {
  int active;
  double amplitude;          /* vertical velocity of the interface at x = 0 [m/s] */
  double wavelength;         /* [m] */
  double interface;          /* height y of the interface [m] */
};

/** A region filled with particles of one phase on the initial lattice. */
struct fluid_region {
  int phase;                 /* index into case.phases */
  struct shape shape;
  double velocity[3];        /* initial velocity [m/s] */
  double velocity_gradient[3][3];   /* u = velocity + G x: G[a][b] = du_a/dx_b [1/s] */
  struct velocity_mode mode; /* added to the initial velocity when active */
};

/** The degrees of freedom of a rigid body (bits of struct body's fixed): translations along x,
 *  y, z and rotations about the case axes (2D: x, y and the rotation about z). */
enum { BODY_DOF_X = 1, BODY_DOF_Y = 2, BODY_DOF_Z = 4, BODY_DOF_RX = 8, BODY_DOF_RY = 16, BODY_DOF_RZ = 32 };

/** A rigid body: a wall whose motion the flow drives (the pair forces of its ghosts on the fluid),
 *  with gravity; 3 degrees of freedom in 2D (quantities per metre of depth), 6 in 3D. */
struct body {
  int active;
  double mass;                  /* [kg] (2D: [kg/m]) */
  double centre[3];             /* centre of mass at t = 0 [m] */
  double inertia[3];            /* principal moments of inertia about the centre of mass, along the
                                   case axes at t = 0 (2D: inertia[2] = I_zz) [kg m^2] (2D: [kg m]) */
  double velocity[3];           /* initial velocity of the centre of mass [m/s] */
  double angular_velocity[3];   /* initial angular velocity (2D: [2], about z) [rad/s] */
  unsigned fixed;               /* BODY_DOF_* held at their initial velocity */
  unsigned prescribed;          /* BODY_DOF_* that follow the wall's motion law (struct wall's
                                   motion; a rotation about the centre of mass) */
};

/** A wall: layers of fixed ghost particles along the boundary of a shape. */
struct wall {
  struct shape shape;
  enum slip_kind slip;
  enum fluid_side fluid_side;   /* inside: a tank (ghosts outside the shape); outside: an obstacle */
  int moving;                   /* the wall follows `motion`, or is a body (else it is fixed) */
  struct wall_motion motion;
  struct body body;             /* active: the wall moves as a rigid body (moving is then 1) */
};

/** An elastic solid (scheme riemann): a box filled with particles on the fluid's lattice spacing,
 *  moved by its stress, gravity and the fluid's pair forces (doc/theory.md §13, §14); the particles
 *  inside the clamp box are held in place. */
struct solid_def {
  double min[3], max[3];     /* the box the particles fill at t = 0, nodes at min + (i + 1/2) dx [m] */
  int has_clamp;             /* clamp_min and clamp_max given */
  double clamp_min[3], clamp_max[3];   /* particles inside are held [m] */
  double rho0;               /* density [kg/m^3] */
  double young;              /* Young's modulus E [Pa] */
  double poisson;            /* Poisson's ratio [-] */
  double damping;            /* Kelvin-Voigt pair coefficient [-] */
  enum solid_model model;
  enum solid_correction correction;
  double probe[3];           /* a point of the solid at t = 0: solids.csv records the displacement of
                                the particle nearest to it [m] */
};

/** A probe read at the output.probes_interval: a pressure sensor (a point, or in 2D a segment of
 *  length diameter along axis centred on position), a wave gauge (elevation of the top of phase
 *  along the vertical line through position) or the integrals over one phase. */
struct probe {
  char name[CASE_MAX_NAME];
  enum probe_kind kind;
  double position[3];        /* pressure, elevation [m] */
  double diameter;           /* pressure: sensor face [m]; 0 = a point */
  double axis[3];            /* pressure with diameter > 0: direction of the face (not normalised) */
  enum probe_interpolation interpolation;   /* pressure */
  int phase;                 /* elevation, integral: index into case.phases */
  int wall;                  /* pressure: the moving wall (a motion or a body) that carries the
                                sensor, its position and axis given at t = 0; -1: fixed in space */
};

#define PROBE_MAX_COLUMNS 6   /* probes.csv columns of one probe (an integral in 3D) */

/** The complete case. Every field has its default filled in after case_load. */
struct case_def {
  char name[CASE_MAX_NAME];
  char description[256];
  char source_file[512];     /* path of the case file */
  int dimension;             /* 2 or 3 */
  enum scheme_kind scheme;
  enum kernel_kind kernel;
  double dx;                 /* initial particle spacing [m] */
  double h_over_dx;          /* smoothing length / dx [-] */
  int has_lattice_origin;    /* resolution.origin given: every fluid region on one lattice */
  double lattice_origin[3];  /* fluid nodes at origin + (i + 1/2) dx [m] */
  double gravity[3];         /* [m/s^2] */
  double potential_omega;    /* quadratic potential 1/2 omega^2 |x - c|^2: force -omega^2 (x - c) [1/s] */
  double potential_centre[3];   /* [m] */
  double t_end;              /* [s] */
  double cfl;                /* [-] */
  double dt_min;             /* a time step below this stops the run as unstable [s] */
  double energy_growth;      /* growth of the mechanical energy [M U_max^2 / 2] that stops the run
                                as unstable; 0 = no check */
  double output_interval;    /* snapshot interval [s]; 0 = first and last only */
  double stats_interval;     /* stats.csv interval [s] */
  double probes_interval;    /* probes.csv interval [s] */
  double progress_interval;  /* wall-clock seconds between progress lines */
  double checkpoint_interval;   /* simulated time between checkpoints [s]; 0 = end of run only */
  double domain_min[3], domain_max[3];   /* [m] */
  int n_phases;
  struct phase phases[CASE_MAX_PHASES];
  int n_fluids;
  struct fluid_region fluids[CASE_MAX_REGIONS];
  int n_walls;
  struct wall walls[CASE_MAX_WALLS];
  int n_probes;
  struct probe probes[CASE_MAX_PROBES];
  int n_solids;
  struct solid_def solids[CASE_MAX_SOLIDS];
  enum init_pressure initial_pressure;
  /* physics */
  double delta;              /* delta-SPH density diffusion coefficient [-] */
  double alpha;              /* artificial viscosity coefficient [-] */
  double acoustic_damper;    /* alpha2 of the acoustic damper [-] */
  enum shifting_kind shifting;
  double u_max;              /* maximum expected velocity for shifting [m/s] (default: liquid c0 / 10) */
  int tensile_control;       /* p_j - p_i for negative p_i outside the free surface (paper 000 Eq. 9) */
  enum free_surface_mode free_surface;   /* detection: auto = on if a free surface exists at t = 0 */
  double surface_band;       /* free-surface region: flagged particles and those within this many h */
  int interface_mode;        /* epsilon/phi strategies of paper 000 Appendix A (4 = the final model) */
  enum damper_form damper_form;
  enum interface_pressure interface_pressure;   /* other-phase pressure in the momentum pair sum */
  enum interface_viscosity interface_viscosity; /* other-phase pairs in the laminar viscosity sum */
  enum spc_model spc_model;  /* scheme same-phase-continuity: paper 003's present model, or its
                                conventional one (all-neighbour continuity, no Shepard pressure) */
  double interface_sharpness;   /* chi of the interface sharpness force (paper 000 Eq. 20), 0 = off */
  int limit_surface_shifting;   /* apply the 0.5 U_max limiter in the free-surface region too */
  double surface_tension;    /* sigma between the fluid phases (CSF, Adami et al. 2010) [N/m], 0 = off */
  double wall_guard;         /* normal-velocity correction within this many dx of a wall, 0 = off */
  double light_penalty;      /* scheme riemann: prefactor of paper 002's penalty force on light
                                phases at walls and solids (Eqs. 21-23), 0 = off [-] */
  enum dissipation_form dissipation_form;   /* scheme generalized-dissipation: paper 004 Eq. 49 as
                                               printed, or its dimensionally consistent form */
  /* parallel */
  double repartition_threshold;  /* re-partition when (max-min)/mean load exceeds this */
  long repartition_every;        /* force a re-partition every N steps (0 = only on imbalance) */
  enum balance_kind balance;     /* balance measured compute time, or particle work alone */
  long top_cells_per_rank;       /* the top cells' size: the largest blocks leaving this many per rank */
  long max_steps;                /* stop after this many steps (0 = no limit) */
};

/** The initial particle spacing of phase ph [m]. */
static inline double case_phase_dx(const struct case_def *c, int ph) { return c->phases[ph].dx_ratio * c->dx; }

/** The largest dx_ratio of the phases: 1 at single resolution. */
static inline int case_max_dx_ratio(const struct case_def *c) {
  int r = 1;
  for (int ph = 0; ph < c->n_phases; ph++)
    if (c->phases[ph].dx_ratio > r) r = c->phases[ph].dx_ratio;
  return r;
}

/** The largest smoothing length of the phases, the one that sets the cells and the wall layers [m]. */
static inline double case_h_max(const struct case_def *c) { return case_max_dx_ratio(c) * c->h_over_dx * c->dx; }

/** The lattice volume dx^dimension of a particle at spacing dx [m^dim]. */
static inline double case_lattice_volume(const struct case_def *c, double dx) {
  return c->dimension == 2 ? dx * dx : dx * dx * dx;
}

/** Whether a wall of c moves. */
static inline int case_walls_move(const struct case_def *c) {
  for (int w = 0; w < c->n_walls; w++)
    if (c->walls[w].moving) return 1;
  return 0;
}

/** The number of walls of c that are rigid bodies. */
static inline int case_n_bodies(const struct case_def *c) {
  int n = 0;
  for (int w = 0; w < c->n_walls; w++) n += c->walls[w].body.active;
  return n;
}

#endif
