#!/usr/bin/env python3
"""Static bubble (cases/static-bubble): the Laplace pressure jump p_in - p_out = sigma / R in 2D.

Over the snapshots from T_START on: R is the radius of the inner phase's area, sqrt(sum V / pi)
(V = m / rho, so the bubble's compression is accounted for); p_in the mean pressure of the inner
phase (phase 1) within R - 3h of the centre, p_out that of the outer phase (phase 0) beyond
R + 3h. Both are averaged over the snapshots, which filters the breathing oscillation the start
from a uniform pressure excites. Checks:
  - |<p_in - p_out> / (sigma / <R>) - 1| <= TOL (default 5 %);
  - the phases stay apart: no particle of one phase lies 3h or more on the other's side of R.
Reported: the spurious currents, the largest fluid speed per snapshot (its maximum and mean over
the window) and as a capillary number mu_out u / sigma.

Usage: check_static_bubble.py RUN_DIR [TOL [T_START]]   (T_START default 0.01 s)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from validation.metrics import read_snapshot, snapshots  # noqa: E402


def first_value(run, key):
    """The first `key: number` of the resolved case (config.yaml, block layout)."""
    with open(os.path.join(run, "config.yaml")) as f:
        for line in f:
            words = line.strip().lstrip("- ").split(":")
            if words[0] == key:
                return float(words[1])
    raise ValueError(f"no {key} in config.yaml")


def bubble_state(path, h):
    """Time, equivalent radius, p_in - p_out, max speed and the count of stray particles."""
    t, s = read_snapshot(path)
    inner = s["phase"] == 1
    r = np.hypot(s["position"][:, 0], s["position"][:, 1])
    radius = np.sqrt(np.sum(s["mass"][inner] / s["density"][inner]) / np.pi)
    core, far = inner & (r < radius - 3 * h), ~inner & (r > radius + 3 * h)
    jump = s["pressure"][core].mean() - s["pressure"][far].mean()
    stray = np.sum(inner & (r >= radius + 3 * h)) + np.sum(~inner & (r <= radius - 3 * h))
    return t, radius, jump, np.hypot(s["velocity"][:, 0], s["velocity"][:, 1]).max(), stray


def main(run, tol=0.05, t_start=0.01):
    sigma, mu_out = first_value(run, "surface_tension"), first_value(run, "viscosity")
    h = first_value(run, "dx") * first_value(run, "h_over_dx")
    rows = np.array([bubble_state(p, h) for p in snapshots(run)])
    window = rows[rows[:, 0] >= t_start - 1e-12]
    t, radius, jump, u_max, stray = window.T
    laplace = sigma / radius.mean()
    err = jump.mean() / laplace - 1
    print(f"{len(window)} snapshots, t = {t[0]:.4f} to {t[-1]:.4f} s: R = {radius.mean() * 1e3:.4f} mm, "
          f"p_in - p_out = {jump.mean():.4f} Pa (snapshots {jump.min():.2f} to {jump.max():.2f}), "
          f"sigma/R = {laplace:.4f} Pa, error {err:+.4f} (limit {tol})")
    print(f"spurious currents: max |u| {u_max.max():.3e} m/s, mean of the per-snapshot maxima "
          f"{u_max.mean():.3e} m/s (capillary number mu u / sigma {mu_out * u_max.mean() / sigma:.3g}); "
          f"stray particles {int(stray.max())}")
    ok = abs(err) <= tol and stray.max() == 0
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3, 4):
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], *map(float, sys.argv[2:])))
