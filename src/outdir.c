/* outdir.c — the output folder: mkdir -p, and a write probe that leaves nothing behind. */
#include "outdir.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* mkdir -p path; *created gets the length of the shortest prefix of path this call created (0 if
 * it created none). Returns 0, or -1 with errno set. */
static int make_dirs(const char *path, size_t *created) {
  char buf[PATH_MAX];
  *created = 0;
  if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf) {
    errno = ENAMETOOLONG;
    return -1;
  }
  size_t n = strlen(buf);
  for (size_t k = 1; k <= n; k++) {
    if (buf[k] != '/' && buf[k] != '\0') continue;
    char end = buf[k];
    buf[k] = '\0';
    int made = mkdir(buf, 0777) == 0;
    if (!made && errno != EEXIST) return -1;
    if (made && !*created) *created = k;
    buf[k] = end;
  }
  return 0;
}

/* Remove the folders of path from the deepest up to the prefix of length created (> 0). */
static void remove_dirs(const char *path, size_t created) {
  char buf[PATH_MAX];
  snprintf(buf, sizeof buf, "%s", path);
  for (size_t k = strlen(buf); created > 0 && k >= created; k--) {
    if (buf[k] != '/' && buf[k] != '\0') continue;
    buf[k] = '\0';
    rmdir(buf);
  }
}

int outdir_create(const char *path) {
  size_t created;
  return make_dirs(path, &created);
}

/* Write and remove a small file in folder path. Returns 0, or -1 with errno set. */
static int write_probe(const char *path) {
  char file[PATH_MAX];
  if (snprintf(file, sizeof file, "%s/.mpsph-probe-%ld", path, (long)getpid()) >= (int)sizeof file) {
    errno = ENAMETOOLONG;
    return -1;
  }
  FILE *f = fopen(file, "w");
  if (!f) return -1;
  int ok = fputs("probe\n", f) >= 0;
  ok &= fclose(f) == 0;
  int saved = errno;
  remove(file);
  errno = saved;
  return ok ? 0 : -1;
}

int outdir_probe(const char *path, char *err, size_t err_len) {
  size_t created = 0;
  int status = make_dirs(path, &created) || write_probe(path);
  if (status)
    snprintf(err, err_len, "cannot write to the output folder '%s': %s", path, strerror(errno));
  remove_dirs(path, created);
  return status;
}

int outdir_write_file(const char *dir, const char *name, void (*fill)(FILE *f, const void *ctx),
                      const void *ctx) {
  char path[PATH_MAX], tmp[PATH_MAX + 8];
  snprintf(path, sizeof(path), "%s/%s", dir, name);
  snprintf(tmp, sizeof(tmp), "%s.tmp", path);
  FILE *f = fopen(tmp, "w");
  if (!f) return -1;
  fill(f, ctx);
  int ok = !ferror(f);
  ok &= fclose(f) == 0;
  return ok ? rename(tmp, path) : -1;
}
