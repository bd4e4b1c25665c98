/* checkpoint_check.h — the rules a checkpoint must satisfy before a restart uses any of it,
 * field by field (doc/user-guide.md section 4.4). */
#ifndef MPSPH_CHECKPOINT_CHECK_H
#define MPSPH_CHECKPOINT_CHECK_H

#include <stddef.h>
#include "case/case.h"
#include "engine/engine.h"
#include "io/io_hdf5.h"

/** The stored run values of a checkpoint that are not engine fields of the stored type. */
struct run_extras {
  double wall_seconds;        /* wall-clock time of the run so far [s] */
  long no_free_surface;       /* free_surface auto switched detection off */
  long finished;              /* the run reached time.end or time.max_steps */
  long wall_guard_hits;       /* the wall guard's corrections on all ranks so far */
};

/** Check the /header of a checkpoint (info) against its case c, before anything is read by
 *  its particle count (which must not exceed what c can generate, so that the particle arrays
 *  fit the memory the run was checked for). e: the engine set up for c (kernel). The same on
 *  every rank (they read the same header). Returns 0, or 1 with "FIELD: got VALUE, expected
 *  RULE" in why. */
int checkpoint_check_header(const struct engine *e, const struct case_def *c,
                            const struct snapshot_info *info, char *why, size_t len);

/** Collective, after the checkpoint was read into e (e->time, e->step and the snapshot series
 *  set from it, each rank holding its block of the particles): check the /run numbers in e
 *  and x, the snapshot series (and that the restart overwrites no snapshot in e->outdir older
 *  than the checkpoint), and every particle row against the checkpoint's case c, the ids
 *  unique over all ranks. Returns 0 on every rank, or 1 on every rank with the message of the
 *  lowest rank that found a fault in why ("FIELD: got VALUE, expected RULE"; for a row
 *  "FIELD: row R (id I): got ..."). */
int checkpoint_check(const struct engine *e, const struct case_def *c,
                     const struct snapshot_info *info, const struct run_extras *x, char *why,
                     size_t len);

#endif
