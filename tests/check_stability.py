#!/usr/bin/env python3
"""Asserted outcomes of the stability scenes (tests/stability_*.sh, doc/stability.md).

Usage: check_stability.py RUN_DIR --dx DX --tank XMIN,YMIN,XMAX,YMAX [options]

Always asserted, on every snapshot of the run (sorted by id):
* the run reached time.end (the last snapshot's time) and every field is finite;
* every fluid particle lies inside the tank, at most dx/2 beyond its boundary (the engine's
  "entered the solid" check uses the same margin), and inside the domain of the case;
* the particle set, the phase and the mass of every particle are those of the first snapshot,
  bit for bit, and so is the mass of every phase summed in id order (mass conserved exactly);
* the time of the last stats.csv row is time.end (the run was not cut short).

Options (each adds an assertion):
  --layers P0,P1[,P2]     phases stacked from the bottom up: for every adjacent pair, the highest
                          particle of the lower phase lies at most 3 dx above the lowest particle
                          of the upper phase (no interpenetration beyond 3 dx), in every snapshot;
  --no-isolated P:Q       no particle of phase P whose fluid neighbours within 3 dx are all of
                          phase Q (at least one; a P particle swallowed by Q), in every snapshot;
  --energy-tol TOL        closed, unforced scene: the mechanical energy E = KE + PE (PE = -m g.x)
                          of the fluid never exceeds E(0) + TOL * E_scale, in every snapshot;
  --energy-scale S        E_scale [J/m]: 'ke0' (initial kinetic energy, default), 'mgdx'
                          (M |g| dx: the work of lifting all the fluid by one particle spacing),
                          'mgh' (the potential energy of the fluid above the tank bottom) or a
                          number. Also printed: KE + PE + internal (Tait) energy;
  --cstab WATER:AIR       stats.csv has a row after every step, and the time step of every full
                          step (the last one is cut to time.end) equals CFL h / c_stab, with
                          c_stab = c0_l sqrt(g_g rho0_l / (g_l rho_min)) and rho_min bracketed by
                          the gas's max density deviation of the row before (the state the step
                          starts from), and c_stab exceeds the largest c0 (the c_stab limit
                          binds, not the acoustic, acceleration, viscous or motion limit);
  --at-wall PHASE         every particle of PHASE ends (last snapshot) within 3 dx of the tank
                          boundary (thrown drops reach the walls and stay there);
  --pressure-cycle PROBE  the probe's pressure rises to at least 5 times its initial value and
                          falls back below half of its peak afterwards (compression and
                          re-expansion of an entrapped air pocket).
Prints the figures of doc/stability.md: energy drift, max density deviation per phase (stats),
steps, wall-clock seconds and steps/s, the time step and its ratio to the acoustic limits.
"""
import argparse
import csv
import glob
import math
import os
import sys

import h5py
import numpy as np

failures = []


def check(ok, msg):
    print(("ok   " if ok else "FAIL ") + msg)
    if not ok:
        failures.append(msg)


def case_of(run):
    """The resolved case (config.yaml). Only a few scalars are needed; they are taken by a line
    scan of the block layout mpsph writes, so that no YAML module is needed."""
    with open(os.path.join(run, "config.yaml")) as f:
        return f.read()


def phases_of(text):
    """[(name, rho0, c0, gamma, incompressible)] from the resolved case text."""
    out = []
    lines = text.splitlines()
    i = lines.index("phases:")
    cur = None
    for ln in lines[i + 1:]:
        if not ln.startswith("  "):
            break
        s = ln.strip()
        if s.startswith("- "):
            if cur:
                out.append(cur)
            cur = {}
            s = s[2:]
        if ":" in s:
            k, v = s.split(":", 1)
            cur[k.strip()] = v.strip().strip("\"")
    if cur:
        out.append(cur)
    return out


def scalar(text, section, key):
    lines = text.splitlines()
    i = lines.index(section + ":")
    for ln in lines[i + 1:]:
        if not ln.startswith("  "):
            break
        k, v = ln.strip().split(":", 1)
        if k == key:
            return v.strip()
    raise KeyError(section + "." + key)


def vector(text, section, key):
    v = scalar(text, section, key)
    return np.array([float(a) for a in v.strip("[]").split(",")])


def load(path):
    with h5py.File(path, "r") as f:
        o = np.argsort(f["particles/id"][:])
        d = {k: f["particles/" + k][:][o] for k in ("position", "velocity", "density", "pressure", "mass", "phase", "id")}
        d["time"] = float(f["header"].attrs["time"])
        d["step"] = int(f["header"].attrs["step"])
    return d


def energy(s, g, phases):
    """Kinetic, potential and internal (Tait) energy of the fluid [J, per metre in 2D]. The
    internal energy of a particle is m int_rho0^rho p/rho'^2 drho' with p = B((rho/rho0)^gamma - 1)
    + p_b: m [B rho0^-gamma (rho^(gamma-1) - rho0^(gamma-1))/(gamma-1) + (B - p_b)(1/rho - 1/rho0)];
    continuity and the (p_i + p_j) pressure gradient exchange it exactly with the kinetic energy."""
    fl = s["phase"] >= 0
    m, x, u = s["mass"][fl], s["position"][fl], s["velocity"][fl]
    ke = 0.5 * np.sum(m * np.sum(u * u, axis=1))
    pe = -np.sum(m * (x @ g))
    ie = 0.0
    for k, p in enumerate(phases):
        sel = s["phase"] == k
        r0, c0, gm, pb = float(p["rho0"]), float(p["c0"]), float(p["gamma"]), float(p.get("p_background", 0))
        b = r0 * c0 * c0 / gm
        r = s["density"][sel]
        ie += np.sum(s["mass"][sel] * (b * r0 ** -gm * (r ** (gm - 1) - r0 ** (gm - 1)) / (gm - 1) + (b - pb) * (1 / r - 1 / r0)))
    return ke, pe, ie


def neighbours_all_other(s, p, q, r):
    """Count particles of phase p whose fluid neighbours within r are all of phase q (>= 1)."""
    fl = s["phase"] >= 0
    x, ph = s["position"][fl], s["phase"][fl]
    n = 0
    for i in np.nonzero(ph == p)[0]:
        d = np.sqrt(np.sum((x - x[i]) ** 2, axis=1))
        near = (d < r) & (d > 0)
        if near.any() and np.all(ph[near] == q):
            n += 1
    return n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("--dx", type=float, required=True)
    ap.add_argument("--tank", required=True)
    ap.add_argument("--layers")
    ap.add_argument("--no-isolated", action="append", default=[])
    ap.add_argument("--energy-tol", type=float)
    ap.add_argument("--energy-scale", default="ke0")
    ap.add_argument("--cstab")
    ap.add_argument("--pressure-cycle")
    ap.add_argument("--at-wall")
    a = ap.parse_args()
    dx = a.dx
    text = case_of(a.run)
    phases = phases_of(text)
    names = [p["name"] for p in phases]
    g = np.array([float(v) for v in text.split("\ngravity: ")[1].splitlines()[0].strip("[]").split(",")])
    t_end = float(scalar(text, "time", "end"))
    cfl = float(scalar(text, "time", "cfl"))
    dmin, dmax = vector(text, "domain", "min"), vector(text, "domain", "max")
    tank = np.array([float(v) for v in a.tank.split(",")])
    dim = len(dmin)
    tmin, tmax = tank[:dim], tank[dim:]

    snaps = sorted(glob.glob(os.path.join(a.run, "snap_*.h5")))
    check(len(snaps) >= 2, f"{len(snaps)} snapshots")
    s0 = load(snaps[0])
    last = load(snaps[-1])
    check(abs(last["time"] - t_end) <= 1e-9 * max(1.0, t_end), f"last snapshot at t = {last['time']:.6g} s = time.end {t_end:g} s (step {last['step']})")

    mass0 = {ph: np.sum(s0["mass"][s0["phase"] == ph]) for ph in range(len(phases))}
    ke0, pe0, ie0 = energy(s0, g, phases)
    e0 = ke0 + pe0
    tot0 = e0 + ie0
    totmax, totmax_t = -math.inf, 0.0
    if a.energy_scale == "ke0":
        scale = ke0
    elif a.energy_scale == "mgdx":   # lifting all the fluid by one particle spacing
        scale = sum(mass0[ph] for ph in mass0) * float(np.linalg.norm(g)) * dx
    elif a.energy_scale == "mgh":   # the potential energy of the fluid above the tank bottom
        scale = pe0 + sum(mass0[ph] for ph in mass0) * float(g @ np.append(np.zeros(dim - 1), 1.0)) * tmin[-1]
    else:
        scale = float(a.energy_scale)
    worst = {"finite": 0, "outside": 0.0, "domain": 0, "masses": 0, "layers": {}, "isolated": {}}
    emax, emax_t, emin = -math.inf, 0.0, math.inf
    for path in snaps:
        s = load(path)
        fl = s["phase"] >= 0
        for k in ("position", "velocity", "density", "pressure", "mass"):
            worst["finite"] += int(np.count_nonzero(~np.isfinite(s[k])))
        x = s["position"][fl]
        beyond = np.max(np.maximum(tmin - x, x - tmax)) / dx   # > 0: beyond the tank boundary [dx]
        worst["outside"] = max(worst["outside"], beyond)
        worst["domain"] += int(np.count_nonzero(np.any((x < dmin) | (x > dmax), axis=1)))
        f0 = s0["phase"] >= 0   # ghosts carry m = rho0 dx^n of the phase they mirror, not a conserved mass
        same = np.array_equal(s["id"], s0["id"]) and np.array_equal(s["phase"], s0["phase"]) and np.array_equal(s["mass"][f0], s0["mass"][f0])
        same = same and all(np.sum(s["mass"][s["phase"] == ph]) == mass0[ph] for ph in mass0)
        worst["masses"] += 0 if same else 1
        if a.layers:
            ly = [names.index(n) for n in a.layers.split(",")]
            for lo, up in zip(ly, ly[1:]):
                ov = (np.max(s["position"][s["phase"] == lo][:, -1]) - np.min(s["position"][s["phase"] == up][:, -1])) / dx
                key = (names[lo], names[up])
                if ov > worst["layers"].get(key, (-math.inf, 0))[0]:
                    worst["layers"][key] = (ov, s["time"])
        for spec in a.no_isolated:
            p, q = (names.index(n) for n in spec.split(":"))
            n = neighbours_all_other(s, p, q, 3 * dx)
            if n > worst["isolated"].get(spec, (-1, 0))[0]:
                worst["isolated"][spec] = (n, s["time"])
        ke, pe, ie = energy(s, g, phases)
        e = ke + pe
        if e + ie > totmax:
            totmax, totmax_t = e + ie, s["time"]
        if e > emax:
            emax, emax_t = e, s["time"]
        emin = min(emin, e)
    check(worst["finite"] == 0, f"every value finite in {len(snaps)} snapshots ({worst['finite']} non-finite)")
    check(worst["outside"] <= 0.5, f"no fluid particle beyond the tank boundary by more than dx/2 (largest: {worst['outside']:.3f} dx; the first fluid row starts at -0.5 dx)")
    check(worst["domain"] == 0, f"no fluid particle outside the domain ({worst['domain']})")
    check(worst["masses"] == 0, "particle set, phases, masses and per-phase mass sums bitwise equal to the initial ones: "
          + ", ".join(f"{names[ph]} {mass0[ph]!r}" for ph in mass0))
    if a.layers:
        for (lo, up), (ov, t) in worst["layers"].items():
            check(ov <= 3.0, f"layers: overlap max y({lo}) - min y({up}) at most 3 dx (largest {ov:.2f} dx at t = {t:.4g} s; -1 dx on the lattice)")
    for spec in a.no_isolated:
        n, t = worst["isolated"][spec]
        p, q = spec.split(":")
        check(n == 0, f"no {p} particle whose neighbours within 3 dx are all {q} (largest count {n} at t = {t:.4g} s)")
    if a.at_wall:
        sel = last["phase"] == names.index(a.at_wall)
        x = last["position"][sel]
        far = np.max(np.min(np.concatenate([x - tmin, tmax - x], axis=1), axis=1)) / dx
        check(far <= 3.0, f"every {a.at_wall} particle ends within 3 dx of the tank boundary (farthest {far:.2f} dx)")
    dmin_phase = math.inf
    for path in snaps:
        s = load(path)
        ph, x = s["phase"], s["position"]
        for k in range(len(phases)):
            for q in range(k + 1, len(phases)):
                xa, xb = x[ph == k], x[ph == q]
                if len(xa) and len(xb) and len(xa) * len(xb) < 4e6:
                    d = np.sqrt(((xa[:, None, :] - xb[None, :, :]) ** 2).sum(-1)).min()
                    dmin_phase = min(dmin_phase, d)
    print(f"smallest distance between particles of different phases: {dmin_phase / dx:.3f} dx")
    growth = (emax - e0) / scale if scale > 0 else math.nan
    print(f"energy: E0 = KE0 + PE0 = {ke0:.6g} + {pe0:.6g} J/m; max E - E0 = {emax - e0:.4g} J/m at t = {emax_t:.4g} s "
          f"({growth:.3e} of the scale {scale:.4g} J/m); min E - E0 = {emin - e0:.4g} J/m; final E - E0 = {ke + pe - e0:.4g} J/m")
    print(f"total energy KE + PE + internal: E0 = {tot0:.6g} J/m (internal {ie0:.4g}); max growth {totmax - tot0:.4g} J/m "
          f"({(totmax - tot0) / scale:.3e} of the scale) at t = {totmax_t:.4g} s; final {ke + pe + ie - tot0:.4g} J/m")
    if a.energy_tol is not None:
        check(growth <= a.energy_tol, f"mechanical energy never above E0 + {a.energy_tol:g} x {scale:.4g} J/m (growth {growth:.3e})")

    with open(os.path.join(a.run, "stats.csv")) as f:
        rows = list(csv.DictReader(f))
    check(abs(float(rows[-1]["time"]) - t_end) <= 1e-9 * max(1.0, t_end), f"stats.csv ends at t = {rows[-1]['time']}")
    for n in names:
        dev = max(float(r[f"max_density_deviation_{n}"]) for r in rows)
        print(f"max density deviation {n}: {dev:.4g}")
    h = dx * float(scalar(text, "resolution", "h_over_dx"))
    steps, wall = int(rows[-1]["step"]), float(rows[-1]["wall_seconds"])
    c_max = max(float(p["c0"]) for p in phases)
    dts = np.array([float(r["dt"]) for r in rows[1:-1]])
    print(f"steps {steps}, wall {wall:.2f} s, {steps / wall:.0f} steps/s; dt from {dts.min():.4g} to {dts.max():.4g} s; "
          f"CFL h / max c0 = {cfl * h / c_max:.4g} s")
    if a.cstab:
        wl, gs = (names.index(n) for n in a.cstab.split(":"))
        pl, pg = phases[wl], phases[gs]
        c0l, rl, gl, rg, gg = (float(pl["c0"]), float(pl["rho0"]), float(pl["gamma"]), float(pg["rho0"]), float(pg["gamma"]))
        bad, cmin = 0, math.inf
        check(all(int(r1["step"]) == int(r0["step"]) + 1 for r0, r1 in zip(rows, rows[1:])),
              "stats.csv has a row after every step (run with output.stats_interval below dt)")
        for r0, r1 in zip(rows[:-2], rows[1:-1]):
            # the step of row r1 starts from the state of row r0: rho_min of the gas lies in
            # rho0 [1 - dev, 1 + dev] with dev its max density deviation there
            dev = float(r0[f"max_density_deviation_{pg['name']}"])
            dt = float(r1["dt"])
            lo = cfl * h / (c0l * math.sqrt(gg * rl / (gl * rg * (1 - dev))))   # rho_min = rho0 (1 - dev)
            hi = cfl * h / (c0l * math.sqrt(gg * rl / (gl * rg * (1 + dev))))   # rho_min = rho0 (1 + dev)
            if not (lo * (1 - 1e-5) <= dt <= hi * (1 + 1e-5)):   # dt is printed to 6 digits
                bad += 1
                if bad <= 3:
                    print(f"     step {r1['step']}: dt {dt:.6g} outside [{lo:.6g}, {hi:.6g}]")
            cmin = min(cmin, cfl * h / hi)
        check(bad == 0, f"the time step of all {len(rows) - 2} full-step rows is CFL h / c_stab ({bad} outside the bracket)")
        check(cmin > c_max, f"c_stab >= {cmin:.4g} m/s exceeds the largest c0 {c_max:g} m/s: the c_stab limit binds "
              f"(dt / (CFL h / max c0) = {dts.max() / (cfl * h / c_max):.4f} at most)")
    if a.pressure_cycle:
        with open(os.path.join(a.run, "probes.csv")) as f:
            pr = list(csv.DictReader(f))
        t = np.array([float(r["time"]) for r in pr])
        p = np.array([float(r[a.pressure_cycle]) for r in pr])
        k = int(np.argmax(p))
        after = p[k:].min()
        print(f"probe {a.pressure_cycle}: p(0) = {p[0]:.5g} Pa, peak {p[k]:.5g} Pa at t = {t[k]:.4g} s, "
              f"lowest after the peak {after:.5g} Pa")
        check(p[k] >= 5 * p[0] and p[0] > 0, f"the pocket pressure rises to at least 5 p(0) (peak / p(0) = {p[k] / p[0]:.2f})")
        check(after <= 0.5 * p[k], f"and falls back below half of its peak afterwards (lowest / peak = {after / p[k]:.3f})")
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
