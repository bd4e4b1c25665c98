/* fuzz_case_load.c — the libFuzzer target of `make fuzz`: the input is a case file. Lines at its
 * start of the form "#set key.path=value" (YAML comments) are also applied as --set overrides.
 * A case that loads must satisfy the contract of case_to_yaml (the resolved text loads again and
 * gives the same text), and a small one is counted by particle generation as `mpsph check` does.
 * Any violation aborts, so the fuzzer reports it like a crash. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case/case_load.h"
#include "case/init.h"
#include "physics/kernel.h"

#define MAX_SETS 4
#define MAX_VISITS 20000.0   /* count the particles only of cases this small (fast) */
#define ERR_LEN 1024

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void violation(const char *what, const char *text) {
  fprintf(stderr, "fuzz_case_load: %s\n%s\n", what, text ? text : "");
  abort();
}

/* The overrides "#set ..." on the first lines of text (each a new string; returns the count). */
static int overrides(const char *text, size_t size, char **sets) {
  int n = 0;
  const char *line = text, *end = text + size;
  while (n < MAX_SETS && end - line > 5 && memcmp(line, "#set ", 5) == 0) {
    const char *nl = memchr(line, '\n', (size_t)(end - line));
    if (!nl) break;
    sets[n++] = strndup(line + 5, (size_t)(nl - line - 5));
    line = nl + 1;
  }
  return n;
}

/* case_to_yaml(c) loads again and writes the same text. */
static void round_trip(const struct case_def *c) {
  char err[ERR_LEN];
  struct case_def again;
  char *yaml = case_to_yaml(c);
  if (!yaml) violation("case_to_yaml returned NULL", NULL);
  if (case_load_string(yaml, strlen(yaml), "config.yaml", 0, NULL, &again, err, sizeof err))
    violation(err, yaml);
  char *yaml2 = case_to_yaml(&again);
  if (strcmp(yaml, yaml2) != 0) violation("the resolved case changed when loaded again", yaml2);
  free(yaml);
  free(yaml2);
}

/* Count the particles of a small case (particle generation's refusals are fine). */
static void count(const struct case_def *c) {
  struct kernel k;
  struct init_counts n;
  char err[ERR_LEN];
  kernel_init(&k, c->kernel, c->dimension, c->h_over_dx * c->dx);
  if (init_visit_count(c, k.support) <= MAX_VISITS)
    init_particles(c, k.support, NULL, &n, err, sizeof err);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static struct case_def c;
  char err[ERR_LEN], *sets[MAX_SETS];
  int n_sets = overrides((const char *)data, size, sets);
  if (case_load_string((const char *)data, size, "fuzz.yaml", n_sets, sets, &c, err, sizeof err) == 0) {
    round_trip(&c);
    count(&c);
  } else if (strchr(err, '\n')) {
    violation("a message of more than one line", err);
  }
  for (int i = 0; i < n_sets; i++) free(sets[i]);
  return 0;
}
