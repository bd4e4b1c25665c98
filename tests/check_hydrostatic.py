#!/usr/bin/env python3
"""Checks of a settled single-phase hydrostatic tank (water depth H, density rho0):

* bottom pressure probe `p_bottom`, averaged over the last second, within TOL_P of rho0 g H;
* kinetic energy decaying: mean over the last 10 % of the run below 0.1 x the mean over the
  first 10 %, and E_k/E_p below 1e-6 at the end (E_p = sum m g y from the tank bottom);
* the snapshots hold every particle with finite values.

Usage: check_hydrostatic.py RUN_DIR [H rho0 g TOL_P]
"""
import glob
import os
import sys

import h5py
import numpy as np


def main(run, depth=1.0, rho0=1000.0, g=9.81, tol_p=0.02):
    stats = np.genfromtxt(os.path.join(run, "stats.csv"), delimiter=",", names=True)
    probes = np.genfromtxt(os.path.join(run, "probes.csv"), delimiter=",", names=True)
    ke, t = stats["kinetic_energy_water"], stats["time"]
    last = probes["time"] > probes["time"][-1] - 1.0
    p_bottom = probes["p_bottom"][last].mean()
    p_exact = rho0 * g * depth
    err_p = abs(p_bottom / p_exact - 1)
    n10 = max(len(ke) // 10, 1)
    decay = ke[-n10:].mean() / ke[:n10].mean()
    snap = sorted(glob.glob(os.path.join(run, "snap_*.h5")))[-1]
    with h5py.File(snap, "r") as f:
        fluid = f["particles/phase"][:] >= 0
        y, m = f["particles/position"][:, 1][fluid], f["particles/mass"][:][fluid]
        finite = all(np.isfinite(f["particles/" + k][:]).all() for k in ("position", "velocity", "density", "pressure"))
    ep = (m * g * y).sum()
    ratio = ke[-1] / ep
    print(f"t_end {t[-1]:.3f} s: p_bottom {p_bottom:.1f} Pa vs rho g H {p_exact:.1f} Pa (error {100 * err_p:.2f} %, "
          f"limit {100 * tol_p:.1f} %)")
    print(f"kinetic energy: last/first 10 % mean = {decay:.3g} (limit 0.1), E_k/E_p at end = {ratio:.3g} (limit 1e-6)")
    ok = err_p <= tol_p and decay < 0.1 and ratio < 1e-6 and finite
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) not in (2, 6):
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], *map(float, sys.argv[2:])))
