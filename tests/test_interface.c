/* test_interface.c — the epsilon/phi/kappa weights of paper 000 Table 1 (mode 4, the final
 * model) and Appendix A Table A.2 (modes 1-3), entry by entry, and the per-pair continuity
 * contributions they give (notes §1.5): same fluid [(rho_j - rho_i) du_j + 2 rho_i du_i],
 * other fluid 2 rho_i du_i, wall rho_i du_i (each dotted with gradW V_j). */
#include "check.h"
#include "physics/interface.h"

/* Expected (eps_ii, eps_ij, phi_ii, phi_ij, kappa) per mode and relation (same, other, wall). */
static const double expected[5][3][5] = {
    {{0}},
    /* mode 1: *1 at solids, *1 at fluid interfaces */
    {{1, 1, 1, 1, 1}, {1, 1, 0, 0, 0}, {1, 1, 0, 0, 0}},
    /* mode 2: *2, *2 */
    {{1, 1, 1, 1, 1}, {1, 0, 1, 0, 0}, {1, 0, 1, 0, 0}},
    /* mode 3: *2 at solids, *1 at fluid interfaces */
    {{1, 1, 1, 1, 1}, {1, 1, 0, 0, 0}, {1, 0, 1, 0, 0}},
    /* mode 4: *1 at solids, *2 at fluid interfaces (Table 1) */
    {{1, 1, 1, 1, 1}, {1, 0, 1, 0, 0}, {1, 1, 0, 0, 0}},
};

int main(void) {
  static const char *rel_name[3] = {"same", "other", "wall"};
  for (int mode = 1; mode <= 4; mode++) {
    struct interface_weights t[3];
    interface_table(mode, t);
    for (int r = 0; r < 3; r++) {
      const double *x = expected[mode][r];
      CHECK(t[r].eps_ii == x[0] && t[r].eps_ij == x[1] && t[r].phi_ii == x[2] && t[r].phi_ij == x[3] &&
                t[r].kappa == x[4],
            "mode %d, %s: got eps_ii %g eps_ij %g phi_ii %g phi_ij %g kappa %g", mode, rel_name[r],
            t[r].eps_ii, t[r].eps_ij, t[r].phi_ii, t[r].phi_ij, t[r].kappa);
    }
  }
  struct interface_weights t[3];
  double ci, cj, rho_i = 1000, rho_j = 1.5;
  interface_table(4, t);
  interface_continuity_coefficients(&t[PAIR_SAME], rho_i, rho_j, &ci, &cj);
  CHECK(ci == 2 * rho_i && cj == rho_j - rho_i, "same fluid: %g du_i + %g du_j", ci, cj);
  interface_continuity_coefficients(&t[PAIR_OTHER], rho_i, rho_j, &ci, &cj);
  CHECK(ci == 2 * rho_i && cj == 0, "other fluid: %g du_i + %g du_j", ci, cj);
  interface_continuity_coefficients(&t[PAIR_WALL], rho_i, rho_j, &ci, &cj);
  CHECK(ci == rho_i && cj == -rho_i, "wall (du_j = 0): %g du_i + %g du_j", ci, cj);
  return check_report("test_interface");
}
