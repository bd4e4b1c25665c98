/* test_kernel.c — kernel moments on a regular lattice (2D and 3D, Gaussian and Wendland C2):
 * sum W V = 1, sum grad W V = 0, sum r_ji (x) grad_i W V = I, and the SPH gradient of a linear
 * field equals its slope; plus F = W'/r against a finite difference of W. */
#include "check.h"
#include "physics/kernel.h"

/* Moments at a particle at `offset` (in units of dx) inside a lattice of spacing dx. */
static void lattice_moments(const struct kernel *k, double dx, const double *offset, double *sum_w,
                            double *sum_g, double *sum_b, double *grad_lin) {
  int dim = k->dim, n = (int)(k->support / dx) + 2, nz = dim == 3 ? n : 0;
  double slope[3] = {0.3, -1.7, 2.2}, vol = dim == 2 ? dx * dx : dx * dx * dx;
  *sum_w = 0;
  for (int a = 0; a < 9; a++) sum_b[a] = 0;
  for (int a = 0; a < 3; a++) sum_g[a] = grad_lin[a] = 0;
  for (int iz = -nz; iz <= nz; iz++)
    for (int iy = -n; iy <= n; iy++)
      for (int ix = -n; ix <= n; ix++) {
        double r[3] = {(ix - offset[0]) * dx, (iy - offset[1]) * dx, dim == 3 ? (iz - offset[2]) * dx : 0};
        double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];   /* r = r_j - r_i */
        if (r2 >= k->support2) continue;
        double f = kernel_f(k, r2), lin = slope[0] * r[0] + slope[1] * r[1] + slope[2] * r[2];
        *sum_w += kernel_w(k, r2) * vol;
        for (int a = 0; a < dim; a++) {
          double g = -f * r[a] * vol;   /* grad_i W_ij V_j, r_i - r_j = -r */
          sum_g[a] += g;
          grad_lin[a] += lin * g;
          for (int b = 0; b < dim; b++) sum_b[a * dim + b] += r[b] * g;
        }
      }
}

/* tol_w bounds |sum W V - 1|; tol_m the first moments (sum grad W V h, the matrix, the gradient
 * of a linear field relative to its slope). A wrong normalisation or sign gives O(1) errors. */
static void check_kernel(enum kernel_kind kind, int dim, double h_over_dx, double tol_w, double tol_m,
                         const char *name) {
  struct kernel k;
  double dx = 0.01, sw, sg[3], sb[9], gl[3], slope[3] = {0.3, -1.7, 2.2};
  double offsets[2][3] = {{0, 0, 0}, {0.37, 0.21, 0.45}};
  kernel_init(&k, kind, dim, h_over_dx * dx);
  for (int o = 0; o < 2; o++) {
    lattice_moments(&k, dx, offsets[o], &sw, sg, sb, gl);
    CHECK_CLOSE(sw, 1.0, tol_w, name);
    for (int a = 0; a < dim; a++) {
      CHECK_CLOSE(sg[a] * k.h, 0.0, tol_m, name);
      CHECK_CLOSE(gl[a], slope[a], tol_m * fabs(slope[a]), name);
      for (int b = 0; b < dim; b++) CHECK_CLOSE(sb[a * dim + b], a == b, tol_m, name);
    }
  }
  for (double q = 0.1; q * k.h < k.support * 0.99; q += 0.37) {
    double r = q * k.h, eps = 1e-6 * k.h;
    double fd = (kernel_w(&k, (r + eps) * (r + eps)) - kernel_w(&k, (r - eps) * (r - eps))) / (2 * eps);
    CHECK_CLOSE(kernel_f(&k, r * r) * r, fd, 1e-6 * fabs(fd) + 1e-9 * k.norm / k.h, name);
  }
  CHECK_CLOSE(kernel_w(&k, k.support2 * (1 - 1e-12)), 0.0, 1e-9 * k.norm, name);
}

/* kernel_exp against libm's exp over the Gaussian's range [-9, 0] (and beyond, to -700):
 * at most 3 units in the last place apart, and exact at 0. */
static void check_exp(void) {
  double worst_ulp = 0, worst_x = 0;
  for (long n = 0; n <= 7000000; n++) {
    double x = -700.0 * n / 7000000.0, y = n < 5000000 ? -9.0 * n / 5000000.0 : x;
    for (int t = 0; t < 2; t++) {
      double z = t ? y : x, ref = exp(z), ulp = nextafter(ref, INFINITY) - ref;
      double err = fabs(kernel_exp(z) - ref) / ulp;
      if (err > worst_ulp) worst_ulp = err, worst_x = z;
    }
  }
  CHECK(worst_ulp <= 3.0, "kernel_exp: %g ulp from libm at x = %.17g", worst_ulp, worst_x);
  CHECK(kernel_exp(0.0) == 1.0, "kernel_exp(0) = %.17g", kernel_exp(0.0));
}

int main(void) {
  check_exp();
  /* Lattice sums are exact only up to the truncation at the cut-off: measured errors are below
   * 1e-5 (sum W; 8e-5 in 3D at h/dx = 1.33) and 3e-3 (moments) for the Gaussian, 5e-3 for
   * Wendland C2. */
  check_kernel(KERNEL_GAUSSIAN, 2, 1.33, 1e-5, 2e-3, "gaussian 2D h/dx=1.33");
  check_kernel(KERNEL_GAUSSIAN, 2, 2.0, 1e-5, 2e-3, "gaussian 2D h/dx=2");
  check_kernel(KERNEL_GAUSSIAN, 3, 1.33, 1e-4, 3e-3, "gaussian 3D h/dx=1.33");
  check_kernel(KERNEL_GAUSSIAN, 3, 2.0, 1e-5, 2e-3, "gaussian 3D h/dx=2");
  check_kernel(KERNEL_WENDLAND_C2, 2, 2.0, 5e-3, 5e-3, "wendland 2D h/dx=2");
  check_kernel(KERNEL_WENDLAND_C2, 3, 2.0, 5e-3, 5e-3, "wendland 3D h/dx=2");
  return check_report("test_kernel");
}
