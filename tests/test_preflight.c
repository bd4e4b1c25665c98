/* test_preflight.c — the pieces of the checks before a run: the bound on the particle count
 * (never below the count, not far above it for the cases of the repository), the memory
 * estimate per rank, the memory available, and the output-folder probe leaving nothing behind. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "case/case_load.h"
#include "check.h"
#include "case/init.h"
#include "physics/kernel.h"
#include "app/mem_estimate.h"
#include "io/outdir.h"

static const char *const CASES[] = {
    "cases/dambreak-1phase/case.yaml", "cases/dambreak-2phase/case.yaml",
    "cases/hydrostatic-1phase/case.yaml", "cases/hydrostatic-2phase/case.yaml",
    "cases/oscillating-drop/case.yaml", "cases/oscillating-drop-2fluid/case.yaml",
    "tests/cases/hydrostatic-3d.yaml", NULL};

static void check_bounds(void) {
  for (int i = 0; CASES[i]; i++) {
    struct case_def c;
    struct kernel k;
    struct init_counts n;
    char err[1024];
    CHECK(case_load(CASES[i], 0, NULL, &c, err, sizeof err) == 0, "%s: %s", CASES[i], err);
    kernel_init(&k, c.kernel, c.dimension, c.h_over_dx * c.dx);
    CHECK(init_particles(&c, k.support, NULL, &n, err, sizeof err) == 0, "%s", err);
    double count = (double)(n.n_fluid + n.n_wall), bound = init_visit_count(&c, k.support);
    CHECK(count <= bound && bound <= 12 * count, "%s: bound %g for %g particles", CASES[i], bound,
          count);
  }
}

/* Particles of each kind: n fluid and n / 4 wall ghosts. */
static const double *kinds_of(double n) {
  static double n_kind[KIND_COUNT];
  n_kind[KIND_FLUID] = n;
  n_kind[KIND_WALL] = n / 4;
  return n_kind;
}

static double owned(const struct mem_estimate *m) { return m->owned[KIND_FLUID] + m->owned[KIND_WALL]; }

static void check_estimate(void) {
  struct case_def c;
  char err[1024];
  CHECK(case_load(CASES[2], 0, NULL, &c, err, sizeof err) == 0, "%s", err);
  double support = 3 * c.h_over_dx * c.dx;
  struct mem_estimate one = mem_estimate_rank(&c, support, kinds_of(1e6), 1, 1);
  CHECK(one.owned[KIND_FLUID] == 1e6 && one.owned[KIND_WALL] == 2.5e5 && one.halo == 0,
        "one rank holds every particle and no halo: %g fluid, %g wall, %g halo", one.owned[KIND_FLUID],
        one.owned[KIND_WALL], one.halo);
  CHECK(one.total == one.process + one.cells + one.startup + one.particle_bytes, "total");
  CHECK(one.startup > 0 && one.cells > 0, "the start-up rows and the cells are counted: %g, %g", one.startup,
        one.cells);
  struct mem_estimate four = mem_estimate_rank(&c, support, kinds_of(1e6), 4, 4);
  /* the largest rank: within the partition's tolerances (3 % of the mean work, 10 % of the mean
     particles), at least the mean share */
  double work = 8 * four.owned[KIND_FLUID] + 2 * four.owned[KIND_WALL];
  CHECK(work <= 1.03 * (8e6 + 2 * 2.5e5) / 4 * (1 + 1e-9) && owned(&four) <= 1.10 * 1.25e6 / 4 * (1 + 1e-9),
        "the largest rank: %g fluid, %g wall", four.owned[KIND_FLUID], four.owned[KIND_WALL]);
  CHECK(owned(&four) >= 1.25e6 / 4, "at least a mean share: %g fluid, %g wall", four.owned[KIND_FLUID],
        four.owned[KIND_WALL]);
  CHECK(four.halo > 0 && four.halo < owned(&four), "a halo band: %g", four.halo);
  struct mem_estimate two = mem_estimate_rank(&c, support, kinds_of(1e6), 2, 2);
  CHECK(two.halo / owned(&two) < four.halo / owned(&four),
        "a half borders one rank, a quarter two: halo fractions %g, %g", two.halo / owned(&two),
        four.halo / owned(&four));
  struct mem_estimate spread = mem_estimate_rank(&c, support, kinds_of(1e6), 4, 1);
  CHECK(four.process > spread.process && spread.process > one.process,
        "MPI's memory on several ranks, more with more ranks on the node: %g, %g, %g", one.process,
        spread.process, four.process);
  struct mem_estimate small = mem_estimate_rank(&c, support, kinds_of(100), 4, 4);
  CHECK(owned(&small) + small.halo <= 125, "the halo is at most the other ranks' particles: %g",
        owned(&small) + small.halo);
}

static void check_available(void) {
  setenv("MPSPH_MEMORY_AVAILABLE", "2e9", 1);
  CHECK(mem_node_available() == 2e9, "from the variable");
  setenv("MPSPH_MEMORY_AVAILABLE", "2GB", 1);
  CHECK(mem_node_available() == -1, "not a number");
  unsetenv("MPSPH_MEMORY_AVAILABLE");
  CHECK(mem_node_available() > 1e8, "MemAvailable: %g", mem_node_available());
}

static void check_probe(void) {
  char dir[64] = "/tmp/test_preflight.XXXXXX", path[256], err[512];
  struct stat st;
  CHECK(mkdtemp(dir) != NULL, "temporary folder");
  snprintf(path, sizeof path, "%s/a/b/", dir);
  CHECK(outdir_probe(path, err, sizeof err) == 0, "a new nested folder: %s", err);
  snprintf(path, sizeof path, "%s/a", dir);
  CHECK(stat(path, &st) != 0, "the probe left nothing behind");
  CHECK(outdir_probe(dir, err, sizeof err) == 0 && stat(dir, &st) == 0, "an existing folder stays");
  snprintf(path, sizeof path, "%s/file", dir);
  FILE *f = fopen(path, "w");
  fclose(f);
  snprintf(path, sizeof path, "%s/file/x/y", dir);
  CHECK(outdir_probe(path, err, sizeof err) == 1 && strstr(err, "Not a directory") != NULL,
        "through a file: %s", err);
  CHECK(outdir_create(path) == -1, "outdir_create through a file fails");
  snprintf(path, sizeof path, "%s/c/d", dir);
  CHECK(outdir_create(path) == 0 && stat(path, &st) == 0 && S_ISDIR(st.st_mode), "mkdir -p");
  rmdir(path);
  snprintf(path, sizeof path, "%s/c", dir);
  rmdir(path);
  snprintf(path, sizeof path, "%s/file", dir);
  unlink(path);
  CHECK(rmdir(dir) == 0, "only what the test made was left");
}

int main(void) {
  check_bounds();
  check_estimate();
  check_available();
  check_probe();
  return check_report("test_preflight");
}
