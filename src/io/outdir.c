/* outdir.c — the output folder: mkdir -p, a write probe that leaves nothing behind, and the
 * lock that keeps a second run out of it. */
#include "io/outdir.h"
#include "base/mem.h"

#include <errno.h>
#include <stdarg.h>
#include <fcntl.h>
#include <libgen.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <time.h>
#include <unistd.h>

#define LOCK_FILE ".mpsph.lock"   /* in the output folder; it stays there after the run */

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

char *outdir_path(const char *dir, const char *name_fmt, ...) {
  va_list args;
  va_start(args, name_fmt);
  int name_len = vsnprintf(NULL, 0, name_fmt, args);
  va_end(args);
  size_t dir_len = strlen(dir), bytes = dir_len + 1 + (size_t)(name_len > 0 ? name_len : 0) + 1;
  char *path = mem_alloc(bytes, "a file path in the output folder");
  snprintf(path, bytes, "%s/", dir);
  va_start(args, name_fmt);
  vsnprintf(path + dir_len + 1, bytes - dir_len - 1, name_fmt, args);
  va_end(args);
  return path;
}

int outdir_create(const char *path) {
  size_t created;
  return make_dirs(path, &created);
}

/* Write and remove a small file in folder path. Returns 0, or -1 with errno set. */
static int write_probe(const char *path) {
  char *file = outdir_path(path, ".mpsph-probe-%ld", (long)getpid());
  FILE *f = fopen(file, "w");
  int ok = f != NULL;
  if (f) {
    ok = fputs("probe\n", f) >= 0;
    ok &= fclose(f) == 0;
  }
  int saved = errno;
  if (f) remove(file);
  free(file);
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
  char *path = outdir_path(dir, "%s", name), *tmp = outdir_path(dir, "%s.tmp", name);
  FILE *f = fopen(tmp, "w");
  int ok = f != NULL;
  if (f) {
    fill(f, ctx);
    ok = !ferror(f);
    ok &= fclose(f) == 0;
    ok = ok && rename(tmp, path) == 0;
  }
  int saved = errno;
  if (f && !ok) unlink(tmp);
  free(path);
  free(tmp);
  errno = saved;
  return ok ? 0 : -1;
}

/* Who holds the lock: "pid P on host H since T", written into the lock file by its holder. */
static void write_holder(int fd) {
  char host[256] = "?", when[64] = "?", text[512];
  time_t now = time(NULL);
  struct tm utc;
  gethostname(host, sizeof host);
  host[sizeof host - 1] = '\0';
  if (gmtime_r(&now, &utc)) strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", &utc);
  int n = snprintf(text, sizeof text, "pid %ld on host %s since %s\n", (long)getpid(), host, when);
  if (ftruncate(fd, 0) == 0 && pwrite(fd, text, (size_t)n, 0) == n) return;
  /* the lock holds without the text: a refused run then names no holder */
}

/* The holder's text of lock file fd (without its newline) into text; "holder unknown" if none. */
static void read_holder(int fd, char *text, size_t len) {
  ssize_t n = pread(fd, text, len - 1, 0);
  text[n > 0 ? n : 0] = '\0';
  text[strcspn(text, "\n")] = '\0';
  if (!text[0]) snprintf(text, len, "holder unknown");
}

int outdir_lock(const char *path, int *fd, char *err, size_t err_len) {
  char *file = outdir_path(path, LOCK_FILE), holder[512];
  struct flock lock = {.l_type = F_WRLCK, .l_whence = SEEK_SET, .l_start = 0, .l_len = 0};
  *fd = outdir_create(path) == 0 ? open(file, O_RDWR | O_CREAT | O_CLOEXEC, 0666) : -1;
  free(file);
  if (*fd < 0) {
    snprintf(err, err_len, "cannot write to the output folder '%s': %s", path, strerror(errno));
    return 1;
  }
  if (fcntl(*fd, F_SETLK, &lock) == 0) {
    write_holder(*fd);
    return 0;
  }
  int busy = errno == EACCES || errno == EAGAIN, saved = errno;
  if (busy) read_holder(*fd, holder, sizeof holder);
  close(*fd);
  *fd = -1;
  if (busy) {
    snprintf(err, err_len, "the output folder '%s' is in use by another run (%s): wait for it to "
             "end, or choose another -o", path, holder);
    return 1;
  }
  fprintf(stderr, "mpsph: warning: cannot lock the output folder '%s' (%s): nothing keeps a second "
          "run out of it\n", path, strerror(saved));
  return 0;
}

double outdir_free_bytes(const char *file) {
  char *dir = mem_strndup(file, SIZE_MAX, "a file path");
  struct statvfs fs;
  int known = statvfs(dirname(dir), &fs) == 0;
  free(dir);
  return known ? (double)fs.f_frsize * (double)(geteuid() == 0 ? fs.f_bfree : fs.f_bavail) : -1;
}

int outdir_room(const char *file, double bytes, char *err, size_t err_len) {
  double room = outdir_free_bytes(file);
  if (room < 0 || room >= bytes) return 0;   /* not known: the write will tell */
  snprintf(err, err_len, "cannot write %s: %s (it needs about %.3g MB, %.3g MB are free)",
           file, strerror(ENOSPC), bytes / 1e6, room / 1e6);
  return 3;
}
