#!/usr/bin/python3
"""Plot one mpsph snapshot as a 2D scatter of its particles.

usage: plot_snapshot.py SNAP.h5 OUT.png [--color pressure|phase|velocity] [--walls]

Particles are coloured by pressure [Pa], phase index or speed |velocity| [m/s]; wall
particles (phase -1) are left out unless --walls draws them in grey; an elastic solid's
particles (phase -2) are drawn in black. The title gives the
case name and the time from the snapshot header. 3D snapshots are projected onto x-y.
"""
import argparse
import re
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the Agg backend)
from matplotlib.colors import BoundaryNorm, ListedColormap  # noqa: E402
from mpl_toolkits.axes_grid1 import make_axes_locatable  # noqa: E402

PHASE_WALL = -1
PHASE_SOLID = -2


def case_name(case_yaml):
    """The top-level `name:` of the case YAML, or '?' (no YAML library needed)."""
    m = re.search(r"^name:\s*['\"]?([^'\"#\n]*?)['\"]?\s*(#.*)?$", case_yaml, re.MULTILINE)
    return m.group(1) if m else "?"


def load(path):
    """Positions (N x 2), phase, particle spacing [m] (median of (m / rho)^(1/dim)), the
    three colourable fields and the header of a snapshot."""
    with h5py.File(path, "r") as f:
        p = f["particles"]
        header = dict(f["header"].attrs)
        with np.errstate(divide="ignore", invalid="ignore"):
            volume = p["mass"][...] / p["density"][...]
        spacing = np.median(volume ** (1.0 / header["dimension"])) if len(volume) else 0.0
        return (p["position"][:, :2], p["phase"][...], spacing,
                {"pressure": p["pressure"][...], "phase": p["phase"][...],
                 "velocity": np.linalg.norm(p["velocity"][...], axis=1)}, header)


def colouring(field, values):
    """Keyword arguments for scatter(), the colour-bar label and ticks (None: automatic)."""
    if field == "phase":
        phases = np.arange(max(int(values.max(initial=0)), 0) + 1)
        cmap = ListedColormap(plt.get_cmap("tab10").colors[:len(phases)])
        norm = BoundaryNorm(np.append(phases, phases[-1] + 1) - 0.5, cmap.N)
        return {"cmap": cmap, "norm": norm}, "phase (index in the case)", phases
    cmap = "viridis" if field == "pressure" else "plasma"
    return {"cmap": cmap}, "pressure [Pa]" if field == "pressure" else "|velocity| [m/s]", None


def marker_size(xy, spacing, axes_points=(450.0, 380.0)):
    """Marker area [pt^2] of a particle `spacing` [m] wide on equal-aspect axes of about
    axes_points (width, height) [pt]."""
    span = np.ptp(xy, axis=0) if len(xy) > 1 else np.zeros(2)
    if span.max() <= 0 or not spacing > 0:
        return 20.0
    points_per_m = min(w / d for w, d in zip(axes_points, span) if d > 0)
    return float(np.clip((spacing * points_per_m) ** 2, 0.05, 60.0))


def plot(path, out, field, walls):
    """Draw the snapshot at path into the PNG out."""
    xy, phase, spacing, fields, header = load(path)
    fluid, wall, solid = phase >= 0, phase == PHASE_WALL, phase == PHASE_SOLID
    size = marker_size(xy, spacing)
    fig, ax = plt.subplots(figsize=(8, 6))
    if walls and wall.any():
        ax.scatter(xy[wall, 0], xy[wall, 1], s=size, c="0.6", linewidths=0)
    if solid.any():
        ax.scatter(xy[solid, 0], xy[solid, 1], s=size, c="k", linewidths=0)
    kwargs, label, ticks = colouring(field, fields[field][fluid])
    sc = ax.scatter(xy[fluid, 0], xy[fluid, 1], s=size, c=fields[field][fluid], linewidths=0,
                    **kwargs)
    ax.set_aspect("equal")
    cax = make_axes_locatable(ax).append_axes("right", size="3%", pad=0.1)  # as tall as ax
    fig.colorbar(sc, cax=cax, label=label, ticks=ticks)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"{case_name(header.get('case_yaml', ''))}   t = {header['time']:.6g} s   "
                 f"(step {header['step']}, {len(xy)} particles)")
    fig.savefig(out, dpi=150, bbox_inches="tight")
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("snapshot", help="snap_NNNNN.h5")
    parser.add_argument("out", help="PNG to write")
    parser.add_argument("--color", choices=["pressure", "phase", "velocity"],
                        default="pressure", help="field to colour by (default pressure)")
    parser.add_argument("--walls", action="store_true", help="draw wall particles in grey")
    args = parser.parse_args()
    try:
        plot(args.snapshot, args.out, args.color, args.walls)
    except (OSError, KeyError) as e:
        print(f"plot_snapshot.py: {args.snapshot}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
