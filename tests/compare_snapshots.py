#!/usr/bin/env python3
"""Compare the snapshots of two run folders bitwise after sorting particles by id.

Usage: compare_snapshots.py DIR_A DIR_B     every snap_*.h5 of A with the same-named one of B
       compare_snapshots.py FILE_A FILE_B   two snapshots (or checkpoints)
Exit 0 when every snapshot has the same time, step and bitwise-identical particle data, and the
same replicated solid arrays (/solids/* of snapshots, /run/solid* of checkpoints) when present.
"""
import glob
import os
import sys

import h5py
import numpy as np

FIELDS = ["position", "velocity", "density", "pressure", "mass", "phase", "id"]


def load(path):
    with h5py.File(path, "r") as f:
        order = np.argsort(f["particles/id"][:], kind="stable")
        data = {k: f["particles/" + k][:][order] for k in FIELDS}
        for group in ("solids", "run"):
            for name in (f[group].keys() if group in f else ()):
                if group == "solids" or name.startswith("solid"):
                    data["%s/%s" % (group, name)] = f[group][name][:]
        head = (float(f["header"].attrs["time"]), int(f["header"].attrs["step"]))
    return head, data


def snapshots(path):
    """The snapshots of a run folder, or the file itself."""
    return [path] if os.path.isfile(path) else sorted(glob.glob(os.path.join(path, "snap_*.h5")))


def main(a, b):
    snaps_a, snaps_b = snapshots(a), snapshots(b)
    if not snaps_a or len(snaps_a) != len(snaps_b):
        print(f"snapshot counts differ or are zero: {len(snaps_a)} vs {len(snaps_b)}")
        return 1
    bad = 0
    for fa, fb in zip(snaps_a, snaps_b):
        (head_a, da), (head_b, db) = load(fa), load(fb)
        if head_a != head_b:
            print(f"{os.path.basename(fa)}: header (time, step) {head_a} vs {head_b}")
            bad += 1
        for k in sorted(set(da) | set(db)):
            if k not in da or k not in db:
                print(f"{os.path.basename(fa)}: {k} in one file only")
                bad += 1
            elif da[k].shape != db[k].shape or not np.array_equal(da[k], db[k]):
                diff = np.max(np.abs(da[k] - db[k])) if da[k].shape == db[k].shape else "shape"
                print(f"{os.path.basename(fa)}: {k} differs (max |diff| {diff})")
                bad += 1
    print(f"compared {len(snaps_a)} snapshots of {a} and {b}: {'identical' if not bad else 'DIFFERENT'}")
    return 1 if bad else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
