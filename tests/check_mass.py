#!/usr/bin/env python3
"""Exact mass conservation: every snapshot of a run holds the same particles (ids) with the same
masses, bit for bit, as the first one, and the run advanced (the last snapshot's step > 0).

Usage: check_mass.py RUN_DIR
"""
import glob
import os
import sys

import h5py
import numpy as np


def masses(path):
    with h5py.File(path, "r") as f:
        order = np.argsort(f["particles/id"][:])
        return f["particles/id"][:][order], f["particles/mass"][:][order], int(f["header"].attrs["step"])


def main(run):
    snaps = sorted(glob.glob(os.path.join(run, "snap_*.h5")))
    ids0, m0, _ = masses(snaps[0])
    bad = 0
    for s in snaps[1:]:
        ids, m, step = masses(s)
        if not (np.array_equal(ids, ids0) and np.array_equal(m, m0)):
            print(f"{os.path.basename(s)}: particle set or masses changed")
            bad += 1
    print(f"{len(snaps)} snapshots, {len(ids0)} particles, total mass {m0.sum():.17g}, last step {step}")
    return 1 if bad or step == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
