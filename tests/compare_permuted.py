#!/usr/bin/env python3
"""Compare two runs of the same case whose axes are permuted cyclically: run B is run A with every
vector v of A given as (v_z, v_x, v_y) (A's z axis is B's x axis). Particles are matched by their
positions in the first snapshot; on every snapshot each particle of B (fluid and wall ghosts) must
have A's permuted position and velocity and A's pressure within the tolerances.
Usage: compare_permuted.py RUN_A RUN_B TOL_POSITION[m] TOL_VELOCITY[m/s] TOL_PRESSURE[Pa]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_snapshots import load, snapshots  # noqa: E402


def permute(v):
    """A's vectors in B's axes: (x, y, z) -> (z, x, y)."""
    return v[:, [2, 0, 1]]


def matching(first_a, first_b):
    """order such that B's particle order[i] is A's particle i (both sorted by id)."""
    scale = 1e-6   # [m]: lattice positions agree far better; they are apart by dx
    key_b = {tuple(k): i for i, k in enumerate(np.round(first_b["position"] / scale).astype(np.int64))}
    keys_a = np.round(permute(first_a["position"]) / scale).astype(np.int64)
    return np.array([key_b[tuple(k)] for k in keys_a])


def main(a, b, tol_x, tol_u, tol_p):
    snaps_a, snaps_b = snapshots(a), snapshots(b)
    if len(snaps_a) < 2 or len(snaps_a) != len(snaps_b):
        print(f"snapshot counts differ or are below 2: {len(snaps_a)} vs {len(snaps_b)}")
        return 1
    order, bad = None, 0
    for fa, fb in zip(snaps_a, snaps_b):
        (head_a, da), (head_b, db) = load(fa), load(fb)
        if order is None:
            order = matching(da, db)
        dx = np.abs(permute(da["position"]) - db["position"][order]).max()
        du = np.abs(permute(da["velocity"]) - db["velocity"][order]).max()
        dp = np.abs(da["pressure"] - db["pressure"][order]).max()
        ok = head_a == head_b and dx <= tol_x and du <= tol_u and dp <= tol_p
        bad += not ok
        print(f"{os.path.basename(fa)} t = {head_a[0]:.4f}: max |dx| {dx:.3g} m, |du| {du:.3g} m/s, "
              f"|dp| {dp:.3g} Pa{'' if ok else '  FAIL'}")
    print(f"{len(snaps_a)} snapshots: {'the permuted runs agree' if not bad else 'DIFFERENT'}")
    return 1 if bad else 0


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2], *map(float, sys.argv[3:])))
