/* test_mem.c — the checked allocator (mem.h): allocations that succeed hold their bytes; one that
 * fails (a size no machine has, an n * size overflowing size_t, a failing library allocation)
 * ends the process with status 3 and a message naming what and how many bytes. Each failure
 * runs in a forked child whose stderr goes to a pipe. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "check.h"
#include "base/mem.h"

enum failure { HUGE_ALLOC, HUGE_CALLOC, OVERFLOW_BYTES, HUGE_REALLOC, LIBRARY };

/* In the child: the failing call of kind k (never returns). */
static void fail_in_child(enum failure k) {
  switch (k) {
    case HUGE_ALLOC: mem_alloc(SIZE_MAX / 2, "test block"); break;
    case HUGE_CALLOC: mem_calloc(SIZE_MAX / 16, 4, "test table"); break;
    case OVERFLOW_BYTES: mem_bytes(SIZE_MAX / 2, 3, "test overflow"); break;
    case HUGE_REALLOC: mem_realloc(mem_alloc(8, "test small"), SIZE_MAX / 2, "test growth"); break;
    case LIBRARY: mem_fail(0, "test library"); break;
  }
  _exit(99);   /* reached only if the call returned */
}

/* Run failure k in a child; check its status is 3 and its stderr contains `expect`. */
static void check_failure(enum failure k, const char *expect) {
  int fd[2];
  if (pipe(fd)) {
    CHECK(0, "pipe");
    return;
  }
  fflush(stdout);
  pid_t pid = fork();
  if (pid == 0) {
    dup2(fd[1], 2);
    close(fd[0]);
    fail_in_child(k);
  }
  close(fd[1]);
  char text[512] = "";
  size_t got = 0;
  ssize_t r;
  while (got < sizeof text - 1 && (r = read(fd[0], text + got, sizeof text - 1 - got)) > 0) got += (size_t)r;
  text[got] = '\0';
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 3, "failure %d: status %d, expected exit 3", k, status);
  CHECK(strstr(text, expect) != NULL, "failure %d: message '%s' lacks '%s'", k, text, expect);
}

int main(void) {
  char *a = mem_alloc(64, "test");
  memset(a, 7, 64);
  a = mem_realloc(a, 1 << 20, "test");
  CHECK(a[63] == 7, "realloc keeps the contents");
  free(a);
  int *z = mem_calloc(1000, sizeof(int), "test");
  int sum = 0;
  for (int k = 0; k < 1000; k++) sum += z[k];
  CHECK(sum == 0, "calloc zero-fills");
  free(z);
  char *s = mem_strndup("abcdef", 3, "test");
  CHECK(!strcmp(s, "abc"), "strndup copies at most n bytes: '%s'", s);
  free(s);
  char bytes_half[64];
  snprintf(bytes_half, sizeof bytes_half, "(%zu bytes)", SIZE_MAX / 2);
  check_failure(HUGE_ALLOC, "mpsph: out of memory: test block");
  check_failure(HUGE_ALLOC, bytes_half);
  check_failure(HUGE_CALLOC, "mpsph: out of memory: test table");
  check_failure(OVERFLOW_BYTES, "mpsph: out of memory: test overflow");
  check_failure(HUGE_REALLOC, "mpsph: out of memory: test growth");
  check_failure(LIBRARY, "mpsph: out of memory: test library (allocated inside a library)");
  return check_report("test_mem");
}
