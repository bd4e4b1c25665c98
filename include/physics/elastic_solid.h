/* elastic_solid.h — a total-Lagrangian SPH elastic solid (paper 002 Eqs. P-13..P-17, P-29..P-33;
 * doc/theory.md §13): every kernel quantity in the reference configuration with a neighbour list
 * built once, the paper's correction matrix B0 or a quadratic one, the deformation gradient F
 * integrated in time, a hyperelastic first Piola–Kirchhoff stress, pairwise Kelvin–Voigt damping,
 * clamped particles, the solid's own time step and sub-steps, and what the fluid coupling will
 * use: the sub-steps of a fluid step with the averaged velocity and acceleration, and the surface
 * normals. In 2D the stress state is plane strain. The reference search grid is dense over the
 * solid's bounding box (meant for compact solids). */
#ifndef MPSPH_ELASTIC_SOLID_H
#define MPSPH_ELASTIC_SOLID_H

#include "physics/kernel.h"

/** How F is formed from the reference neighbours: F_a = I + sum_b (u_b - u_a) (x) g_ab, with the
 *  pair weights g_ab of one of these. */
enum elastic_correction {
  ELASTIC_CORRECTION_LINEAR,      /* paper 002's: g_ab = V_b B0_a grad0_a W_ab, exact for linear fields */
  ELASTIC_CORRECTION_QUADRATIC,   /* kernel-weighted least squares on the linear and quadratic
                                     monomials: exact for quadratic fields, also at the edges */
  ELASTIC_CORRECTION_COUNT
};

/** The strain-energy functions (the table in elastic_solid.c gives their names). */
enum elastic_model {
  ELASTIC_SVK,           /* Saint Venant–Kirchhoff: S = lambda tr(E) I + 2 G E, E Green–Lagrange */
  ELASTIC_NEO_HOOKEAN,   /* compressible neo-Hookean: S = G (I - C^-1) + lambda ln(J) C^-1 */
  ELASTIC_MODEL_COUNT
};

/** A solid's material. */
struct elastic_material {
  enum elastic_model model;
  double rho0;      /* reference density [kg/m^3] */
  double young;     /* Young's modulus E [Pa] */
  double poisson;   /* Poisson's ratio nu [-], in (-1, 1/2) */
  double damping;   /* Kelvin–Voigt pair coefficient (notes §1.9: SPHinXsys' 0.25; the paper only
                       cites its damping); 0 = none */
  enum elastic_correction correction;
};

/** An elastic solid: n particles on a lattice of spacing dx in its reference configuration. The
 *  vectors hold dim values per particle, the matrices dim*dim (row-major). */
struct elastic_solid {
  int dim, n;
  struct elastic_material mat;
  double lambda, shear;   /* Lamé constants [Pa] */
  double c_s;             /* sound speed sqrt(K/rho0), K the bulk modulus [m/s] */
  double dx, vol0, mass;  /* spacing [m], reference volume dx^dim and mass of a particle */
  struct kernel k;        /* in the reference configuration */
  double w_zero;          /* W(0) [1/m^dim] */
  double step_length;     /* the length of the acoustic time-step limit: h for the linear
                             correction, less for the quadratic (elastic_solid.c) [m] */
  double *x0, *x, *v;     /* reference and current positions [m], velocity [m/s] */
  double *acc;            /* acceleration of the last sub-step [m/s^2] */
  double *acc_ext;        /* acceleration held over the sub-steps (loads from outside) [m/s^2] */
  double *F, *dF;         /* deformation gradient [-] and its rate [1/s] */
  double *P;              /* scratch: first Piola–Kirchhoff stress of each particle, with (quadratic
                             correction) the strain gradient's conjugate to F [Pa] */
  double *R;              /* scratch (quadratic correction): the strain gradient's conjugates to
                             dF/dX_k, dim^3 per particle [Pa m] */
  unsigned char *clamped; /* 1: held at x0 with v = 0 */
  double *normal0;        /* reference surface normal (unit, outward; 0 deeper than a support below
                             the surface, where its kernel sum cancels) [-] */
  double *normal;         /* current normal: F^-T normal0 normalised (elastic_update_normals) [-] */
  double *x_step;         /* positions at the start of the last elastic_advance [m] */
  double *v_avg, *acc_avg;  /* velocity and acceleration averaged over the last elastic_advance,
                               the wall's state the fluid sees (notes §1.7) [m/s], [m/s^2] */
  double dt_avg;          /* the length of the last elastic_advance (0 before the first) [s] */
  int *nb_first;          /* reference neighbours of a: nb[nb_first[a] .. nb_first[a+1]) */
  int *nb;
  int *nb_reverse;        /* the pair (b, a) of pair (a, b): its index in b's list */
  double *nb_g;           /* the gradient weights g_ab (dim per pair) [1/m] */
  double *nb_hess;        /* (quadratic correction) the second-derivative weights, a symmetric
                             dim x dim matrix per pair [1/m^2] */
  double *nb_grad0;       /* grad0_a W_ab (dim per pair) [1/m^(dim+1)] */
  double *nb_w_ratio;     /* W(r0_ab) / W(0) [-] */
  double *nb_r0_sq;       /* |x0_a - x0_b|^2 [m^2] */
};

/** Set up solid s in dim = 2 or 3 dimensions from n reference positions x0 [m] (dim per particle,
 *  copied) on a lattice of spacing dx [m], with kernel `kind` of smoothing length h [m]: the
 *  reference neighbour list, the gradient weights of mat's correction, the reference normals
 *  (-sum_b V0 grad0_a W_ab normalised, 0 where that sum vanishes to round-off), F = I, v = 0,
 *  nothing clamped. Returns 0, or -1 with a message on stderr for parameters out of range or a particle
 *  whose weights cannot be formed (too few independent neighbours: the particle is named); s is
 *  then freed. */
int elastic_solid_init(struct elastic_solid *s, int dim, int n, const double *x0, double dx,
                       enum kernel_kind kind, double h, const struct elastic_material *mat);

/** Release s's arrays. */
void elastic_solid_free(struct elastic_solid *s);

/** The name of a strain-energy model (as in case files and messages). */
const char *elastic_model_name(enum elastic_model model);

/** The name of a correction (as in case files and messages). */
const char *elastic_correction_name(enum elastic_correction correction);

/** First Piola–Kirchhoff stress P [Pa] (dim*dim) of deformation gradient F under `model` with
 *  Lamé constants lambda and shear [Pa] (neo-Hookean: det F > 0, else NaN). */
void elastic_pk1(int dim, enum elastic_model model, double lambda, double shear, const double *F,
                 double *P);

/** Strain energy per reference volume [J/m^3] of deformation gradient F (as elastic_pk1). */
double elastic_energy_density(int dim, enum elastic_model model, double lambda, double shear,
                              const double *F);

/** dF/dt [1/s] of every particle from the current velocities (Eq. P-33). */
void elastic_deformation_rate(struct elastic_solid *s);

/** The acceleration of every particle: the stress's pair force (minus the gradient of the strain
 *  energy sum_a V0 psi(F_a); with the linear correction Eq. P-13 with the factor 2 of notes §1.9),
 *  the Kelvin–Voigt damping, gravity g (dim values) [m/s^2] and acc_ext, into acc [m/s^2]. */
void elastic_acceleration(struct elastic_solid *s, const double *g);

/** One sub-step of length dt [s] (Eqs. P-30..P-32) under gravity g [m/s^2]: half F and x, the
 *  acceleration, the full v, the clamp, half x, dF/dt and half F. F stays the gradient of x when
 *  dF holds the rate of the current v on entry: call elastic_deformation_rate after setting v
 *  other than through a sub-step. */
void elastic_substep(struct elastic_solid *s, double dt, const double *g);

/** The solid's time-step limit Delta t_s (Eq. P-29, with step_length for h in its acoustic
 *  part) [s] from its current v and acc; NaN if one of them is not finite. */
double elastic_time_step(const struct elastic_solid *s);

/** Advance the solid by one fluid step dt > 0 [s] in kappa = floor(dt / Delta t_s) + 1 equal
 *  sub-steps (notes §1.10; Delta t_s from elastic_time_step at the start, whose acceleration part
 *  is that of the last sub-step, before a new acc_ext) with acc_ext held, and set
 *  v_avg = (x_end - x_start)/dt and acc_avg = (v_avg_new - v_avg_old)/((dt_prev + dt)/2), the
 *  time between the two averages' centres (dt_prev the previous advance's length, dt before
 *  the first). Returns kappa, or -1
 *  (nothing done) for dt not positive or a time step that is not a number or too small. */
int elastic_advance(struct elastic_solid *s, double dt, const double *g);

/** The current normals from the reference ones by Nanson's formula: F^-T normal0, normalised
 *  (notes §1.7, A15). */
void elastic_update_normals(struct elastic_solid *s);

/** Kinetic plus strain energy of the solid [J] (2D: [J/m]), with the strain gradient's energy of
 *  the quadratic correction; gravity's potential not included. */
double elastic_energy(const struct elastic_solid *s);

#endif
