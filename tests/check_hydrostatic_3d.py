#!/usr/bin/env python3
"""Two-phase hydrostatic box in 3D (tests/cases/hydrostatic-3d-2phase.yaml): water (first phase)
below y = Hw, air above up to the lid, gravity along -y. Analytic pressure with p = p_b at the lid:
air p = rho_a g (lid - y), water p = rho_a g (lid - Hw) + rho_w g (Hw - y). Hw is the top of the
first fluid box, the lid the top of the first wall box; rho0, p_b and g come from the run's
config.yaml.

Checks (all asserted), in every snapshot from T_START on:
* away from the interface, i.e. over every fluid particle more than one kernel support 3h from
  y = Hw, max |p - p_b - p_exact| / (rho_w g Hw) <= TOL (default 2 %); the same error over all
  particles, the interface rows included, is printed only;
* no water particle above Hw + 3 dx and no air particle below Hw - 3 dx;
* every value finite;
and each phase's volume sum m/rho drifts by less than 0.5 % (stats.csv).

Usage: check_hydrostatic_3d.py RUN_DIR [TOL [T_START]]   (T_START default 0: every snapshot but
the initial one)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from validation.metrics import hydrostatic_exact, read_config, read_csv, read_snapshot, snapshots  # noqa: E402


def tank(case):
    """Hw, lid [m], rho_w, rho_a [kg/m^3], p_b [Pa], g [m/s^2], dx and h [m] of the resolved case."""
    water, air = case["phases"][0], case["phases"][1]
    dx = case["resolution"]["dx"]
    return {"h_w": case["fluids"][0]["box"]["max"][1], "lid": case["walls"][0]["box"]["max"][1],
            "rho_w": water["rho0"], "rho_a": air["rho0"], "p_b": water["p_background"],
            "g": float(np.linalg.norm(case["gravity"])), "dx": dx, "h": dx * case["resolution"]["h_over_dx"]}


def snapshot_errors(path, c):
    """Time, the pressure error away from the interface and everywhere (fractions of rho_w g Hw),
    the water particles above Hw + 3dx and air below Hw - 3dx, and whether all values are finite."""
    t, s = read_snapshot(path)
    y = s["position"][:, 1]
    exact = hydrostatic_exact(y, c["h_w"], c["rho_w"], c["rho_a"], c["lid"], c["g"])
    err = np.abs(s["pressure"] - c["p_b"] - exact) / (c["rho_w"] * c["g"] * c["h_w"])
    far = np.abs(y - c["h_w"]) > 3 * c["h"]
    stray = int(np.sum((s["phase"] == 0) & (y > c["h_w"] + 3 * c["dx"])) +
                np.sum((s["phase"] == 1) & (y < c["h_w"] - 3 * c["dx"])))
    finite = all(np.isfinite(s[k]).all() for k in ("position", "velocity", "density", "pressure"))
    return t, err[far].max(), err.max(), stray, finite


def main(run, tol=0.02, t_start=0.0):
    c = tank(read_config(run))
    rows = [snapshot_errors(p, c) for p in snapshots(run)[1:]]
    rows = [r for r in rows if r[0] >= t_start - 1e-12]
    t, far, everywhere, stray, finite = (np.array(v) for v in zip(*rows))
    worst = int(np.argmax(far))
    stats = read_csv(os.path.join(run, "stats.csv"))
    names = [k[len("volume_"):] for k in stats if k.startswith("volume_")]
    drift = [abs(stats["volume_" + n][-1] / stats["volume_" + n][0] - 1) for n in names]
    print(f"{len(t)} snapshots, t = {t[0]:.3f} to {t[-1]:.3f} s (Hw/dx = {c['h_w'] / c['dx']:.0f}): pressure error "
          f"beyond 3h of the interface max {100 * far.max():.2f} % of rho_w g Hw at t = {t[worst]:.3f} s "
          f"(limit {100 * tol:.1f} %); last snapshot {100 * far[-1]:.2f} %")
    print(f"with the interface rows: max {100 * everywhere.max():.2f} % (not asserted)")
    print(f"water above Hw + 3dx or air below Hw - 3dx: {stray.max()}; volume drift "
          + ", ".join(f"{n} {100 * d:.3f} %" for n, d in zip(names, drift)) + " (limit 0.5 %)")
    ok = far.max() <= tol and stray.max() == 0 and finite.all() and max(drift) < 0.005
    print("PASS" if ok else "FAIL")
    return int(not ok)


if __name__ == "__main__":
    args = sys.argv[1:]
    if not 1 <= len(args) <= 3:
        sys.exit(__doc__)
    sys.exit(main(args[0], *(float(a) for a in args[1:])))
