/* wall_guard.h — normal-velocity correction of fluid particles closing on a wall. */
#ifndef MPSPH_WALL_GUARD_H
#define MPSPH_WALL_GUARD_H

struct engine;

/** After a step: every owned fluid particle closer than physics.wall_guard x dx to a wall's
 *  boundary (or inside its solid) whose velocity relative to the wall points into it loses that
 *  normal component (free slip against the wall). Returns the number of corrections made on this
 *  rank and adds it to e->wall_guard_hits. Local: no communication. */
long wall_guard_apply(struct engine *e);

#endif
