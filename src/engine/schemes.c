/* schemes.c — the table of the schemes (include/engine/schemes.h) and each scheme's own pieces:
 * its terms, its operations in the pipeline and its refusals of the options it cannot run. */
#include <stdio.h>
#include "engine/schemes.h"
#include "physics/passes.h"

/* Schemes delta-sph: the Shepard density and pressure first (the wall ghosts interpolate it). */
static void shepard_pressure_ops(struct engine *e) {
  engine_add_volumes_and_lists(e);
  engine_add_cell_pass(e, "Shepard density and pressure (delta-sph)", pass_shepard_density, 0);
  engine_add_op(e, "halo: Shepard densities, pressures", NULL, HF_RHO_SHEPARD | HF_P, 0);
}

/* Schemes delta-plus and delta-sph: the gradient pass and the right-hand sides. */
static void gradients_and_rhs_ops(struct engine *e) {
  static const char *names[2][2] = {{"gradients: div u", "gradients: div u, shifting velocity"},
                                    {"gradients: renormalised density gradient, div u",
                                     "gradients: renormalised density gradient, div u, shifting velocity"}};
  unsigned f = e->prm.features;
  engine_add_cell_pass(e, names[(f & FEAT_DIFFUSION) != 0][(f & FEAT_SHIFT) != 0], pass_gradients, 0);
  int damper_div = !(f & FEAT_DAMPER) ? 0 : (f & FEAT_DAMPER_OWN_PHASE) ? HF_DIV_OWN : HF_DIV;
  int halo = ((f & FEAT_DIFFUSION) ? HF_GRAD_RHO : 0) | ((f & FEAT_SHIFT) ? HF_SHIFT : 0) | damper_div;
  if (halo) engine_add_op(e, "halo: gradient-pass results", NULL, halo, 0);
  engine_add_cell_pass(e, "fluid rhs: continuity and momentum", pass_fluid_rhs, 0);
}

/* Scheme same-phase-continuity: its own pair passes (its refusals keep the delta-plus terms out). */
static void same_phase_ops(struct engine *e) {
  if (e->c->spc_model == SPC_PRESENT) {
    engine_add_cell_pass(e, "Shepard pressure over all phases (same-phase-continuity)", pass_shepard_pressure, 0);
    engine_add_op(e, "halo: Shepard pressures", NULL, HF_P_SHEPARD, 0);
  }
  engine_add_cell_pass(e, "same-phase continuity and momentum rhs", pass_same_phase_rhs, 0);
}

/* Scheme generalized-dissipation: its gradient pass and right-hand sides. */
static void gd_ops(struct engine *e) {
  engine_add_cell_pass(e, "gradients: Shepard sum Gamma, renormalised pressure gradient", pass_gd_gradients, 0);
  engine_add_op(e, "halo: Gamma, pressure gradients", NULL, HF_GD, 0);
  engine_add_cell_pass(e, "fluid rhs: continuity with generalized dissipation, momentum", pass_gd_rhs, 0);
}

/* Scheme riemann: the walls, the potential, (with a light phase) the transport velocity and the
 * surface tension; the delta-plus options of the case do not apply. */
static unsigned riemann_terms(const struct engine *e) {
  const struct case_def *c = e->c;
  unsigned f = (c->n_walls ? FEAT_WALLS : 0) | (c->potential_omega > 0 ? FEAT_CENTRAL : 0);
  if (c->surface_tension > 0 && c->n_phases > 1) f |= FEAT_SURFACE_TENSION;
  for (int ph = 0; ph < c->n_phases; ph++)
    if (riemann_light_phase(c, ph)) f |= FEAT_TRANSPORT_VELOCITY;
  return f;
}

/* Schemes whose viscosity always couples the phases with the harmonic mean (interface_viscosity
 * harmonic, their default) refuse none; why names the scheme's equation. Returns 0 or 1. */
static int coupled_viscosity_refused(const struct case_def *c, const char *scheme, const char *why, char *err,
                                     size_t len) {
  if (c->interface_viscosity != IFACE_VISC_NONE) return 0;
  return snprintf(err, len, "%s: physics.interface_viscosity: none is not available with scheme %s "
                  "(its viscosity, %s, always couples the phases: harmonic)", c->source_file, scheme, why), 1;
}

/* Rigid bodies take their force from the rhs pass of schemes delta-plus and delta-sph (the body
 * loads): the other schemes refuse them. Returns 0 or 1. */
static int bodies_refused(const struct case_def *c, const char *scheme, char *err, size_t len) {
  for (int w = 0; w < c->n_walls; w++)
    if (c->walls[w].body.active)
      return snprintf(err, len, "%s: walls.%d.body: rigid bodies are not available with scheme %s in this "
                      "version (schemes delta-plus and delta-sph have them)", c->source_file, w, scheme), 1;
  return 0;
}

/* The first phase with dx_ratio > 1, or -1. */
static int coarse_phase(const struct case_def *c) {
  for (int ph = 0; ph < c->n_phases; ph++)
    if (c->phases[ph].dx_ratio > 1) return ph;
  return -1;
}

/* Multi-resolution is in scheme riemann's pair terms only: the others refuse it. Returns 0 or 1. */
static int coarse_refused(const struct case_def *c, const char *scheme, char *err, size_t len) {
  int ph = coarse_phase(c);
  if (ph < 0) return 0;
  return snprintf(err, len, "%s: phases.%d.dx_ratio: multi-resolution is not available with scheme %s in this "
                  "version (scheme riemann has it)", c->source_file, ph, scheme), 1;
}

/* Elastic solids are in the pair terms of schemes riemann and delta-plus only: the others refuse
 * them. Returns 0 or 1. */
static int solids_refused(const struct case_def *c, const char *scheme, char *err, size_t len) {
  if (!c->n_solids) return 0;
  return snprintf(err, len, "%s: solids: elastic solids are not available with scheme %s in this version "
                  "(schemes riemann and delta-plus have them)", c->source_file, scheme), 1;
}

/* Neither multi-resolution nor elastic solids. Returns 0 or 1. */
static int multires_or_solids_refused(const struct case_def *c, const char *scheme, char *err, size_t len) {
  return coarse_refused(c, scheme, err, len) || solids_refused(c, scheme, err, len);
}

/* Scheme riemann's multi-resolution: a coarser phase must be a light one (paper 002: h_L >= h_H),
 * and the surface tension's colour gradient and a wave gauge's colour are single resolution.
 * Returns 0 or 1. */
static int multires_refused(const struct case_def *c, char *err, size_t len) {
  for (int ph = 0; ph < c->n_phases; ph++)
    if (c->phases[ph].dx_ratio > 1 && !riemann_light_phase(c, ph))
      return snprintf(err, len, "%s: phases.%d.dx_ratio: only a light phase (a gas lighter than another phase) "
                      "may be coarser (paper 002's multi-resolution)", c->source_file, ph), 1;
  int coarse = coarse_phase(c);
  if (coarse >= 0 && c->surface_tension > 0)
    return snprintf(err, len, "%s: physics.surface_tension: not available with multi-resolution (phases.%d.dx_ratio "
                    "> 1) in this version", c->source_file, coarse), 1;
  for (int k = 0; k < c->n_probes; k++)
    if (c->probes[k].kind == PROBE_ELEVATION && c->phases[c->probes[k].phase].dx_ratio > 1)
      return snprintf(err, len, "%s: probes.%d: a wave gauge of a phase with dx_ratio > 1 is not available in this "
                      "version (its colour is summed at h)", c->source_file, k), 1;
  return 0;
}

/* Scheme delta-plus has the elastic solids (its fluid rhs pass, doc/theory.md section 14) but not
 * the multi-resolution; delta-sph has neither. */
static int delta_refused(const struct case_def *c, char *err, size_t len) {
  if (c->scheme == SCHEME_DELTA_SPH) return multires_or_solids_refused(c, "delta-sph", err, len);
  return coarse_refused(c, "delta-plus", err, len);
}

/* The options of paper 000 that schemes same-phase-continuity and generalized-dissipation do not
 * have (keys under physics), with the value that leaves each off. */
static const char *const DELTA_PLUS_ONLY[][2] = {{"shifting", "none"}, {"tensile_control", "false"},
                                                 {"acoustic_damper", "0"}, {"interface_sharpness", "0"},
                                                 {"interface_pressure", "sum"}};

/* The first option of DELTA_PLUS_ONLY the case turns on (its index), or -1. */
static int delta_plus_option(const struct case_def *c) {
  return c->shifting != SHIFTING_NONE ? 0
         : c->tensile_control ? 1
         : c->acoustic_damper > 0 ? 2
         : c->interface_sharpness > 0 ? 3
         : c->interface_pressure != IFACE_P_SUM ? 4 : -1;
}

/* Scheme same-phase-continuity has its own pair pass (paper 003): the delta-plus terms are not in
 * it, so a case asking for one is refused rather than run without it. Its viscosity always couples
 * the phases (interface_viscosity harmonic, its default): refuse none. */
static int same_phase_terms(const struct case_def *c, char *err, size_t len) {
  int k = delta_plus_option(c);
  if (coupled_viscosity_refused(c, "same-phase-continuity", "paper 003 Eq. 21 with the harmonic mean", err, len) ||
      bodies_refused(c, "same-phase-continuity", err, len) ||
      multires_or_solids_refused(c, "same-phase-continuity", err, len))
    return 1;
  if (k < 0) return 0;
  snprintf(err, len, "%s: physics.%s: only %s with scheme same-phase-continuity (paper 003 has no such term)",
           c->source_file, DELTA_PLUS_ONLY[k][0], DELTA_PLUS_ONLY[k][1]);
  return 1;
}

/* Scheme generalized-dissipation (paper 004) has none of paper 000's shifting, tensile control,
 * acoustic damper, sharpness force or interface-pressure options: refuse them by name. Its
 * viscosity always couples the phases (interface_viscosity harmonic, its default): refuse none. */
static int gd_unsupported(const struct case_def *c, char *err, size_t len) {
  int k = delta_plus_option(c);
  if (coupled_viscosity_refused(c, "generalized-dissipation", "paper 004 Eq. 10", err, len) ||
      bodies_refused(c, "generalized-dissipation", err, len) ||
      multires_or_solids_refused(c, "generalized-dissipation", err, len))
    return 1;
  if (k < 0) return 0;
  snprintf(err, len, "%s: physics.%s: not part of scheme generalized-dissipation (use none, false, 0 or sum)",
           c->source_file, DELTA_PLUS_ONLY[k][0]);
  return 1;
}

/* Scheme riemann: fixed walls only (its dual stepper does not move walls); its viscous pair term
 * takes the harmonic mean of the two particles' viscosities, across phases too: refuse none. */
static int riemann_supported(const struct case_def *c, char *err, size_t len) {
  if (bodies_refused(c, "riemann", err, len) || multires_refused(c, err, len)) return 1;
  for (int w = 0; w < c->n_walls; w++)
    if (c->walls[w].moving)
      return snprintf(err, len, "%s: walls: scheme riemann supports fixed walls only in this version", c->source_file), 1;
  return coupled_viscosity_refused(c, "riemann", "paper 002 Eqs. 6-9 with the harmonic mean", err, len);
}

/* The schemes, indexed by enum scheme_kind. */
static const struct scheme SCHEMES[] = {
    [SCHEME_DELTA_PLUS] = {0, engine_option_terms, engine_assemble_stage, NULL, gradients_and_rhs_ops,
                           engine_delta_plus_dt, engine_step_rk, delta_refused},
    [SCHEME_DELTA_SPH] = {FEAT_SHEPARD, engine_option_terms, engine_assemble_stage, shepard_pressure_ops,
                          gradients_and_rhs_ops, engine_delta_plus_dt, engine_step_rk, delta_refused},
    [SCHEME_SAME_PHASE_CONTINUITY] = {FEAT_SAME_PHASE_CONTINUITY, engine_option_terms, engine_assemble_stage,
                                      NULL, same_phase_ops, engine_delta_plus_dt, engine_step_rk, same_phase_terms},
    [SCHEME_GENERALIZED_DISSIPATION] = {FEAT_GENERALIZED_DISSIPATION, engine_option_terms, engine_assemble_stage,
                                        NULL, gd_ops, gd_time_step, engine_step_rk, gd_unsupported},
    [SCHEME_RIEMANN] = {FEAT_RIEMANN, riemann_terms, engine_assemble_dual, NULL, NULL, NULL, engine_step_dual,
                        riemann_supported},
};
_Static_assert(sizeof SCHEMES / sizeof SCHEMES[0] == SCHEME_COUNT, "one entry per enum scheme_kind");

const struct scheme *scheme_of(enum scheme_kind k) { return &SCHEMES[k]; }
