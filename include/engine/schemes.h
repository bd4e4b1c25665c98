/* schemes.h — the table of the schemes: for each value of enum scheme_kind (include/case/case.h,
 * one line of SCHEME_LIST there with its spelling) its feature bit, the case options it runs, its passes in
 * the pipeline, its time-step rule, its time stepping and what it refuses. The engine and the
 * command line dispatch through it (src/engine/schemes.c). */
#ifndef MPSPH_SCHEMES_H
#define MPSPH_SCHEMES_H
#include <stddef.h>
#include "engine/engine.h"

/* One scheme. The pipeline builders run once per assembly, never per pair. */
struct scheme {
  unsigned feature;                                /* its own FEAT_* bit (engine.h), 0 for none */
  unsigned (*terms)(const struct engine *e);       /* the FEAT_* bits of the case options it runs */
  void (*pipeline)(struct engine *e);              /* appends all its operations to e->ops */
  void (*pressure)(struct engine *e);              /* RK stage: the operations that set the pressure before
                                                      the wall ghosts (NULL: volumes and lists after them) */
  void (*rhs)(struct engine *e);                   /* RK stage: its right-hand-side operations */
  double (*time_step)(const struct pass_ctx *ctx, double a_max, double adv_max, const char **limit);
                                                   /* RK stage: its dt limits (NULL: its own stepping) */
  int (*step)(struct engine *e);                   /* one step; returns 0 or 2 */
  int (*refuse)(const struct case_def *c, char *err, size_t len);   /* options it cannot run: 0, or 1
                                                                       with the reason in err (NULL: none) */
};

/** The entry of scheme k. */
const struct scheme *scheme_of(enum scheme_kind k);

/* What engine_step.c offers the entries. */

/** Append an operation (a pass, or a halo update of the HF_* fields in mask when pass is NULL). */
void engine_add_op(struct engine *e, const char *name, pass_fn pass, int mask, int once);

/** Append a cell pass: a pass that visits the owned particles through pass_for_each_owned and
 *  so honours the context's cell list; after a halo update it runs overlapped with it, over the
 *  interior cells first. */
void engine_add_cell_pass(struct engine *e, const char *name, pass_fn pass, int once);

/** Append the particle volumes and the neighbour lists (the lists once per step). */
void engine_add_volumes_and_lists(struct engine *e);

/** The FEAT_* bits of the delta-plus options of the case (diffusion, viscosity, walls, shifting,
 *  damper, free surface, tensile control, sharpness, potential, surface tension). */
unsigned engine_option_terms(const struct engine *e);

/** The pipeline of one RK stage, with the scheme's pressure and rhs operations in their place. */
void engine_assemble_stage(struct engine *e);

/** One RK4 step (the midpoint predictor-corrector with same-phase-continuity). Returns 0 or 2. */
int engine_step_rk(struct engine *e);

/** The time-step limits of paper 000 Eq. 12 (paper 003's CFL with same-phase-continuity); *limit
 *  names the smallest. adv_max is not used (the motion limit is the caller's). */
double engine_delta_plus_dt(const struct pass_ctx *ctx, double a_max, double adv_max, const char **limit);

#endif
