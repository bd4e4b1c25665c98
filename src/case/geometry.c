/* geometry.c — inside tests, nearest boundary points, ray lengths and lattices of shapes. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include "case/geometry.h"

/* The height of a box's cosine surface over x (its last axis is the vertical). */
static double surface_height(const struct shape *s, int dim, const double *x) {
  double k = 2 * acos(-1.0) / s->surface_wavelength, sum = 0;
  for (int d = 0; d < dim - 1; d++) sum += cos(k * x[d]);
  return s->surface_level + s->surface_amplitude * sum;
}

static int box_contains(const struct shape *s, int dim, const double *x) {
  for (int d = 0; d < dim; d++)
    if (x[d] < s->min[d] || x[d] > s->max[d]) return 0;
  if (s->surface == SURFACE_NONE) return 1;
  double z = surface_height(s, dim, x);   /* a point on it belongs to the floor's side only */
  return s->surface == SURFACE_FLOOR ? x[dim - 1] >= z : x[dim - 1] < z;
}

static int circle_contains(const struct shape *s, int dim, const double *x) {
  double r2 = 0;
  for (int d = 0; d < dim; d++) r2 += (x[d] - s->centre[d]) * (x[d] - s->centre[d]);
  return r2 <= s->radius * s->radius && r2 >= s->inner_radius * s->inner_radius;
}

/* Crossing-number test; points on an edge may go either way. */
static int polygon_contains(const struct shape *s, const double *x) {
  int inside = 0, n = s->n_vertices;
  for (int a = 0, b = n - 1; a < n; b = a++) {
    const double *va = s->vertex[a], *vb = s->vertex[b];
    if ((va[1] > x[1]) != (vb[1] > x[1]) &&
        x[0] < (vb[0] - va[0]) * (x[1] - va[1]) / (vb[1] - va[1]) + va[0])
      inside = !inside;
  }
  return inside;
}

int shape_contains(const struct shape *s, int dim, const double *x) {
  switch (s->kind) {
    case SHAPE_BOX: return box_contains(s, dim, x);
    case SHAPE_CIRCLE: return circle_contains(s, dim, x);
    default: return polygon_contains(s, x);
  }
}

static double box_nearest(const struct shape *s, int dim, const double *x, double *q) {
  if (!box_contains(s, dim, x)) {
    double d2 = 0;
    for (int d = 0; d < dim; d++) {
      q[d] = fmin(fmax(x[d], s->min[d]), s->max[d]);
      d2 += (x[d] - q[d]) * (x[d] - q[d]);
    }
    return sqrt(d2);
  }
  double best = DBL_MAX;
  int best_axis = 0;
  double best_value = 0;
  for (int d = 0; d < dim; d++) {
    double to_min = x[d] - s->min[d], to_max = s->max[d] - x[d];
    if (to_min < best) { best = to_min; best_axis = d; best_value = s->min[d]; }
    if (to_max < best) { best = to_max; best_axis = d; best_value = s->max[d]; }
  }
  for (int d = 0; d < dim; d++) q[d] = x[d];
  q[best_axis] = best_value;
  return best;
}

static double circle_nearest(const struct shape *s, int dim, const double *x, double *q) {
  double r2 = 0;
  for (int d = 0; d < dim; d++) r2 += (x[d] - s->centre[d]) * (x[d] - s->centre[d]);
  double r = sqrt(r2);
  int inner = s->inner_radius > 0 && fabs(r - s->inner_radius) < fabs(r - s->radius);
  double radius = inner ? s->inner_radius : s->radius;
  for (int d = 0; d < dim; d++)
    q[d] = s->centre[d] + (r > 0 ? (x[d] - s->centre[d]) / r : (d == 0)) * radius;
  return fabs(r - radius);
}

/* Nearest point to x on segment [a, b]; returns the squared distance. */
static double segment_nearest(const double *a, const double *b, const double *x, double *q) {
  double ex = b[0] - a[0], ey = b[1] - a[1];
  double len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / len2 : 0;
  t = fmin(fmax(t, 0.0), 1.0);
  q[0] = a[0] + t * ex;
  q[1] = a[1] + t * ey;
  return (x[0] - q[0]) * (x[0] - q[0]) + (x[1] - q[1]) * (x[1] - q[1]);
}

static double polygon_nearest(const struct shape *s, const double *x, double *q) {
  double best = DBL_MAX, c[2];
  for (int a = 0, n = s->n_vertices; a < n; a++) {
    double d2 = segment_nearest(s->vertex[a], s->vertex[(a + 1) % n], x, c);
    if (d2 < best) { best = d2; q[0] = c[0]; q[1] = c[1]; }
  }
  return sqrt(best);
}

double shape_nearest_boundary(const struct shape *s, int dim, const double *x, double *q) {
  switch (s->kind) {
    case SHAPE_BOX: return box_nearest(s, dim, x, q);
    case SHAPE_CIRCLE: return circle_nearest(s, dim, x, q);
    default: return polygon_nearest(s, x, q);
  }
}

int walls_solid_at(const struct case_def *c, const struct frame *frames, const double *x, double *depth) {
  int dim = c->dimension, has_tank = 0, in_tank = 0, nearest_tank = -1;
  double q[3], nearest = INFINITY;
  for (int w = 0; w < c->n_walls; w++) {
    const struct shape *s = &c->walls[w].shape;
    double xw[3] = {x[0], x[1], dim == 3 ? x[2] : 0};   /* x in the wall's frame at t = 0 */
    if (frames && c->walls[w].moving) frame_reference(&frames[w], dim, x, xw);
    int inside = shape_contains(s, dim, xw), obstacle = c->walls[w].fluid_side == FLUID_OUTSIDE;
    if (obstacle && inside) {
      if (depth) *depth = shape_nearest_boundary(s, dim, xw, q);
      return w;
    }
    if (obstacle) continue;
    has_tank = 1;
    in_tank |= inside;
    double d = inside ? INFINITY : shape_nearest_boundary(s, dim, xw, q);
    if (d < nearest || nearest_tank < 0) nearest = d, nearest_tank = w;
  }
  if (!has_tank || in_tank) return -1;
  if (depth) *depth = nearest;
  return nearest_tank;
}

static double box_ray(const struct shape *s, int dim, const double *x, const double *dir) {
  double t0 = 0, t1 = DBL_MAX;
  for (int d = 0; d < dim; d++) {
    if (fabs(dir[d]) < 1e-300) {
      if (x[d] < s->min[d] || x[d] > s->max[d]) return 0;
      continue;
    }
    double ta = (s->min[d] - x[d]) / dir[d], tb = (s->max[d] - x[d]) / dir[d];
    t0 = fmax(t0, fmin(ta, tb));
    t1 = fmin(t1, fmax(ta, tb));
  }
  return t1 > t0 ? t1 - t0 : 0;
}

/* Length of the ray inside the full ball of the given radius. */
static double ball_ray(const struct shape *s, double radius, int dim, const double *x, const double *dir) {
  double b = 0, c = -radius * radius;
  for (int d = 0; d < dim; d++) {
    double e = x[d] - s->centre[d];
    b += e * dir[d];
    c += e * e;
  }
  double disc = b * b - c;
  if (disc <= 0) return 0;
  double t0 = fmax(-b - sqrt(disc), 0.0), t1 = -b + sqrt(disc);
  return t1 > t0 ? t1 - t0 : 0;
}

/* The inner ball lies inside the outer one, so the annulus takes the difference. */
static double circle_ray(const struct shape *s, int dim, const double *x, const double *dir) {
  double outer = ball_ray(s, s->radius, dim, x, dir);
  return s->inner_radius > 0 ? outer - ball_ray(s, s->inner_radius, dim, x, dir) : outer;
}

static int compare_double(const void *a, const void *b) {
  double u = *(const double *)a, v = *(const double *)b;
  return (u > v) - (u < v);
}

static double polygon_ray(const struct shape *s, const double *x, const double *dir) {
  double t[CASE_MAX_VERTICES + 1];
  int nt = 0, n = s->n_vertices;
  for (int a = 0; a < n; a++) {
    const double *p = s->vertex[a], *q = s->vertex[(a + 1) % n];
    double ex = q[0] - p[0], ey = q[1] - p[1];
    double den = dir[0] * ey - dir[1] * ex;
    if (fabs(den) < 1e-300) continue;
    double wx = p[0] - x[0], wy = p[1] - x[1];
    double tr = (wx * ey - wy * ex) / den, ts = (wx * dir[1] - wy * dir[0]) / den;
    if (tr > 0 && ts >= 0 && ts <= 1) t[nt++] = tr;
  }
  qsort(t, nt, sizeof(double), compare_double);
  double total = 0, t_prev = 0;
  for (int k = 0; k < nt; k++) {
    double mid[2] = {x[0] + 0.5 * (t_prev + t[k]) * dir[0], x[1] + 0.5 * (t_prev + t[k]) * dir[1]};
    if (polygon_contains(s, mid)) total += t[k] - t_prev;
    t_prev = t[k];
  }
  return total;
}

double shape_ray_length(const struct shape *s, int dim, const double *x, const double *dir) {
  switch (s->kind) {
    case SHAPE_BOX: return box_ray(s, dim, x, dir);
    case SHAPE_CIRCLE: return circle_ray(s, dim, x, dir);
    default: return polygon_ray(s, x, dir);
  }
}

void shape_bbox(const struct shape *s, int dim, double margin, double *lo, double *hi) {
  for (int d = 0; d < dim; d++) {
    if (s->kind == SHAPE_BOX) { lo[d] = s->min[d]; hi[d] = s->max[d]; }
    else if (s->kind == SHAPE_CIRCLE) { lo[d] = s->centre[d] - s->radius; hi[d] = s->centre[d] + s->radius; }
    else {
      lo[d] = hi[d] = s->vertex[0][d];
      for (int v = 1; v < s->n_vertices; v++) {
        lo[d] = fmin(lo[d], s->vertex[v][d]);
        hi[d] = fmax(hi[d], s->vertex[v][d]);
      }
    }
    lo[d] -= margin;
    hi[d] += margin;
  }
}

/* Area [m^2], centroid [m] and second moments about the centroid per unit area [m^2] (about x:
 * mean y^2, about y: mean x^2) of a polygon, from its triangles with the first vertex. */
static void polygon_moments(const struct shape *s, double *centroid, double *mean_x2, double *mean_y2) {
  double area = 0, cx = 0, cy = 0, sxx = 0, syy = 0;
  const double (*v)[2] = s->vertex;
  for (int k = 0; k < s->n_vertices; k++) {   /* shoelace sums over the edges */
    const double *a = v[k], *b = v[(k + 1) % s->n_vertices];
    double cross = a[0] * b[1] - b[0] * a[1];
    area += cross / 2;
    cx += (a[0] + b[0]) * cross / 6;
    cy += (a[1] + b[1]) * cross / 6;
    sxx += (a[0] * a[0] + a[0] * b[0] + b[0] * b[0]) * cross / 12;
    syy += (a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) * cross / 12;
  }
  centroid[0] = cx / area;
  centroid[1] = cy / area;
  *mean_x2 = sxx / area - centroid[0] * centroid[0];
  *mean_y2 = syy / area - centroid[1] * centroid[1];
}

void shape_mass_properties(const struct shape *s, int dim, double *centroid, double *inertia) {
  double sq[3] = {0, 0, 0};   /* mean squared offset from the centroid along each axis [m^2] */
  for (int d = 0; d < 3; d++) centroid[d] = 0;
  if (s->kind == SHAPE_BOX)
    for (int d = 0; d < dim; d++) {
      centroid[d] = 0.5 * (s->min[d] + s->max[d]);
      sq[d] = (s->max[d] - s->min[d]) * (s->max[d] - s->min[d]) / 12;
    }
  else if (s->kind == SHAPE_CIRCLE) {
    double r = s->radius, ri = s->inner_radius;
    /* disc or annulus: (r^2 + ri^2)/4 per axis; ball or shell: (r^5 - ri^5)/(5 (r^3 - ri^3)) */
    double per_axis = dim == 2 ? (r * r + ri * ri) / 4
                               : (pow(r, 5) - pow(ri, 5)) / (5 * (pow(r, 3) - pow(ri, 3)));
    for (int d = 0; d < dim; d++) {
      centroid[d] = s->centre[d];
      sq[d] = per_axis;
    }
  } else
    polygon_moments(s, centroid, &sq[0], &sq[1]);
  inertia[0] = sq[1] + sq[2];
  inertia[1] = sq[0] + sq[2];
  inertia[2] = sq[0] + sq[1];
}

void shape_anchor(const struct shape *s, int dim, double *anchor) {
  double hi[3];
  shape_bbox(s, dim, 0.0, anchor, hi);
}

void lattice_cover(struct lattice *l, int dim, double dx, const double *anchor,
                   const double *lo, const double *hi) {
  l->dim = dim;
  l->dx = dx;
  for (int d = 0; d < 3; d++) {
    l->origin[d] = d < dim ? anchor[d] : 0;
    l->first[d] = 0;
    l->count[d] = 1;
  }
  for (int d = 0; d < dim; d++) {
    l->first[d] = (long)floor((lo[d] - anchor[d]) / dx - 0.5);
    long last = (long)ceil((hi[d] - anchor[d]) / dx - 0.5);
    l->count[d] = last - l->first[d] + 1;
  }
}


/* ---- polygon validity ---- */

/* Sign of the turn a -> b -> c: 1 left, -1 right, 0 collinear. */
static int turn(const double *a, const double *b, const double *c) {
  double cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return (cross > 0) - (cross < 0);
}

/* Point p, collinear with segment [a, b], lies on it. */
static int on_segment(const double *a, const double *b, const double *p) {
  return p[0] >= fmin(a[0], b[0]) && p[0] <= fmax(a[0], b[0]) && p[1] >= fmin(a[1], b[1]) &&
         p[1] <= fmax(a[1], b[1]);
}

/* The closed segments [a, b] and [c, d] have a point in common. */
static int segments_meet(const double *a, const double *b, const double *c, const double *d) {
  int t1 = turn(c, d, a), t2 = turn(c, d, b), t3 = turn(a, b, c), t4 = turn(a, b, d);
  if (t1 * t2 < 0 && t3 * t4 < 0) return 1;
  return (t1 == 0 && on_segment(c, d, a)) || (t2 == 0 && on_segment(c, d, b)) ||
         (t3 == 0 && on_segment(a, b, c)) || (t4 == 0 && on_segment(a, b, d));
}

/* Edges [a, b] and [b, c], which share b, have more than b in common: c folds back onto [a, b]
 * or a lies on [b, c]. */
static int edges_fold(const double *a, const double *b, const double *c) {
  return turn(a, b, c) == 0 && (on_segment(a, b, c) || on_segment(b, c, a));
}

/* Edges i < j of the n-gon v meet anywhere but at the vertex two neighbouring edges share. */
static int edges_meet(const double (*v)[2], int n, int i, int j) {
  const double *a = v[i], *b = v[(i + 1) % n], *c = v[j], *d = v[(j + 1) % n];
  if (j == i + 1) return edges_fold(a, b, d);
  if (i == 0 && j == n - 1) return edges_fold(c, a, b);
  return segments_meet(a, b, c, d);
}

enum polygon_fault polygon_fault(const struct shape *s, int *a, int *b) {
  int n = s->n_vertices;
  const double (*v)[2] = s->vertex;
  for (*a = 0; *a < n; ++*a)
    for (*b = *a + 1; *b < n; ++*b)
      if (v[*a][0] == v[*b][0] && v[*a][1] == v[*b][1]) return POLYGON_REPEATED_VERTEX;
  for (*a = 0; *a < n; ++*a)
    for (*b = *a + 1; *b < n; ++*b)
      if (edges_meet(v, n, *a, *b)) return POLYGON_EDGES_MEET;
  double area2 = 0;
  for (int k = 0; k < n; k++)
    area2 += v[k][0] * v[(k + 1) % n][1] - v[(k + 1) % n][0] * v[k][1];
  return area2 == 0 ? POLYGON_NO_AREA : POLYGON_SIMPLE;
}
