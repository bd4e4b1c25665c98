/* elastic_solid.c — the total-Lagrangian elastic solid of paper 002 (include/physics/elastic_solid.h;
 * doc/theory.md §13 gives the equations as implemented). */
#include "physics/elastic_solid.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/mem.h"
#include "parallel/grid.h"
#include "physics/linalg.h"

/* The strain-energy models' names, in enum order. */
static const char *const model_names[ELASTIC_MODEL_COUNT] = {"saint-venant-kirchhoff", "neo-hookean"};

const char *elastic_model_name(enum elastic_model model) { return model_names[model]; }

/* The corrections' names, in enum order. */
static const char *const correction_names[ELASTIC_CORRECTION_COUNT] = {"linear", "quadratic"};

const char *elastic_correction_name(enum elastic_correction correction) { return correction_names[correction]; }

/* The right Cauchy–Green tensor C = F^T F. */
static void right_cauchy_green(int dim, const double *F, double *C) { linalg_matmul(dim, F, 1, F, C); }

/* Second Piola–Kirchhoff stress S of F. */
static void pk2(int dim, enum elastic_model model, double lambda, double shear, const double *F, double *S) {
  double C[9], C_inv[9];
  right_cauchy_green(dim, F, C);
  if (model == ELASTIC_SVK) {   /* E = (C - I)/2 */
    double trace_E = 0;
    for (int d = 0; d < dim; d++) trace_E += 0.5 * (C[d * dim + d] - 1.0);
    for (int r = 0; r < dim; r++)
      for (int c = 0; c < dim; c++)
        S[r * dim + c] = shear * (C[r * dim + c] - (r == c)) + (r == c ? lambda * trace_E : 0.0);
    return;
  }
  double lambda_ln_J = lambda * log(linalg_det(dim, F));
  linalg_inverse(dim, C, C_inv);
  for (int r = 0; r < dim * dim; r++) S[r] = shear * ((r % (dim + 1) == 0) - C_inv[r]) + lambda_ln_J * C_inv[r];
}

void elastic_pk1(int dim, enum elastic_model model, double lambda, double shear, const double *F, double *P) {
  double S[9];
  pk2(dim, model, lambda, shear, F, S);
  linalg_matmul(dim, F, 0, S, P);
}

double elastic_energy_density(int dim, enum elastic_model model, double lambda, double shear, const double *F) {
  double C[9];
  right_cauchy_green(dim, F, C);
  if (model == ELASTIC_SVK) {   /* lambda/2 tr(E)^2 + G E:E */
    double trace_E = 0, e_e = 0;
    for (int r = 0; r < dim; r++)
      for (int c = 0; c < dim; c++) {
        double e = 0.5 * (C[r * dim + c] - (r == c));
        e_e += e * e;
        if (r == c) trace_E += e;
      }
    return 0.5 * lambda * trace_E * trace_E + shear * e_e;
  }
  double trace_C = 0, ln_J = log(linalg_det(dim, F));   /* G/2 (tr C - d) - G ln J + lambda/2 ln^2 J */
  for (int d = 0; d < dim; d++) trace_C += C[d * dim + d];
  return 0.5 * shear * (trace_C - dim) - shear * ln_J + 0.5 * lambda * ln_J * ln_J;
}

/* The reference positions binned on a grid of cells no smaller than the support
 * (parallel/grid.h), in index order within a cell (a counting sort): cell_of[a], the cells'
 * starts first[c..c+1) into sorted. */
struct reference_grid {
  struct grid g;
  int *cell_of, *sorted;
  size_t *first;
};

/* Bin s's reference positions into grid; -1 (with a message) when the grid is too large to index. */
static int grid_build(const struct elastic_solid *s, struct reference_grid *grid) {
  const int dim = s->dim, n = s->n;
  double lo[3], hi[3];
  for (int d = 0; d < dim; d++) {
    lo[d] = INFINITY, hi[d] = -INFINITY;
    for (int a = 0; a < n; a++) lo[d] = fmin(lo[d], s->x0[a * dim + d]), hi[d] = fmax(hi[d], s->x0[a * dim + d]);
  }
  if (grid_init(&grid->g, dim, lo, hi, s->k.support) != 0) {
    fprintf(stderr, "mpsph: elastic solid of %d particles: its extent holds too many cells of %g m\n", n,
            s->k.support);
    return -1;
  }
  size_t n_cells = (size_t)grid->g.n_cells;
  grid->cell_of = mem_alloc(mem_bytes(n, sizeof *grid->cell_of, "elastic cell index"), "elastic cell index");
  grid->first = mem_calloc(n_cells + 1, sizeof *grid->first, "elastic cell starts");
  grid->sorted = mem_alloc(mem_bytes(n, sizeof *grid->sorted, "elastic sorted particles"), "elastic sorted particles");
  for (int a = 0; a < n; a++) {
    grid->cell_of[a] = grid_cell_of(&grid->g, s->x0 + (size_t)a * dim);
    grid->first[grid->cell_of[a] + 1]++;
  }
  for (size_t c = 0; c < n_cells; c++) grid->first[c + 1] += grid->first[c];
  size_t *fill = mem_alloc(mem_bytes(n_cells, sizeof *fill, "elastic cell fill"), "elastic cell fill");
  memcpy(fill, grid->first, n_cells * sizeof *fill);
  for (int a = 0; a < n; a++) grid->sorted[fill[grid->cell_of[a]]++] = a;
  free(fill);
  return 0;
}

/* Append to s->nb particle a's neighbours among the particles of the cells around its own
 * (grid_stencil: those within the support, a excluded), in cell order and index order within a
 * cell. */
static void append_neighbours(struct elastic_solid *s, const struct reference_grid *grid, int a, size_t *count,
                              size_t *capacity) {
  const int dim = s->dim;
  long cells[27];
  int n_cells = grid_stencil(&grid->g, grid->cell_of[a], 1, cells);
  for (int k = 0; k < n_cells; k++)
    for (size_t i = grid->first[cells[k]]; i < grid->first[cells[k] + 1]; i++) {
      int b = grid->sorted[i];
      double r2 = 0;
      for (int d = 0; d < dim; d++) {
        double diff = s->x0[a * dim + d] - s->x0[b * dim + d];
        r2 += diff * diff;
      }
      if (b == a || r2 >= s->k.support2) continue;
      if (*count == *capacity) {
        *capacity *= 2;
        s->nb = mem_realloc(s->nb, mem_bytes(*capacity, sizeof *s->nb, "elastic neighbours"), "elastic neighbours");
      }
      s->nb[(*count)++] = b;
    }
}

/* The reference neighbour list (nb_first, nb); -1 when its grid is too large or it has more pairs
 * than an int counts. */
static int build_reference_list(struct elastic_solid *s) {
  struct reference_grid grid;
  if (grid_build(s, &grid) != 0) return -1;
  size_t capacity = (size_t)s->n * 16, count = 0;
  s->nb_first = mem_alloc(mem_bytes((size_t)s->n + 1, sizeof *s->nb_first, "elastic neighbour starts"),
                          "elastic neighbour starts");
  s->nb = mem_alloc(mem_bytes(capacity, sizeof *s->nb, "elastic neighbours"), "elastic neighbours");
  for (int a = 0; a < s->n && count <= INT_MAX; a++) {
    s->nb_first[a] = (int)count;
    append_neighbours(s, &grid, a, &count, &capacity);
  }
  free(grid.cell_of), free(grid.first), free(grid.sorted);
  if (count > INT_MAX) {
    fprintf(stderr, "mpsph: elastic solid of %d particles: more than %d reference pairs\n", s->n, INT_MAX);
    return -1;
  }
  s->nb_first[s->n] = (int)count;
  return 0;
}

/* The quadratic correction's basis in units of h: the linear monomials of d = (x0_b - x0_a)/h,
 * then the quadratic ones. Returns their number. */
static int quadratic_basis(int dim, const double *d, double *p) {
  int count = 0;
  for (int i = 0; i < dim; i++) p[count++] = d[i];
  for (int i = 0; i < dim; i++)
    for (int j = i; j < dim; j++) p[count++] = d[i] * d[j];
  return count;
}

/* Solve the symmetric positive system M y = rhs of size m (Gaussian elimination with partial
 * pivoting on copies); returns the smallest pivot relative to M's largest diagonal entry. */
static double solve_small(int m, const double *M, const double *rhs, double *y) {
  double a[9 * 9], b[9], largest = 0, smallest = INFINITY;
  memcpy(a, M, sizeof(double) * m * m), memcpy(b, rhs, sizeof(double) * m);
  for (int i = 0; i < m; i++) largest = fmax(largest, fabs(a[i * m + i]));
  for (int col = 0; col < m; col++) {
    int pivot = col;
    for (int r = col + 1; r < m; r++)
      if (fabs(a[r * m + col]) > fabs(a[pivot * m + col])) pivot = r;
    for (int c = 0; c < m; c++) {
      double t = a[col * m + c];
      a[col * m + c] = a[pivot * m + c], a[pivot * m + c] = t;
    }
    double t = b[col];
    b[col] = b[pivot], b[pivot] = t;
    smallest = fmin(smallest, fabs(a[col * m + col]));
    for (int r = col + 1; r < m; r++) {
      double factor = a[r * m + col] / a[col * m + col];
      for (int c = col; c < m; c++) a[r * m + c] -= factor * a[col * m + c];
      b[r] -= factor * b[col];
    }
  }
  for (int r = m - 1; r >= 0; r--) {
    double sum = b[r];
    for (int c = r + 1; c < m; c++) sum -= a[r * m + c] * y[c];
    y[r] = sum / a[r * m + r];
  }
  return largest > 0 ? smallest / largest : 0;
}

/* Particle a's weights by kernel-weighted least squares on the quadratic basis:
 * M = sum_b V_b W_ab p_b p_b^T, c = M^-1 sum_b V_b W_ab p_b (q_b - q_a) the Taylor coefficients of
 * a field q; g_ab the weights of its gradient and nb_hess those of its second derivatives.
 * Returns M's relative smallest pivot. */
static double quadratic_weights(struct elastic_solid *s, int a) {
  const int dim = s->dim;
  double M[81] = {0}, p[9], d[3], rows[9][9], unit[9], pivot = 1;
  int m = 0;
  for (int pass = 0; pass < 2; pass++) {   /* 0: M and its inverse; 1: the weights */
    if (pass == 1) {
      for (int i = 0; i < m; i++) {   /* the rows of M^-1 (M is symmetric) */
        for (int j = 0; j < m; j++) unit[j] = i == j;
        pivot = fmin(pivot, solve_small(m, M, unit, rows[i]));
      }
      if (!(pivot > 1e-9)) return pivot;
    }
    for (int q = s->nb_first[a]; q < s->nb_first[a + 1]; q++) {
      int b = s->nb[q];
      double r2 = 0;
      for (int i = 0; i < dim; i++)
        d[i] = (s->x0[b * dim + i] - s->x0[a * dim + i]) / s->k.h, r2 += d[i] * d[i] * s->k.h * s->k.h;
      m = quadratic_basis(dim, d, p);
      double w = s->vol0 * kernel_w(&s->k, r2);
      if (pass == 0) {
        for (int i = 0; i < m; i++)
          for (int j = 0; j < m; j++) M[i * m + j] += w * p[i] * p[j];
        continue;
      }
      double coeff[9];
      for (int i = 0; i < m; i++) {
        coeff[i] = 0;
        for (int j = 0; j < m; j++) coeff[i] += rows[i][j] * p[j];
        coeff[i] *= w;
      }
      for (int i = 0; i < dim; i++) s->nb_g[(size_t)q * dim + i] = coeff[i] / s->k.h;
      double *hess = s->nb_hess + (size_t)q * dim * dim;
      for (int i = 0, c = dim; i < dim; i++)   /* d^2 q / dx_i dx_j = (i == j ? 2 : 1) c_ij / h^2 */
        for (int j = i; j < dim; j++, c++)
          hess[i * dim + j] = hess[j * dim + i] = (i == j ? 2.0 : 1.0) * coeff[c] / (s->k.h * s->k.h);
    }
  }
  return pivot;
}

/* Particle a's gradient weights with paper 002's correction: B0_a = (sum_b V_b (x0_b - x0_a) (x)
 * grad0_a W_ab)^-1, g_ab = V_b B0_a grad0_a W_ab. Returns |det B0^-1|. */
static double linear_weights(struct elastic_solid *s, int a) {
  const int dim = s->dim;
  double sum[9] = {0}, B0[9];
  for (int q = s->nb_first[a]; q < s->nb_first[a + 1]; q++) {
    int b = s->nb[q];
    for (int r = 0; r < dim; r++)
      for (int c = 0; c < dim; c++)
        sum[r * dim + c] += s->vol0 * (s->x0[b * dim + r] - s->x0[a * dim + r]) * s->nb_grad0[(size_t)q * dim + c];
  }
  double det = linalg_inverse(dim, sum, B0);
  for (int q = s->nb_first[a]; q < s->nb_first[a + 1]; q++)
    for (int r = 0; r < dim; r++) {
      double g = 0;
      for (int c = 0; c < dim; c++) g += B0[r * dim + c] * s->nb_grad0[(size_t)q * dim + c];
      s->nb_g[(size_t)q * dim + r] = s->vol0 * g;
    }
  return fabs(det);
}

/* Each reference pair's kernel gradient, W ratio, squared distance and reverse pair (the relation
 * is symmetric: the separation's square is the same bitwise both ways). */
static void reference_pair_terms(struct elastic_solid *s) {
  const int dim = s->dim;
  size_t pairs = (size_t)s->nb_first[s->n];
  s->nb_grad0 = mem_alloc(mem_bytes(pairs * dim, sizeof(double), "elastic kernel gradients"), "elastic kernel gradients");
  s->nb_w_ratio = mem_alloc(mem_bytes(pairs, sizeof(double), "elastic kernel ratios"), "elastic kernel ratios");
  s->nb_r0_sq = mem_alloc(mem_bytes(pairs, sizeof(double), "elastic pair distances"), "elastic pair distances");
  s->nb_reverse = mem_alloc(mem_bytes(pairs, sizeof(int), "elastic reverse pairs"), "elastic reverse pairs");
  for (int a = 0; a < s->n; a++)
    for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++) {
      int b = s->nb[p];
      double r2 = 0, diff[3];
      for (int d = 0; d < dim; d++) diff[d] = s->x0[a * dim + d] - s->x0[b * dim + d], r2 += diff[d] * diff[d];
      double f = kernel_f(&s->k, r2);
      for (int d = 0; d < dim; d++) s->nb_grad0[(size_t)p * dim + d] = f * diff[d];
      s->nb_w_ratio[p] = kernel_w(&s->k, r2) / s->w_zero;
      s->nb_r0_sq[p] = r2;
      int q = s->nb_first[b];
      while (s->nb[q] != a) q++;
      s->nb_reverse[p] = q;
    }
}

/* The largest sum_b |g_ab| over the particles. */
static double largest_weight_sum(const struct elastic_solid *s) {
  double largest = 0;
  for (int a = 0; a < s->n; a++) {
    double sum = 0;
    for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++) {
      double g2 = 0;
      for (int d = 0; d < s->dim; d++) g2 += s->nb_g[(size_t)p * s->dim + d] * s->nb_g[(size_t)p * s->dim + d];
      sum += sqrt(g2);
    }
    largest = fmax(largest, sum);
  }
  return largest;
}

/* The gradient weights of `correction` for every particle; -1 (the particle named on stderr) when
 * a particle's neighbours do not determine them (relative pivot of M_a or |det B0_a^-1| at most
 * 1e-9). */
static int gradient_weights(struct elastic_solid *s, enum elastic_correction correction) {
  const int dim = s->dim;
  for (int a = 0; a < s->n; a++) {
    double quality = correction == ELASTIC_CORRECTION_LINEAR ? linear_weights(s, a) : quadratic_weights(s, a);
    if (!(quality > 1e-9)) {
      fprintf(stderr, "mpsph: elastic solid particle %d at (%g, %g%s): its %d reference neighbours do not "
                      "determine the %s correction (%g)\n",
              a, s->x0[a * dim], s->x0[a * dim + 1], dim == 3 ? ", ..." : "", s->nb_first[a + 1] - s->nb_first[a],
              elastic_correction_name(correction), quality);
      return -1;
    }
  }
  return 0;
}

/* The pair terms, the weights of the solid's correction and the step length: h, shortened for the
 * quadratic correction by the ratio of the largest sum_b |g_ab| of the linear correction to its
 * own (its weights are two to three times larger at the edges, and so is the stiffest particle's
 * frequency). -1 as gradient_weights. */
static int reference_terms(struct elastic_solid *s) {
  const int dim = s->dim;
  size_t pairs = (size_t)s->nb_first[s->n];
  reference_pair_terms(s);
  s->nb_g = mem_alloc(mem_bytes(pairs * dim, sizeof(double), "elastic gradient weights"), "elastic gradient weights");
  if (gradient_weights(s, ELASTIC_CORRECTION_LINEAR) != 0) return -1;
  s->step_length = s->k.h;
  if (s->mat.correction == ELASTIC_CORRECTION_LINEAR) return 0;
  double largest_linear = largest_weight_sum(s);
  s->nb_hess = mem_alloc(mem_bytes(pairs * dim * dim, sizeof(double), "elastic Hessian weights"),
                         "elastic Hessian weights");
  s->R = mem_alloc(mem_bytes((size_t)s->n * dim * dim * dim, sizeof(double), "elastic gradient stresses"),
                   "elastic gradient stresses");
  if (gradient_weights(s, ELASTIC_CORRECTION_QUADRATIC) != 0) return -1;
  s->step_length = s->k.h * largest_linear / largest_weight_sum(s);
  return 0;
}

/* sum = sum_b (q_b - q_a) (x) g_ab over a's reference neighbours, for a vector field q (dim per
 * particle). */
static inline __attribute__((always_inline)) void gradient_sum(const struct elastic_solid *s, int a, const double *q,
                                                                double *sum, const int dim) {
  for (int r = 0; r < dim * dim; r++) sum[r] = 0;
  for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++) {
    const double *g = s->nb_g + (size_t)p * dim;
    int b = s->nb[p];
    for (int r = 0; r < dim; r++) {
      double dq = q[b * dim + r] - q[a * dim + r];
      for (int c = 0; c < dim; c++) sum[r * dim + c] += dq * g[c];
    }
  }
}

/* v scaled to unit length in place, or 0 when |v| <= tiny. */
static void normalise(int dim, double *v, double tiny) {
  double norm = 0;
  for (int d = 0; d < dim; d++) norm += v[d] * v[d];
  norm = sqrt(norm);
  for (int d = 0; d < dim; d++) v[d] = norm > tiny ? v[d] / norm : 0.0;
}

/* normal0 = -sum_b V0 grad0_a W_ab normalised (zero inside, where the sum cancels to round-off),
 * and normal = normal0. */
static void reference_normals(struct elastic_solid *s) {
  const int dim = s->dim;
  for (int a = 0; a < s->n; a++) {
    double *n0 = s->normal0 + (size_t)a * dim;
    for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++)
      for (int d = 0; d < dim; d++) n0[d] -= s->vol0 * s->nb_grad0[(size_t)p * dim + d];
    normalise(dim, n0, 1e-9 / s->k.h);
  }
  memcpy(s->normal, s->normal0, sizeof(double) * s->n * dim);
}

/* 1 if the n * dim values of x are finite. */
static int all_finite(const double *x, size_t count) {
  for (size_t i = 0; i < count; i++)
    if (!isfinite(x[i])) return 0;
  return 1;
}

/* A message on stderr and 0 for parameters elastic_solid_init cannot take. */
static int valid_parameters(int dim, int n, const double *x0, double dx, enum kernel_kind kind, double h,
                            const struct elastic_material *mat) {
  const char *problem =
      dim != 2 && dim != 3                                    ? "the dimension is not 2 or 3"
      : n < 1                                                 ? "it has no particles"
      : !all_finite(x0, (size_t)n * dim)                      ? "a position is not finite"
      : !(dx > 0) || !(h > 0)                                 ? "its spacing or smoothing length is not positive"
      : kind != KERNEL_GAUSSIAN && kind != KERNEL_WENDLAND_C2 ? "its kernel is unknown"
      : !(mat->rho0 > 0) || !(mat->young > 0)                 ? "its density or Young's modulus is not positive"
      : !(mat->poisson > -1 && mat->poisson < 0.5)            ? "its Poisson's ratio is not in (-1, 1/2)"
      : !(mat->damping >= 0)                                  ? "its damping is negative"
      : (unsigned)mat->model >= ELASTIC_MODEL_COUNT           ? "its strain-energy model is unknown"
      : (unsigned)mat->correction >= ELASTIC_CORRECTION_COUNT ? "its correction is unknown"
                                                              : NULL;
  if (problem) fprintf(stderr, "mpsph: elastic solid: %s\n", problem);
  return problem == NULL;
}

int elastic_solid_init(struct elastic_solid *s, int dim, int n, const double *x0, double dx,
                       enum kernel_kind kind, double h, const struct elastic_material *mat) {
  memset(s, 0, sizeof *s);
  if (!valid_parameters(dim, n, x0, dx, kind, h, mat)) return -1;
  s->dim = dim, s->n = n, s->mat = *mat, s->dx = dx;
  double E = mat->young, nu = mat->poisson;
  s->shear = E / (2 * (1 + nu));
  s->lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  s->c_s = sqrt(E / (3 * (1 - 2 * nu)) / mat->rho0);
  s->vol0 = dim == 2 ? dx * dx : dx * dx * dx;
  s->mass = mat->rho0 * s->vol0;
  kernel_init(&s->k, kind, dim, h);
  s->w_zero = kernel_w(&s->k, 0.0);
  size_t vec = mem_bytes((size_t)n * dim, sizeof(double), "elastic solid vectors");
  size_t mat_bytes = mem_bytes((size_t)n * dim * dim, sizeof(double), "elastic solid matrices");
  s->x0 = mem_alloc(vec, "elastic reference positions");
  memcpy(s->x0, x0, vec);
  s->x = mem_alloc(vec, "elastic positions");
  memcpy(s->x, x0, vec);
  s->v = mem_calloc((size_t)n * dim, sizeof(double), "elastic velocities");
  s->acc = mem_calloc((size_t)n * dim, sizeof(double), "elastic accelerations");
  s->acc_ext = mem_calloc((size_t)n * dim, sizeof(double), "elastic external accelerations");
  s->F = mem_alloc(mat_bytes, "elastic deformation gradients");
  s->dF = mem_calloc((size_t)n * dim * dim, sizeof(double), "elastic deformation rates");
  s->P = mem_alloc(mat_bytes, "elastic stresses");
  s->clamped = mem_calloc((size_t)n, 1, "elastic clamp flags");
  s->normal0 = mem_calloc((size_t)n * dim, sizeof(double), "elastic reference normals");
  s->normal = mem_calloc((size_t)n * dim, sizeof(double), "elastic normals");
  s->x_step = mem_calloc((size_t)n * dim, sizeof(double), "elastic step start positions");
  s->v_avg = mem_calloc((size_t)n * dim, sizeof(double), "elastic averaged velocities");
  s->acc_avg = mem_calloc((size_t)n * dim, sizeof(double), "elastic averaged accelerations");
  for (int a = 0; a < n; a++)
    for (int r = 0; r < dim * dim; r++) s->F[(size_t)a * dim * dim + r] = r % (dim + 1) == 0;
  if (build_reference_list(s) != 0 || reference_terms(s) != 0) {
    elastic_solid_free(s);
    return -1;
  }
  reference_normals(s);
  return 0;
}

void elastic_solid_free(struct elastic_solid *s) {
  double **arrays[] = {&s->x0, &s->x, &s->v, &s->acc, &s->acc_ext, &s->F, &s->dF, &s->P, &s->R,
                       &s->normal0, &s->normal, &s->x_step, &s->v_avg, &s->acc_avg,
                       &s->nb_g, &s->nb_hess, &s->nb_grad0, &s->nb_w_ratio, &s->nb_r0_sq};
  for (size_t i = 0; i < sizeof arrays / sizeof *arrays; i++) free(*arrays[i]), *arrays[i] = NULL;
  free(s->clamped), free(s->nb_first), free(s->nb), free(s->nb_reverse);
  s->clamped = NULL, s->nb_first = s->nb = s->nb_reverse = NULL;
}

void elastic_deformation_rate(struct elastic_solid *s) {
  for (int a = 0; a < s->n; a++)   /* the loops specialised to the dimension */
    if (s->dim == 2) gradient_sum(s, a, s->v, s->dF + (size_t)a * 4, 2);
    else gradient_sum(s, a, s->v, s->dF + (size_t)a * 9, 3);
}

/* The Kelvin–Voigt pair stress's scalar factor for pair p of a and b (notes §1.9):
 * damping (W_ab/W0) (1/2) rho0 c_s h d (x_ab . v_ab)/|x0_ab|^2 [Pa], applied to (F_a + F_b)/2. */
static inline __attribute__((always_inline)) double damping_factor(const struct elastic_solid *s, int p, int a,
                                                                     int b, const int dim) {
  double xv = 0;
  for (int d = 0; d < dim; d++) xv += (s->x[a * dim + d] - s->x[b * dim + d]) * (s->v[a * dim + d] - s->v[b * dim + d]);
  return s->mat.damping * s->nb_w_ratio[p] * 0.5 * s->mat.rho0 * s->c_s * s->k.h * dim * xv / s->nb_r0_sq[p];
}

/* The strain-gradient part of the quadratic correction at particle a (doc/theory.md §13): with
 * D_k = dF/dX_k from the positions and the Hessian weights, G_k = sym(F^T D_k) and
 * S_k = lambda tr(G_k) I + 2 G G_k, the cell's energy beyond V0 psi(F) is
 * V0 dx^2/24 sum_k G_k : S_k (a strain varying linearly across the cell); its conjugates are
 * Q = dx^2/12 sum_k D_k S_k (to F, added to P) and R_k = dx^2/12 F S_k (to D_k). Returns the
 * energy per reference volume. */
static inline __attribute__((always_inline)) double strain_gradient(const struct elastic_solid *s, int a, double *Q,
                                                                     double *R, const int dim) {
  const int dd = dim * dim;
  const double *F = s->F + (size_t)a * dd, weight = s->dx * s->dx / 12;
  double D[27] = {0}, energy = 0;
  for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++) {
    const double *hess = s->nb_hess + (size_t)p * dd;
    int b = s->nb[p];
    for (int i = 0; i < dim; i++) {
      double dx_i = s->x[b * dim + i] - s->x[a * dim + i];
      for (int k = 0; k < dim; k++)
        for (int j = 0; j < dim; j++) D[k * dd + i * dim + j] += dx_i * hess[k * dim + j];
    }
  }
  for (int r = 0; r < dd; r++) Q[r] = 0;
  for (int k = 0; k < dim; k++) {
    double FtD[9], G[9], S[9], trace = 0, DS[9];
    linalg_matmul(dim, F, 1, D + k * dd, FtD);
    for (int r = 0; r < dim; r++)
      for (int c = 0; c < dim; c++) G[r * dim + c] = 0.5 * (FtD[r * dim + c] + FtD[c * dim + r]);
    for (int d = 0; d < dim; d++) trace += G[d * dim + d];
    for (int r = 0; r < dd; r++) S[r] = 2 * s->shear * G[r] + (r % (dim + 1) == 0 ? s->lambda * trace : 0.0);
    for (int r = 0; r < dd; r++) energy += 0.5 * weight * G[r] * S[r];
    linalg_matmul(dim, D + k * dd, 0, S, DS);
    linalg_matmul(dim, F, 0, S, R + k * dd);
    for (int r = 0; r < dd; r++) Q[r] += weight * DS[r], R[k * dd + r] *= weight;
  }
  return energy;
}

/* out_i += sign sum_(k,j) R_k[i][j] H[k][j]: a pair's strain-gradient force. */
static inline __attribute__((always_inline)) void gradient_pair_force(const int dim, const double *R, const double *hess,
                                                                       double sign, double *out) {
  for (int k = 0; k < dim; k++)
    for (int i = 0; i < dim; i++) {
      double sum = 0;
      for (int j = 0; j < dim; j++) sum += R[k * dim * dim + i * dim + j] * hess[k * dim + j];
      out[i] += sign * sum;
    }
}

/* Each particle's P (with the strain gradient's Q) and R, then the pair sums (elastic_acceleration),
 * with the dimension a constant. */
static inline __attribute__((always_inline)) void acceleration(struct elastic_solid *s, const double *g, const int dim) {
  const int dd = dim * dim;
  const int gradient = s->mat.correction == ELASTIC_CORRECTION_QUADRATIC;
  for (int a = 0; a < s->n; a++) {
    double *P = s->P + (size_t)a * dd, Q[9];
    elastic_pk1(dim, s->mat.model, s->lambda, s->shear, s->F + (size_t)a * dd, P);
    if (!gradient) continue;
    strain_gradient(s, a, Q, s->R + (size_t)a * dim * dd, dim);
    for (int r = 0; r < dd; r++) P[r] += Q[r];
  }
  /* f_a = -d/dx_a of the strain energy = V0 (P_a sum_b g_ab - sum_b P_b g_ba) (+ the Hessian
   * weights' like terms), per unit mass */
  const double inv_rho0 = 1.0 / s->mat.rho0, damping_scale = s->vol0 / s->mat.rho0;
  for (int a = 0; a < s->n; a++) {
    double stress[3] = {0, 0, 0}, damping[3] = {0, 0, 0};
    const double *P_a = s->P + (size_t)a * dd, *F_a = s->F + (size_t)a * dd;
    for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++) {
      int b = s->nb[p], p_ba = s->nb_reverse[p];
      const double *P_b = s->P + (size_t)b * dd, *g_ab = s->nb_g + (size_t)p * dim, *g_ba = s->nb_g + (size_t)p_ba * dim;
      for (int r = 0; r < dim; r++)
        for (int c = 0; c < dim; c++) stress[r] += P_a[r * dim + c] * g_ab[c] - P_b[r * dim + c] * g_ba[c];
      if (gradient) {
        gradient_pair_force(dim, s->R + (size_t)a * dim * dd, s->nb_hess + (size_t)p * dd, 1.0, stress);
        gradient_pair_force(dim, s->R + (size_t)b * dim * dd, s->nb_hess + (size_t)p_ba * dd, -1.0, stress);
      }
      if (s->mat.damping > 0) {
        const double *F_b = s->F + (size_t)b * dd, *grad = s->nb_grad0 + (size_t)p * dim;
        double half_factor = 0.5 * damping_factor(s, p, a, b, dim);
        for (int r = 0; r < dim; r++)
          for (int c = 0; c < dim; c++) damping[r] += half_factor * (F_a[r * dim + c] + F_b[r * dim + c]) * grad[c];
      }
    }
    for (int d = 0; d < dim; d++)
      s->acc[a * dim + d] = inv_rho0 * stress[d] + damping_scale * damping[d] + g[d] + s->acc_ext[a * dim + d];
  }
}

void elastic_acceleration(struct elastic_solid *s, const double *g) {
  if (s->dim == 2) acceleration(s, g, 2);
  else acceleration(s, g, 3);
}

/* x += dt v (a clamped particle has v = 0). */
static void drift(struct elastic_solid *s, double dt) {
  for (size_t i = 0; i < (size_t)s->n * s->dim; i++) s->x[i] += dt * s->v[i];
}

/* F += dt dF/dt. */
static void strain(struct elastic_solid *s, double dt) {
  for (size_t i = 0; i < (size_t)s->n * s->dim * s->dim; i++) s->F[i] += dt * s->dF[i];
}

void elastic_substep(struct elastic_solid *s, double dt, const double *g) {
  const int dim = s->dim;
  strain(s, 0.5 * dt);
  drift(s, 0.5 * dt);
  elastic_acceleration(s, g);
  for (int a = 0; a < s->n; a++)
    for (int d = 0; d < dim; d++) {
      size_t i = (size_t)a * dim + d;
      s->v[i] = s->clamped[a] ? 0.0 : s->v[i] + dt * s->acc[i];
    }
  drift(s, 0.5 * dt);
  for (int a = 0; a < s->n; a++)
    if (s->clamped[a]) memcpy(s->x + (size_t)a * dim, s->x0 + (size_t)a * dim, dim * sizeof(double));
  elastic_deformation_rate(s);
  strain(s, 0.5 * dt);
}

int elastic_advance(struct elastic_solid *s, double dt, const double *g) {
  const size_t values = (size_t)s->n * s->dim;
  double steps = floor(dt / elastic_time_step(s)) + 1;
  if (!(dt > 0) || !(steps <= INT_MAX)) return -1;
  int kappa = (int)steps;
  memcpy(s->x_step, s->x, values * sizeof(double));
  for (int step = 0; step < kappa; step++) elastic_substep(s, dt / kappa, g);
  const double centres = 0.5 * ((s->dt_avg > 0 ? s->dt_avg : dt) + dt);   /* dt when dt repeats */
  for (size_t i = 0; i < values; i++) {
    double v_avg = (s->x[i] - s->x_step[i]) / dt;
    s->acc_avg[i] = (v_avg - s->v_avg[i]) / centres;
    s->v_avg[i] = v_avg;
  }
  s->dt_avg = dt;
  return kappa;
}

void elastic_update_normals(struct elastic_solid *s) {
  const int dim = s->dim, dd = dim * dim;
  for (int a = 0; a < s->n; a++) {
    double F_inv[9], *normal = s->normal + (size_t)a * dim;
    const double *n0 = s->normal0 + (size_t)a * dim;
    linalg_inverse(dim, s->F + (size_t)a * dd, F_inv);
    for (int r = 0; r < dim; r++) {   /* (F^-T n0)_r = sum_c F^-1[c][r] n0_c */
      normal[r] = 0;
      for (int c = 0; c < dim; c++) normal[r] += F_inv[c * dim + r] * n0[c];
    }
    normalise(dim, normal, 0.0);
  }
}

double elastic_time_step(const struct elastic_solid *s) {
  double v_max = 0, a_max = 0;
  for (int a = 0; a < s->n; a++) {
    double v2 = 0, a2 = 0;
    for (int d = 0; d < s->dim; d++) v2 += s->v[a * s->dim + d] * s->v[a * s->dim + d],
                                     a2 += s->acc[a * s->dim + d] * s->acc[a * s->dim + d];
    if (!isfinite(v2 + a2)) return NAN;
    v_max = fmax(v_max, sqrt(v2)), a_max = fmax(a_max, sqrt(a2));
  }
  double dt = s->step_length / (s->c_s + v_max);
  if (a_max > 0) dt = fmin(dt, sqrt(s->k.h / a_max));
  return 0.6 * dt;
}

double elastic_energy(const struct elastic_solid *s) {
  const int dim = s->dim;
  double kinetic = 0, strain_energy = 0;
  for (int a = 0; a < s->n; a++) {
    for (int d = 0; d < dim; d++) kinetic += 0.5 * s->mass * s->v[a * dim + d] * s->v[a * dim + d];
    const double *F = s->F + (size_t)a * dim * dim;
    strain_energy += s->vol0 * elastic_energy_density(dim, s->mat.model, s->lambda, s->shear, F);
    if (s->mat.correction == ELASTIC_CORRECTION_QUADRATIC) {
      double Q[9], R[27];
      strain_energy += s->vol0 * strain_gradient(s, a, Q, R, dim);
    }
  }
  return kinetic + strain_energy;
}
