/* pass_wall_ghosts.c — values of the ghost particles (Marrone et al. 2011, CMAME 200), fixed in
 * their wall's frame: Shepard interpolation at the ghost's mirror point r* of velocity and
 * pressure, u_k = u* with its normal component relative to the wall mirrored (free slip) or
 * 2 u_w - u* (no slip), u_w and a_w = 0 for a fixed wall, and
 *  - with the paper's pair sum, over every phase: p_k = p* + rho* (g - a_w).(r_k - r*);
 *  - with the density-weighted interface pressure and several phases, over the phase with the
 *    largest Shepard weight at r* only, each neighbour's pressure carried to the ghost along its
 *    own hydrostatic and inertial gradient (Adami, Hu & Adams 2012, JCP 231:7057, Eq. 27):
 *    p_k = sum_j [p_j + rho_j (g - a_w).(r_k - r_j)] W V_j / sum_j W V_j. */
#include <string.h>
#include "physics/passes.h"
#include "physics/pair_chunk.h"

/* Shepard sums at one point: {sum W V, and sum W V times p, rho, u[3]} over every fluid phase
 * (all; left zero in a one-phase case, where it would equal phase[0]) and over each phase on its
 * own (phase[k]); per phase also sum W V rho r[3] when with_rho_r (the density-weighted
 * interface pressure's ghosts need it). */
enum { SHEPARD_W, SHEPARD_P, SHEPARD_RHO, SHEPARD_U, SHEPARD_RHO_R = SHEPARD_U + 3, SHEPARD_SUMS = SHEPARD_RHO_R + 3 };
struct shepard {
  double all[SHEPARD_SUMS], phase[CASE_MAX_PHASES][SHEPARD_SUMS];
  int with_rho_r, one_phase;
};

/* Call fn for candidate j with its weight W V_j if it lies within the kernel support of xs: V_j
 * from vol (this stage's volumes m/rho, pass_fluid_volumes) or, with vol NULL, m_j / rho_j; 1 if
 * it did. */
static inline int visit_if_near(const struct pass_ctx *ctx, const double *xs, long j, const double *vol, near_fn fn,
                                void *arg) {
  const struct parts *p = ctx->p;
  double r2 = 0;
  for (int d = 0; d < p->dim; d++) r2 += (xs[d] - p->x[d][j]) * (xs[d] - p->x[d][j]);
  if (r2 >= ctx->prm->kern.support2) return 0;
  fn(arg, ctx, j, kernel_w(&ctx->prm->kern, r2) * (vol ? vol[j] : p->m[j] / p->rho[j]));
  return 1;
}

/* Add weight wv times slot j's values to the sums a, over `dim` velocity components. */
static inline __attribute__((always_inline)) void add_values(double *a, const struct parts *p, long j, double wv,
                                                             const int dim) {
  a[SHEPARD_W] += wv;
  a[SHEPARD_P] += wv * p->p[j];
  a[SHEPARD_RHO] += wv * p->rho[j];
  for (int d = 0; d < dim; d++) a[SHEPARD_U + d] += wv * p->v[d][j];
}

/* The fluid of the cells around point xs (the boundary particles of each cell follow its fluid,
 * space_sort) without the cells farther than the list radius: the cell skin covers the fluid's
 * motion within a step, so no fluid within the kernel support is left out at any stage; the same
 * ranges at a list's build and at every stage of the step (the cells do not change within it). */
static void fluid_ranges_at(const struct pass_ctx *ctx, const double *xs, struct neighbour_ranges *r) {
  neighbour_ranges_fluid_within(ctx->space, grid_cell_clamped(&ctx->space->grid, xs), xs, ctx->prm->list_radius,
                                r);
}

/* Call fn for every particle of the ranges r within the kernel support of xs, weights as
 * visit_if_near's; returns the number of calls. */
static long visit_ranges(const struct pass_ctx *ctx, const double *xs, const struct neighbour_ranges *r,
                         const double *vol, near_fn fn, void *arg) {
  long n = 0;
  for (int k = 0; k < r->n; k++)
    for (long j = r->start[k]; j < r->start[k] + r->count[k]; j++) n += visit_if_near(ctx, xs, j, vol, fn, arg);
  return n;
}

long visit_near(const struct pass_ctx *ctx, const double *xs, int with_walls, near_fn fn, void *arg) {
  struct neighbour_ranges r;
  if (with_walls) neighbour_ranges(ctx->space, grid_cell_clamped(&ctx->space->grid, xs), &r);
  else fluid_ranges_at(ctx, xs, &r);   /* the fluid alone: no boundary particle to skip */
  return visit_ranges(ctx, xs, &r, NULL, fn, arg);
}

/* The candidates of a mirror point's list (nlist_point_add: a header word, then the kept words
 * of a mask over the fluid ranges of fluid_ranges_at), in stencil order. */
struct listed {
  const uint64_t *point;      /* the list */
  int words, first, w, k;     /* kept words, the first one's number, the word and range now */
  long range_first;           /* candidate number of the first slot of range k */
  uint64_t bits;              /* the bits of word w not yet visited */
  struct neighbour_ranges r;  /* the stencil ranges, read only when a bit is set */
};

/* Start walking the list at point, of mirror point xs. */
static inline void listed_start(struct listed *it, const struct pass_ctx *ctx, const double *xs,
                                const uint64_t *point) {
  it->point = point;
  it->words = nlist_point_words(point, &it->first);
  it->w = it->k = 0;
  it->range_first = 0;
  it->bits = it->words ? point[1] : 0;
  if (it->words) fluid_ranges_at(ctx, xs, &it->r);
}

/* The slots of the next kept word of the list that has a bit set (its candidates in stencil
 * order); 0 when none is left. */
static inline int listed_slots(struct listed *it, long *slot) {
  while (!it->bits) {
    if (++it->w >= it->words) return 0;
    it->bits = it->point[1 + it->w];
  }
  int n = 0;
  for (uint64_t bits = it->bits; bits; bits &= bits - 1) {
    long b = 64L * (it->first + it->w) + __builtin_ctzll(bits);
    while (b >= it->range_first + it->r.count[it->k]) it->range_first += it->r.count[it->k++];
    slot[n++] = it->r.start[it->k] + (b - it->range_first);
  }
  it->bits = 0;
  return n;
}

/* The next chunk c of the listed candidates of xs within the kernel support, with their weights
 * W V_j from this stage's volumes (dim a literal where inlined); 0 when none is left. */
static inline __attribute__((always_inline)) int listed_chunk(const struct pass_ctx *ctx, struct listed *it,
                                                              const double *xs, const int dim,
                                                              struct pair_chunk *c) {
  long slot[PAIR_CHUNK];
  const double *restrict x[3] = {ctx->p->x[0], ctx->p->x[1], ctx->p->x[2]};
  const int m = listed_slots(it, slot);
  if (m) pair_chunk_fill(slot, m, &ctx->prm->kern, x, ctx->w->vol, xs, dim, CHUNK_W, c);
  return m > 0;
}

/* visit_near without walls, over the listed candidates of xs (dim a literal where inlined): the
 * same candidates in the same order, with the weights from this stage's volumes (visit_near
 * divides m/rho). */
static inline __attribute__((always_inline)) long visit_listed_dim(const struct pass_ctx *ctx, const double *xs,
                                                                   const uint64_t *point, near_fn fn, void *arg,
                                                                   const int dim) {
  struct listed it;
  struct pair_chunk c;
  long n = 0;
  listed_start(&it, ctx, xs, point);
  while (listed_chunk(ctx, &it, xs, dim, &c)) {
    for (int k = 0; k < c.n; k++) fn(arg, ctx, c.j[k], c.fv[k]);
    n += c.n;
  }
  return n;
}

/* visit_listed_dim in the particles' dimension. */
static long visit_listed(const struct pass_ctx *ctx, const double *xs, const uint64_t *point, near_fn fn,
                         void *arg) {
  if (ctx->p->dim == 3) return visit_listed_dim(ctx, xs, point, fn, arg, 3);
  return visit_listed_dim(ctx, xs, point, fn, arg, 2);
}

/* The Shepard sums a (zero) of one phase over the listed candidates of xs, inlined with a literal
 * dim: the sums of visit_listed with add_shepard, in the same order, kept in a local copy. */
static inline __attribute__((always_inline)) long listed_one_phase_dim(const struct pass_ctx *ctx,
                                                                       const double *xs,
                                                                       const uint64_t *point, double *a,
                                                                       const int dim) {
  double sums[SHEPARD_U + 3] = {0};
  struct listed it;
  struct pair_chunk c;
  long n = 0;
  listed_start(&it, ctx, xs, point);
  while (listed_chunk(ctx, &it, xs, dim, &c)) {
    for (int k = 0; k < c.n; k++) add_values(sums, ctx->p, c.j[k], c.fv[k], dim);
    n += c.n;
  }
  memcpy(a, sums, sizeof sums);
  return n;
}

/* Add fluid slot j with weight wv to the Shepard sums arg: all phases and its own. */
static void add_shepard(void *arg, const struct pass_ctx *ctx, long j, double wv) {
  struct shepard *s = arg;
  const struct parts *p = ctx->p;
  double *own = s->phase[p->phase[j]];
  if (!s->one_phase) add_values(s->all, p, j, wv, p->dim);
  add_values(own, p, j, wv, p->dim);
  for (int d = 0; s->with_rho_r && d < p->dim; d++) own[SHEPARD_RHO_R + d] += wv * p->rho[j] * p->x[d][j];
}

/* Empty Shepard sums, with the density-weighted moments if the ghosts need them. */
static void shepard_clear(const struct pass_ctx *ctx, struct shepard *s) {
  memset(s, 0, sizeof(*s));
  s->with_rho_r = ctx->c->interface_pressure == IFACE_P_DENSITY_WEIGHTED && ctx->c->n_phases > 1;
  s->one_phase = ctx->c->n_phases == 1;
}

/* The Shepard sums s (cleared) at ghost k's mirror point xs from its list: with one phase by the
 * specialised loop, else through visit_listed. */
static long shepard_listed(const struct pass_ctx *ctx, const double *xs, const uint64_t *point,
                           struct shepard *s) {
  if (!s->one_phase) return visit_listed(ctx, xs, point, add_shepard, s);
  if (ctx->p->dim == 3) return listed_one_phase_dim(ctx, xs, point, s->phase[0], 3);
  return listed_one_phase_dim(ctx, xs, point, s->phase[0], 2);
}

/* The Shepard sums s at mirror point xs of a moving wall's ghost, which has no list: over the fluid
 * of the cells around it, with this stage's volumes. */
static void shepard_at(const struct pass_ctx *ctx, const double *xs, struct shepard *s, long *pairs) {
  struct neighbour_ranges r;
  shepard_clear(ctx, s);
  fluid_ranges_at(ctx, xs, &r);
  *pairs += visit_ranges(ctx, xs, &r, ctx->w->vol, add_shepard, s);
}

static int majority_phase(const struct pass_ctx *ctx, const struct shepard *s) {
  int best = 0;
  for (int ph = 1; ph < ctx->c->n_phases; ph++)
    if (s->phase[ph][SHEPARD_W] > s->phase[best][SHEPARD_W]) best = ph;
  return best;
}

/* Velocity [m/s] and acceleration [m/s^2] of wall w at point x (zero for a fixed wall). */
static void wall_kinematics(const struct pass_ctx *ctx, int w, const double *x, double *u, double *a) {
  int dim = ctx->p->dim;
  for (int d = 0; d < 3; d++) u[d] = a[d] = 0;
  if (!ctx->c->walls[w].moving) return;
  frame_velocity(&ctx->prm->frames[w], dim, x, u);
  frame_acceleration(&ctx->prm->frames[w], dim, x, a);
}

/* Pressure [Pa] of ghost k from the Shepard sums src at its mirror point xs, with the hydrostatic
 * and inertial correction for the body acceleration g - a_w (aw the wall's acceleration): from the
 * mirror point with the mean density (mixed phases), or from each neighbour with its own density
 * (one phase: exact for a hydrostatic field whatever part of the support is filled). */
static double ghost_pressure(const struct pass_ctx *ctx, long k, const double *xs, const double *src,
                             const double *aw, int per_neighbour) {
  double pressure = src[SHEPARD_P] / src[SHEPARD_W], rho_star = src[SHEPARD_RHO] / src[SHEPARD_W];
  for (int d = 0; d < ctx->p->dim; d++) {
    double acc = ctx->c->gravity[d] - aw[d];
    pressure += per_neighbour ? acc * (ctx->p->x[d][k] * rho_star - src[SHEPARD_RHO_R + d] / src[SHEPARD_W])
                              : rho_star * acc * (ctx->p->x[d][k] - xs[d]);
  }
  return pressure;
}

/* Set ghost k from the Shepard sums at its mirror point xs: pressure with the hydrostatic and
 * inertial correction, velocity mirrored relative to the wall's. */
static void ghost_from_shepard(struct pass_ctx *ctx, long k, const double *xs, const struct shepard *s) {
  struct parts *p = ctx->p;
  int dim = p->dim, w = p->wall[k];
  double u[3] = {0, 0, 0}, n[3], nn = 0, un = 0, pressure = 0, mid[3] = {0, 0, 0}, uw[3], aw[3];
  for (int d = 0; d < dim; d++) mid[d] = 0.5 * (xs[d] + p->x[d][k]);
  wall_kinematics(ctx, w, mid, uw, aw);
  /* the sums the ghost takes its values from: with the density-weighted interface pressure its
   * majority phase's only (the ghost stands for that phase, theory section 4); with the paper's
   * pair sum every phase's (Marrone et al. 2011: a ghost beside a water particle in air carries
   * part of its pressure; with one phase the same sums) */
  int ph = majority_phase(ctx, s);
  const double *src = ctx->c->interface_pressure == IFACE_P_DENSITY_WEIGHTED || s->one_phase ? s->phase[ph] : s->all;
  if (src[SHEPARD_W] > 0) {
    for (int d = 0; d < dim; d++) u[d] = src[SHEPARD_U + d] / src[SHEPARD_W];
    pressure = ghost_pressure(ctx, k, xs, src, aw, s->with_rho_r);
  }
  for (int d = 0; d < dim; d++) {
    n[d] = xs[d] - p->x[d][k];
    nn += n[d] * n[d];
  }
  for (int d = 0; d < dim; d++) un += nn > 0 ? (u[d] - uw[d]) * n[d] / nn : 0.0;
  int no_slip = ctx->c->walls[w].slip == SLIP_NO;
  for (int d = 0; d < dim; d++) p->v[d][k] = no_slip ? 2.0 * uw[d] - u[d] : u[d] - 2.0 * un * n[d];
  p->p[k] = pressure;
  p->rho[k] = ctx->c->phases[ph].rho0;
  p->m[k] = p->rho[k] * ctx->prm->vol0;
}

void wall_mirror_point(const struct pass_ctx *ctx, long k, double *xs) {
  const struct parts *p = ctx->p;
  double off[3] = {0, 0, 0};
  for (int d = 0; d < p->dim; d++) off[d] = p->mirror[d][k];
  if (ctx->c->walls[p->wall[k]].moving)   /* the body-frame offset turned with the wall */
    frame_turn(&ctx->prm->frames[p->wall[k]], p->dim, off, off);
  for (int d = 0; d < 3; d++) xs[d] = d < p->dim ? p->x[d][k] + off[d] : 0.0;
}

/* 1 if ghost k has a list at its mirror point, built once per step: its wall is fixed (not moved
 * by a motion, nor a body), so the mirror point stays put within the step. */
static int listed_ghost(const struct pass_ctx *ctx, long k) {
  return part_has(ctx->p->phase[k], KIND_MIRRORED) && !ctx->c->walls[ctx->p->wall[k]].moving;
}

void pass_wall_ghost_lists(struct pass_ctx *ctx) {
  nlist_points_clear(ctx->nl, ctx->prm->list_radius);
  for (long k = 0; k < ctx->p->n_owned; k++) {
    if (!listed_ghost(ctx, k)) continue;
    double xs[3];
    struct neighbour_ranges r;
    wall_mirror_point(ctx, k, xs);
    fluid_ranges_at(ctx, xs, &r);
    nlist_point_add(ctx->nl, ctx->p, xs, &r);
  }
}

void pass_wall_ghosts(struct pass_ctx *ctx) {
  struct parts *p = ctx->p;
  long pairs = 0;
  const uint64_t *point = ctx->nl->point_bits;   /* the next list: they follow the listed ghosts' order */
  for (long k = 0; k < p->n_owned; k++) {
    if (!part_has(p->phase[k], KIND_MIRRORED)) continue;
    double xs[3];
    struct shepard s;
    wall_mirror_point(ctx, k, xs);
    if (listed_ghost(ctx, k)) {
      shepard_clear(ctx, &s);
      pairs += shepard_listed(ctx, xs, point, &s);
      point = nlist_point_next(point);
    } else {
      shepard_at(ctx, xs, &s, &pairs);
    }
    ghost_from_shepard(ctx, k, xs, &s);
  }
  ctx->out.pairs += pairs;
}
