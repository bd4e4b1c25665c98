#!/usr/bin/python3
"""Copies of an mpsph checkpoint with one damage each, for tests/restart_damaged.sh.

usage: damage_checkpoint.py SRC DIR DAMAGE...

Each damage (a key of DAMAGES, or truncated) makes DIR/DAMAGE.h5: a copy of SRC with one value
or one dataset changed, keeping the stored type, or the first half of SRC. A particle's damage
hits row 0, the last row (on two ranks, read by the other rank), or the first fluid particle or
wall ghost.
"""
import os
import shutil
import sys

import h5py
import numpy as np


def set_attr(group, name, value):
    """Attribute name of group := value, in its stored type."""
    group.attrs.modify(name, np.asarray(value, dtype=group.attrs[name].dtype))


def set_row(f, path, row, value):
    """Row `row` (negative: from the end) of dataset path := value."""
    f[path][row] = value


def replace(f, path, data):
    """Dataset path := data (any length), in its stored type."""
    dtype = f[path].dtype
    del f[path]
    f.create_dataset(path, data=np.asarray(data, dtype=dtype))


def first(f, want_ghost):
    """Row of the first wall ghost (want_ghost) or fluid particle."""
    phase = f["particles/phase"][...]
    return int(np.flatnonzero((phase == -1) == want_ghost)[0])


DAMAGES = {
    "n_particles_negative": lambda f: set_attr(f["header"], "n_particles", -1),
    "n_particles_huge": lambda f: set_attr(f["header"], "n_particles", 10**12),
    "n_particles_more": lambda f: set_attr(f["header"], "n_particles",
                                           f["header"].attrs["n_particles"] + 1),
    "density_rows_short": lambda f: replace(f, "particles/density", f["particles/density"][:-1]),
    "time_nan": lambda f: set_attr(f["header"], "time", np.nan),
    "step_negative": lambda f: set_attr(f["header"], "step", -3),
    "dimension_3": lambda f: set_attr(f["header"], "dimension", 3),
    "dt_negative": lambda f: set_attr(f["run"], "dt", -1e-4),
    "next_output_nan": lambda f: set_attr(f["run"], "next_output", np.nan),
    "next_stats_past": lambda f: set_attr(f["run"], "next_stats", -1e300),
    "last_stats_step_future": lambda f: set_attr(f["run"], "last_stats_step", 1 << 40),
    "finished_2": lambda f: set_attr(f["run"], "finished", 2),
    "series_empty": lambda f: (replace(f, "run/snapshot_times", []),
                               replace(f, "run/snapshot_particles", [])),
    "series_short": lambda f: (replace(f, "run/snapshot_times", f["run/snapshot_times"][:-1]),
                               replace(f, "run/snapshot_particles",
                                       f["run/snapshot_particles"][:-1])),
    "series_long": lambda f: (replace(f, "run/snapshot_times",
                                      np.linspace(0, f["header"].attrs["time"], 10)),
                              replace(f, "run/snapshot_particles",
                                      np.full(10, f["header"].attrs["n_particles"]))),
    "series_after_time": lambda f: set_row(f, "run/snapshot_times", -1,
                                           f["header"].attrs["time"] * 2),
    "phase_out_of_range": lambda f: set_row(f, "particles/phase", first(f, False), 7),
    "wall_out_of_range": lambda f: set_row(f, "particles/wall", first(f, True), 5),
    "wall_on_fluid": lambda f: set_row(f, "particles/wall", first(f, False), 0),
    "id_negative": lambda f: set_row(f, "particles/id", -1, -4),
    "id_duplicate": lambda f: set_row(f, "particles/id", -1, f["particles/id"][0]),
    "id_too_large": lambda f: set_row(f, "particles/id", 0, f["header"].attrs["n_particles"]),
    "density_negative": lambda f: set_row(f, "particles/density", -1, -1000.0),
    "mass_zero": lambda f: set_row(f, "particles/mass", 0, 0.0),
    "pressure_inf": lambda f: set_row(f, "particles/pressure", 0, np.inf),
    "velocity_nan": lambda f: set_row(f, "particles/velocity", -1, [0.0, np.nan]),
    "position_outside": lambda f: set_row(f, "particles/position", -1, [100.0, 0.5]),
    "mirror_nan": lambda f: set_row(f, "particles/mirror", first(f, False), [np.nan, 0.0]),
    "mirror_far": lambda f: set_row(f, "particles/mirror", first(f, True), [0.0, 5.0]),
}


def truncate(src, dst):
    """The first half of the file, as a full disk or a killed copy leaves it."""
    with open(src, "rb") as f:
        data = f.read()
    with open(dst, "wb") as f:
        f.write(data[: len(data) // 2])


def damaged_copy(src, dst, damage):
    """dst: src with the damage."""
    if damage == "truncated":
        truncate(src, dst)
        return
    shutil.copyfile(src, dst)
    with h5py.File(dst, "r+") as f:
        DAMAGES[damage](f)


def main():
    src, folder, damages = sys.argv[1], sys.argv[2], sys.argv[3:]
    for damage in damages:
        damaged_copy(src, os.path.join(folder, damage + ".h5"), damage)
    return 0


if __name__ == "__main__":
    sys.exit(main())
