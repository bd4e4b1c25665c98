/* engine_checkpoint.h — checkpoint.h5: the state a run needs to continue bitwise-identically,
 * and the restart from it on any number of ranks. */
#ifndef MPSPH_ENGINE_CHECKPOINT_H
#define MPSPH_ENGINE_CHECKPOINT_H

#include "engine/engine.h"

/** Write OUTDIR/checkpoint.h5 through a temporary file: every particle with ghosts' mirror
 *  points and wall indices, time, step, last dt, output schedule, snapshot series, the
 *  free-surface decision, wall-clock seconds so far, whether the run is finished, and the
 *  resolved case. Collective. Returns 0, or 3 with a message on rank 0. */
int engine_checkpoint_write(struct engine *e);

/** Restart from the checkpoint at `path`: refuse (status 1, message on rank 0) when it is
 *  missing or unreadable, its case differs from e->c in anything but time.end,
 *  time.max_steps, output.* and parallel.*, or a field breaks a rule of checkpoint_check.h;
 *  otherwise give each rank a block of its particles (cells not yet assigned) and restore the
 *  run state. Collective. Returns 0 or 1 (the same on every rank). */
int engine_checkpoint_read(struct engine *e, const char *path);

#endif
