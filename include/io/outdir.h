/* outdir.h — the output folder: create it, and probe before a run that files can be written. */
#ifndef MPSPH_OUTDIR_H
#define MPSPH_OUTDIR_H

#include <stddef.h>
#include <stdio.h>

/** The name of snapshot k in the output folder (a printf format of k). */
#define OUTDIR_SNAPSHOT_NAME "snap_%05d.h5"

/** The name of the checkpoint in the output folder (written, and --restart's default). */
#define OUTDIR_CHECKPOINT_NAME "checkpoint.h5"

/** "dir/" followed by name_fmt formatted with the arguments (printf-style), in a string from
 *  mem.h that the caller frees: a file path in the output folder, never cut short. */
char *outdir_path(const char *dir, const char *name_fmt, ...) __attribute__((format(printf, 2, 3)));

/** Create the folder path and its missing parents (mkdir -p). Returns 0, or -1 with errno set. */
int outdir_create(const char *path);

/** Whether files can be written in the folder path: create it if missing, write and remove a
 *  probe file, then remove the folders this call created, so that nothing is left behind.
 *  Returns 0, or 1 with "cannot write to the output folder '<path>': <reason>" in err. */
int outdir_probe(const char *path, char *err, size_t err_len);

/** Rank 0 of a run: create the folder path if missing and lock it for the time of the run: an
 *  fcntl write lock on path/.mpsph.lock, which names its holder (pid, host, start time). The lock
 *  is released when *fd is closed or the process ends, however it ends (kill -9 too), so a stale
 *  lock never blocks a restart; the file itself stays. Returns 0 with *fd the lock (-1 when the
 *  file system has no locks: a warning is printed and the run goes on unlocked), or 1 with
 *  "the output folder '<path>' is in use by another run (<holder>)..." or "cannot write to the
 *  output folder '<path>': <reason>" in err. */
int outdir_lock(const char *path, int *fd, char *err, size_t err_len);

/** Bytes this process can still write in the file system of the folder of `file` (for root, also
 *  the blocks reserved to root), or -1 when statvfs cannot tell. */
double outdir_free_bytes(const char *file);

/** Whether the file system of the folder of `file` has `bytes` free (for root, also the blocks
 *  reserved to root). Returns 0 (also when it cannot tell), or 3 with "cannot write <file>: No
 *  space left on device (it needs about N MB, M MB are free)" in err. */
int outdir_room(const char *file, double bytes, char *err, size_t err_len);

/** Write dir/name through the temporary file dir/name.tmp, renamed when complete, so that a crash
 *  never leaves a half-written file in its place: fill(f, ctx) writes the content. Returns 0, or
 *  -1 with errno set (the previous file, if any, is left as it was; the temporary one removed). */
int outdir_write_file(const char *dir, const char *name, void (*fill)(FILE *f, const void *ctx),
                      const void *ctx);

#endif
