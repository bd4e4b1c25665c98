/* test_probes.c — the interpolation of the pressure sensors: first-order MLS reproduces a linear
 * field exactly at a point with one-sided (wall-truncated) neighbours, where Shepard does not;
 * both give a constant field; MLS falls back to Shepard when the neighbours are collinear. */
#include <math.h>
#include "check.h"
#include "io/probes.h"

/* A Gaussian weight of offset r (units of h). */
static double weight(const double *r) { return exp(-(r[0] * r[0] + r[1] * r[1])); }

/* Moments at the origin of f = a + g.x sampled on a jittered lattice of spacing 0.75 h above
 * y >= y_min (y_min = 0: a point on a wall, only half the support filled). */
static void fill(struct probe_sums *s, double a, const double *g, double y_min) {
  probe_sums_init(s, 2);
  for (int i = -4; i <= 4; i++)
    for (int j = -4; j <= 4; j++) {
      double r[2] = {0.75 * i + 0.05 * sin(7.0 * i + 3.0 * j), 0.75 * j + 0.375 + 0.05 * cos(5.0 * i - j)};
      if (r[1] < y_min) continue;
      probe_sums_add(s, r, weight(r) * 0.5625, a + g[0] * r[0] + g[1] * r[1]);
    }
}

int main(void) {
  struct probe_sums s;
  const double g[2] = {0.7, -4905.0}, zero[2] = {0, 0};
  fill(&s, 4905.0, g, 0.0);
  double mls = probe_sums_mls(&s), shepard = probe_sums_shepard(&s);
  CHECK_CLOSE(mls, 4905.0, 1e-9, "MLS reproduces a linear field at a wall");
  CHECK(fabs(shepard - 4905.0) > 100.0, "Shepard at a wall is biased by the gradient: %g", shepard);
  fill(&s, 4905.0, g, -10.0);
  CHECK_CLOSE(probe_sums_mls(&s), 4905.0, 1e-9, "MLS reproduces a linear field inside the fluid");
  fill(&s, 2.5, zero, 0.0);
  CHECK_CLOSE(probe_sums_shepard(&s), 2.5, 1e-14, "Shepard reproduces a constant");
  CHECK_CLOSE(probe_sums_mls(&s), 2.5, 1e-12, "MLS reproduces a constant");
  probe_sums_init(&s, 2);
  for (int i = -3; i <= 3; i++) {   /* collinear neighbours: the gradient is undetermined */
    double r[2] = {0.5 * i, 0.2};
    probe_sums_add(&s, r, weight(r), 1.0 + r[0]);
  }
  CHECK_CLOSE(probe_sums_mls(&s), probe_sums_shepard(&s), 0, "MLS falls back to Shepard on a line");
  probe_sums_init(&s, 2);
  CHECK(probe_sums_shepard(&s) == 0 && probe_sums_mls(&s) == 0, "no neighbour reads 0");
  return check_report("test_probes");
}
