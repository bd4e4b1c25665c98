/* interface.h — the epsilon/phi/kappa weights of the delta-u terms at fluid–fluid and fluid–solid
 * interfaces (paper 000 Table 1, Eqs. 16–19, Appendix A Table A.2). */
#ifndef MPSPH_INTERFACE_H
#define MPSPH_INTERFACE_H

/** Relation of neighbour j to particle i. */
enum pair_relation { PAIR_SAME = 0, PAIR_OTHER = 1, PAIR_WALL = 2 };

/** Weights of one relation: the contribution of pair (i, j) to drho_i/dt from the delta-u terms
 *  is [-rho_i (eps_ij du_j - eps_ii du_i) + phi_ij rho_j du_j + phi_ii rho_i du_i] . gradW_ij V_j;
 *  kappa_ij switches the pair in the momentum delta-u term. */
struct interface_weights {
  double eps_ii, eps_ij, phi_ii, phi_ij, kappa;
};

/** The weights of the three relations for interface mode 1..4 of Appendix A
 *  (1: *1 solid, *1 fluid; 2: *2, *2; 3: *2 solid, *1 fluid; 4: *1 solid, *2 fluid = final model). */
void interface_table(int mode, struct interface_weights table[3]);

/** Coefficients of du_i and du_j in the pair's continuity contribution
 *  [c_i du_i + c_j du_j] . gradW_ij V_j: c_i = (eps_ii + phi_ii) rho_i, c_j = phi_ij rho_j - eps_ij rho_i. */
static inline void interface_continuity_coefficients(const struct interface_weights *w, double rho_i,
                                                     double rho_j, double *c_i, double *c_j) {
  *c_i = (w->eps_ii + w->phi_ii) * rho_i;
  *c_j = w->phi_ij * rho_j - w->eps_ij * rho_i;
}

#endif
