#!/usr/bin/env python3
"""check_panel_metric.py - the pieces of metrics.panel_slamming on constructed input: inside_polygon
and depth_inside on a concave polygon (the panel of cases/panel-slamming), stray_air on a lattice
of water with one lone air particle, an air column and an air layer on top, and pocket_air on a
pocket between the panel's dents. Exit status 1 on a failed check."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

results = []   # (passed, what) of each check, printed at the end
check = lambda ok, what: results.append((bool(ok), what))  # noqa: E731

panel = np.array([[-0.32, 0.1], [-0.25, 0.1], [-0.19, 0.02], [-0.15, 0.02], [-0.09, 0.1], [0.09, 0.1], [0.15, 0.03],
                  [0.19, 0.03], [0.25, 0.1], [0.32, 0.1], [0.32, 0.3], [-0.32, 0.3]])
points = np.array([[-0.17, 0.05], [0.0, 0.05], [0.0, 0.2], [-0.17, 0.01], [0.17, 0.04], [0.4, 0.2], [0.0, 0.099]])
inside = metrics.inside_polygon(points, panel)
check(list(inside) == [True, False, True, False, True, False, False],
      "inside the dents and the body, outside in the pocket, under a tip, beside and just under the face: %s" % inside)
depth = metrics.depth_inside(points[[0, 2]], panel)
check(np.allclose(depth, [0.03, 0.1]), "depth inside: %s m (0.03 to the left tip, 0.1 to the face)" % depth)

dx = 0.01
x, y = np.meshgrid(np.arange(20) * dx, np.arange(20) * dx)
lattice = np.column_stack([x.ravel(), y.ravel()])
phase = np.where(lattice[:, 1] >= 0.15, 1, 0)           # an air layer on top (y >= 0.15)
phase[(lattice[:, 0] < 0.025) & (lattice[:, 1] < 0.15)] = 1   # an air column of three particles' width
lone = np.argmin(np.hypot(lattice[:, 0] - 0.1, lattice[:, 1] - 0.07))
phase[lone] = 1
snap = {"position": lattice, "phase": phase, "pressure": np.zeros(len(phase))}
check(metrics.stray_air(snap, dx) == 1, "one stray air particle: %d" % metrics.stray_air(snap, dx))

pocket = {"position": np.array([[0.0, 0.05], [0.05, 0.09], [0.0, 0.02], [-0.17, 0.05], [0.12, 0.09], [0.0, 0.05]]),
          "phase": np.array([1, 1, 1, 1, 1, 0]), "pressure": np.zeros(6)}
air = metrics.pocket_air(pocket, panel, (3, 6, 5))
check(list(air) == [True, True, False, False, False, False],
      "pocket air: between the tips under the face; not below the tips, beside them, in a dent, nor water: %s" % air)
for ok, what in results:
    print("%s %s" % ("ok  " if ok else "FAIL", what))
sys.exit(0 if all(ok for ok, _ in results) else 1)
