/* wall_guard.h — normal-velocity correction of fluid particles closing on a wall. */
#ifndef MPSPH_WALL_GUARD_H
#define MPSPH_WALL_GUARD_H

#include "physics/pass_ctx.h"

/** After a step: every owned fluid particle closer than physics.wall_guard x dx to a wall's
 *  boundary (or inside its solid) whose velocity relative to the wall points into it loses that
 *  normal component (free slip against the wall), the walls at the frames ctx->prm->frames.
 *  Returns the number of corrections made on this rank. Local: no communication. */
long wall_guard_apply(const struct pass_ctx *ctx);

#endif
