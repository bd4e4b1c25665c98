#!/usr/bin/env python3
"""Checks of an elastic solid's solids.csv (tests/physics_elastic_gate.sh).

  check_gate.py hydrostatic RUN T0 LIMIT
                                     a solid clamped whole holds the case's water column: the
                                     horizontal force of the water on it, mean over t >= T0,
                                     within 2 % of the hydrostatic thrust rho0 g H^2 / 2 (H the
                                     height of fluid region 0), and every sample within LIMIT
                                     (a fraction)
  check_gate.py snapshot RUN         the last snapshot's /solids group agrees with the rest of the
                                     run: the displacement of the probe's particle (the one whose
                                     reference position is nearest the case's probe) equals
                                     solids.csv's last row (its 12 digits), the stress is symmetric, and the solid
                                     particles' pressures are -tr(sigma)/dim, to round-off
  check_gate.py early RUN            the elastic gate's free end over the experiment's points with
                                     t <= 0.1 s: |u_SPH - u_exp| within 15 % of max |u_exp| over
                                     0-0.4 s, horizontally and vertically (notes seed-002 section
                                     2.4, acceptance 4)
Exit status 1 on a failed check."""
import os
import sys

import glob

import h5py
import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cases", "elastic-gate-antoci",
                         "reference", "fsi_elastic_gate_antoci2007_tip_displacement_digitized.csv")


def hydrostatic(run, t0, limit):
    with open(os.path.join(run, "config.yaml")) as f:
        case = yaml.safe_load(f)
    box = case["fluids"][0]["box"]
    height = box["max"][1] - box["min"][1]
    thrust = case["phases"][0]["rho0"] * abs(case["gravity"][1]) * height ** 2 / 2
    s = metrics.read_csv(os.path.join(run, "solids.csv"))
    force = np.abs(s["solid0_fx"][s["time"] >= t0])
    mean, worst = force.mean() / thrust - 1, np.abs(force / thrust - 1).max()
    print("hydrostatic thrust %.3f N/m: mean force over t >= %g s %+.2f %%, largest sample deviation %.2f %% "
          "(%d samples)" % (thrust, t0, 100 * mean, 100 * worst, len(force)))
    return len(force) > 10 and abs(mean) < 0.02 and worst < limit


def snapshot(run):
    with open(os.path.join(run, "config.yaml")) as f:
        case = yaml.safe_load(f)
    probe, dim = np.array(case["solids"][0]["probe"]), case["dimension"]
    with h5py.File(sorted(glob.glob(os.path.join(run, "snap_*.h5")))[-1], "r") as f:
        t = float(f["header"].attrs["time"])
        g = f["solids"]
        x0 = g["solid0_reference_position"][:].reshape(-1, dim)
        u = g["solid0_displacement"][:].reshape(-1, dim)
        sigma = g["solid0_stress"][:].reshape(-1, dim, dim)
        solid = f["particles/phase"][:] == -2
        ids = f["particles/id"][:][solid]
        pressure = f["particles/pressure"][:][solid][np.argsort(ids)]
    s = metrics.read_csv(os.path.join(run, "solids.csv"))
    k = int(np.argmin(np.linalg.norm(x0 - probe, axis=1)))
    row = np.array([s["solid0_u" + "xyz"[d]][-1] for d in range(dim)])
    scale = np.abs(sigma).max()
    checks = [abs(s["time"][-1] - t) < 1e-12, np.abs(u[k] - row).max() <= 1e-10 * max(np.abs(row).max(), 1e-30),
              np.abs(sigma - np.transpose(sigma, (0, 2, 1))).max() <= 1e-9 * scale,
              np.abs(pressure + np.trace(sigma, axis1=1, axis2=2) / dim).max() <= 1e-12 * scale]
    print("snapshot at t = %.6g s (solids.csv %.6g): probe displacement %s against %s; stress asymmetry %.3g, "
          "pressure vs -tr(sigma)/dim %.3g, of %.3g Pa" % (
              t, s["time"][-1], u[k], row, np.abs(sigma - np.transpose(sigma, (0, 2, 1))).max(),
              np.abs(pressure + np.trace(sigma, axis1=1, axis2=2) / dim).max(), scale))
    return all(checks)


def early(run):
    got = metrics.gate_early(run, REFERENCE)
    if got is None:
        print("solids.csv ends before t = 0.1 s")
        return False
    print("largest |u_SPH - u_exp| for t <= 0.1 s in units of max |u_exp|: x %.3f, y %.3f (limit 0.15)" % (
        got["x"], got["y"]))
    return all(v < 0.15 for v in got.values())


if __name__ == "__main__":
    mode = sys.argv[1]
    ok = hydrostatic(sys.argv[2], float(sys.argv[3]), float(sys.argv[4])) if mode == "hydrostatic" else \
        snapshot(sys.argv[2]) if mode == "snapshot" else early(sys.argv[2])
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)
