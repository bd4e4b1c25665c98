/* solids.c — the elastic solids of a run (engine/solids.h): set-up from the case, their particles
 * among the fluid's, the coupling (the loads taken, the solids moved over a fluid sub-step of
 * riemann or a step of delta-plus), solids.csv. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "engine/solids.h"
#include "engine/engine.h"
#include "base/mem.h"
#include "physics/linalg.h"

/* The nodes min + (i + 1/2) dx of solid k's box, dim per node, into a new array; their number in *n. */
static double *box_nodes(const struct case_def *c, const struct solid_def *k, int *n) {
  const int dim = c->dimension;
  long count[3] = {1, 1, 1};
  for (int d = 0; d < dim; d++) count[d] = lround((k->max[d] - k->min[d]) / c->dx);   /* whole (case_load) */
  long total = count[0] * count[1] * count[2];
  double *x = mem_calloc((size_t)(total > 0 ? total : 1) * (size_t)dim, sizeof(double), "solid nodes");
  long m = 0;
  for (long iz = 0; iz < count[2]; iz++)
    for (long iy = 0; iy < count[1]; iy++)
      for (long ix = 0; ix < count[0]; ix++, m++) {
        long idx[3] = {ix, iy, iz};
        for (int d = 0; d < dim; d++) x[m * dim + d] = k->min[d] + ((double)idx[d] + 0.5) * c->dx;
      }
  *n = (int)total;
  return x;
}

/* 1 if x (dim values) lies in the box [lo, hi]. */
static int in_box(const double *x, const double *lo, const double *hi, int dim) {
  for (int d = 0; d < dim; d++)
    if (x[d] < lo[d] || x[d] > hi[d]) return 0;
  return 1;
}

/* The particle of s nearest to point q. */
static int nearest(const struct elastic_solid *s, const double *q) {
  int best = 0;
  double best_r2 = INFINITY;
  for (int a = 0; a < s->n; a++) {
    double r2 = 0;
    for (int d = 0; d < s->dim; d++) r2 += (s->x0[a * s->dim + d] - q[d]) * (s->x0[a * s->dim + d] - q[d]);
    if (r2 < best_r2) best_r2 = r2, best = a;
  }
  return best;
}

/* Set up solid k of the case into r. Returns 0, or 1 with a message (on stderr, rank 0 only). */
static int init_one(struct engine *e, int k, struct solid_run *r) {
  const struct case_def *c = e->c;
  const struct solid_def *def = &c->solids[k];
  int n;
  double *x0 = box_nodes(c, def, &n);
  if (n < 1) {
    if (e->rank == 0)
      fprintf(stderr, "mpsph: %s: solids.%d: its box holds no particle at resolution.dx %g\n", c->source_file, k, c->dx);
    free(x0);
    return 1;
  }
  struct elastic_material mat = {.model = def->model == SOLID_SVK ? ELASTIC_SVK : ELASTIC_NEO_HOOKEAN,
                                 .rho0 = def->rho0, .young = def->young, .poisson = def->poisson,
                                 .damping = def->damping,
                                 .correction = def->correction == SOLID_LINEAR ? ELASTIC_CORRECTION_LINEAR
                                                                               : ELASTIC_CORRECTION_QUADRATIC};
  int rc = elastic_solid_init(&r->s, c->dimension, n, x0, c->dx, c->kernel, e->prm.h, &mat);
  free(x0);
  if (rc) {
    if (e->rank == 0) fprintf(stderr, "mpsph: %s: solids.%d: the elastic solid cannot be set up (above)\n", c->source_file, k);
    return 1;
  }
  for (int a = 0; def->has_clamp && a < n; a++)
    r->s.clamped[a] = (unsigned char)in_box(r->s.x0 + (size_t)a * c->dimension, def->clamp_min, def->clamp_max,
                                            c->dimension);
  r->probe = nearest(&r->s, def->probe);
  const int dim = c->dimension;
  r->displacement = mem_calloc((size_t)n * dim, sizeof(double), "solid displacements");
  r->stress = mem_calloc((size_t)n * dim * dim, sizeof(double), "solid stresses");
  r->von_mises = mem_calloc((size_t)n, sizeof(double), "solid von Mises stresses");
  r->x_start = mem_calloc((size_t)n * dim, sizeof(double), "solid step positions");
  return 0;
}

/* Every solid's averaged velocity and acceleration and current normals into the view's arrays. */
static void publish(struct solids *S, int dim) {
  for (int k = 0; k < S->n; k++) {
    const struct solid_run *r = &S->run[k];
    const size_t at = (size_t)r->first * dim, bytes = (size_t)r->s.n * dim * sizeof(double);
    memcpy(S->v_avg + at, r->s.v_avg, bytes);
    memcpy(S->acc_avg + at, r->s.acc_avg, bytes);
    memcpy(S->normal + at, r->s.normal, bytes);
  }
}

int solids_init(struct engine *e) {
  struct solids *S = &e->solids;
  memset(S, 0, sizeof *S);
  long total = 0;
  for (int k = 0; k < e->c->n_solids; k++) {
    if (init_one(e, k, &S->run[k])) return 1;
    S->n = k + 1;
    S->run[k].first = total;
    total += S->run[k].s.n;
  }
  if (!S->n) return 0;
  const int dim = e->c->dimension;
  S->v_avg = mem_calloc((size_t)total * dim, sizeof(double), "solid velocities");
  S->acc_avg = mem_calloc((size_t)total * dim, sizeof(double), "solid accelerations");
  S->normal = mem_calloc((size_t)total * dim, sizeof(double), "solid normals");
  S->view = (struct solid_view){.id0 = -1, .n = total, .v = S->v_avg, .a = S->acc_avg, .normal = S->normal};
  publish(S, dim);
  load_gather_init(&S->gather, e->n_ranks);
  return 0;
}

/* Solid particle a of solid run r into its copy in slot i of p: position, velocity v~, density
 * rho0/J and pressure -tr(sigma)/dim. */
static void set_copy(const struct solid_run *r, int a, struct parts *p, long i) {
  const struct elastic_solid *s = &r->s;
  const int dim = s->dim;
  const double *F = s->F + (size_t)a * dim * dim;
  double P[9], tr = 0, J = linalg_det(dim, F);
  elastic_pk1(dim, s->mat.model, s->lambda, s->shear, F, P);
  for (int d = 0; d < dim; d++) {   /* tr(sigma) = tr(P F^T) / J */
    p->x[d][i] = s->x[(size_t)a * dim + d];
    p->v[d][i] = s->v_avg[(size_t)a * dim + d];
    for (int k = 0; k < dim; k++) tr += P[d * dim + k] * F[d * dim + k];
  }
  p->rho[i] = s->mat.rho0 / J;
  p->p[i] = -tr / (J * dim);
}

/* The first solid (index, or -1) whose box holds an owned fluid particle of e strictly inside;
 * that particle's position into x. */
static int fluid_inside(const struct engine *e, double *x) {
  const struct parts *p = &e->p;
  const double tol = 1e-9 * e->c->dx;
  for (int k = 0; k < e->c->n_solids; k++)
    for (long i = 0; i < p->n_owned; i++) {
      int inside = part_has(p->phase[i], KIND_INTEGRATED);
      for (int d = 0; d < p->dim && inside; d++)
        inside = p->x[d][i] > e->c->solids[k].min[d] + tol && p->x[d][i] < e->c->solids[k].max[d] - tol;
      if (!inside) continue;
      for (int d = 0; d < p->dim; d++) x[d] = p->x[d][i];
      return k;
    }
  return -1;
}

/* 1 (with a message on rank 0 naming the solid of highest index that has one) when a fluid particle
 * lies inside a solid's box on some rank. Collective. */
static int fluid_overlaps(const struct engine *e) {
  double x[3] = {0, 0, 0};
  int mine = fluid_inside(e, x), any;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, e->comm);
  if (any < 0) return 0;
  struct { int k, rank; } in = {mine, e->rank}, out;
  MPI_Allreduce(&in, &out, 1, MPI_2INT, MPI_MAXLOC, e->comm);
  MPI_Bcast(x, 3, MPI_DOUBLE, out.rank, e->comm);
  if (e->rank == 0)
    fprintf(stderr, "mpsph: %s: solids.%d: a fluid particle lies inside the solid's box, at (%g, %g, %g), expected "
            "fluid regions that leave the solid free\n", e->c->source_file, out.k, x[0], x[1], x[2]);
  return 1;
}

int solids_add_particles(struct engine *e) {
  struct solids *S = &e->solids;
  if (!S->n) return 0;
  if (fluid_overlaps(e)) return 1;
  double n_fluid, n_wall;
  engine_global_counts(e, &n_fluid, &n_wall);
  S->view.id0 = (int64_t)(n_fluid + n_wall);
  struct parts *p = &e->p;
  const long first_new = p->n_owned;
  int outside = 0;
  for (int k = 0; k < S->n; k++) {
    const struct solid_run *r = &S->run[k];
    for (int a = 0; a < r->s.n; a++) {
      int cell = grid_cell_of(&e->space.grid, r->s.x0 + (size_t)a * p->dim);
      if (cell < 0) outside = 1;
      if (cell < 0 || space_cell_owner(&e->space, cell) != e->rank) continue;
      long i = p->n_owned++;
      parts_reserve(p, p->n_owned);
      set_copy(r, a, p, i);
      p->m[i] = r->s.mass;
      p->phase[i] = PHASE_SOLID;
      p->id[i] = S->view.id0 + r->first + a;
      p->cell[i] = -1;
      if (p->wall) {
        p->wall[i] = -1;
        for (int d = 0; d < p->dim; d++) p->mirror[d][i] = 0.0;
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &outside, 1, MPI_INT, MPI_MAX, e->comm);
  if (outside) {
    if (e->rank == 0) fprintf(stderr, "mpsph: %s: solids: a solid particle lies outside the domain\n", e->c->source_file);
    return 1;
  }
  space_assign_cells(&e->space, p, first_new, p->n_owned - first_new);
  for (int k = 0; k < S->n && e->rank == 0; k++) {
    const struct elastic_solid *q = &S->run[k].s;
    int held = 0;
    for (int a = 0; a < q->n; a++) held += q->clamped[a];
    printf("solid %d: %d particles (%d clamped), %s, %s correction, sound speed %.4g m/s, time step %.3g s\n", k,
           q->n, held, elastic_model_name(q->mat.model), elastic_correction_name(q->mat.correction), q->c_s,
           elastic_time_step(q));
  }
  return 0;
}

void solids_take_loads(struct engine *e, double weight, int first) {
  struct solids *S = &e->solids;
  const int dim = e->c->dimension;
  long total = load_gather_all(&S->gather, &S->loads, e->comm), at = 0;
  const struct body_load *all = S->gather.all;
  for (int k = 0; k < S->n; k++) {
    struct solid_run *r = &S->run[k];
    if (first) {
      memset(r->force, 0, sizeof r->force);
      memset(r->s.acc_ext, 0, (size_t)r->s.n * dim * sizeof(double));
    }
    for (; at < total && all[at].wall < r->first + r->s.n; at++) {
      double *acc = r->s.acc_ext + (size_t)(all[at].wall - r->first) * dim;
      for (int d = 0; d < dim; d++) {
        acc[d] += weight * all[at].force[d] / r->s.mass;
        r->force[d] += weight * all[at].force[d];
      }
    }
  }
}

/* The copies of the solid particles among this rank's particles (owned and halo) from the solids. */
static void update_copies(struct engine *e) {
  struct solids *S = &e->solids;
  struct parts *p = &e->p;
  for (long i = 0; i < p->n_owned + p->n_halo; i++) {
    if (p->phase[i] != PHASE_SOLID) continue;
    long g = (long)(p->id[i] - S->view.id0);
    int k = 0;
    while (g >= S->run[k].first + S->run[k].s.n) k++;
    set_copy(&S->run[k], (int)(g - S->run[k].first), p, i);
  }
}

int solids_move(struct engine *e, double dt) {
  struct solids *S = &e->solids;
  const int dim = e->c->dimension;
  S->substeps = 0;
  for (int k = 0; k < S->n; k++) {
    struct solid_run *r = &S->run[k];
    int kappa = elastic_advance(&r->s, dt, e->c->gravity);
    if (kappa < 0) {
      if (e->rank == 0)
        fprintf(stderr, "mpsph: step %ld, t = %.9g s: solids.%d: its state is not finite or its time step "
                "vanished: unstable\n", e->step, e->time, k);
      return 2;
    }
    if (kappa > S->substeps) S->substeps = kappa;
    elastic_update_normals(&r->s);
  }
  publish(S, dim);
  update_copies(e);
  S->substeps_total += S->substeps;
  S->advances++;
  return 0;
}

int solids_advance(struct engine *e, double dt) {
  solids_take_loads(e, 1.0, 1);
  return solids_move(e, dt);
}

/* The Cauchy stress of particle a of s in 3D (its deformation gradient with F_zz = 1 in 2D: plane
 * strain) into sigma (3 x 3). */
static void cauchy_3d(const struct elastic_solid *s, int a, double *sigma) {
  const int dim = s->dim;
  double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, P[9];
  for (int r = 0; r < dim; r++)
    for (int c = 0; c < dim; c++) F[3 * r + c] = s->F[(size_t)a * dim * dim + r * dim + c];
  elastic_pk1(3, s->mat.model, s->lambda, s->shear, F, P);
  double J = linalg_det(3, F);
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      double sum = 0;
      for (int k = 0; k < 3; k++) sum += P[3 * r + k] * F[3 * c + k];
      sigma[3 * r + c] = sum / J;
    }
}

/* Solid run r's displacements, stresses and von Mises stresses from its current state. */
static void derived_state(struct solid_run *r) {
  const struct elastic_solid *s = &r->s;
  const int dim = s->dim;
  for (int a = 0; a < s->n; a++) {
    double sg[9];
    cauchy_3d(s, a, sg);
    for (int d = 0; d < dim; d++) r->displacement[a * dim + d] = s->x[a * dim + d] - s->x0[a * dim + d];
    for (int i = 0; i < dim; i++)
      for (int j = 0; j < dim; j++) r->stress[(size_t)a * dim * dim + i * dim + j] = sg[3 * i + j];
    double dev = (sg[0] - sg[4]) * (sg[0] - sg[4]) + (sg[4] - sg[8]) * (sg[4] - sg[8]) + (sg[8] - sg[0]) * (sg[8] - sg[0]);
    double shear = sg[1] * sg[1] + sg[2] * sg[2] + sg[5] * sg[5];
    r->von_mises[a] = sqrt(0.5 * dev + 3.0 * shear);
  }
}

int solids_snapshot_arrays(struct engine *e, struct hdf5_array *v) {
  static const char *const what[SOLID_SNAPSHOT_ARRAYS] = {"reference_position", "displacement", "stress", "von_mises"};
  int n = 0;
  for (int k = 0; k < e->solids.n; k++) {
    struct solid_run *r = &e->solids.run[k];
    const long vec = (long)r->s.n * r->s.dim;
    double *at[SOLID_SNAPSHOT_ARRAYS] = {r->s.x0, r->displacement, r->stress, r->von_mises};
    const long size[SOLID_SNAPSHOT_ARRAYS] = {vec, vec, vec * r->s.dim, r->s.n};
    derived_state(r);
    for (int j = 0; j < SOLID_SNAPSHOT_ARRAYS; j++) {
      snprintf(r->snapshot_names[j], sizeof r->snapshot_names[j], "solid%d_%s", k, what[j]);
      v[n++] = (struct hdf5_array){r->snapshot_names[j], at[j], size[j]};
    }
  }
  return n;
}

int solids_arrays(struct engine *e, struct hdf5_array *v) {
  static const char *const what[SOLID_ARRAYS] = {"x", "v", "acc", "F", "dF", "v_avg", "acc_avg", "dt_avg", "force"};
  int n = 0;
  for (int k = 0; k < e->solids.n; k++) {
    struct solid_run *r = &e->solids.run[k];
    struct elastic_solid *s = &r->s;
    const long vec = (long)s->n * s->dim, mat = vec * s->dim;
    double *at[SOLID_ARRAYS] = {s->x, s->v, s->acc, s->F, s->dF, s->v_avg, s->acc_avg, &s->dt_avg, r->force};
    const long size[SOLID_ARRAYS] = {vec, vec, vec, mat, mat, vec, vec, 1, 3};
    for (int j = 0; j < SOLID_ARRAYS; j++) {
      snprintf(r->names[j], sizeof r->names[j], "solid%d_%s", k, what[j]);
      v[n++] = (struct hdf5_array){r->names[j], at[j], size[j]};
    }
  }
  return n;
}

int solids_restarted(struct engine *e, const char *path) {
  struct solids *S = &e->solids;
  struct hdf5_array a[CASE_MAX_SOLIDS * SOLID_ARRAYS];
  for (int k = 0, n = solids_arrays(e, a); k < n; k++)
    for (long j = 0; j < a[k].n; j++)
      if (!isfinite(a[k].at[j])) {
        if (e->rank == 0)
          fprintf(stderr, "mpsph: cannot restart from %s: /run/%s[%ld] is %g, expected a finite number\n", path,
                  a[k].name, j, a[k].at[j]);
        return 1;
      }
  double n_fluid, n_wall;
  engine_global_counts(e, &n_fluid, &n_wall);
  S->view.id0 = (int64_t)(n_fluid + n_wall);
  long count[2] = {0, 0};   /* the solid particles read, those of them with an id out of range */
  for (long i = 0; i < e->p.n_owned; i++)
    if (e->p.phase[i] == PHASE_SOLID) {
      count[0]++;
      count[1] += e->p.id[i] < S->view.id0 || e->p.id[i] >= S->view.id0 + S->view.n;
    }
  MPI_Allreduce(MPI_IN_PLACE, count, 2, MPI_LONG, MPI_SUM, e->comm);
  if (count[0] != S->view.n || count[1]) {
    if (e->rank == 0)
      fprintf(stderr, "mpsph: cannot restart from %s: it holds %ld solid particles (%ld with an id outside %lld to "
              "%lld), expected the case's %ld\n", path, count[0], count[1], (long long)S->view.id0,
              (long long)(S->view.id0 + S->view.n - 1), S->view.n);
    return 1;
  }
  if (!S->n) return 0;
  for (int k = 0; k < S->n; k++) elastic_update_normals(&S->run[k].s);
  publish(S, e->c->dimension);
  return 0;
}

/* The largest Euclidean norm of the n vectors of dim values a - b (b NULL: of a). */
static double largest_norm(const double *a, const double *b, long n, int dim) {
  double q2 = 0;
  for (long i = 0; i < n; i++) {
    double q = 0;
    for (int d = 0; d < dim; d++) {
      double x = a[i * dim + d] - (b ? b[i * dim + d] : 0.0);
      q += x * x;
    }
    if (!(q <= q2)) q2 = q;   /* NaN propagates */
  }
  return sqrt(q2);
}

double solids_max_speed(const struct engine *e) {
  return largest_norm(e->solids.v_avg, NULL, e->solids.view.n, e->c->dimension);
}

void solids_step_start(struct engine *e) {
  for (int k = 0; k < e->solids.n; k++)
    memcpy(e->solids.run[k].x_start, e->solids.run[k].s.x, (size_t)e->solids.run[k].s.n * e->c->dimension * sizeof(double));
}

void solids_motion(const struct engine *e, double *m) {
  const int dim = e->c->dimension;
  for (int k = 0; k < e->solids.n; k++) {
    const struct solid_run *r = &e->solids.run[k];
    double q[3] = {largest_norm(r->s.v_avg, NULL, r->s.n, dim), largest_norm(r->s.acc_avg, NULL, r->s.n, dim),
                   largest_norm(r->s.x, r->x_start, r->s.n, dim)};
    for (int j = 0; j < 3; j++)
      if (!(q[j] <= m[j])) m[j] = q[j];
  }
}

void solids_csv_header(const struct engine *e, FILE *f) {
  const char *axis = "xyz";
  fputs("step,time", f);
  for (int k = 0; k < e->solids.n; k++) {
    for (int d = 0; d < e->c->dimension; d++) fprintf(f, ",solid%d_u%c", k, axis[d]);
    for (int d = 0; d < e->c->dimension; d++) fprintf(f, ",solid%d_f%c", k, axis[d]);
    fprintf(f, ",solid%d_energy", k);
  }
  fputc('\n', f);
}

void solids_csv_row(const struct engine *e, FILE *f) {
  const int dim = e->c->dimension;
  fprintf(f, "%ld,%.10g", e->step, e->time);
  for (int k = 0; k < e->solids.n; k++) {
    const struct solid_run *r = &e->solids.run[k];
    for (int d = 0; d < dim; d++)
      fprintf(f, ",%.12g", r->s.x[(size_t)r->probe * dim + d] - r->s.x0[(size_t)r->probe * dim + d]);
    for (int d = 0; d < dim; d++) fprintf(f, ",%.12g", r->force[d]);
    fprintf(f, ",%.12g", elastic_energy(&r->s));
  }
  fputc('\n', f);
}

void solids_free(struct solids *S) {
  for (int k = 0; k < S->n; k++) {
    elastic_solid_free(&S->run[k].s);
    free(S->run[k].displacement);
    free(S->run[k].stress);
    free(S->run[k].von_mises);
    free(S->run[k].x_start);
  }
  free(S->v_avg);
  free(S->acc_avg);
  free(S->normal);
  free(S->loads.at);
  if (S->n) load_gather_free(&S->gather);
  memset(S, 0, sizeof *S);
}
