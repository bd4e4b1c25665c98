#!/usr/bin/env python3
"""check_layered_sloshing.py - the linear layered sloshing of the three-liquid case
(scripts/validation/metrics.py: layered_modes, layered_sloshing, sloshing_layers) against closed forms:
  - one layer: omega^2 = g k tanh(k h), and at resonance with x = A (1 - cos(omega t)) the first mode's
    elevation is (F / 2 omega) t sin(omega t) cos(k (x - X(t))), F = 4 L A omega^4 / (g pi^2), at a
    gauge fixed in space at x (the tank displaced by X);
  - three layers of one density: the free-surface mode of the one-layer tank, the others at omega = 0,
    and the same elevation as one layer;
  - two layers: the roots of Lamb's two-layer relation (Hydrodynamics section 231)
    omega^4 (rho1 coth k h1 coth k h2 + rho2) - omega^2 g k rho1 (coth k h1 + coth k h2) + (rho1 - rho2) g^2 k^2 = 0;
  - the metric on a constructed run (the gauges the linear solution times 0.9, the interfaces times 1.1,
    volumes drifting 0.2 %): error 0.1, the RMS misfit 10 % and the drift in its notes; with a snapshot of three lattice
    layers holding one water particle inside the lowest, that particle counted among the others.
Exit status 1 on a failed check."""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

results = []   # (passed, what) of each check, printed at the end
check = lambda ok, what: results.append((bool(ok), what))  # noqa: E731
G = metrics.G

# one layer
L, H, A = 1.5, 0.6, 0.005
k = math.pi / L
w2, shapes, d = metrics.layered_modes(k, [H], [1000.0])
omega = math.sqrt(G * k * math.tanh(k * H))
check(abs(math.sqrt(w2[0]) / omega - 1) < 1e-12, "one layer: omega %.12f against sqrt(g k tanh k h) %.12f"
      % (math.sqrt(w2[0]), omega))
t = np.linspace(0, 3, 301)
# a gauge fixed in space at x = 0.5 m sees the mode at 0.5 - X(t) in the tank, which the sway X moves
# by +X (a sign error there is 4.6 % of the elevation); the y modes, at the mid-line's tank-frame
# offset, taken out with a second call without x motion
eta = metrics.layered_sloshing(t, 0.5, 0.5, (L, 1.0), [H], [1000.0], A, (omega, 4.14), n_odd=1)[0]
eta_y = metrics.layered_sloshing(t, 0.5, 0.5, (L, 1.0), [H], [1000.0], A, (0.0, 4.14), n_odd=1)[0]
force = 4 * L * A * omega ** 4 / (G * math.pi ** 2)
closed = force / (2 * omega) * t * np.sin(omega * t) * np.cos(k * (0.5 - A * (1 - np.cos(omega * t))))
worst = np.max(np.abs(eta - eta_y - closed)) / np.max(np.abs(closed))
check(worst < 1e-9, "one layer at resonance, gauge at x = 0.5 m: (F / 2 omega) t sin(omega t) cos(k (x - X)) "
      "within %.1e of its largest value" % worst)

# three layers of one density
w2_3, _, _ = metrics.layered_modes(k, [0.2, 0.2, 0.2], [1000.0] * 3)
check(abs(math.sqrt(w2_3[-1]) / omega - 1) < 1e-12 and np.all(np.abs(w2_3[:-1]) < 1e-9),
      "three layers of one density: omega %s against %.12f and 0, 0" % (np.sqrt(np.abs(w2_3)), omega))
eta_3 = metrics.layered_sloshing(t, 0.0, 0.5, (L, 1.0), [0.2, 0.2, 0.2], [1000.0] * 3, A, (omega, 4.14))[2]
eta_1 = metrics.layered_sloshing(t, 0.0, 0.5, (L, 1.0), [H], [1000.0], A, (omega, 4.14))[0]
check(np.max(np.abs(eta_3 - eta_1)) < 1e-9 * np.max(np.abs(eta_1)), "three layers of one density: the free "
      "surface of one layer within %.1e m" % np.max(np.abs(eta_3 - eta_1)))

# two layers: Lamb's relation
rho1, rho2, h1, h2 = 1000.0, 846.0, 0.1, 0.05
for kk in (math.pi / 0.57, 3 * math.pi / 0.57):
    c1, c2 = 1 / math.tanh(kk * h1), 1 / math.tanh(kk * h2)
    roots = np.sort(np.roots([rho1 * c1 * c2 + rho2, -G * kk * rho1 * (c1 + c2), (rho1 - rho2) * G ** 2 * kk ** 2]))
    w2_2, _, _ = metrics.layered_modes(kk, [h1, h2], [rho1, rho2])
    check(np.max(np.abs(np.sort(w2_2) / roots - 1)) < 1e-10, "two layers, k = %.3f 1/m: omega^2 %s against "
          "Lamb's %s" % (kk, np.sort(w2_2), roots))

# the metric on a constructed run
with tempfile.TemporaryDirectory() as run:
    where = {"S1": (0.4, 0.5425), "I1": (0.4, 0.5425), "S2": (1.185, 0.5425), "I2": (1.185, 0.5425)}
    tt = np.round(np.arange(0, 3.0 + 1e-9, 0.01), 6)
    cols = {}
    for g, (x, y) in where.items():
        lin = metrics.layered_sloshing(tt, x, y, (1.5, 1.0), (0.2, 0.2, 0.2), (1300.0, 1000.0, 780.0), 0.0425,
                                       (4.18, 4.14))
        cols[g] = (0.6 + 0.9 * lin[2]) if g[0] == "S" else (0.4 + 1.1 * lin[1])
    for c in ("C1", "C2", "C3", "C4"):
        cols[c] = 0.6 + 0.01 * np.sin(tt)
    for p in ("DIC", "WAT", "CYC"):
        cols[p + "_volume"] = 0.3 * (1 + 0.002 * tt / tt[-1])
    with open(os.path.join(run, "probes.csv"), "w") as f:
        f.write("step,time," + ",".join(cols) + "\n")
        for i, ti in enumerate(tt):
            f.write("%d,%g," % (i, ti) + ",".join("%.12g" % cols[c][i] for c in cols) + "\n")
    with open(os.path.join(run, "config.yaml"), "w") as f:
        f.write("probes:\n" + "".join("  - {name: %s, position: [%g, %g, 0.5]}\n" % (g, x, y)
                                      for g, (x, y) in where.items()))
    err, notes, _ = metrics.sloshing_layers(run, 0.05)
    check(abs(err - 0.1) < 1e-9 and "0.200 / 0.200 / 0.200 %" in notes and "eta_lin 10 %" in notes,
          "metric: error %.12f (0.1 expected), notes: %s" % (err, notes))
    # a snapshot at 2.8 s: three lattice layers 6 particles deep, one water particle in the middle of
    # the dichloromethane layer, and a wall particle (phase -1) left out
    import h5py
    dx = 0.05
    grid = (np.stack(np.meshgrid(*[np.arange(6)] * 2, np.arange(18), indexing="ij"), -1).reshape(-1, 3) + 0.5) * dx
    phase = (grid[:, 2] // (6 * dx)).astype(np.int32)
    phase[np.argmin(np.sum((grid - [0.15, 0.15, 0.15]) ** 2, axis=1))] = 1
    with h5py.File(os.path.join(run, "snap_00028.h5"), "w") as f:
        f.create_group("header").attrs["time"] = 2.8
        n = len(grid) + 1
        f["particles/phase"] = np.append(phase, -1)
        f["particles/position"] = np.vstack([grid, [[0, 0, -dx]]])
        for key in ("density", "pressure", "mass"):
            f["particles/" + key] = np.zeros(n)
        f["particles/velocity"] = np.zeros((n, 3))
    _, notes, _ = metrics.sloshing_layers(run, dx)
    check(notes.endswith("at t = 2.80 s 0 / 1 / 0 particles among the other liquids only, 0.154 % of 648"),
          "metric: one water particle among dichloromethane: %s" % notes[notes.rfind(";") + 2:])

for ok, what in results:
    print(("PASS " if ok else "FAIL ") + what)
sys.exit(0 if all(ok for ok, _ in results) else 1)
