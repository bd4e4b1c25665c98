#!/usr/bin/env python3
"""Compare the pressure columns of two runs' probes.csv (same rows) from time T_FROM on: the
largest difference relative to the largest |p| of the first run must stay below TOL.
Usage: compare_probes.py RUN_A RUN_B T_FROM TOL"""
import os
import sys

import numpy as np


def main(run_a, run_b, t_from, tol):
    a = np.genfromtxt(os.path.join(run_a, "probes.csv"), delimiter=",", names=True)
    b = np.genfromtxt(os.path.join(run_b, "probes.csv"), delimiter=",", names=True)
    if a.shape != b.shape or not np.array_equal(a["time"], b["time"]):
        print("compare_probes: FAIL: the runs have different rows")
        sys.exit(1)
    rows = a["time"] >= float(t_from)
    worst = 0.0
    for key in a.dtype.names[2:]:
        rel = np.max(np.abs(a[key][rows] - b[key][rows])) / np.max(np.abs(a[key][rows]))
        print(f"compare_probes: {key} max difference {rel:.3g} of max |p| from t = {t_from}")
        worst = max(worst, rel)
    if not worst < float(tol):
        print(f"compare_probes: FAIL: {worst:.3g} >= {tol}")
        sys.exit(1)
    print("compare_probes: ok")


if __name__ == "__main__":
    main(*sys.argv[1:])
