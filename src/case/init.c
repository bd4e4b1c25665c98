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

void init_add_fluid(const struct case_def *c, int k, const double *x, int64_t id, struct parts *p) {
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
  p->m[i] = p->rho[i] * case_lattice_volume(c, case_phase_dx(c, c->fluids[k].phase));
  p->phase[i] = c->fluids[k].phase;
  p->id[i] = id;
  p->cell[i] = -1;
  if (p->wall) {
    p->wall[i] = -1;
    for (int d = 0; d < c->dimension; d++) p->mirror[d][i] = 0.0;
  }
}

void init_add_ghost(const struct case_def *c, int w, const double *x, int64_t id, struct parts *p) {
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
  p->m[i] = p->rho[i] * case_lattice_volume(c, c->dx);
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

/* A fluid region's lattice at its phase's spacing, anchored at the case's lattice origin or the
 * shape's anchor. */
static void open_fluid(struct init_source *s, const struct case_def *c, int k) {
  const struct shape *sh = &c->fluids[k].shape;
  double lo[3], hi[3], anchor[3];
  shape_bbox(sh, c->dimension, 0, lo, hi);
  if (c->has_lattice_origin) memcpy(anchor, c->lattice_origin, sizeof anchor);
  else shape_anchor(sh, c->dimension, anchor);
  lattice_cover(&s->l, c->dimension, case_phase_dx(c, c->fluids[k].phase), anchor, lo, hi);
  for (int d = 0; d < 3; d++) s->n[d] = s->l.count[d];
}

/* A wall's candidate ghost nodes. A tank box gets layers anchored to each of its faces, so every
 * face has ghosts at (k + 1/2) dx whatever the box size (its interior nodes are never ghosts and
 * are skipped); other walls use the lattice anchored at the shape's lower corner. */
static void open_wall(struct init_source *s, const struct case_def *c, int w, double thickness) {
  const struct shape *sh = &c->walls[w].shape;
  s->layers = (int)lround(thickness / c->dx);
  s->tank = sh->kind == SHAPE_BOX && c->walls[w].fluid_side == FLUID_INSIDE;
  if (s->tank) {
    s->n[1] = s->n[2] = 1;
    for (int d = 0; d < c->dimension; d++) {
      s->axis[d] = mem_calloc((size_t)((sh->max[d] - sh->min[d]) / c->dx) + 2 * s->layers + 4,
                              sizeof(double), "wall lattice axis");
      s->n[d] = tank_axis(sh, d, c->dx, s->layers, s->axis[d]);
    }
    return;
  }
  double lo[3], hi[3], anchor[3];
  shape_bbox(sh, c->dimension, thickness, lo, hi);
  shape_anchor(sh, c->dimension, anchor);
  lattice_cover(&s->l, c->dimension, c->dx, anchor, lo, hi);
  for (int d = 0; d < 3; d++) s->n[d] = s->l.count[d];
}

void init_rows_open(struct init_rows *r, const struct case_def *c, double support) {
  memset(r, 0, sizeof *r);
  r->thickness = init_wall_layers(c, support) * c->dx;
  for (int k = 0; k < c->n_fluids + c->n_walls; k++) {
    struct init_source *s = &r->src[r->n_sources++];
    s->wall = k < c->n_fluids ? -1 : k - c->n_fluids;
    if (s->wall < 0) open_fluid(s, c, k);
    else open_wall(s, c, s->wall, r->thickness);
    s->first_row = r->n_rows;
    r->n_rows += s->n[1] * s->n[2];
  }
}

void init_rows_close(struct init_rows *r) {
  for (int k = 0; k < r->n_sources; k++)
    for (int d = 0; d < 3; d++) free(r->src[k].axis[d]);
  memset(r, 0, sizeof *r);
}

int init_row_source(const struct init_rows *r, long row) {
  int k = 0;
  while (k + 1 < r->n_sources && r->src[k + 1].first_row <= row) k++;
  return k;
}

void init_source_extent(const struct init_rows *r, int k, int dim, double *lo, double *hi, double *in_lo,
                        double *in_hi) {
  const struct init_source *s = &r->src[k];
  for (int d = 0; d < dim; d++) {
    long n = s->n[d];
    lo[d] = s->tank ? s->axis[d][0] : lattice_coord(&s->l, d, 0);
    hi[d] = s->tank ? s->axis[d][n - 1] : lattice_coord(&s->l, d, n - 1);
    in_lo[d] = s->tank && n > 2 * s->layers ? s->axis[d][s->layers - 1] : INFINITY;
    in_hi[d] = s->tank && n > 2 * s->layers ? s->axis[d][n - s->layers] : -INFINITY;
  }
}

/* Position of node (ix, iy, iz) of source s. */
static void node_at(const struct init_source *s, int dim, long ix, long iy, long iz, double *x) {
  long idx[3] = {ix, iy, iz};
  for (int d = 0; d < 3; d++) {
    if (d >= dim) x[d] = 0;
    else if (s->tank) x[d] = s->axis[d][idx[d]];
    else x[d] = lattice_coord(&s->l, d, idx[d]);
  }
}

/* 1 if index i of an axis with n tank nodes is an interior (not a layer) node. */
static int tank_interior(const struct init_source *s, long i, long n) {
  return i >= s->layers && i < n - s->layers;
}

/* The next candidate index at or after ix in row (iy, iz) of s: a tank's interior nodes of an
 * interior row are skipped. */
static long next_candidate(const struct init_source *s, int dim, long ix, long iy, long iz) {
  if (!s->tank || !tank_interior(s, ix, s->n[0])) return ix;
  int interior_row = tank_interior(s, iy, s->n[1]) && (dim == 2 || tank_interior(s, iz, s->n[2]));
  return interior_row ? s->n[0] - s->layers : ix;
}

/* Whether fluid node x of region k is a particle: 1 yes, 0 no, -1 with a message (regions
 * overlap). */
static int fluid_node(const struct case_def *c, int k, const double *x, char *err, size_t len) {
  if (!shape_contains(&c->fluids[k].shape, c->dimension, x) || walls_solid_at(c, NULL, x, NULL) >= 0) return 0;
  if (wall_distance(c, x) < 0.5 * case_phase_dx(c, c->fluids[k].phase) * (1 - BOUNDARY_TOL)) return 0;
  int j = earlier_region(c, k, x);
  if (j < 0) return 1;
  snprintf(err, len, "%s: fluids.%d overlaps fluids.%d (both contain the point (%g, %g%s)); "
           "fluid regions must not overlap", c->source_file, k, j, x[0], x[1],
           c->dimension == 3 ? ", ..." : "");
  return -1;
}

/* Whether node x of wall w is a ghost: 1 yes, 0 no, -1 with a message (outside the domain). */
static int wall_node(const struct case_def *c, const struct init_rows *r, int w, const double *x,
                     char *err, size_t len) {
  if (!ghost_of(c, w, r->thickness, x) || walls_solid_at(c, NULL, x, NULL) < 0) return 0;
  if (earlier_wall(c, w, r->thickness, x) >= 0) return 0;
  if (inside_domain(c, x)) return 1;
  snprintf(err, len, "%s: walls.%d: its %d ghost layers (%g m thick) reach (%g, %g%s) outside "
           "the domain: the domain must extend at least %g m beyond the wall", c->source_file, w,
           r->src[c->n_fluids + w].layers, r->thickness, x[0], x[1], c->dimension == 3 ? ", ..." : "",
           r->thickness);
  return -1;
}

/* Visit the particles of row `row` among its nodes [0, ix_end): fn(ctx, x, source, ordinal in
 * the row) for each. Returns the particles, or -1 with a message. */
static long visit_row(const struct case_def *c, const struct init_rows *r, long row, long ix_end,
                      init_node_fn fn, void *ctx, char *err, size_t len) {
  int k = init_row_source(r, row), dim = c->dimension;
  const struct init_source *s = &r->src[k];
  long q = row - s->first_row, iy = q % s->n[1], iz = q / s->n[1], count = 0;
  double x[3];
  for (long ix = next_candidate(s, dim, 0, iy, iz); ix < ix_end; ix = next_candidate(s, dim, ix + 1, iy, iz)) {
    node_at(s, dim, ix, iy, iz, x);
    int ok = s->wall < 0 ? fluid_node(c, k, x, err, len) : wall_node(c, r, s->wall, x, err, len);
    if (ok < 0) return -1;
    if (!ok) continue;
    if (fn) fn(ctx, x, k, count);
    count++;
  }
  return count;
}

long init_count_rows(const struct case_def *c, const struct init_rows *r, long first, long end,
                     int *counts, init_node_fn fn, void *ctx, char *err, size_t len) {
  for (long row = first; row < end; row++) {
    const struct init_source *s = &r->src[init_row_source(r, row)];
    long n = visit_row(c, r, row, s->n[0], fn, ctx, err, len);
    if (n < 0) return row;
    counts[row - first] = (int)n;
  }
  return -1;
}

long init_visit_row(const struct case_def *c, const struct init_rows *r, long row, long ix_end,
                    init_node_fn fn, void *ctx) {
  char err[8];
  return visit_row(c, r, row, ix_end, fn, ctx, err, sizeof err);
}

/* The first of the n increasing coordinates a[] that is at least v (n if none). */
static long lower_bound(const double *a, long n, double v) {
  long lo = 0, hi = n;
  while (lo < hi) {
    long mid = lo + (hi - lo) / 2;
    if (a[mid] < v) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/* Index range [*lo, *hi] along axis d of source s of the nodes within [a, b]; empty when *lo > *hi. */
static void axis_range(const struct init_source *s, int d, double a, double b, long *lo, long *hi) {
  if (!s->tank) {
    double base = lattice_coord(&s->l, d, 0);
    *lo = (long)fmax(0.0, ceil((a - base) / s->l.dx));
    *hi = (long)fmin((double)(s->n[d] - 1), floor((b - base) / s->l.dx));
    return;
  }
  *lo = lower_bound(s->axis[d], s->n[d], a);
  *hi = lower_bound(s->axis[d], s->n[d], nextafter(b, INFINITY)) - 1;
}

int init_rows_in_box(const struct init_rows *r, int k, int dim, const double *lo, const double *hi,
                     long *first, long *last) {
  const struct init_source *s = &r->src[k];
  for (int d = 0; d < 3; d++) {
    first[d] = last[d] = 0;
    if (d < dim) axis_range(s, d, lo[d], hi[d], &first[d], &last[d]);
    if (first[d] > last[d]) return 0;
  }
  return 1;
}

/* Context of init_particles: the particles and the counts it fills, the next id. */
struct fill {
  const struct case_def *c;
  struct parts *p;
  struct init_counts *n;
  int64_t id;
};

/* Add (with parts) and count the particle at x of source k. */
static void fill_node(void *ctx, const double *x, int k, long ordinal) {
  (void)ordinal;
  struct fill *f = ctx;
  const struct case_def *c = f->c;
  if (k < c->n_fluids) {
    if (f->p) init_add_fluid(c, k, x, f->id, f->p);
    f->n->fluid[c->fluids[k].phase]++;
    f->n->n_fluid++;
  } else {
    if (f->p) init_add_ghost(c, k - c->n_fluids, x, f->id, f->p);
    f->n->n_wall++;
  }
  f->id++;
}

int init_no_fluid(const struct case_def *c, long n_fluid, char *err, size_t err_len) {
  if (n_fluid > 0) return 0;
  snprintf(err, err_len, "%s: fluids: no fluid particle was generated (regions empty, or all "
           "outside the walls)", c->source_file);
  return 1;
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
  double total = init_wall_visit_count(c, support);
  for (int k = 0; k < c->n_fluids; k++)
    total += lattice_bound(&c->fluids[k].shape, c->dimension, 0, case_phase_dx(c, c->fluids[k].phase));
  return isnan(total) ? INFINITY : total;
}

double init_wall_visit_count(const struct case_def *c, double support) {
  int dim = c->dimension, layers = init_wall_layers(c, support);
  double total = 0;
  for (int w = 0; w < c->n_walls; w++) {
    const struct shape *s = &c->walls[w].shape;
    if (s->kind == SHAPE_BOX && c->walls[w].fluid_side == FLUID_INSIDE)
      total += tank_bound(s, dim, layers, c->dx);
    else
      total += lattice_bound(s, dim, layers * c->dx, c->dx);
  }
  return isnan(total) ? INFINITY : total;
}

int init_particles(const struct case_def *c, double support, struct parts *p,
                   struct init_counts *counts, char *err, size_t err_len) {
  memset(counts, 0, sizeof(*counts));
  if (p) p->n_owned = p->n_halo = 0;
  struct init_rows r;
  init_rows_open(&r, c, support);
  struct fill f = {c, p, counts, 0};
  int status = 0;
  for (long row = 0; row < r.n_rows && !status; row++)
    status = visit_row(c, &r, row, r.src[init_row_source(&r, row)].n[0], fill_node, &f, err, err_len) < 0;
  init_rows_close(&r);
  return status || init_no_fluid(c, counts->n_fluid, err, err_len);
}
