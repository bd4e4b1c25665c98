#!/usr/bin/env python3
"""Static bubble (cases/static-bubble, tests/cases/static-bubble-3d.yaml): the Laplace pressure
jump p_in - p_out = sigma / R in 2D, 2 sigma / R in 3D.

Over the snapshots from T_START on: R is the radius of the inner phase's area, sqrt(sum V / pi),
or volume, (3 sum V / (4 pi))^(1/3) in 3D (V = m / rho, so the bubble's compression is accounted
for); p_in the mean pressure of the inner phase (phase 1) within R - 3h of the centre, p_out that
of the outer phase (phase 0) beyond R + 3h. Both are averaged over the snapshots, which filters
the breathing oscillation the start from a uniform pressure excites. Checks:
  - |<p_in - p_out> / ((d - 1) sigma / <R>) - 1| <= TOL (default 5 %);
  - the phases stay apart: no particle of one phase lies 3h or more on the other's side of R.
Reported: the spurious currents, the largest fluid speed per snapshot (its maximum and mean over
the window) and as a capillary number mu_out u / sigma.

Usage: check_static_bubble.py RUN_DIR [TOL [T_START]]   (T_START default 0.01 s)
"""
import os
import sys


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from validation.metrics import read_config, static_bubble_series  # noqa: E402  (the measure, one copy)


def main(run, tol=0.05, t_start=0.01):
    rows, tension = static_bubble_series(run, t_start)
    case = read_config(run)
    sigma, mu_out = case["physics"]["surface_tension"], case["phases"][0]["viscosity"]
    t, radius, jump, u_max, stray = rows.T
    laplace = tension / radius.mean()
    err = jump.mean() / laplace - 1
    print(f"{len(t)} snapshots, t = {t[0]:.4f} to {t[-1]:.4f} s: R = {radius.mean() * 1e3:.4f} mm, "
          f"p_in - p_out = {jump.mean():.4f} Pa (snapshots {jump.min():.2f} to {jump.max():.2f}), "
          f"{case['dimension'] - 1} sigma/R = {laplace:.4f} Pa, error {err:+.4f} (limit {tol})")
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
