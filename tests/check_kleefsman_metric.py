#!/usr/bin/env python3
"""check_kleefsman_metric.py - metrics.kleefsman_dambreak on constructed input: a run folder whose
probes.csv (every 2 ms, to 1 s) holds gauges offset from a constructed experiment (every 1 ms, to
2 s) by known amounts, a dry gauge written as nan, and a P1 with a peak inside the impact window
and a larger one outside it. The heights are piecewise linear with kinks on both grids, so the
interpolation is exact and the RMS is known. Exit status 1 on a failed check."""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

results = []   # (passed, what) of each check, printed at the end
check = lambda ok, what: results.append((bool(ok), what))  # noqa: E731

DEPTH = 0.55
OFFSETS = {"H1": 0.0, "H2": 0.011, "H3": -0.022, "H4": 0.0}   # RMS / H: 0, 0.02, 0.04, 0


def heights(t):
    """The constructed experiment: H1 dry until 0.5 s then rising, H2-H4 linear in t [m]."""
    return {"H1": np.where(t < 0.5, 0.0, 0.2 * (t - 0.5)), "H2": 0.1 + 0.05 * t, "H3": 0.3 - 0.1 * t,
            "H4": 0.55 - 0.2 * t}


def triangle(t, t0, peak, half=0.01):
    """A triangular pulse of height peak [Pa] centred on t0, half-width half [s]."""
    return peak * np.clip(1 - np.abs(t - t0) / half, 0, None)


def write_reference(path):
    t = np.round(np.arange(0, 2.0005, 0.001), 6)
    h = heights(t)
    cols = [t, triangle(t, 0.415, 11000.0)] + [np.zeros_like(t)] * 7 + [h[g] for g in metrics.KLEEFSMAN_GAUGES]
    with open(path, "w") as f:
        f.write("# constructed\nt_s,P1_Pa,P2_Pa,P3_Pa,P4_Pa,P5_Pa,P6_Pa,P7_Pa,P8_Pa,H1_m,H2_m,H3_m,H4_m\n")
        np.savetxt(f, np.column_stack(cols), delimiter=",", fmt="%.9g")


def write_probes(run):
    t = np.round(np.arange(0, 1.0005, 0.002), 6)
    h = heights(t)
    p1 = triangle(t, 0.45, 9000.0) + triangle(t, 0.8, 20000.0)   # the second outside 0.3-0.7 s
    cols = [np.arange(len(t)), t, p1] + [np.zeros_like(t)] * 7
    for g in metrics.KLEEFSMAN_GAUGES:
        cols.append(np.where(h[g] > 0, h[g] + OFFSETS[g], np.nan))   # dry: nan, as the gauge writes it
    with open(os.path.join(run, "probes.csv"), "w") as f:
        f.write("step,time,P1,P2,P3,P4,P5,P6,P7,P8,H1,H2,H3,H4\n")
        np.savetxt(f, np.column_stack(cols), delimiter=",", fmt="%.9g")


with tempfile.TemporaryDirectory() as run:
    ref = os.path.join(run, "reference.csv")
    write_reference(ref)
    write_probes(run)
    err, notes, curves = metrics.kleefsman_dambreak(run, 0.05, ref)
print(notes)
expected = math.sqrt((0.02 ** 2 + 0.04 ** 2) / 4)
check(abs(err - expected) < 1e-9, "error %.9f, expected sqrt((0.02^2 + 0.04^2) / 4) = %.9f" % (err, expected))
check("1001 samples per gauge to 1.00 s" in notes, "only the experiment's samples to the run's end (1 s) count")
check("H1 0.0000" in notes and "H2 0.0200" in notes and "H3 0.0400" in notes,
      "per gauge: the dry gauge (nan) read as 0, the offsets 0.011 and -0.022 m as 0.02 and 0.04 of H")
check("P1 peak in 0.3-0.7 s 9000 Pa at 0.450 s (experiment 11000 Pa at 0.415 s)" in notes,
      "P1's peak inside the impact window, not the larger one at 0.8 s, and the experiment's")
check(np.isnan(curves["H1"][0]) and len(curves["t_ref"]) == 2001, "curves: the run's columns as written, the whole reference")
for ok, what in results:
    print("%s %s" % ("ok  " if ok else "FAIL", what))
sys.exit(0 if all(ok for ok, _ in results) else 1)
