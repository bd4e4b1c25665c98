/* init.c — initial particle generation. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "physics/eos.h"
#include "case/geometry.h"
#include "case/init.h"
#include "base/mem.h"

#define BOUNDARY_TOL 1e-9   /* relative tolerance on distances to wall boundaries */

/* Distance from x to the nearest wall boundary (infinity without walls). */
static double wall_distance(const struct case_def *c, const double *x) {
  double best = INFINITY, q[3];
  for (int w = 0; w < c->n_walls; w++)
    best = fmin(best, shape_nearest_boundary(&c->walls[w].shape, c->dimension, x, q));
  return best;
}

/* 1 if x is a ghost node of wall w: on its solid side, within the wall thickness. */
static int ghost_of(const struct case_def *c, int w, double thickness, const double *x) {
  const struct wall *wl = &c->walls[w];
  int inside = shape_contains(&wl->shape, c->dimension, x);
  if (inside == (wl->fluid_side == FLUID_INSIDE)) return 0;
  double q[3], d = shape_nearest_boundary(&wl->shape, c->dimension, x, q);
  return d <= thickness * (1 + BOUNDARY_TOL) && d >= 0.5 * c->dx * (1 - BOUNDARY_TOL);
}

/* The fluid region containing x, or -1. */
static int region_at(const struct case_def *c, const double *x) {
  for (int k = 0; k < c->n_fluids; k++)
    if (shape_contains(&c->fluids[k].shape, c->dimension, x)) return k;
  return -1;
}

/* Add the interface mode's velocity at x (2D): V e^(-k|y - y0|) (sgn(y - y0) sin kx, cos kx). */
static void add_velocity_mode(const struct velocity_mode *mode, const double *x, double *u) {
  if (!mode->active) return;
  double k = 2 * acos(-1.0) / mode->wavelength, dy = x[1] - mode->interface;
  double decay = mode->amplitude * exp(-k * fabs(dy));
  u[0] += (dy > 0 ? 1 : dy < 0 ? -1 : 0) * decay * sin(k * x[0]);
  u[1] += decay * cos(k * x[0]);
}

/* Initial velocity of region k at x: velocity + G x, plus the region's interface mode. */
static void region_velocity(const struct case_def *c, int k, const double *x, double *u) {
  for (int a = 0; a < c->dimension; a++) {
    u[a] = c->fluids[k].velocity[a];
    for (int b = 0; b < c->dimension; b++) u[a] += c->fluids[k].velocity_gradient[a][b] * x[b];
  }
  add_velocity_mode(&c->fluids[k].mode, x, u);
}

/* Acceleration the pressure must balance at x in region k: body force minus the convective
 * acceleration (u.grad)u = G u of the initial linear velocity field. */
static void effective_acceleration(const struct case_def *c, int k, const double *x, double *a) {
  double u[3], w2 = c->potential_omega * c->potential_omega;
  region_velocity(c, k, x, u);
  for (int i = 0; i < c->dimension; i++) {
    a[i] = c->gravity[i] - w2 * (x[i] - c->potential_centre[i]);
    for (int j = 0; j < c->dimension; j++) a[i] -= c->fluids[k].velocity_gradient[i][j] * u[j];
  }
}

/* 1 if the case has only uniform gravity and uniform initial velocities. */
static int uniform_forcing(const struct case_def *c) {
  if (c->potential_omega > 0) return 0;
  for (int k = 0; k < c->n_fluids; k++)
    for (int a = 0; a < c->dimension; a++)
      for (int b = 0; b < c->dimension; b++)
        if (c->fluids[k].velocity_gradient[a][b] != 0) return 0;
  return 1;
}

/* p(x) = integral of rho (-a . d) ds along the straight ray from x in the direction d = -a/|a| of
 * the balancing acceleration at x, midpoint rule with steps of dx/8, until the domain ends. */
static double marched_pressure(const struct case_def *c, const double *x) {
  int k0 = region_at(c, x), dim = c->dimension;
  double a[3], dir[3], len = 0, ds = c->dx / 8, p = 0;
  if (k0 < 0) return 0;
  effective_acceleration(c, k0, x, a);
  for (int d = 0; d < dim; d++) len += a[d] * a[d];
  if (len == 0) return 0;
  for (int d = 0; d < dim; d++) dir[d] = -a[d] / sqrt(len);
  for (double s = 0.5 * ds;; s += ds) {
    double y[3] = {0, 0, 0}, ay[3], along = 0;
    for (int d = 0; d < dim; d++) y[d] = x[d] + s * dir[d];
    for (int d = 0; d < dim; d++)
      if (y[d] < c->domain_min[d] || y[d] > c->domain_max[d]) return p;
    int k = region_at(c, y);
    if (k < 0) continue;
    effective_acceleration(c, k, y, ay);
    for (int d = 0; d < dim; d++) along -= ay[d] * dir[d];
    p += c->phases[c->fluids[k].phase].rho0 * along * ds;
  }
}

double init_hydrostatic_pressure(const struct case_def *c, const double *x) {
  if (!uniform_forcing(c)) return marched_pressure(c, x);
  double g = 0, up[3] = {0, 0, 0};
  for (int d = 0; d < c->dimension; d++) g += c->gravity[d] * c->gravity[d];
  g = sqrt(g);
  if (g == 0) return 0;
  for (int d = 0; d < c->dimension; d++) up[d] = -c->gravity[d] / g;
  double p = 0;
  for (int k = 0; k < c->n_fluids; k++)
    p += c->phases[c->fluids[k].phase].rho0 * g *
         shape_ray_length(&c->fluids[k].shape, c->dimension, x, up);
  return p;
}

int init_wall_layers(const struct case_def *c, double support) {
  return (int)ceil(support / c->dx - BOUNDARY_TOL);
}

static double cell_volume(const struct case_def *c) {
  return c->dimension == 2 ? c->dx * c->dx : c->dx * c->dx * c->dx;
}

/* Store a fluid particle of region k at x in the next slot of p. */
static void add_fluid(const struct case_def *c, int k, const double *x, int64_t id, struct parts *p) {
  const struct phase *ph = &c->phases[c->fluids[k].phase];
  long i = p->n_owned++;
  parts_reserve(p, p->n_owned);
  double pressure = ph->p_background;
  if (c->initial_pressure == INIT_PRESSURE_HYDROSTATIC) pressure += init_hydrostatic_pressure(c, x);
  double u[3];
  region_velocity(c, k, x, u);
  for (int d = 0; d < c->dimension; d++) {
    p->x[d][i] = x[d];
    p->v[d][i] = u[d];
  }
  p->p[i] = pressure;
  p->rho[i] = eos_density(ph, pressure);
  p->m[i] = p->rho[i] * cell_volume(c);
  p->phase[i] = c->fluids[k].phase;
  p->id[i] = id;
  p->cell[i] = -1;
  if (p->wall) {
    p->wall[i] = -1;
    for (int d = 0; d < c->dimension; d++) p->mirror[d][i] = 0.0;
  }
}

/* Store a ghost of wall w at x, with the offset 2 (q - x) to its mirror point across the wall
 * boundary point q nearest to x (fixed in the wall's frame). */
static void add_ghost(const struct case_def *c, int w, const double *x, int64_t id, struct parts *p) {
  long i = p->n_owned++;
  parts_reserve(p, p->n_owned);
  double q[3];
  shape_nearest_boundary(&c->walls[w].shape, c->dimension, x, q);
  for (int d = 0; d < c->dimension; d++) {
    p->x[d][i] = x[d];
    p->v[d][i] = 0;
    p->mirror[d][i] = 2 * (q[d] - x[d]);
  }
  p->p[i] = 0;
  p->rho[i] = c->phases[0].rho0;
  p->m[i] = p->rho[i] * cell_volume(c);
  p->phase[i] = PHASE_WALL;
  p->id[i] = id;
  p->cell[i] = -1;
  p->wall[i] = w;
}

/* The first fluid region before k that contains x, or -1. */
static int earlier_region(const struct case_def *c, int k, const double *x) {
  for (int j = 0; j < k; j++)
    if (shape_contains(&c->fluids[j].shape, c->dimension, x)) return j;
  return -1;
}

static int fill_fluids(const struct case_def *c, int rank, int n_ranks, struct parts *p,
                       struct init_counts *n, int64_t *ordinal, char *err, size_t err_len) {
  for (int k = 0; k < c->n_fluids; k++) {
    const struct shape *s = &c->fluids[k].shape;
    double lo[3], hi[3], anchor[3], x[3];
    struct lattice l;
    shape_bbox(s, c->dimension, 0, lo, hi);
    if (c->has_lattice_origin) memcpy(anchor, c->lattice_origin, sizeof anchor);
    else shape_anchor(s, c->dimension, anchor);
    lattice_cover(&l, c->dimension, c->dx, anchor, lo, hi);
    for (long node = 0, size = lattice_size(&l); node < size; node++) {
      lattice_node(&l, node, x);
      if (!shape_contains(s, c->dimension, x) || walls_solid_at(c, NULL, x, NULL) >= 0) continue;
      if (wall_distance(c, x) < 0.5 * c->dx * (1 - BOUNDARY_TOL)) continue;
      int j = earlier_region(c, k, x);
      if (j >= 0) {
        snprintf(err, err_len, "%s: fluids.%d overlaps fluids.%d (both contain the point (%g, %g%s)); "
                 "fluid regions must not overlap", c->source_file, k, j, x[0], x[1],
                 c->dimension == 3 ? ", ..." : "");
        return 1;
      }
      if (p && *ordinal % n_ranks == rank) add_fluid(c, k, x, *ordinal, p);
      (*ordinal)++;
      n->fluid[c->fluids[k].phase]++;
      n->n_fluid++;
    }
  }
  return 0;
}

/* The first wall before w whose ghost layer contains x, or -1. */
static int earlier_wall(const struct case_def *c, int w, double thickness, const double *x) {
  for (int j = 0; j < w; j++)
    if (ghost_of(c, j, thickness, x)) return j;
  return -1;
}

static int inside_domain(const struct case_def *c, const double *x) {
  for (int d = 0; d < c->dimension; d++)
    if (x[d] < c->domain_min[d] || x[d] > c->domain_max[d]) return 0;
  return 1;
}

/* Coordinates along axis d of the ghost nodes of a tank box: layers below min and above max at
 * (k + 1/2) dx from each face, and the interior lattice anchored at min. Returns the count. */
static int tank_axis(const struct shape *s, int d, double dx, int layers, double *out) {
  int n = 0;
  for (int k = layers - 1; k >= 0; k--) out[n++] = s->min[d] - (k + 0.5) * dx;
  for (int i = 0; s->min[d] + (i + 0.5) * dx < s->max[d]; i++) out[n++] = s->min[d] + (i + 0.5) * dx;
  for (int k = 0; k < layers; k++) out[n++] = s->max[d] + (k + 0.5) * dx;
  return n;
}

/* The candidate ghost nodes of a wall, enumerated without storing them. A tank box gets layers
 * anchored to each of its faces, so every face has ghosts at (k + 1/2) dx whatever the box size;
 * its interior nodes are skipped (they are never ghosts). Other walls use the lattice anchored at
 * the shape's lower corner. */
struct wall_nodes {
  int dim, tank, layers;
  long n[3], count;          /* nodes per axis and in total, interior included */
  double *axis[3];           /* tank: node coordinates along each axis */
  struct lattice l;          /* other walls */
};

static void wall_nodes_open(struct wall_nodes *wn, const struct case_def *c, int w, double thickness) {
  const struct shape *s = &c->walls[w].shape;
  memset(wn, 0, sizeof *wn);
  wn->dim = c->dimension;
  wn->layers = (int)lround(thickness / c->dx);
  wn->tank = s->kind == SHAPE_BOX && c->walls[w].fluid_side == FLUID_INSIDE;
  if (wn->tank) {
    wn->n[1] = wn->n[2] = 1;
    for (int d = 0; d < wn->dim; d++) {
      wn->axis[d] = mem_calloc((size_t)((s->max[d] - s->min[d]) / c->dx) + 2 * wn->layers + 4, sizeof(double),
                               "wall lattice axis");
      wn->n[d] = tank_axis(s, d, c->dx, wn->layers, wn->axis[d]);
    }
    wn->count = wn->n[0] * wn->n[1] * wn->n[2];
    return;
  }
  double lo[3], hi[3], anchor[3];
  shape_bbox(s, wn->dim, thickness, lo, hi);
  shape_anchor(s, wn->dim, anchor);
  lattice_cover(&wn->l, wn->dim, c->dx, anchor, lo, hi);
  wn->count = lattice_size(&wn->l);
}

/* 1 if index i of an axis with n tank nodes is an interior (not a layer) node. */
static int tank_interior(const struct wall_nodes *wn, long i, long n) {
  return i >= wn->layers && i < n - wn->layers;
}

/* The first candidate node at or after node k (tank interior rows skipped). */
static long wall_nodes_skip(const struct wall_nodes *wn, long k) {
  if (!wn->tank) return k;
  long ix = k % wn->n[0], iy = (k / wn->n[0]) % wn->n[1], iz = k / (wn->n[0] * wn->n[1]);
  int interior_row = tank_interior(wn, iy, wn->n[1]) && (wn->dim == 2 || tank_interior(wn, iz, wn->n[2]));
  return interior_row && tank_interior(wn, ix, wn->n[0]) ? k - ix + wn->n[0] - wn->layers : k;
}

/* Position of node k. */
static void wall_nodes_get(const struct wall_nodes *wn, long k, double *x) {
  if (!wn->tank) {
    lattice_node(&wn->l, k, x);
    return;
  }
  long idx[3] = {k % wn->n[0], (k / wn->n[0]) % wn->n[1], k / (wn->n[0] * wn->n[1])};
  for (int d = 0; d < wn->dim; d++) x[d] = wn->axis[d][idx[d]];
}

static void wall_nodes_close(struct wall_nodes *wn) {
  for (int d = 0; d < 3; d++) free(wn->axis[d]);
}

static int fill_walls(const struct case_def *c, double thickness, int rank, int n_ranks,
                      struct parts *p, struct init_counts *n, int64_t *ordinal, char *err,
                      size_t err_len) {
  int dim = c->dimension, status = 0;
  for (int w = 0; w < c->n_walls && !status; w++) {
    struct wall_nodes wn;
    double x[3] = {0, 0, 0};
    wall_nodes_open(&wn, c, w, thickness);
    for (long k = wall_nodes_skip(&wn, 0); k < wn.count && !status; k = wall_nodes_skip(&wn, k + 1)) {
      wall_nodes_get(&wn, k, x);
      if (!ghost_of(c, w, thickness, x) || walls_solid_at(c, NULL, x, NULL) < 0) continue;
      if (earlier_wall(c, w, thickness, x) >= 0) continue;
      if (!inside_domain(c, x)) {
        snprintf(err, err_len, "%s: walls.%d: its %d ghost layers (%g m thick) reach (%g, %g%s) outside "
                 "the domain: the domain must extend at least %g m beyond the wall", c->source_file, w,
                 wn.layers, thickness, x[0], x[1], dim == 3 ? ", ..." : "", thickness);
        status = 1;
        break;
      }
      if (p && *ordinal % n_ranks == rank) add_ghost(c, w, x, *ordinal, p);
      (*ordinal)++;
      n->n_wall++;
    }
    wall_nodes_close(&wn);
  }
  return status;
}

/* Nodes of a lattice of spacing dx covering the bounding box of s grown by margin (a bound). */
static double lattice_bound(const struct shape *s, int dim, double margin, double dx) {
  double lo[3], hi[3], n = 1;
  shape_bbox(s, dim, margin, lo, hi);
  for (int d = 0; d < dim; d++) n *= (hi[d] - lo[d]) / dx + 2;
  return n;
}

/* Nodes of the ghost layers of a tank box (a bound): all its axis nodes less the interior ones. */
static double tank_bound(const struct shape *s, int dim, int layers, double dx) {
  double all = 1, interior = 1;
  for (int d = 0; d < dim; d++) {
    double n = (s->max[d] - s->min[d]) / dx + 1;
    all *= n + 2 * layers;
    interior *= n;
  }
  return all - interior;
}

double init_visit_count(const struct case_def *c, double support) {
  int dim = c->dimension, layers = init_wall_layers(c, support);
  double total = 0;
  for (int k = 0; k < c->n_fluids; k++) total += lattice_bound(&c->fluids[k].shape, dim, 0, c->dx);
  for (int w = 0; w < c->n_walls; w++) {
    const struct shape *s = &c->walls[w].shape;
    if (s->kind == SHAPE_BOX && c->walls[w].fluid_side == FLUID_INSIDE)
      total += tank_bound(s, dim, layers, c->dx);
    else
      total += lattice_bound(s, dim, layers * c->dx, c->dx);
  }
  return isnan(total) ? INFINITY : total;
}

int init_particles(const struct case_def *c, double support, int rank, int n_ranks,
                   struct parts *p, struct init_counts *counts, char *err, size_t err_len) {
  memset(counts, 0, sizeof(*counts));
  int64_t ordinal = 0;
  double thickness = init_wall_layers(c, support) * c->dx;
  if (p) p->n_owned = p->n_halo = 0;
  if (fill_fluids(c, rank, n_ranks, p, counts, &ordinal, err, err_len)) return 1;
  if (fill_walls(c, thickness, rank, n_ranks, p, counts, &ordinal, err, err_len)) return 1;
  if (counts->n_fluid == 0) {
    snprintf(err, err_len, "%s: fluids: no fluid particle was generated (regions empty, or all "
             "outside the walls)", c->source_file);
    return 1;
  }
  return 0;
}
