/* linalg.h — small dense 2x2 / 3x3 linear algebra for the per-particle matrices. */
#ifndef MPSPH_LINALG_H
#define MPSPH_LINALG_H

#include <math.h>

/** Solve M x = b for a dim x dim matrix M (row-major); returns det(M) (x is inf/nan if 0). */
static inline double linalg_solve(int dim, const double *m, const double *b, double *x) {
  if (dim == 2) {
    double det = m[0] * m[3] - m[1] * m[2];
    x[0] = (m[3] * b[0] - m[1] * b[1]) / det;
    x[1] = (m[0] * b[1] - m[2] * b[0]) / det;
    return det;
  }
  double c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8], c02 = m[3] * m[7] - m[4] * m[6];
  double det = m[0] * c00 + m[1] * c01 + m[2] * c02;
  double adj[9] = {c00, m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
                   c01, m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
                   c02, m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]};
  for (int a = 0; a < 3; a++) x[a] = (adj[3 * a] * b[0] + adj[3 * a + 1] * b[1] + adj[3 * a + 2] * b[2]) / det;
  return det;
}

/** Smallest eigenvalue of a symmetric dim x dim matrix (closed form; trigonometric in 3D). */
static inline double linalg_min_eigenvalue(int dim, const double *m) {
  if (dim == 2) {
    double mean = 0.5 * (m[0] + m[3]), half = 0.5 * (m[0] - m[3]);
    return mean - sqrt(half * half + m[1] * m[1]);
  }
  double p1 = m[1] * m[1] + m[2] * m[2] + m[5] * m[5], q = (m[0] + m[4] + m[8]) / 3.0;
  double p2 = (m[0] - q) * (m[0] - q) + (m[4] - q) * (m[4] - q) + (m[8] - q) * (m[8] - q) + 2 * p1;
  if (p2 <= 0) return q;
  double p = sqrt(p2 / 6.0), b[9];
  for (int k = 0; k < 9; k++) b[k] = (m[k] - (k % 4 == 0 ? q : 0)) / p;
  double r = 0.5 * (b[0] * (b[4] * b[8] - b[5] * b[7]) - b[1] * (b[3] * b[8] - b[5] * b[6]) +
                    b[2] * (b[3] * b[7] - b[4] * b[6]));
  double phi = acos(fmin(fmax(r, -1.0), 1.0)) / 3.0;
  return q + 2 * p * cos(phi + 2.0 * 3.14159265358979323846 / 3.0);
}

/** det(M) of a dim x dim matrix (row-major). */
static inline double linalg_det(int dim, const double *m) {
  if (dim == 2) return m[0] * m[3] - m[1] * m[2];
  return m[0] * (m[4] * m[8] - m[5] * m[7]) + m[1] * (m[5] * m[6] - m[3] * m[8]) +
         m[2] * (m[3] * m[7] - m[4] * m[6]);
}

/** inv = M^-1 of a dim x dim matrix (row-major); returns det(M) (inv is inf/nan if 0). */
static inline double linalg_inverse(int dim, const double *m, double *inv) {
  double det = linalg_det(dim, m);
  if (dim == 2) {
    inv[0] = m[3] / det, inv[1] = -m[1] / det, inv[2] = -m[2] / det, inv[3] = m[0] / det;
    return det;
  }
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {   /* inv[r][c] = cofactor of m[c][r] / det */
      int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      inv[3 * r + c] = (m[3 * r1 + c1] * m[3 * r2 + c2] - m[3 * r1 + c2] * m[3 * r2 + c1]) / det;
    }
  return det;
}

/** out = A B (transpose_a: A^T B) of dim x dim matrices (row-major); out is not A or B. */
static inline void linalg_matmul(int dim, const double *a, int transpose_a, const double *b, double *out) {
  for (int r = 0; r < dim; r++)
    for (int c = 0; c < dim; c++) {
      double sum = 0;
      for (int k = 0; k < dim; k++) sum += (transpose_a ? a[k * dim + r] : a[r * dim + k]) * b[k * dim + c];
      out[r * dim + c] = sum;
    }
}

#endif
