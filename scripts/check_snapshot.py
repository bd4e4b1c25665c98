#!/usr/bin/python3
"""Check an mpsph output folder against the snapshot contract (doc: /work/shared/DESIGN.md).

usage: check_snapshot.py OUTDIR

Opens every OUTDIR/snap_*.h5 and OUTDIR/snapshots.xdmf, checks that every contracted header
attribute and /particles dataset exists with the right shape and type, that the ids are unique,
that no temporary file was left behind and that the XDMF index matches the snapshots.
OUTDIR/checkpoint.h5, when present, is checked like a snapshot plus its /run group.
Prints one line per file; exits 1 on any problem.
"""
import argparse
import glob
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

HEADER = {  # attribute -> kind of numpy dtype ('f' float, 'i' integer, 'O'/'U' string)
    "time": "f", "step": "i", "dimension": "i", "n_particles": "i",
    "code_version": "str", "case_yaml": "str",
}
# dataset -> (dtype, vector?) ; vectors are N x dim, scalars N
PARTICLES = {
    "position": (np.float64, True), "velocity": (np.float64, True),
    "density": (np.float64, False), "pressure": (np.float64, False),
    "mass": (np.float64, False), "phase": (np.int32, False), "id": (np.int64, False),
}
RUN_NUMBERS = ("dt", "next_output", "next_stats", "next_probes", "next_checkpoint",
               "last_snapshot_step", "last_stats_step", "last_probes_step", "wall_seconds",
               "no_free_surface", "finished", "wall_guard_hits")
XDMF_TYPES = {np.dtype(np.float64): ("Float", "8"), np.dtype(np.int32): ("Int", "4"),
              np.dtype(np.int64): ("Int", "8")}


def check_header(f, problems):
    """Header attributes: presence and type; returns them as a dict (missing ones absent)."""
    if "header" not in f:
        problems.append("no /header group")
        return {}
    attrs = dict(f["header"].attrs)
    for name, kind in HEADER.items():
        if name not in attrs:
            problems.append(f"/header has no attribute {name}")
        elif kind == "str" and not isinstance(attrs[name], str):
            problems.append(f"/header/{name} is {type(attrs[name]).__name__}, not a string")
        elif kind != "str" and (np.ndim(attrs[name]) != 0
                                or np.asarray(attrs[name]).dtype.kind != kind):
            problems.append(f"/header/{name} is not a scalar of kind '{kind}'")
    if attrs.get("dimension") not in (2, 3):
        problems.append(f"/header/dimension is {attrs.get('dimension')}, not 2 or 3")
    if isinstance(attrs.get("case_yaml"), str) and not attrs["case_yaml"].strip():
        problems.append("/header/case_yaml is empty")
    return attrs


def check_particles(f, n, dim, problems):
    """Contracted datasets: shape (n[, dim]) and dtype; extra (optional) fields: n rows; ids
    unique; phases not below -1."""
    if "particles" not in f:
        problems.append("no /particles group")
        return
    group = f["particles"]
    for name, (dtype, vector) in PARTICLES.items():
        if name not in group:
            problems.append(f"no /particles/{name}")
            continue
        d = group[name]
        want = (n, dim) if vector else (n,)
        if d.shape != want:
            problems.append(f"/particles/{name} has shape {d.shape}, want {want}")
        if d.dtype != np.dtype(dtype):
            problems.append(f"/particles/{name} is {d.dtype}, want {np.dtype(dtype)}")
    for name in set(group) - set(PARTICLES):
        if not isinstance(group[name], h5py.Dataset) or group[name].shape[:1] != (n,):
            problems.append(f"optional /particles/{name} does not have {n} rows")
    if "id" in group and group["id"].shape == (n,):
        if len(np.unique(group["id"][...])) != n:
            problems.append("ids are not unique")
    if "phase" in group and group["phase"].shape == (n,) and n and group["phase"][...].min() < -1:
        problems.append("phase below -1 (walls are -1)")


def check_h5(path):
    """Check one snapshot; returns (problems, header attributes, dataset shapes and dtypes)."""
    problems = []
    try:
        with h5py.File(path, "r") as f:
            attrs = check_header(f, problems)
            n, dim = attrs.get("n_particles", -1), attrs.get("dimension", -1)
            check_particles(f, n, dim, problems)
            shapes = {k: (v.shape, v.dtype) for k, v in f.get("particles", {}).items()
                      if isinstance(v, h5py.Dataset)}
    except Exception as e:  # any unreadable content is a finding, not a crash
        return [f"cannot read: {e}"], {}, {}
    return problems, attrs, shapes


def check_checkpoint(path):
    """checkpoint.h5: a snapshot plus the /run group (run state and snapshot series)."""
    problems, attrs, _ = check_h5(path)
    try:
        with h5py.File(path, "r") as f:
            run = f.get("run")
            if run is None:
                return problems + ["no /run group"], attrs
            problems += [f"/run has no attribute {k}" for k in RUN_NUMBERS if k not in run.attrs]
            times, counts = run.get("snapshot_times"), run.get("snapshot_particles")
            if times is None or counts is None or times.shape != counts.shape:
                problems.append("/run/snapshot_times and snapshot_particles missing or unequal")
    except Exception as e:  # any unreadable content is a finding, not a crash
        problems.append(f"cannot read: {e}")
    return problems, attrs


def check_item(item, outdir, snaps, where, problems):
    """One HDF DataItem: names an existing snapshot dataset with matching dimensions and type."""
    file_name, _, dataset = (item.text or "").strip().partition(":")
    info = snaps.get(file_name)
    if info is None or not os.path.exists(os.path.join(outdir, file_name)):
        problems.append(f"{where}: refers to missing file {file_name!r}")
        return
    shape, dtype = info[2].get(dataset.rpartition("/")[2], (None, None))
    if shape is None or not dataset.startswith("/particles/"):
        problems.append(f"{where}: refers to missing dataset {dataset!r}")
        return
    if tuple(int(x) for x in item.get("Dimensions", "").split()) != shape:
        problems.append(f"{where}: Dimensions {item.get('Dimensions')} but dataset has {shape}")
    if (item.get("NumberType", "Float"), item.get("Precision", "4")) != XDMF_TYPES.get(dtype):
        problems.append(f"{where}: NumberType/Precision do not match {dtype}")


def check_grid(grid, outdir, name, snaps, problems):
    """One Uniform grid of the temporal collection against snapshot `name`."""
    attrs = snaps[name][1]
    time, topo, geo = grid.find("Time"), grid.find("Topology"), grid.find("Geometry")
    if time is None or float(time.get("Value", "nan")) != attrs.get("time"):
        problems.append(f"{name}: Time does not match the header time {attrs.get('time')}")
    if topo is None or topo.get("TopologyType") != "Polyvertex" or \
            int(topo.get("NumberOfElements", -1)) != attrs.get("n_particles"):
        problems.append(f"{name}: Topology is not Polyvertex of n_particles elements")
    want_geo = {2: "XY", 3: "XYZ"}.get(attrs.get("dimension"))
    if geo is None or geo.get("GeometryType") != want_geo or geo.find("DataItem") is None:
        problems.append(f"{name}: Geometry is not {want_geo} with a DataItem")
    else:
        check_item(geo.find("DataItem"), outdir, snaps, f"{name} geometry", problems)
    found = {a.get("Name"): a for a in grid.findall("Attribute")}
    for field in [k for k in PARTICLES if k != "position"]:
        kind = "Vector" if PARTICLES[field][1] else "Scalar"
        item = found[field].find("DataItem") if field in found else None
        if item is None or found[field].get("AttributeType") != kind:
            problems.append(f"{name}: no {kind} attribute {field} with a DataItem")
        else:
            check_item(item, outdir, snaps, f"{name} {field}", problems)


def check_xdmf(outdir, snaps):
    """snapshots.xdmf: a temporal collection with one grid per snapshot, in order."""
    path = os.path.join(outdir, "snapshots.xdmf")
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        return [f"cannot read: {e}"]
    collection = root.find("Domain/Grid")
    if root.tag != "Xdmf" or collection is None or collection.get("GridType") != "Collection" \
            or collection.get("CollectionType") != "Temporal":
        return ["no Domain/Grid of GridType Collection, CollectionType Temporal"]
    grids, names = collection.findall("Grid"), sorted(snaps)
    problems = [] if len(grids) == len(names) else \
        [f"{len(grids)} grids for {len(names)} snapshots"]
    for grid, name in zip(grids, names):
        try:
            check_grid(grid, outdir, name, snaps, problems)
        except ValueError as e:  # a number attribute that is not a number
            problems.append(f"{name}: {e}")
    return problems


def check_series(snaps, problems):
    """Across snapshots: one dimension, times and steps non-decreasing."""
    attrs = [snaps[name][1] for name in sorted(snaps)]
    if len({a.get("dimension") for a in attrs}) > 1:
        problems.append("snapshots disagree on the dimension")
    for key in ("time", "step"):
        values = [a.get(key) for a in attrs]
        if None not in values and any(b < a for a, b in zip(values, values[1:])):
            problems.append(f"{key} decreases between snapshots")


def report(name, problems, summary=""):
    print(f"{name}: " + ("ok" + summary if not problems else "FAIL: " + "; ".join(problems)))
    return not problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", help="an mpsph output folder")
    outdir = parser.parse_args().outdir
    snaps, ok = {}, True
    for path in sorted(glob.glob(os.path.join(outdir, "snap_*.h5"))):
        name = os.path.basename(path)
        snaps[name] = check_h5(path)
        a = snaps[name][1]
        ok &= report(name, snaps[name][0], f"  time={a.get('time')} step={a.get('step')} "
                     f"dimension={a.get('dimension')} n_particles={a.get('n_particles')}")
    if not snaps:
        ok &= report(outdir, ["no snap_*.h5 files"])
    leftovers = glob.glob(os.path.join(outdir, "*.tmp"))
    series = [f"temporary files left: {' '.join(map(os.path.basename, leftovers))}"] \
        if leftovers else []
    check_series(snaps, series)
    ok &= report("series", series, f"  {len(snaps)} snapshots")
    if snaps:
        ok &= report("snapshots.xdmf", check_xdmf(outdir, snaps), f"  {len(snaps)} grids")
    checkpoint = os.path.join(outdir, "checkpoint.h5")
    if os.path.exists(checkpoint):
        problems, a = check_checkpoint(checkpoint)
        ok &= report("checkpoint.h5", problems, f"  time={a.get('time')} step={a.get('step')}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
