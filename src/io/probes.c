/* probes.c — probes.csv: pressure sensors (Shepard or first-order MLS at a point, or averaged
 * over the sample points of a 2D segment), wave gauges (the 0.5 crossing of a phase's kernel
 * colour along a vertical line) and per-phase integrals. Interpolated values are computed on the
 * rank owning the sample point's cell and the others add zero, so they do not depend on the
 * number of ranks; the integrals are sums over ranks, equal to round-off. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "case/case_load.h"
#include "physics/passes.h"
#include "io/probes.h"
#include "base/mem.h"

#define SENSOR_SPACING 0.25   /* sample spacing on a sensor face / dx */
#define GAUGE_SPACING 0.125   /* sample spacing along a wave gauge's line / dx */
#define MLS_PIVOT 1e-8        /* smallest pivot / sum W V of an MLS solve, else Shepard */

void probe_sums_init(struct probe_sums *s, int dim) {
  memset(s, 0, sizeof(*s));
  s->dim = dim;
}

void probe_sums_add(struct probe_sums *s, const double *r, double wv, double f) {
  double basis[4] = {1, r[0], r[1], s->dim == 3 ? r[2] : 0};
  for (int a = 0; a <= s->dim; a++) {
    s->b[a] += wv * f * basis[a];
    for (int b = 0; b <= s->dim; b++) s->m[a][b] += wv * basis[a] * basis[b];
  }
}

double probe_sums_shepard(const struct probe_sums *s) {
  return s->m[0][0] > 0 ? s->b[0] / s->m[0][0] : 0.0;
}

double probe_sums_mls(const struct probe_sums *s) {
  int n = s->dim + 1;
  double m[4][4], b[4];
  memcpy(m, s->m, sizeof(m));
  memcpy(b, s->b, sizeof(b));
  for (int k = 0; k < n; k++) {   /* Gaussian elimination with partial pivoting */
    int piv = k;
    for (int i = k + 1; i < n; i++)
      if (fabs(m[i][k]) > fabs(m[piv][k])) piv = i;
    if (!(fabs(m[piv][k]) > MLS_PIVOT * s->m[0][0])) return probe_sums_shepard(s);
    for (int j = 0; j < n; j++) {
      double t = m[k][j];
      m[k][j] = m[piv][j], m[piv][j] = t;
    }
    double t = b[k];
    b[k] = b[piv], b[piv] = t;
    for (int i = k + 1; i < n; i++) {
      double f = m[i][k] / m[k][k];
      for (int j = k; j < n; j++) m[i][j] -= f * m[k][j];
      b[i] -= f * b[k];
    }
  }
  double x[4];
  for (int k = n - 1; k >= 0; k--) {
    x[k] = b[k];
    for (int j = k + 1; j < n; j++) x[k] -= m[k][j] * x[j];
    x[k] /= m[k][k];
  }
  return x[0];
}

void probes_write_header(FILE *f, const struct case_def *c) {
  char col[2 * CASE_MAX_NAME];
  fprintf(f, "step,time");
  for (int k = 0; k < c->n_probes; k++)
    for (int i = 0; i < case_probe_column(c, k, 0, NULL, 0); i++) {
      case_probe_column(c, k, i, col, sizeof col);
      fprintf(f, ",%s", col);
    }
  fprintf(f, "\n");
}

/* ---- sample points ---- */

/* The vertical of the gauges: the axis of the largest gravity component, and +1 or -1 for up. */
static int vertical_axis(const struct case_def *c, double *up) {
  int a = 0;
  for (int d = 1; d < c->dimension; d++)
    if (fabs(c->gravity[d]) > fabs(c->gravity[a])) a = d;
  *up = c->gravity[a] > 0 ? -1.0 : 1.0;
  return a;
}

/* The number of sample points of probe k (its slots in the reduced buffer). */
static int n_samples(const struct engine *e, const struct probe *p) {
  const struct case_def *c = e->c;
  double up;
  if (p->kind == PROBE_INTEGRAL) return 4 + c->dimension;   /* V, K, P, M, M x */
  if (p->kind == PROBE_PRESSURE)
    return p->diameter > 0 ? (int)ceil(p->diameter / (SENSOR_SPACING * c->dx)) : 1;
  int a = vertical_axis(c, &up);
  return 1 + (int)ceil((c->domain_max[a] - c->domain_min[a]) / (GAUGE_SPACING * c->dx));
}

/* Sample point i of n of a pressure sensor or wave gauge [m]; a gauge's points run upwards
 * from the domain's bottom at the spacing *step [m]. */
static void sample_point(const struct engine *e, const struct probe *p, int i, int n, double *x,
                         double *step) {
  const struct case_def *c = e->c;
  double up, len = 0;
  memcpy(x, p->position, sizeof(p->position));
  if (p->kind == PROBE_ELEVATION) {
    int a = vertical_axis(c, &up);
    *step = (c->domain_max[a] - c->domain_min[a]) / (n - 1);
    x[a] = (up > 0 ? c->domain_min[a] : c->domain_max[a]) + up * i * *step;
    return;
  }
  double axis[3] = {p->axis[0], p->axis[1], p->axis[2]};
  if (p->wall >= 0) {   /* carried by a moving wall: where its frame at the last step's end puts it */
    frame_position(&e->prm.frames[p->wall], c->dimension, p->position, x);
    frame_turn(&e->prm.frames[p->wall], c->dimension, axis, axis);
  }
  if (p->diameter == 0) return;
  for (int d = 0; d < c->dimension; d++) len += axis[d] * axis[d];
  double s = ((i + 0.5) / n - 0.5) * p->diameter / sqrt(len);   /* midpoint rule */
  for (int d = 0; d < c->dimension; d++) x[d] += s * axis[d];
}

/* ---- interpolation at one point ---- */

struct probe_sample {
  const double *x;
  struct probe_sums sums;
  int phase;          /* the gauge's phase */
  double colour;      /* sum W V over that phase */
};

/* The acoustic damper's stress -rho0 alpha2 c0 h D_j of slot j [Pa]: 0 without the damper, for
 * gases and for wall ghosts (the pair sums of the damper give them none). */
static double damper_stress(const struct pass_ctx *ctx, long j) {
  if (part_has(ctx->p->phase[j], KIND_BOUNDARY)) return 0.0;
  double zeta = damper_viscosity(ctx, ctx->p->phase[j]);
  return zeta > 0 ? -zeta * damper_divergence(ctx->w)[j] : 0.0;
}

/* Add slot j to the pressure moments around q->x (offsets in units of h). */
static void add_pressure(void *arg, const struct pass_ctx *ctx, long j, double wv) {
  struct probe_sample *q = arg;
  double r[3] = {0, 0, 0};
  if (ctx->p->phase[j] == PHASE_SOLID) return;   /* its p is the solid's mean stress, not the fluid's */
  for (int d = 0; d < ctx->p->dim; d++) r[d] = (ctx->p->x[d][j] - q->x[d]) / ctx->prm->h;
  probe_sums_add(&q->sums, r, wv, ctx->p->p[j] + damper_stress(ctx, j));
}

/* Add slot j to the colour of the gauge's phase. */
static void add_colour(void *arg, const struct pass_ctx *ctx, long j, double wv) {
  struct probe_sample *q = arg;
  if (ctx->p->phase[j] == q->phase) q->colour += wv;
}

/* The pressure [Pa] of probe p at x over the fluid and the wall ghosts (which carry the pressure
 * extrapolated across the wall, so that a sensor on the wall reads the wall pressure; not over an
 * elastic solid's particles, whose p is the solid's mean stress); with the
 * acoustic damper, of p + its stress, the pressure the pair forces act with (doc/theory.md). */
static double pressure_at(const struct pass_ctx *ctx, const struct probe *p, const double *x) {
  struct probe_sample q = {.x = x};
  probe_sums_init(&q.sums, ctx->p->dim);
  visit_near(ctx, x, 1, add_pressure, &q);
  return p->interpolation == INTERP_MLS ? probe_sums_mls(&q.sums) : probe_sums_shepard(&q.sums);
}

/* The colour sum W V of the probe's phase at x [-]: 1 inside the phase, 1/2 on its surface. */
static double colour_at(const struct pass_ctx *ctx, const struct probe *p, const double *x) {
  struct probe_sample q = {.x = x, .phase = p->phase};
  visit_near(ctx, x, 0, add_colour, &q);
  return q.colour;
}

/* Slots out[0..n-1] of a pressure sensor or gauge: the values at the sample points this rank
 * owns (the others stay zero). */
static void sample_probe(const struct engine *e, const struct pass_ctx *ctx, const struct probe *p, int n,
                         double *out) {
  double x[3], step;
  for (int i = 0; i < n; i++) {
    sample_point(e, p, i, n, x, &step);
    if (space_cell_owner(&e->space, grid_cell_clamped(&e->space.grid, x)) != e->rank) continue;
    out[i] = p->kind == PROBE_PRESSURE ? pressure_at(ctx, p, x) : colour_at(ctx, p, x);
  }
}

/* This rank's sums of an integral probe: volume, kinetic energy, potential energy -m g.x, mass
 * and mass times position. */
static void integrate_probe(const struct engine *e, const struct probe *p, double *out) {
  const struct parts *part = &e->p;
  int dim = part->dim;
  for (long i = 0; i < part->n_owned; i++) {
    if (part->phase[i] != p->phase) continue;
    double m = part->m[i], v2 = 0, gx = 0;
    for (int d = 0; d < dim; d++) {
      v2 += part->v[d][i] * part->v[d][i];
      gx += e->c->gravity[d] * part->x[d][i];
      out[4 + d] += m * part->x[d][i];
    }
    out[0] += m / part->rho[i];
    out[1] += 0.5 * m * v2;
    out[2] -= m * gx;
    out[3] += m;
  }
}

/* ---- the row ---- */

/* The elevation [m] along a gauge's line from its n colour samples: the highest point where the
 * colour falls through 1/2 going up, linear between samples; nan if there is none. */
static double gauge_elevation(const struct engine *e, const struct probe *p, int n, const double *c) {
  double x0[3], x1[3], step;
  for (int i = n - 2; i >= 0; i--) {
    if (!(c[i] >= 0.5 && c[i + 1] < 0.5)) continue;
    double up;
    int a = vertical_axis(e->c, &up);
    sample_point(e, p, i, n, x0, &step);
    sample_point(e, p, i + 1, n, x1, &step);
    return x0[a] + (c[i] - 0.5) / (c[i] - c[i + 1]) * (x1[a] - x0[a]);
  }
  return NAN;
}

/* Print the columns of probe p from its n reduced slots v. */
static void print_probe(FILE *f, const struct engine *e, const struct probe *p, int n, const double *v) {
  double sum = 0;
  if (p->kind == PROBE_ELEVATION) {
    fprintf(f, ",%.10g", gauge_elevation(e, p, n, v));
  } else if (p->kind == PROBE_PRESSURE) {
    for (int i = 0; i < n; i++) sum += v[i];
    fprintf(f, ",%.8g", sum / n);
  } else {
    fprintf(f, ",%.15g,%.15g,%.15g", v[0], v[1], v[2]);
    for (int d = 0; d < e->c->dimension; d++) fprintf(f, ",%.15g", v[3] > 0 ? v[4 + d] / v[3] : NAN);
  }
}

/* Whether the case has a pressure sensor (the only probe that reads the damper's stress). */
static int reads_pressure(const struct case_def *c) {
  for (int k = 0; k < c->n_probes; k++)
    if (c->probes[k].kind == PROBE_PRESSURE) return 1;
  return 0;
}

void probes_write_row(struct engine *e, FILE *f) {
  const struct case_def *c = e->c;
  int total = 0, n[CASE_MAX_PROBES];
  for (int k = 0; k < c->n_probes; k++) total += n[k] = n_samples(e, &c->probes[k]);
  if (total > e->probe_buf_len) {   /* the sample count is fixed by the case: sized once */
    free(e->probe_buf);
    e->probe_buf = mem_calloc(total, sizeof(double), "probe samples");
    e->probe_buf_len = total;
  }
  double *buf = e->probe_buf;
  if (reads_pressure(c)) engine_damper_divergence_now(e);   /* the sensors read the damper's stress */
  const struct pass_ctx ctx = engine_pass_ctx(e);   /* the interpolation's view of the particles */
  memset(buf, 0, (size_t)total * sizeof(double));
  for (int k = 0, at = 0; k < c->n_probes; at += n[k++]) {
    if (c->probes[k].kind == PROBE_INTEGRAL) integrate_probe(e, &c->probes[k], buf + at);
    else sample_probe(e, &ctx, &c->probes[k], n[k], buf + at);
  }
  MPI_Reduce(e->rank ? buf : MPI_IN_PLACE, buf, total, MPI_DOUBLE, MPI_SUM, 0, e->comm);
  if (e->rank == 0) {
    fprintf(f, "%ld,%.10g", e->step, e->time);
    for (int k = 0, at = 0; k < c->n_probes; at += n[k++]) print_probe(f, e, &c->probes[k], n[k], buf + at);
    fprintf(f, "\n");
  }
}
