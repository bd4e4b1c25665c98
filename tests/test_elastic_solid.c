/* test_elastic_solid.c — the total-Lagrangian elastic solid (src/physics/elastic_solid.c):
 *  1. the stress models: P = dpsi/dF (central differences of the energy density) at a finite
 *     strain, both models, 2D and 3D; the linear-elastic stress at small strain; zero stress for a
 *     rotation;
 *  2. on a block of particles (2D and 3D, both corrections): dF/dt of a linear velocity field is
 *     its gradient at every particle, and with the quadratic correction that of a quadratic field
 *     too (also at the edges), as are its second derivatives from the Hessian weights; a rigidly
 *     rotated block (F = R) has no acceleration; for any x, F and v field the pair forces (damping
 *     on) sum to zero (momentum, to round-off); the time-step limit of Eq. P-29 with its step
 *     length (0.360 h in 2D, 0.343 h in 3D for the quadratic correction), below the stability
 *     limit 2/omega_max of the block clamped on a face (power iteration); the stress force is minus the gradient of the
 *     strain energy (central differences of elastic_energy) at a corner, an edge and the centre of
 *     a randomly deformed block, both models;
 *  2c. the reference normals of a block, Nanson's formula under a rotation and a stretch (2D) and
 *     a non-symmetric F (3D), and the fluid step's sub-steps (kappa) and averaged velocity and
 *     acceleration on a falling block;
 *  3. a cantilever plate clamped at one end (the oscillating plate of Gray, Monaghan & Swift 2001,
 *     CMAME 190: H = 0.02 m, rho0 = 1000 kg/m^3, E = 2 MPa, nu = 0.3975; 6 particles through the
 *     thickness, quadratic correction) released with the first mode's velocity profile: at
 *     L/H = 20 its period is the Euler–Bernoulli one of plane strain,
 *     T = 2 pi / omega, omega^2 = E H^2 k^4 / (12 rho0 (1 - nu^2)), k L = 1.8751, within 3 %, and
 *     its energy (sampled every 20 sub-steps) stays within 0.1 % over 1.1 periods; at L/H = 10
 *     with the damping of paper 002's cases (0.25, notes §1.9) it loses between 0.1 % and 0.5 % of
 *     its energy per period (measured 0.22 %: the damping acts, and barely on the first mode);
 *  3b. the plate at L/H = 10 released at 0.05 c_s, both models: the tip swings beyond L/3 and the
 *     energy stays within 0.1 % over a period;
 *  4. the plate at L/H = 20 under a uniform pressure q on its top face, relaxed to rest, deflects
 *     at the tip as the static Euler–Bernoulli cantilever, w = q L^4 / (8 E' I) with
 *     E' = E / (1 - nu^2), I = H^3/12, within 3 %.
 * Usage: test_elastic_solid [--table] (--table: the tables of doc/theory.md §13, both corrections;
 * about 9 minutes; no checks). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "physics/elastic_solid.h"

#define PI 3.14159265358979323846

static const struct elastic_material plate_rubber = {ELASTIC_SVK, 1000.0, 2.0e6, 0.3975, 0.0,
                                                     ELASTIC_CORRECTION_QUADRATIC};

/* 1. Stress models against the energy density and the linear limit. */
static void check_stress_models(void) {
  const double lambda = 3.0e6, shear = 1.2e6, eps = 1e-6;
  const double F2[4] = {1.1, 0.2, -0.05, 0.93}, F3[9] = {1.05, 0.1, 0.0, -0.07, 0.96, 0.03, 0.02, -0.04, 1.12};
  for (int model = 0; model < ELASTIC_MODEL_COUNT; model++)
    for (int dim = 2; dim <= 3; dim++) {
      const double *F = dim == 2 ? F2 : F3;
      double P[9], worst = 0, scale = 0;
      elastic_pk1(dim, model, lambda, shear, F, P);
      for (int r = 0; r < dim * dim; r++) {
        double Fp[9], Fm[9];
        memcpy(Fp, F, sizeof(double) * dim * dim), memcpy(Fm, F, sizeof(double) * dim * dim);
        Fp[r] += eps, Fm[r] -= eps;
        double dpsi = (elastic_energy_density(dim, model, lambda, shear, Fp) -
                       elastic_energy_density(dim, model, lambda, shear, Fm)) / (2 * eps);
        worst = fmax(worst, fabs(dpsi - P[r])), scale = fmax(scale, fabs(P[r]));
      }
      CHECK(worst < 1e-6 * scale, "%s %dD: P differs from dpsi/dF by %g (|P| %g)", elastic_model_name(model),
            dim, worst, scale);
      /* small symmetric strain e: P = lambda tr(e) I + 2 G e to first order */
      double e[9] = {2e-7, 1e-7, 0, 1e-7, -3e-7, 0.5e-7, 0, 0.5e-7, 1e-7}, Fs[9], Ps[9];
      for (int r = 0; r < dim; r++)
        for (int c = 0; c < dim; c++) Fs[r * dim + c] = (r == c) + e[r * 3 + c];
      elastic_pk1(dim, model, lambda, shear, Fs, Ps);
      double tr = 0, err = 0;
      for (int d = 0; d < dim; d++) tr += e[d * 3 + d];
      for (int r = 0; r < dim; r++)
        for (int c = 0; c < dim; c++) {
          double linear = 2 * shear * e[r * 3 + c] + (r == c) * lambda * tr;
          err = fmax(err, fabs(Ps[r * dim + c] - linear));
        }
      CHECK(err < 1e-6 * 2 * shear * 3e-7, "%s %dD: small-strain stress off the linear law by %g Pa",
            elastic_model_name(model), dim, err);
      double R[9] = {cos(0.7), -sin(0.7), 0, sin(0.7), cos(0.7), 0, 0, 0, 1}, R2[4] = {R[0], R[1], R[3], R[4]}, Pr[9];
      elastic_pk1(dim, model, lambda, shear, dim == 2 ? R2 : R, Pr);
      double largest = 0;
      for (int r = 0; r < dim * dim; r++) largest = fmax(largest, fabs(Pr[r]));
      CHECK(largest < 1e-9 * shear, "%s %dD: a rotation is stressed (%g Pa)", elastic_model_name(model), dim, largest);
    }
}

/* A block of nx x ny (x nz) particles of spacing dx, Wendland C2 at h = 1.3 dx. */
static int make_block(struct elastic_solid *s, int dim, int nx, int ny, int nz, double dx,
                      const struct elastic_material *mat, double x_offset) {
  int n = nx * ny * (dim == 3 ? nz : 1);
  double *x0 = malloc(sizeof(double) * n * dim);
  for (int i = 0, a = 0; i < (dim == 3 ? nz : 1); i++)
    for (int j = 0; j < ny; j++)
      for (int l = 0; l < nx; l++, a++) {
        x0[a * dim] = x_offset + (l + 0.5) * dx, x0[a * dim + 1] = (j + 0.5) * dx;
        if (dim == 3) x0[a * dim + 2] = (i + 0.5) * dx;
      }
  int status = elastic_solid_init(s, dim, n, x0, dx, KERNEL_WENDLAND_C2, 1.3 * dx, mat);
  free(x0);
  return status;
}

/* The largest angular frequency [1/s] of s linearised about its reference state (free particles
 * only): power iteration on u -> -acc(x0 + u) with F = I + grad u, u of 1e-7 dx. */
static double largest_frequency(struct elastic_solid *s) {
  const int dim = s->dim, values = s->n * dim;
  const double zero_g[3] = {0, 0, 0}, amplitude = 1e-7 * s->dx;
  double *u = malloc(sizeof(double) * values), omega2 = 0;
  srand(3);
  for (int i = 0; i < values; i++) u[i] = s->clamped[i / dim] ? 0 : rand() / (double)RAND_MAX - 0.5;
  for (int iteration = 0; iteration < 2000; iteration++) {
    double norm = 0;
    for (int i = 0; i < values; i++) norm += u[i] * u[i];
    for (int i = 0; i < values; i++) s->v[i] = u[i] * amplitude / sqrt(norm), s->x[i] = s->x0[i] + s->v[i];
    elastic_deformation_rate(s);   /* grad u, with v standing for u */
    for (int i = 0; i < values * dim; i++) s->F[i] = (i % (dim * dim)) % (dim + 1) == 0 ? 1 + s->dF[i] : s->dF[i];
    memset(s->v, 0, sizeof(double) * values);
    elastic_acceleration(s, zero_g);
    double acc2 = 0;
    for (int i = 0; i < values; i++) u[i] = s->clamped[i / dim] ? 0 : -s->acc[i], acc2 += u[i] * u[i];
    omega2 = sqrt(acc2) / amplitude;
  }
  free(u);
  return sqrt(omega2);
}

/* 2. The discrete operators on a block, with the given correction. */
static void check_block(int dim, enum elastic_correction correction) {
  struct elastic_solid s;
  struct elastic_material mat = plate_rubber;
  mat.correction = correction;
  const double dx = 0.01, A[9] = {0.3, -0.2, 0.1, 0.05, -0.4, 0.2, 0.15, 0.1, 0.25};
  const double zero_g[3] = {0, 0, 0};
  int init = make_block(&s, dim, 7, 6, 5, dx, &mat, 0.0);
  CHECK(init == 0, "%dD block: init", dim);
  if (init != 0) return;
  const int dd = dim * dim;
  /* dF/dt of v = A x0 is A everywhere */
  for (int a = 0; a < s.n; a++)
    for (int r = 0; r < dim; r++) {
      s.v[a * dim + r] = 0;
      for (int c = 0; c < dim; c++) s.v[a * dim + r] += A[r * 3 + c] * s.x0[a * dim + c];
    }
  elastic_deformation_rate(&s);
  double err = 0;
  for (int a = 0; a < s.n; a++)
    for (int r = 0; r < dim; r++)
      for (int c = 0; c < dim; c++) err = fmax(err, fabs(s.dF[a * dd + r * dim + c] - A[r * 3 + c]));
  CHECK(err < 1e-12, "%dD block, %s: dF/dt of a linear velocity field off its gradient by %g", dim,
        elastic_correction_name(correction), err);
  if (correction == ELASTIC_CORRECTION_QUADRATIC) {   /* v_r = x0 . A_r x0: dF/dt = (A_r + A_r^T) x0 */
    for (int a = 0; a < s.n; a++)
      for (int r = 0; r < dim; r++) {
        s.v[a * dim + r] = 0;
        for (int i = 0; i < dim; i++)
          for (int j = 0; j < dim; j++) s.v[a * dim + r] += A[(r + i) % 3 * 3 + j] * s.x0[a * dim + i] * s.x0[a * dim + j];
      }
    elastic_deformation_rate(&s);
    err = 0;
    for (int a = 0; a < s.n; a++)
      for (int r = 0; r < dim; r++)
        for (int c = 0; c < dim; c++) {
          double exact = 0;
          for (int j = 0; j < dim; j++) exact += (A[(r + c) % 3 * 3 + j] + A[(r + j) % 3 * 3 + c]) * s.x0[a * dim + j];
          err = fmax(err, fabs(s.dF[a * dd + r * dim + c] - exact));
        }
    CHECK(err < 1e-11, "%dD block, quadratic: dF/dt of a quadratic velocity field off its gradient by %g", dim, err);
    err = 0;   /* the Hessian weights: sum_b (v_b - v_a) H_ab,kj = d^2 v / dx_k dx_j = A_(r+k) + A_(r+k)^T */
    for (int a = 0; a < s.n; a++)
      for (int r = 0; r < dim; r++)
        for (int k = 0; k < dim; k++)
          for (int j = 0; j < dim; j++) {
            double sum = 0, exact = A[(r + k) % 3 * 3 + j] + A[(r + j) % 3 * 3 + k];
            for (int p = s.nb_first[a]; p < s.nb_first[a + 1]; p++)
              sum += (s.v[s.nb[p] * dim + r] - s.v[a * dim + r]) * s.nb_hess[(p * dim + k) * dim + j];
            err = fmax(err, fabs(sum - exact));
          }
    CHECK(err < 1e-9, "%dD block, quadratic: second derivatives of a quadratic field off by %g", dim, err);
  }
  /* a rigid rotation: F = R, x = R x0, v = 0, no acceleration */
  double c = cos(0.9), sn = sin(0.9), R[9] = {c, -sn, 0, sn, c, 0, 0, 0, 1};
  for (int a = 0; a < s.n; a++) {
    for (int r = 0; r < dim; r++) {
      s.v[a * dim + r] = 0;
      s.x[a * dim + r] = 0;
      for (int k = 0; k < dim; k++) s.x[a * dim + r] += R[r * 3 + k] * s.x0[a * dim + k];
      for (int k = 0; k < dim; k++) s.F[a * dd + r * dim + k] = R[r * 3 + k];
    }
  }
  elastic_acceleration(&s, zero_g);
  double largest = 0;
  for (int i = 0; i < s.n * dim; i++) largest = fmax(largest, fabs(s.acc[i]));
  CHECK(largest < 1e-6, "%dD block: a rotated block accelerates (%g m/s^2)", dim, largest);
  /* any x, F and v field: the pair forces cancel (damping on) */
  s.mat.damping = 0.25;
  srand(7);
  for (int i = 0; i < s.n * dim; i++) s.x[i] = s.x0[i] + 0.1 * dx * (rand() / (double)RAND_MAX - 0.5);
  for (int i = 0; i < s.n * dd; i++) s.F[i] = (i % (dim + 1) == 0) + 0.05 * (rand() / (double)RAND_MAX - 0.5);
  for (int i = 0; i < s.n * dim; i++) s.v[i] = rand() / (double)RAND_MAX - 0.5;
  elastic_acceleration(&s, zero_g);
  double momentum[3] = {0, 0, 0}, scale = 0;
  for (int a = 0; a < s.n; a++)
    for (int d = 0; d < dim; d++) momentum[d] += s.mass * s.acc[a * dim + d], scale += s.mass * fabs(s.acc[a * dim + d]);
  for (int d = 0; d < dim; d++)
    CHECK(fabs(momentum[d]) < 1e-13 * scale, "%dD block: the pair forces sum to %g along %d (of %g)", dim,
          momentum[d], d, scale);
  /* the time step (Eq. P-29): acoustic with v = acc = 0 */
  memset(s.v, 0, sizeof(double) * s.n * dim), memset(s.acc, 0, sizeof(double) * s.n * dim);
  if (correction == ELASTIC_CORRECTION_LINEAR) CHECK_CLOSE(s.step_length, 1.3 * dx, 1e-15, "linear: step length h");
  else   /* 0.36 h in 2D, 0.343 h in 3D (doc/theory.md §13) */
    CHECK(fabs(s.step_length / (1.3 * dx) - (dim == 2 ? 0.360 : 0.343)) < 0.002, "quadratic %dD: step length %g h", dim,
          s.step_length / (1.3 * dx));
  CHECK_CLOSE(elastic_time_step(&s), 0.6 * s.step_length / s.c_s, 1e-15, "time step at rest");
  s.acc[0] = 1e9;
  CHECK_CLOSE(elastic_time_step(&s), 0.6 * sqrt(1.3 * dx / 1e9), 1e-15, "time step limited by acceleration");
  /* the step is stable: below 2 / omega_max of the linearised block (clamped on its first column) */
  for (int a = 0; a < s.n; a++) s.clamped[a] = s.x0[a * dim] < dx;
  double dt_max = 2 / largest_frequency(&s), dt_s = 0.6 * s.step_length / s.c_s;
  printf("%dD block, %s: stability limit %.4f h/c_s, time step %.4f h/c_s\n", dim, elastic_correction_name(correction),
         dt_max * s.c_s / s.k.h, dt_s * s.c_s / s.k.h);
  CHECK(dt_s < dt_max, "%dD %s: time step %g s above the stability limit %g s", dim,
        elastic_correction_name(correction), dt_s, dt_max);
  elastic_solid_free(&s);
}

/* Nanson's formula in 3D under a non-symmetric F: F^T n is parallel to n0 with n a unit vector. */
static void check_normals_3d(void) {
  struct elastic_solid s;
  const double F[9] = {1.2, 0.3, -0.1, 0.05, 0.9, 0.2, -0.15, 0.1, 1.1};
  int init = make_block(&s, 3, 5, 5, 5, 0.01, &plate_rubber, 0.0);
  CHECK(init == 0, "3D normals block: init");
  if (init != 0) return;
  for (int a = 0; a < s.n; a++) memcpy(s.F + a * 9, F, sizeof F);
  elastic_update_normals(&s);
  double err = 0;
  int surface = 0;
  for (int a = 0; a < s.n; a++) {
    const double *n = s.normal + a * 3, *n0 = s.normal0 + a * 3;
    if (n0[0] == 0 && n0[1] == 0 && n0[2] == 0) continue;
    double ftn[3], cross[3];
    for (int c = 0; c < 3; c++) ftn[c] = F[c] * n[0] + F[3 + c] * n[1] + F[6 + c] * n[2];
    cross[0] = ftn[1] * n0[2] - ftn[2] * n0[1], cross[1] = ftn[2] * n0[0] - ftn[0] * n0[2];
    cross[2] = ftn[0] * n0[1] - ftn[1] * n0[0];
    double dot = ftn[0] * n0[0] + ftn[1] * n0[1] + ftn[2] * n0[2];
    err = fmax(err, fabs(cross[0]) + fabs(cross[1]) + fabs(cross[2]) + (dot > 0 ? 0 : 1));
    err = fmax(err, fabs(hypot(hypot(n[0], n[1]), n[2]) - 1));
    surface++;
  }
  CHECK(surface > 0 && err < 1e-14, "3D normals: F^T n off n0 by %g over %d particles", err, surface);
  elastic_solid_free(&s);
}

/* 2c. Normals and the fluid step on a 2D block of 7 x 7: the reference normal is (0, 1) at the
 * middle of the top row, zero at the centre; F = R turns the normals by R, F = diag(2, 1) turns a
 * corner's (n_x, n_y) to (n_x/2, n_y) normalised; a block moving at v0 and falling under g through
 * a fluid step of several sub-steps has v_avg = v0 + g dt/2 and acc_avg = v_avg/dt (from rest),
 * then acc_avg = g; a step of 0 s is refused. Then the 3D normals. */
static void check_normals_and_advance(void) {
  struct elastic_solid s;
  const double dx = 0.01;
  int init = make_block(&s, 2, 7, 7, 1, dx, &plate_rubber, 0.0);
  CHECK(init == 0, "normals block: init");
  if (init != 0) return;
  const int top_middle = 6 * 7 + 3, centre = 3 * 7 + 3, corner = 0;
  CHECK(fabs(s.normal0[top_middle * 2]) < 1e-12 && fabs(s.normal0[top_middle * 2 + 1] - 1) < 1e-12,
        "top normal (%g, %g)", s.normal0[top_middle * 2], s.normal0[top_middle * 2 + 1]);
  CHECK(s.normal0[centre * 2] == 0 && s.normal0[centre * 2 + 1] == 0, "centre normal (%g, %g)", s.normal0[centre * 2],
        s.normal0[centre * 2 + 1]);
  double c = cos(0.6), sn = sin(0.6), err = 0;
  for (int a = 0; a < s.n; a++) s.F[a * 4] = c, s.F[a * 4 + 1] = -sn, s.F[a * 4 + 2] = sn, s.F[a * 4 + 3] = c;
  elastic_update_normals(&s);
  for (int a = 0; a < s.n; a++) {
    const double *n0 = s.normal0 + a * 2;
    err = fmax(err, fabs(s.normal[a * 2] - (c * n0[0] - sn * n0[1])) + fabs(s.normal[a * 2 + 1] - (sn * n0[0] + c * n0[1])));
  }
  CHECK(err < 1e-14, "rotated normals off by %g", err);
  for (int a = 0; a < s.n; a++) s.F[a * 4] = 2, s.F[a * 4 + 1] = s.F[a * 4 + 2] = 0, s.F[a * 4 + 3] = 1;
  elastic_update_normals(&s);
  double expect[2] = {0.5 * s.normal0[corner * 2], s.normal0[corner * 2 + 1]}, norm = hypot(expect[0], expect[1]);
  CHECK(fabs(s.normal[corner * 2] - expect[0] / norm) < 1e-14 && fabs(s.normal[corner * 2 + 1] - expect[1] / norm) < 1e-14,
        "stretched corner normal (%g, %g)", s.normal[corner * 2], s.normal[corner * 2 + 1]);
  for (int a = 0; a < s.n; a++) s.F[a * 4] = s.F[a * 4 + 3] = 1, s.F[a * 4 + 1] = s.F[a * 4 + 2] = 0;
  const double v0[2] = {1.0, -0.5}, g[2] = {0.0, -9.81};
  for (int a = 0; a < s.n; a++) s.v[a * 2] = v0[0], s.v[a * 2 + 1] = v0[1];
  elastic_deformation_rate(&s);
  elastic_acceleration(&s, g);
  const double dt_fluid = 3.5 * elastic_time_step(&s);
  int kappa = elastic_advance(&s, dt_fluid, g);
  CHECK(kappa == 4, "kappa %d for a fluid step of 3.5 sub-step limits", kappa);
  double v_err = 0, a_err = 0;   /* v_avg = v0 + g dt/2 (exact for constant g); acc_avg = v_avg/dt from rest */
  for (int i = 0; i < s.n * 2; i++) {
    double v_avg = v0[i % 2] + 0.5 * g[i % 2] * dt_fluid;
    v_err = fmax(v_err, fabs(s.v_avg[i] - v_avg)), a_err = fmax(a_err, fabs(s.acc_avg[i] - v_avg / dt_fluid));
  }
  CHECK(v_err < 1e-9 && a_err < 1e-9 / dt_fluid, "falling block: v_avg off by %g, acc_avg by %g", v_err, a_err);
  elastic_advance(&s, dt_fluid, g);
  a_err = 0;
  for (int i = 0; i < s.n * 2; i++) a_err = fmax(a_err, fabs(s.acc_avg[i] - g[i % 2]));
  CHECK(a_err < 1e-6, "falling block, second step: acc_avg off g by %g", a_err);
  CHECK(elastic_advance(&s, 0.0, g) == -1, "a fluid step of 0 s is refused");
  elastic_solid_free(&s);
  check_normals_3d();
}

/* F of every particle from the positions: I + sum_b (u_b - u_a) (x) g_ab. */
static void deformation_from_positions(struct elastic_solid *s) {
  const int dim = s->dim;
  for (int a = 0; a < s->n; a++)
    for (int r = 0; r < dim; r++)
      for (int c = 0; c < dim; c++) {
        double sum = r == c;
        for (int p = s->nb_first[a]; p < s->nb_first[a + 1]; p++) {
          int b = s->nb[p];
          sum += (s->x[b * dim + r] - s->x0[b * dim + r] - s->x[a * dim + r] + s->x0[a * dim + r]) * s->nb_g[p * dim + c];
        }
        s->F[(a * dim + r) * dim + c] = sum;
      }
}

/* 2b. The stress force is minus the gradient of the strain energy (central differences of
 * elastic_energy with F from the positions) at a corner, an edge and an inner particle of a block
 * deformed at random by up to 5 % of dx, for the given correction and model. */
static void check_energy_gradient(int dim, enum elastic_correction correction, enum elastic_model model) {
  struct elastic_solid s;
  struct elastic_material mat = plate_rubber;
  mat.correction = correction, mat.model = model;
  const double dx = 0.01, eps = 1e-7 * dx, zero_g[3] = {0, 0, 0};
  int init = make_block(&s, dim, 7, 7, 7, dx, &mat, 0.0);
  CHECK(init == 0, "%dD energy-gradient block: init", dim);
  if (init != 0) return;
  srand(11);
  for (int i = 0; i < s.n * dim; i++) s.x[i] += 0.05 * dx * (rand() / (double)RAND_MAX - 0.5);
  deformation_from_positions(&s);
  elastic_acceleration(&s, zero_g);
  int probes[3] = {0, 2, 3 * 7 + 3 + (dim == 3 ? 3 * 49 : 0)};   /* a corner, an edge, the centre */
  double worst = 0, scale = 0;
  for (int k = 0; k < 3; k++)
    for (int d = 0; d < dim; d++) {
      size_t i = (size_t)probes[k] * dim + d;
      double x = s.x[i], energy[2];
      for (int side = 0; side < 2; side++) {
        s.x[i] = x + (side ? eps : -eps);
        deformation_from_positions(&s);
        energy[side] = elastic_energy(&s);
      }
      s.x[i] = x;
      double force = -(energy[1] - energy[0]) / (2 * eps);
      worst = fmax(worst, fabs(force - s.mass * s.acc[i])), scale = fmax(scale, fabs(force));
    }
  CHECK(worst < 1e-5 * scale, "%dD %s, %s: the force differs from -dE/dx by %g (of %g)", dim,
        elastic_correction_name(correction), elastic_model_name(model), worst, scale);
  elastic_solid_free(&s);
}

/* A plate clamped at x < 0: its free length and thickness [m], particle layers, material and the
 * tip speed of its release in units of c_s. */
struct plate {
  double length, thickness;
  int layers;
  struct elastic_material mat;
  double tip_speed;
};

/* The plate of Gray et al. (thickness 0.02 m) with the given length, layers, correction, damping. */
static struct plate gray_plate(double length, int layers, enum elastic_correction correction, double damping) {
  struct plate out = {length, 0.02, layers, plate_rubber, 0.01};
  out.mat.correction = correction, out.mat.damping = damping;
  return out;
}

/* The plate's particles: its length beyond a clamp of 4 columns (x < 0), centred on y = 0. */
static int make_cantilever(struct elastic_solid *s, const struct plate *plate) {
  const double dx = plate->thickness / plate->layers;
  int columns = (int)lround(plate->length / dx) + 4;
  if (make_block(s, 2, columns, plate->layers, 1, dx, &plate->mat, -4 * dx) != 0) return -1;
  for (int a = 0; a < s->n; a++) {
    s->x0[a * 2 + 1] -= 0.5 * plate->thickness, s->x[a * 2 + 1] -= 0.5 * plate->thickness;
    s->clamped[a] = s->x0[a * 2] < 0;
  }
  return 0;
}

/* Mean vertical displacement of the last column (the tip). */
static double tip_deflection(const struct elastic_solid *s) {
  double sum = 0, x_end = -INFINITY;
  int count = 0;
  for (int a = 0; a < s->n; a++) x_end = fmax(x_end, s->x0[a * 2]);
  for (int a = 0; a < s->n; a++)
    if (s->x0[a * 2] > x_end - 1e-9) sum += s->x[a * 2 + 1] - s->x0[a * 2 + 1], count++;
  return sum / count;
}

/* The first bending mode's shape of a clamped-free beam at x (k the wave number). */
static double mode_shape(double k, double length, double x) {
  double kl = k * length;
  return (sin(kl) + sinh(kl)) * (cos(k * x) - cosh(k * x)) - (cos(kl) + cosh(kl)) * (sin(k * x) - sinh(k * x));
}

/* What a free vibration measured. */
struct vibration {
  double period, period_eb;       /* from the tip's zero crossings; Euler–Bernoulli's [s] */
  double energy_change;           /* largest |E - E0| / E0 */
  double energy_loss_per_period;  /* (E0 - E_end) / E0 per Euler–Bernoulli period */
  double tip_max;                 /* largest |tip deflection| [m] */
};

/* Release a cantilever with the first mode's velocity (the plate's tip speed) and run `periods`
 * Euler–Bernoulli periods. */
static struct vibration free_vibration(const struct plate *plate, double periods) {
  const double length = plate->length, thickness = plate->thickness, k = 1.875104 / length, g[2] = {0, 0};
  struct vibration out = {NAN, NAN, NAN, NAN, 0};
  struct elastic_solid s;
  if (make_cantilever(&s, plate) != 0) return out;
  double E_plane = s.mat.young / (1 - s.mat.poisson * s.mat.poisson);
  double omega = sqrt(E_plane * thickness * thickness * pow(k, 4) / (12 * s.mat.rho0));
  out.period_eb = 2 * PI / omega;
  for (int a = 0; a < s.n; a++)
    if (!s.clamped[a])
      s.v[a * 2 + 1] = plate->tip_speed * s.c_s * mode_shape(k, length, s.x0[a * 2]) / mode_shape(k, length, length);
  elastic_deformation_rate(&s);
  elastic_acceleration(&s, g);
  double e0 = elastic_energy(&s), t = 0, w_prev = 0, crossings[64];
  int n_cross = 0, steps = 0;
  out.energy_change = 0;
  while (t < periods * out.period_eb) {
    double dt = elastic_time_step(&s);
    elastic_substep(&s, dt, g);
    t += dt;
    double w = tip_deflection(&s);
    out.tip_max = fmax(out.tip_max, fabs(w));
    if (w_prev != 0 && (w > 0) != (w_prev > 0) && n_cross < 64) crossings[n_cross++] = t - dt * w / (w - w_prev);
    w_prev = w;
    double change = ++steps % 20 == 0 ? fabs(elastic_energy(&s) - e0) / e0 : 0;
    if (!(change <= out.energy_change)) out.energy_change = change;   /* a NaN sticks */
  }
  if (n_cross >= 2) out.period = 2 * (crossings[n_cross - 1] - crossings[0]) / (n_cross - 1);
  out.energy_loss_per_period = (e0 - elastic_energy(&s)) / e0 / (t / out.period_eb);
  elastic_solid_free(&s);
  return out;
}

/* 3. The first mode's period of a slender plate (L/H = 20, where Euler–Bernoulli holds) without
 * damping, and the energy without and with the damping of paper 002's cases (L/H = 10). */
static void check_cantilever_frequency(void) {
  struct plate slender = gray_plate(0.4, 6, ELASTIC_CORRECTION_QUADRATIC, 0.0);
  struct plate damped_plate = gray_plate(0.2, 6, ELASTIC_CORRECTION_QUADRATIC, 0.25);
  struct vibration plain = free_vibration(&slender, 1.1);
  printf("cantilever L/H 20, no damping: period %.5f s, Euler-Bernoulli %.5f s (%+.2f %%), "
         "largest energy change %.4f %%\n",
         plain.period, plain.period_eb, 100 * (plain.period / plain.period_eb - 1), 100 * plain.energy_change);
  CHECK(fabs(plain.period / plain.period_eb - 1) < 0.03, "undamped period %g s against %g s", plain.period,
        plain.period_eb);
  CHECK(plain.energy_change < 1e-3, "undamped energy changes by %g of its initial value", plain.energy_change);
  struct vibration damped = free_vibration(&damped_plate, 2.0);
  printf("cantilever L/H 10, damping 0.25: period %.5f s (%+.2f %% from Euler-Bernoulli), "
         "energy lost per period %.3f %%\n",
         damped.period, 100 * (damped.period / damped.period_eb - 1), 100 * damped.energy_loss_per_period);
  CHECK(damped.energy_loss_per_period > 0.001 && damped.energy_loss_per_period < 0.005,
        "damped energy loss per period %g", damped.energy_loss_per_period);
}

/* 3b. Large deflection: the plate at L/H = 10 released at a tip speed of 0.05 c_s, both models: the
 * tip swings beyond a third of the length, and over one Euler–Bernoulli period the energy stays
 * within 0.1 %. */
static void check_large_deflection(void) {
  for (int model = 0; model < ELASTIC_MODEL_COUNT; model++) {
    struct plate plate = gray_plate(0.2, 6, ELASTIC_CORRECTION_QUADRATIC, 0.0);
    plate.mat.model = model, plate.tip_speed = 0.05;
    struct vibration run = free_vibration(&plate, 1.0);
    printf("cantilever L/H 10, tip speed 0.05 c_s, %s: tip swings to %.3f L, largest energy change %.4f %%\n",
           elastic_model_name(model), run.tip_max / plate.length, 100 * run.energy_change);
    CHECK(run.tip_max > plate.length / 3, "large deflection, %s: the tip swings only to %g m", elastic_model_name(model),
          run.tip_max);
    CHECK(run.energy_change < 1e-3, "large deflection, %s: energy changes by %g", elastic_model_name(model),
          run.energy_change);
  }
}

/* The tip deflection over Euler–Bernoulli's, q L^4 / (8 E' I), of a cantilever under a uniform
 * pressure q on its top face, relaxed to rest by a velocity damping of the test's own (critical
 * for the first mode). */
static double static_deflection(const struct plate *plate) {
  const double length = plate->length, thickness = plate->thickness, q = 0.2, g[2] = {0, 0};
  struct elastic_solid s;
  if (make_cantilever(&s, plate) != 0) return NAN;
  double y_top = -INFINITY;
  for (int a = 0; a < s.n; a++) y_top = fmax(y_top, s.x0[a * 2 + 1]);
  for (int a = 0; a < s.n; a++)
    if (!s.clamped[a] && s.x0[a * 2 + 1] > y_top - 1e-9) s.acc_ext[a * 2 + 1] = -q * s.dx / s.mass;
  double E_plane = s.mat.young / (1 - s.mat.poisson * s.mat.poisson), inertia = pow(thickness, 3) / 12;
  double w_eb = -q * pow(length, 4) / (8 * E_plane * inertia);
  double k = 1.875104 / length, omega = sqrt(E_plane * inertia * pow(k, 4) / (s.mat.rho0 * thickness));
  double t = 0;   /* critical damping: the first mode's residual (1 + omega t) e^(-omega t) */
  elastic_acceleration(&s, g);
  while (t < 12 / omega) {   /* below 1e-4 */
    double dt = elastic_time_step(&s), relax = exp(-2 * omega * dt);
    elastic_substep(&s, dt, g);
    for (int i = 0; i < s.n * 2; i++) s.v[i] *= relax;
    t += dt;
  }
  double w = tip_deflection(&s);
  elastic_solid_free(&s);
  return w / w_eb;
}

/* 4. The static deflection of a plate 0.4 m long (L/H = 20). */
static void check_static_deflection(void) {
  struct plate plate = gray_plate(0.4, 6, ELASTIC_CORRECTION_QUADRATIC, 0.0);
  double ratio = static_deflection(&plate);
  printf("static cantilever L/H 20: tip deflection %.4f of Euler-Bernoulli's\n", ratio);
  CHECK(fabs(ratio - 1) < 0.03, "static tip deflection %g of Euler-Bernoulli's", ratio);
}

/* The first period over Euler–Bernoulli's of a 3D beam of square section (H = W = 0.02 m, the
 * material of Gray et al., `layers` particles across, L/H = 10, clamped over 4 layers; a narrow
 * beam: omega^2 = E H^2 k^4 / (12 rho0)), released with the first mode's velocity at 0.01 c_s. */
static double period_3d(enum elastic_correction correction, int layers) {
  const double thickness = 0.02, length = 0.2, dx = thickness / layers, k = 1.875104 / length, g[3] = {0, 0, 0};
  struct elastic_material mat = plate_rubber;
  mat.correction = correction;
  struct elastic_solid s;
  if (make_block(&s, 3, (int)lround(length / dx) + 4, layers, layers, dx, &mat, -4 * dx) != 0) return NAN;
  double period_eb = 2 * PI / sqrt(mat.young * thickness * thickness * pow(k, 4) / (12 * mat.rho0));
  double tip_x = -INFINITY, t = 0, w_prev = 0, crossings[2];
  int n_cross = 0;
  for (int a = 0; a < s.n; a++) {
    s.clamped[a] = s.x0[a * 3] < 0;
    tip_x = fmax(tip_x, s.x0[a * 3]);
    if (!s.clamped[a])
      s.v[a * 3 + 1] = 0.01 * s.c_s * mode_shape(k, length, s.x0[a * 3]) / mode_shape(k, length, length);
  }
  elastic_deformation_rate(&s);
  elastic_acceleration(&s, g);
  while (n_cross < 2 && t < 2 * period_eb) {   /* the half period between the first two crossings */
    double dt = elastic_time_step(&s), w = 0;
    elastic_substep(&s, dt, g);
    t += dt;
    int count = 0;
    for (int a = 0; a < s.n; a++)
      if (s.x0[a * 3] > tip_x - 1e-9) w += s.x[a * 3 + 1] - s.x0[a * 3 + 1], count++;
    w /= count;
    if (w_prev != 0 && (w > 0) != (w_prev > 0)) crossings[n_cross++] = t - dt * w / (w - w_prev);
    w_prev = w;
  }
  elastic_solid_free(&s);
  return n_cross == 2 ? 2 * (crossings[1] - crossings[0]) / period_eb : NAN;
}

/* The tables of doc/theory.md §13 (about 9 minutes): the plate of Gray et al. with both corrections
 * at 4, 6 and 10 layers, L/H = 20 and 10; the gate of Antoci et al. (paper 002 §4.4: L = 79 mm,
 * b = 5 mm, rho0 = 1100 kg/m^3, E = 7.8 MPa, nu = 0.47) dry at 4 layers; a 3D beam at 6 layers. */
static void print_table(void) {
  printf("layers  correction  static w/w_EB (L/H 20)  period/T_EB (L/H 20)  period/T_EB (L/H 10)\n");
  for (int correction = 0; correction < ELASTIC_CORRECTION_COUNT; correction++)
    for (int layers = 4; layers <= 10; layers += layers == 4 ? 2 : 4) {
      struct plate slender = gray_plate(0.4, layers, correction, 0.0), stocky = gray_plate(0.2, layers, correction, 0.0);
      struct vibration slender_run = free_vibration(&slender, 2.0), stocky_run = free_vibration(&stocky, 2.0);
      printf("%6d  %10s  %22.4f  %20.4f  %20.4f\n", layers, elastic_correction_name(correction),
             static_deflection(&slender), slender_run.period / slender_run.period_eb,
             stocky_run.period / stocky_run.period_eb);
      fflush(stdout);
    }
  for (int correction = 0; correction < ELASTIC_CORRECTION_COUNT; correction++) {
    struct plate gate = {0.079, 0.005, 4, {ELASTIC_SVK, 1100.0, 7.8e6, 0.47, 0.0, correction}, 0.01};
    struct vibration run = free_vibration(&gate, 2.0);
    printf("gate of Antoci et al., dry, 4 layers, %s: period %.5f s, Euler-Bernoulli %.5f s, ratio %.4f\n",
           elastic_correction_name(correction), run.period, run.period_eb, run.period / run.period_eb);
  }
  for (int correction = 0; correction < ELASTIC_CORRECTION_COUNT; correction++)
    printf("3D beam of square section, L/H 10, 6 layers, %s: period / Euler-Bernoulli %.4f\n",
           elastic_correction_name(correction), period_3d(correction, 6));
}

int main(int argc, char **argv) {
  if (argc > 1 && strcmp(argv[1], "--table") == 0) {
    print_table();
    return 0;
  }
  check_stress_models();
  for (int correction = 0; correction < ELASTIC_CORRECTION_COUNT; correction++)
    for (int dim = 2; dim <= 3; dim++) {
      check_block(dim, correction);
      for (int model = 0; model < ELASTIC_MODEL_COUNT; model++) check_energy_gradient(dim, correction, model);
    }
  check_normals_and_advance();
  check_cantilever_frequency();
  check_large_deflection();
  check_static_deflection();
  return check_report("test_elastic_solid");
}
