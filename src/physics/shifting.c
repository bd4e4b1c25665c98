/* shifting.c — the particle shifting velocity of paper 000 Eqs. 13-15:
 *   du_i = -2 h U_max sum_j grad_i W_ij V_j           (Ma c0 = U_max, sum over all neighbours)
 *   du_i <- (I - n_i n_i) du_i  in the free-surface region (tangential only)
 *   |du_i| <= 0.5 U_max outside the free-surface region (inside it too with limit_surface_shifting)
 * Isolated particles (fewer than ISOLATED_NEIGHBOURS neighbours, or detected with lambda below
 * ISOLATED_LAMBDA) are not shifted; wall ghosts never are. */
#include <math.h>
#include "physics/passes.h"

#define ISOLATED_NEIGHBOURS 5
#define ISOLATED_LAMBDA 0.2

void shifting_velocity(const struct pass_ctx *ctx, long i, const double *sum_gradw, int n_neighbours) {
  const struct case_def *c = ctx->c;
  const int dim = ctx->p->dim;
  const double u_max = c->u_max, limit = 0.5 * u_max;
  double du[3] = {0, 0, 0}, norm2 = 0;
  int in_region = ctx->w->region && ctx->w->region[i] > 0;
  int isolated = n_neighbours < ISOLATED_NEIGHBOURS || (in_region && ctx->w->lambda[i] < ISOLATED_LAMBDA);
  for (int d = 0; d < dim && !isolated; d++) du[d] = -2.0 * ctx->prm->h * u_max * sum_gradw[d];
  if (in_region && !isolated) {
    double dn = 0;
    for (int d = 0; d < dim; d++) dn += du[d] * ctx->w->normal[d][i];
    for (int d = 0; d < dim; d++) du[d] -= dn * ctx->w->normal[d][i];
  }
  for (int d = 0; d < dim; d++) norm2 += du[d] * du[d];
  double scale = 1.0;
  if (norm2 >= limit * limit && (!in_region || c->limit_surface_shifting)) scale = limit / sqrt(norm2);
  for (int d = 0; d < dim; d++) ctx->w->du[d][i] = scale * du[d];
}
