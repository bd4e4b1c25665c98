/* check.h — a minimal assertion helper for the C unit tests.
 * Each test program prints one line per check ("ok"/"FAIL") and exits non-zero on any failure.
 * scripts/run-tests counts the programs' results. */
#ifndef MPSPH_TEST_CHECK_H
#define MPSPH_TEST_CHECK_H

#include <stdio.h>
#include <math.h>

static int check_failures = 0;
static int check_count = 0;

#define CHECK(cond, ...)                                                   \
  do {                                                                     \
    check_count++;                                                         \
    if (!(cond)) {                                                         \
      check_failures++;                                                    \
      printf("FAIL %s:%d: ", __FILE__, __LINE__);                          \
      printf(__VA_ARGS__);                                                 \
      printf("\n");                                                        \
    }                                                                      \
  } while (0)

#define CHECK_CLOSE(a, b, tol, what)                                       \
  CHECK(fabs((double)(a) - (double)(b)) <= (tol), "%s: %.17g vs %.17g (tol %g)", what, \
        (double)(a), (double)(b), (double)(tol))

/** Print the summary line and return the exit status for main(). */
static inline int check_report(const char *name) {
  printf("%s: %d checks, %d failed\n", name, check_count, check_failures);
  return check_failures ? 1 : 0;
}

#endif
