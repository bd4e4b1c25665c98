/* test_geometry.c — shapes against analytic values: inside tests, nearest boundary points
 * (mirror points of the wall ghosts), ray lengths (hydrostatic start), lattice cover. A box and
 * the same rectangle as a polygon must agree; polygon faults (crossing, touching, degenerate). */
#include <math.h>
#include "check.h"
#include "case/geometry.h"

static struct shape box2(double x0, double y0, double x1, double y1) {
  struct shape s = {.kind = SHAPE_BOX, .min = {x0, y0, 0}, .max = {x1, y1, 0}};
  return s;
}

static struct shape rect_polygon(double x0, double y0, double x1, double y1) {
  struct shape s = {.kind = SHAPE_POLYGON, .n_vertices = 4,
                    .vertex = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
  return s;
}

static void check_box_and_polygon(void) {
  struct shape b = box2(0, 0, 2, 1), p = rect_polygon(0, 0, 2, 1);
  double pts[6][2] = {{0.4, 0.45}, {1.9, 0.2}, {-0.3, 0.5}, {2.2, 1.3}, {1.0, -0.05}, {0.1, 0.95}};
  for (int k = 0; k < 6; k++) {
    double qb[3], qp[3];
    CHECK(shape_contains(&b, 2, pts[k]) == shape_contains(&p, 2, pts[k]), "inside test point %d", k);
    double db = shape_nearest_boundary(&b, 2, pts[k], qb), dp = shape_nearest_boundary(&p, 2, pts[k], qp);
    CHECK_CLOSE(db, dp, 1e-14, "distance box vs polygon");
    CHECK_CLOSE(qb[0], qp[0], 1e-14, "nearest x");
    CHECK_CLOSE(qb[1], qp[1], 1e-14, "nearest y");
  }
  double x[2] = {2.2, 1.3}, q[3];
  shape_nearest_boundary(&b, 2, x, q);   /* outside a corner: the corner */
  CHECK(q[0] == 2 && q[1] == 1, "corner is the nearest point (%g, %g)", q[0], q[1]);
  double up[2] = {0, 1}, y[2] = {0.5, 0.25};
  CHECK_CLOSE(shape_ray_length(&b, 2, y, up), 0.75, 1e-14, "box ray");
  CHECK_CLOSE(shape_ray_length(&p, 2, y, up), 0.75, 1e-14, "polygon ray");
}

static void check_circle(void) {
  struct shape c = {.kind = SHAPE_CIRCLE, .centre = {1, 1, 1}, .radius = 0.5};
  double in[3] = {1.2, 1.1, 1.0}, out[3] = {1.5, 1.5, 1.0}, q[3];
  CHECK(shape_contains(&c, 3, in) && !shape_contains(&c, 3, out), "ball inside test");
  double d = shape_nearest_boundary(&c, 3, out, q);
  CHECK_CLOSE(d, sqrt(0.5) - 0.5, 1e-14, "distance to the sphere");
  CHECK_CLOSE(q[0], 1 + 0.5 / sqrt(2), 1e-14, "nearest point on the sphere");
  double dir[3] = {0, 1, 0}, centre[3] = {1, 1, 1};
  CHECK_CLOSE(shape_ray_length(&c, 3, centre, dir), 0.5, 1e-14, "ray from the centre");
  double below[3] = {1, 0, 1};
  CHECK_CLOSE(shape_ray_length(&c, 3, below, dir), 1.0, 1e-14, "ray through the ball");
}

static void check_concave_polygon(void) {
  /* an L shape: the vertical ray at x = 1.5 crosses the lower arm only */
  struct shape l = {.kind = SHAPE_POLYGON, .n_vertices = 6,
                    .vertex = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  double a[2] = {1.5, 0.2}, b[2] = {0.5, 0.2}, up[2] = {0, 1}, corner[2] = {1.5, 1.5}, q[3];
  CHECK_CLOSE(shape_ray_length(&l, 2, a, up), 0.8, 1e-14, "L ray, short arm");
  CHECK_CLOSE(shape_ray_length(&l, 2, b, up), 1.8, 1e-14, "L ray, long arm");
  CHECK(!shape_contains(&l, 2, corner), "notch is outside");
  CHECK_CLOSE(shape_nearest_boundary(&l, 2, corner, q), 0.5, 1e-14, "notch distance");
}

static void check_lattice(void) {
  struct lattice l;
  double anchor[2] = {0, 0}, lo[2] = {0, 0}, hi[2] = {1, 0.5}, x[3] = {0, 0, 0};
  lattice_cover(&l, 2, 0.1, anchor, lo, hi);
  long inside = 0;
  struct shape b = box2(0, 0, 1, 0.5);
  for (long j = 0; j < l.count[1]; j++)
    for (long i = 0; i < l.count[0]; i++) {
      x[0] = lattice_coord(&l, 0, i);
      x[1] = lattice_coord(&l, 1, j);
      inside += shape_contains(&b, 2, x);
    }
  CHECK(inside == 50, "a 1 x 0.5 box at dx 0.1 holds 50 nodes, got %ld", inside);
}

/* A tank made of two boxes (an L) with a disc obstacle in the first. */
static void check_walls_solid(void) {
  struct case_def c = {.dimension = 2, .n_walls = 3};
  c.walls[0].shape = box2(0, 0, 1, 1);
  c.walls[1].shape = (struct shape){.kind = SHAPE_CIRCLE, .centre = {0.5, 0.5, 0}, .radius = 0.1};
  c.walls[1].fluid_side = FLUID_OUTSIDE;
  c.walls[2].shape = box2(1, 0, 2, 0.5);
  double fluid[2] = {0.2, 0.2}, arm[2] = {1.5, 0.2}, obstacle[2] = {0.5, 0.55}, out[2] = {1.5, 0.8};
  double right[2] = {2.25, 0.2}, depth = -1;
  CHECK(walls_solid_at(&c, NULL, fluid, &depth) == -1 && depth == -1, "fluid in the first tank");
  CHECK(walls_solid_at(&c, NULL, arm, &depth) == -1, "fluid in the second tank");
  CHECK(walls_solid_at(&c, NULL, obstacle, &depth) == 1, "inside the obstacle");
  CHECK_CLOSE(depth, 0.05, 1e-14, "depth inside the obstacle");
  CHECK(walls_solid_at(&c, NULL, out, &depth) == 2, "outside both tanks: the nearer one");
  CHECK_CLOSE(depth, 0.3, 1e-14, "depth outside the tanks");
  CHECK(walls_solid_at(&c, NULL, right, NULL) == 2, "no depth asked");
  c.n_walls = 0;
  CHECK(walls_solid_at(&c, NULL, out, &depth) == -1, "no walls: fluid everywhere");
}

/* The fault of the polygon with the n vertices xy (x0, y0, x1, y1, ...) and what it names in *a, *b. */
static enum polygon_fault fault_of(int n, const double *xy, int *a, int *b) {
  struct shape s = {.kind = SHAPE_POLYGON, .n_vertices = n};
  for (int k = 0; k < n; k++) {
    s.vertex[k][0] = xy[2 * k];
    s.vertex[k][1] = xy[2 * k + 1];
  }
  *a = *b = -1;
  return polygon_fault(&s, a, b);
}

/* Simple polygons (either orientation, concave) pass; crossing, touching, folded, repeated and
 * flat ones are named with the edges or vertices at fault. */
static void check_polygon_faults(void) {
  int a, b;
  const double square[] = {0, 0, 1, 0, 1, 1, 0, 1}, clockwise[] = {0, 0, 0, 1, 1, 1, 1, 0};
  const double ell[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
  CHECK(fault_of(4, square, &a, &b) == POLYGON_SIMPLE, "square");
  CHECK(fault_of(4, clockwise, &a, &b) == POLYGON_SIMPLE, "clockwise square");
  CHECK(fault_of(6, ell, &a, &b) == POLYGON_SIMPLE, "L shape");
  const double bowtie[] = {0, 0, 1, 1, 1, 0, 0, 1};
  CHECK(fault_of(4, bowtie, &a, &b) == POLYGON_EDGES_MEET && a == 0 && b == 2, "bow tie: edges %d %d", a, b);
  const double touch[] = {0, 0, 2, 0, 2, 2, 1, 0, 0, 2};   /* vertex 3 lies on edge 0 */
  CHECK(fault_of(5, touch, &a, &b) == POLYGON_EDGES_MEET && a == 0 && b == 2, "vertex on an edge: %d %d", a, b);
  const double spike[] = {0, 0, 2, 0, 1, 0, 1, 1};   /* edge 1 folds back onto edge 0 */
  CHECK(fault_of(4, spike, &a, &b) == POLYGON_EDGES_MEET && a == 0 && b == 1, "fold: edges %d %d", a, b);
  const double flat[] = {0, 0, 1, 0, 2, 0};
  CHECK(fault_of(3, flat, &a, &b) == POLYGON_EDGES_MEET && a == 0 && b == 2, "collinear: edges %d %d", a, b);
  const double repeated[] = {0, 0, 1, 0, 1, 0, 0, 1};
  CHECK(fault_of(4, repeated, &a, &b) == POLYGON_REPEATED_VERTEX && a == 1 && b == 2, "repeated: %d %d", a, b);
  const double closed[] = {0, 0, 1, 0, 1, 1, 0, 0};   /* first vertex repeated at the end */
  CHECK(fault_of(4, closed, &a, &b) == POLYGON_REPEATED_VERTEX && a == 0 && b == 3, "closed ring: %d %d", a, b);
}

/* A 3D box with a cosine floor (and the box below it with the same ceiling) z = 2 + 0.05 (cos 2 pi x + cos 2 pi y): above it inside, below it
 * outside, the plain box's faces unchanged; every point in one of the two. */
static void check_box_floor(void) {
  struct shape b = {.kind = SHAPE_BOX, .min = {0, 0, 1.8}, .max = {1, 1, 4}, .surface = SURFACE_FLOOR,
                    .surface_level = 2, .surface_amplitude = 0.05, .surface_wavelength = 1};
  struct shape c = b;   /* the region below: the same surface as a ceiling */
  c.surface = SURFACE_CEILING;
  c.min[2] = 0;
  c.max[2] = 2.2;
  double centre_up[3] = {0.5, 0.5, 1.91}, centre_down[3] = {0.5, 0.5, 1.89};
  double corner_up[3] = {0.01, 0.01, 2.11}, corner_down[3] = {0.01, 0.01, 2.09}, outside[3] = {0.5, 0.5, 4.1};
  CHECK(shape_contains(&b, 3, centre_up), "above the trough at (0.5, 0.5, 1.9)");
  CHECK(!shape_contains(&b, 3, centre_down), "below the trough at (0.5, 0.5, 1.9)");
  CHECK(shape_contains(&b, 3, corner_up), "above the crest near (0, 0, 2.1)");
  CHECK(!shape_contains(&b, 3, corner_down), "below the crest near (0, 0, 2.1)");
  CHECK(!shape_contains(&b, 3, outside), "above the box");
  double pts[5][3] = {{0.5, 0.5, 1.9}, {0.3, 0.7, 1.95}, {0.1, 0.2, 2.05}, {0.5, 0.5, 1.85}, {0, 0, 2.1}};
  for (int k = 0; k < 5; k++)
    CHECK(shape_contains(&b, 3, pts[k]) != shape_contains(&c, 3, pts[k]), "floor xor ceiling at point %d", k);
}

int main(void) {
  check_box_floor();
  check_polygon_faults();
  check_box_and_polygon();
  check_circle();
  check_concave_polygon();
  check_lattice();
  check_walls_solid();
  return check_report("test_geometry");
}
