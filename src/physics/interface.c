/* interface.c — strategies *1 (Eq. 18) and *2 (Eq. 19) of paper 000 and the modes built from them. */
#include "physics/interface.h"

/* Strategy *1: eps = 1 always; phi = 1 only within the same set. Strategy *2: eps_ii = phi_ii = 1
 * always; eps_ij = phi_ij = 1 only within the same set. */
static struct interface_weights strategy(int which, int same_set) {
  struct interface_weights w;
  if (which == 1) {
    w.eps_ii = w.eps_ij = 1;
    w.phi_ii = w.phi_ij = same_set;
  } else {
    w.eps_ii = w.phi_ii = 1;
    w.eps_ij = w.phi_ij = same_set;
  }
  w.kappa = same_set;
  return w;
}

void interface_table(int mode, struct interface_weights table[3]) {
  static const int solid_strategy[5] = {0, 1, 2, 2, 1}, fluid_strategy[5] = {0, 1, 2, 1, 2};
  table[PAIR_SAME] = strategy(1, 1);
  table[PAIR_OTHER] = strategy(fluid_strategy[mode], 0);
  table[PAIR_WALL] = strategy(solid_strategy[mode], 0);
}
