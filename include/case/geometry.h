/* geometry.h — shapes of the case: inside tests, distance to the boundary, mirror points,
 * ray lengths, lattice enumeration. Lengths in m. */
#ifndef MPSPH_GEOMETRY_H
#define MPSPH_GEOMETRY_H

#include "case/case.h"

/** 1 if point x lies inside the closed shape s (dim 2 or 3). */
int shape_contains(const struct shape *s, int dim, const double *x);

/** Nearest point q on the boundary of s to x; returns the distance |x - q|. */
double shape_nearest_boundary(const struct shape *s, int dim, const double *x, double *q);

/** Length of the part of the ray x + t*dir (t > 0, |dir| = 1) that lies inside s. */
double shape_ray_length(const struct shape *s, int dim, const double *x, const double *dir);

/** The wall of case c whose solid holds x, or -1 where fluid may be. The solid is everything
 *  outside the tanks (walls with fluid_side inside) when the case has a tank, and the inside of
 *  each obstacle (fluid_side outside); shapes are closed. Outside every tank the nearest tank is
 *  returned. depth (may be NULL) receives the distance from x to that wall's boundary [m].
 *  frames (may be NULL: every wall where the case puts it) holds the moving walls' frames now. */
int walls_solid_at(const struct case_def *c, const struct frame *frames, const double *x, double *depth);

/** What makes a polygon unusable as a shape. */
enum polygon_fault {
  POLYGON_SIMPLE = 0,        /* none: a simple polygon enclosing an area */
  POLYGON_REPEATED_VERTEX,   /* two vertices are the same point */
  POLYGON_EDGES_MEET,        /* two edges cross or touch (neighbouring edges: beyond their vertex) */
  POLYGON_NO_AREA            /* the enclosed area is 0 */
};

/** Whether the polygon s (2D, n_vertices >= 3) is simple and encloses an area. Edge k joins
 *  vertex k to vertex k + 1 (the last edge to vertex 0). Returns POLYGON_SIMPLE, or the first
 *  fault found with the two vertices (POLYGON_REPEATED_VERTEX) or edges (POLYGON_EDGES_MEET)
 *  concerned in *a < *b. */
enum polygon_fault polygon_fault(const struct shape *s, int *a, int *b);

/** Centroid [m] and principal moments of inertia about it along the case axes, per unit mass
 *  [m^2], of s filled uniformly (a box, a disc or annulus, a ball or shell, a 2D polygon: its
 *  axes need not be principal, so inertia[0..1] are then the moments about x and y only); 2D:
 *  inertia[2] about z. */
void shape_mass_properties(const struct shape *s, int dim, double *centroid, double *inertia);

/** Axis-aligned bounding box of s, grown by `margin` on every side. */
void shape_bbox(const struct shape *s, int dim, double margin, double *lo, double *hi);

/** A Cartesian lattice of spacing dx whose nodes are origin + (i + 1/2) dx, covering [lo, hi]. */
struct lattice {
  int dim;
  double dx, origin[3];
  long first[3], count[3];   /* node index range per axis */
};

/** The lattice of spacing dx anchored at `anchor` covering the box [lo, hi]. */
void lattice_cover(struct lattice *l, int dim, double dx, const double *anchor,
                   const double *lo, const double *hi);

/** Coordinate along axis d of the lattice's node i of that axis (0 <= i < count[d]) [m]. */
static inline double lattice_coord(const struct lattice *l, int d, long i) {
  return l->origin[d] + ((double)(l->first[d] + i) + 0.5) * l->dx;
}

/** Anchor of the lattice used to fill shape s: box min, circle centre - radius, polygon bbox min. */
void shape_anchor(const struct shape *s, int dim, double *anchor);

#endif
