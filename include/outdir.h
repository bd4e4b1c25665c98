/* outdir.h — the output folder: create it, and probe before a run that files can be written. */
#ifndef MPSPH_OUTDIR_H
#define MPSPH_OUTDIR_H

#include <stddef.h>

/** Create the folder path and its missing parents (mkdir -p). Returns 0, or -1 with errno set. */
int outdir_create(const char *path);

/** Whether files can be written in the folder path: create it if missing, write and remove a
 *  probe file, then remove the folders this call created, so that nothing is left behind.
 *  Returns 0, or 1 with "cannot write to the output folder '<path>': <reason>" in err. */
int outdir_probe(const char *path, char *err, size_t err_len);

#endif
