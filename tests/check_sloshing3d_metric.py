#!/usr/bin/env python3
"""check_sloshing3d_metric.py - metrics.sloshing_growth on constructed input: run folders whose
probes.csv (every 5 ms) holds the gauge as the still level 0.15 m plus the linear resonant
solution at the gauge (metrics.forced_sloshing_linear) times a known factor, to 3 s and to 2 s,
and once with an offset at t = 0 kept to the end (the metric subtracts the first reading). The
rate is checked against the notes' figures (0.0131 m/s x 0.994). Exit status 1 on a failed check."""
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

results = []   # (passed, what) of each check, printed at the end
check = lambda ok, what: results.append((bool(ok), what))  # noqa: E731

OMEGA = 6.0578
RATE = metrics.forced_sloshing_rate(0.57, 0.005, OMEGA, 0.02)


def write_run(folder, factor, t_end, offset=0.0):
    """A run folder with probes.csv: WG = 0.15 + offset + factor x the linear solution, 0 to t_end."""
    os.makedirs(folder)
    t = np.round(np.arange(0, t_end + 1e-9, 0.005), 6)
    wg = 0.15 + offset + factor * metrics.forced_sloshing_linear(t, RATE, OMEGA)
    with open(os.path.join(folder, "probes.csv"), "w") as f:
        f.write("step,time,WG\n")
        for k, (ti, w) in enumerate(zip(t, wg)):
            f.write("%d,%.6f,%.10f\n" % (k, ti, w))
    return folder


check(abs(RATE - 0.0131 * 0.994) < 0.0001, "linear rate %.5f m/s is the notes' 0.0131 x 0.994" % RATE)
with tempfile.TemporaryDirectory() as tmp:
    for name, factor, t_end, offset, expect in (("exact", 1.0, 3.0, 0.0, 0.0), ("low", 0.8, 3.0, 0.0, 0.2),
                                                ("high", 1.1, 3.0, 0.002, 0.1), ("short", 0.9, 2.0, 0.0, 0.1)):
        err, notes, curves = metrics.sloshing_growth(write_run(os.path.join(tmp, name), factor, t_end, offset), 0.015)
        # the extrema fall on t = n pi / omega; the 5 ms sampling misses them by at most 2.5 ms
        check(abs(err - expect) < 2e-3, "%s: error %.5f, expected %.3f (%s)" % (name, err, expect, notes))
    n = len(metrics.half_period_extrema(np.arange(0, 3.0, 0.005), np.zeros(600), OMEGA, 3.0)[0])
    check(n == 5, "five half-period windows end by 3 s (%d)" % n)

for ok, what in results:
    print("%s %s" % ("ok  " if ok else "FAIL", what))
sys.exit(0 if all(ok for ok, _ in results) else 1)
