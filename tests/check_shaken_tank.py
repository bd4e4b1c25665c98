#!/usr/bin/env python3
"""Shaken closed tank (tests/cases/shaken-tank.yaml): a tank full of water moved sideways by a
prescribed law has the rigid motion with the tank as its exact solution, with the pressure
gradient grad p = rho (g - a_tank). Checked on every snapshot from t = SETTLE on, once the
acoustic waves the ramp excites have been damped (the case's damper, alpha2 = 1, takes them
out in about 0.2 s; with alpha2 = 10 the damper's bulk viscosity alpha2 c0 h makes the pressure
lag the acceleration by about 8 % at this c0 and period):
  - mean fluid velocity against the tank's, relative to the largest tank speed;
  - horizontal pressure gradient (least-squares plane through the fluid pressures) against
    -rho a_tank, relative to rho max|a_tank|; vertical gradient against -rho g;
  - no fluid particle outside the moving tank.
Usage: check_shaken_tank.py RUN_DIR TOL_VELOCITY TOL_GRADIENT
"""
import glob
import math
import os
import sys

import h5py
import numpy as np

A, PERIOD, RAMP = 0.05, 1.0, 0.25     # the case's translation law
SETTLE = 0.5                          # [s]
L, RHO, G = 0.4, 1000.0, 9.81


def ramp(t):
    """Smooth (quintic) ramp and its two derivatives."""
    if t >= RAMP:
        return 1.0, 0.0, 0.0
    s = t / RAMP
    return (s ** 3 * (10 - 15 * s + 6 * s * s), 30 * s * s * (1 - s) ** 2 / RAMP,
            60 * s * (1 - s) * (1 - 2 * s) / RAMP ** 2)


def tank(t):
    """Displacement, velocity, acceleration of the tank: A r(t) sin(w t)."""
    w = 2 * math.pi / PERIOD
    r, r1, r2 = ramp(t)
    s, c = math.sin(w * t), math.cos(w * t)
    return A * r * s, A * (r1 * s + r * w * c), A * (r2 * s + 2 * r1 * w * c - r * w * w * s)


def main(run, tol_u, tol_grad):
    w = 2 * math.pi / PERIOD
    u_scale, a_scale = A * w, A * w * w
    worst_u = worst_gx = worst_gy = 0.0
    outside = 0
    for path in sorted(glob.glob(os.path.join(run, "snap_*.h5"))):
        with h5py.File(path, "r") as f:
            t = float(f["header"].attrs["time"])
            fluid = f["particles/phase"][:] >= 0
            x = f["particles/position"][:][fluid]
            u = f["particles/velocity"][:][fluid]
            p = f["particles/pressure"][:][fluid]
            m = f["particles/mass"][:][fluid]
        if t < SETTLE:
            continue
        d, ut, at = tank(t)
        worst_u = max(worst_u, abs(np.average(u[:, 0], weights=m) - ut) / u_scale)
        coef, *_ = np.linalg.lstsq(np.c_[np.ones(len(p)), x[:, 0], x[:, 1]], p, rcond=None)
        worst_gx = max(worst_gx, abs(coef[1] + RHO * at) / (RHO * a_scale))
        worst_gy = max(worst_gy, abs(coef[2] + RHO * G) / (RHO * G))
        outside += int(np.sum((x[:, 0] < d - 1e-9) | (x[:, 0] > d + L + 1e-9) | (x[:, 1] < -1e-9)))
    print(f"mean velocity error {100 * worst_u:.2f} % of A w; horizontal pressure gradient error "
          f"{100 * worst_gx:.2f} % of rho A w^2; vertical {100 * worst_gy:.2f} % of rho g; "
          f"{outside} fluid particles outside the tank")
    ok = worst_u <= tol_u and worst_gx <= tol_grad and worst_gy <= tol_grad and outside == 0
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], float(sys.argv[2]), float(sys.argv[3])))
