#!/usr/bin/env python3
"""check_air_pocket_metric.py - metrics.air_pocket (the air-pocket sloshing study) on synthetic
runs written here: a tank swaying by d(t), its right part holding an air pocket whose particles'
density follows a prescribed compression, probes.csv with p_a1 the pocket's adiabatic pressure
and p_w1 in phase with it. Checks: the adiabatic error vanishes for a consistent probe and is
RMS(shift)/range for a shifted one; air left of the partition (variant #1) is not counted; the
phase error vanishes for p_w1 = p_a1 + const; the variants' agreement is RMS/range of the
difference of the two runs' probes; a run ending before 12 s reports the 5-12 s criteria as n.a. Exit status 1 on a failed
check."""
import math
import os
import sys
import tempfile

import h5py
import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

failed = 0
B = 1.0 * 340.0 ** 2 / 1.4   # the air's rho0 c0^2 / gamma [Pa]
X_SPLIT = 0.918


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what))
    failed += not ok


def pocket_pressure(t):
    """The prescribed pocket pressure [Pa]."""
    return 300.0 * math.sin(3.68 * t) + 50.0


def write_run(folder, t_end, left_air, probe_shift=0.0, w2_bump=0.0):
    """A synthetic run to t_end: snapshots every 0.5 s, probes every 0.05 s."""
    os.makedirs(folder)
    fluids = [{"phase": "water", "box": {"min": [0, 0], "max": [0.85, 0.17]}}]
    if left_air:
        fluids.append({"phase": "air", "box": {"min": [0, 0.17], "max": [0.85, 0.408]}})
    config = {"phases": [{"name": "water", "rho0": 1000.0, "c0": 20.0, "gamma": 7.0},
                         {"name": "air", "rho0": 1.0, "c0": 340.0, "gamma": 1.4}], "fluids": fluids}
    with open(os.path.join(folder, "config.yaml"), "w") as f:
        yaml.safe_dump(config, f)
    for k, t in enumerate(np.arange(0, t_end + 1e-9, 0.5)):
        shift = 0.04 * math.sin(3.68 * t)   # the tank's displacement: the pocket moves with it
        n = 30
        x = np.concatenate([[-0.06 + shift], 1.0 + shift + 0.01 * np.arange(n), 0.9 + shift + 0.0 * np.arange(5),
                            0.1 + shift + 0.01 * np.arange(n if left_air else 0)])
        phase = np.concatenate([[-1], np.ones(n), np.zeros(5), np.ones(n if left_air else 0)]).astype(np.int32)
        rho = np.ones(len(x))
        rho[1:1 + n] = (1 + pocket_pressure(t) / B) ** (1 / 1.4)   # the pocket's air
        rho[phase == 0] = 1000.0
        rho[1 + n + 5:] = 0.97   # the left tank's air (variant #1): other than the pocket's
        mass = np.where(phase == 0, 1000.0, 1.0) * 1e-4
        with h5py.File(os.path.join(folder, "snap_%05d.h5" % k), "w") as f:
            f.create_group("header").attrs["time"] = t
            pos = np.zeros((len(x), 2))
            pos[:, 0] = x
            for name, data in (("phase", phase), ("position", pos), ("velocity", np.zeros_like(pos)),
                               ("density", rho), ("pressure", np.zeros(len(x))), ("mass", mass)):
                f["particles/" + name] = data
    t = np.arange(0, t_end + 1e-9, 0.05)
    p_a1 = np.array([pocket_pressure(s) for s in t]) + probe_shift
    rows = np.column_stack([np.arange(len(t)), t, 600 + 100 * np.sin(2 * t) + w2_bump, 650 + 30 * np.cos(t), 700 + p_a1, p_a1])
    np.savetxt(os.path.join(folder, "probes.csv"), rows, delimiter=",", header="step,time,p_w2,p_w3,p_w1,p_a1",
               comments="")


with tempfile.TemporaryDirectory() as tmp:
    write_run(os.path.join(tmp, "a", "v2_dx0.017_np2"), 12.0, False)
    write_run(os.path.join(tmp, "a", "v1_dx0.017_np2"), 12.0, True, w2_bump=20.0)
    err, notes, curves = metrics.air_pocket(os.path.join(tmp, "a", "v2_dx0.017_np2"), 0.017, x_split=X_SPLIT)
    print("   " + notes)
    win = (curves["t"] >= 5) & (curves["t"] <= 12)
    w2 = 600 + 100 * np.sin(2 * curves["t"][win])
    expect = 20.0 / np.ptp(w2)
    check(abs(err - expect) < 1e-9 and "worst: variants" in notes,
          "variant #2 against #1 (p_w2 off by 20 Pa): error %.6f = 20 Pa / range(p_w2) %.6f" % (err, expect))
    check("adiabatic 0.0000" in notes and "phase 0.0000" in notes,
          "a consistent probe: adiabatic and phase errors vanish")
    err1, notes1, _ = metrics.air_pocket(os.path.join(tmp, "a", "v1_dx0.017_np2"), 0.017, x_split=X_SPLIT)
    check(abs(err1 - expect) < 1e-9 and "pocket particles 30 to 30" in notes1,
          "variant #1: the same agreement (%.6f), the left tank's air not counted in the pocket" % err1)

    write_run(os.path.join(tmp, "b", "v2_dx0.017_np1"), 3.0, False, probe_shift=12.0)
    err, notes, _ = metrics.air_pocket(os.path.join(tmp, "b", "v2_dx0.017_np1"), 0.017, x_split=X_SPLIT)
    print("   " + notes)
    t = np.arange(0, 3.0 + 1e-9, 0.5)
    p = np.array([pocket_pressure(s) for s in t]) + 12.0
    check(abs(err - 12.0 / np.ptp(p)) < 1e-6, "a probe 12 Pa off: adiabatic error %.6f = 12 Pa / range %.6f" %
          (err, 12.0 / np.ptp(p)))
    check(notes.count("n.a.") == 1 and "before 12 s" in notes, "a run ending at 3 s: phase and agreement n.a.")
sys.exit(1 if failed else 0)
