#!/usr/bin/env python3
"""Rising bubble (cases/rising-bubble-hysing): the benchmark quantities of Hysing et al. 2009.

From every snapshot of RUN_DIR, over the particles of the lightest phase (the bubble), with the
particle volume V = m / rho:
  - y_c, the centroid height  sum V y / sum V                       [m]
  - v_c, the mean rise velocity sum V v / sum V                       [m/s]
  - the circularity 2 sqrt(pi A) / P of the bubble's outline: the colour of the bubble,
    C = sum_bubble W V / sum_all W V (Gaussian kernel of the run's h, cut at 3h, over the fluid
    particles of every phase), is sampled on a grid of spacing dx/4 and its 0.5 contour is taken
    (contourpy, matplotlib's contouring library); P is the length of the longest closed contour
    and A the area it encloses (shoelace), so the circle of the same area has the perimeter
    2 sqrt(pi A).
Printed: the minimum circularity and its time, the maximum rise velocity and its time (each
refined by a parabola through the extreme sample and its two neighbours), y_c at the last
snapshot (t = 3 for the case), their errors against the reference file, and the drift of the
bubble's volume (sum V) from stats.csv. A CSV time series is written to RUN_DIR/bubble_rise.csv
(or --csv PATH).

The reference file (default cases/rising-bubble-hysing/reference/hysing2009_tc1.csv) has
'#' comment lines, then the header quantity,value and the rows c_min, t_c_min, v_max, t_v_max,
y_c_end. Without --tol the script only reports (exit 0); with --tol REL it fails (exit 1) when
one of the three values c_min, v_max, y_c_end is off by more than REL (relative), or when the
last snapshot is not at the reference end time; --tol C,V,Y gives one bound each, in that order.

With a curve file (default reference/hysing2009_tc1_digitised.csv beside the reference: '#'
comments, header series,time,value, series y_c or v_c) the run's y_c(t) and v_c(t), linear between
snapshots, are compared at its times and the largest differences printed (for information only).

As a diagnostic (not one of the benchmark numbers), when probes.csv has the bubble's integral
probe (<phase>_com_y), the rise velocity is also taken as the time derivative of its centre of
mass, averaged over a moving window of --smooth seconds (default 0.2): v_c of the snapshots
carries fluctuations of a few 1e-3 on time scales of 0.1-0.2 s, which the window removes.

With --curve-tol REL the script also fails when v_c(t) differs from the digitised rise velocity by
more than REL of its peak at any digitised time up to the run's end (the validation study's
measure, scripts/validation/metrics.py), so a run shorter than t = 3 can be checked.

Usage: check_bubble_rise.py RUN_DIR [--ref FILE] [--curves FILE] [--csv PATH] [--tol REL] [--curve-tol REL]
       [--smooth S]
"""
import argparse
import glob
import os

import sys

import contourpy
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from validation.metrics import (bubble_curve_errors, bubble_moments, bubble_phase, read_config,  # noqa: E402
                                read_csv, read_reference, read_snapshot)  # (one copy of each)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_REF = os.path.join(HERE, "..", "cases", "rising-bubble-hysing", "reference", "hysing2009_tc1.csv")
DEFAULT_CURVES = os.path.join(os.path.dirname(DEFAULT_REF), "hysing2009_tc1_digitised.csv")


def colour_grid(x, vol, inside, h, spacing, lo, hi):
    """Shepard colour of the bubble on the grid nodes lo + k spacing up to hi: X, Y, C."""
    gx = np.arange(lo[0], hi[0] + 0.5 * spacing, spacing)
    gy = np.arange(lo[1], hi[1] + 0.5 * spacing, spacing)
    nx, ny = len(gx), len(gy)
    num, den = np.zeros(nx * ny), np.zeros(nx * ny)
    reach = int(np.ceil(3 * h / spacing))
    # nearest grid node of each particle, then the kernel stamped at every offset of the stencil
    ix = np.rint((x[:, 0] - lo[0]) / spacing).astype(int)
    iy = np.rint((x[:, 1] - lo[1]) / spacing).astype(int)
    for di in range(-reach, reach + 1):
        for dj in range(-reach, reach + 1):
            jx, jy = ix + di, iy + dj
            ok = (jx >= 0) & (jx < nx) & (jy >= 0) & (jy < ny)
            r2 = (gx[jx[ok]] - x[ok, 0]) ** 2 + (gy[jy[ok]] - x[ok, 1]) ** 2
            w = np.where(r2 < 9 * h * h, np.exp(-r2 / (h * h)), 0.0) * vol[ok]
            flat = jx[ok] * ny + jy[ok]
            den += np.bincount(flat, weights=w, minlength=nx * ny)
            num += np.bincount(flat, weights=w * inside[ok], minlength=nx * ny)
    c = np.divide(num, den, out=np.zeros_like(num), where=den > 0).reshape(nx, ny)
    return gx, gy, c


def outline(gx, gy, c):
    """Perimeter, enclosed area and count of the closed 0.5 contours; the longest one is the bubble."""
    lines = contourpy.contour_generator(gx, gy, c.T).lines(0.5)
    closed = [l for l in lines if len(l) > 3 and np.allclose(l[0], l[-1])]
    if not closed:
        return np.nan, np.nan, 0
    longest = max(closed, key=lambda l: np.sum(np.hypot(*np.diff(l, axis=0).T)))
    perimeter = np.sum(np.hypot(*np.diff(longest, axis=0).T))
    px, py = longest[:, 0], longest[:, 1]
    area = 0.5 * abs(np.dot(px[:-1], py[1:]) - np.dot(px[1:], py[:-1]))
    return perimeter, area, len(closed)


def bubble_row(path, bubble, h, dx, box):
    """t, area, y_c, v_c, circularity, contour area, perimeter, number of contours."""
    t, s = read_snapshot(path)
    vol = s["mass"] / s["density"]
    inside = (s["phase"] == bubble).astype(float)
    b = s["phase"] == bubble
    area, y_c, v_c = bubble_moments(s, bubble)
    # the grid covers the bubble plus 4h, clipped to the column
    lo = np.maximum(s["position"][b].min(axis=0) - 4 * h, box[0])
    hi = np.minimum(s["position"][b].max(axis=0) + 4 * h, box[1])
    near = np.all((s["position"] > lo - 3 * h) & (s["position"] < hi + 3 * h), axis=1)
    gx, gy, c = colour_grid(s["position"][near], vol[near], inside[near], h, dx / 4, lo, hi)
    perimeter, c_area, n_lines = outline(gx, gy, c)
    circ = 2 * np.sqrt(np.pi * c_area) / perimeter
    return t, area, y_c, v_c, circ, c_area, perimeter, n_lines


def extremum(t, f, kind):
    """Extreme value of samples f(t) and its time, refined by a parabola through 3 samples."""
    k = int(np.nanargmin(f) if kind == "min" else np.nanargmax(f))
    if 0 < k < len(f) - 1:
        a, b, c = np.polyfit(t[k - 1:k + 2] - t[k], f[k - 1:k + 2], 2)
        if a != 0 and abs(b / (2 * a)) <= (t[k + 1] - t[k - 1]) / 2:
            ts = -b / (2 * a)
            return c - b * b / (4 * a), t[k] + ts
    return f[k], t[k]


def read_quantities(path):
    """quantity -> value of the reference CSV ('#' comments, header quantity,value)."""
    ref = read_reference(path)
    return dict(zip(ref["quantity"], ref["value"].astype(float)))


def compare_curves(path, t, y_c, v_c):
    """Print the largest differences of y_c(t) and v_c(t) from the digitised points within the
    run's times, relative to the reference's peak rise velocity; return the v_c one."""
    e = bubble_curve_errors(t, y_c, v_c, path)
    v_peak = e["v_c_ref"][1].max()
    for name, unit in (("v_c", ""), ("y_c", " m")):
        print(f"{name} against the digitised points: largest difference {e[name] * v_peak:.4f}{unit} "
              f"({100 * e[name]:.2f} % of the peak rise velocity{' times 1 s' if unit else ''})")
    return e["v_c"]


def probe_rise_velocity(run, phase_name, window):
    """Max of d(com_y)/dt of the bubble's integral probe, raw and averaged over `window` seconds."""
    path = os.path.join(run, "probes.csv")
    if not os.path.exists(path):
        return None
    probes = read_csv(path)
    if phase_name + "_com_y" not in probes:
        return None
    t, y = probes["time"], probes[phase_name + "_com_y"]
    v = np.gradient(y, t)
    inside = (t >= t[0] + window / 2) & (t <= t[-1] - window / 2)
    mean = np.array([v[np.abs(t - tk) <= window / 2].mean() for tk in t[inside]])
    k, kr = int(np.argmax(mean)), int(np.argmax(v))
    return v[kr], t[kr], mean[k], t[inside][k]


def volume_drift(run, bubble_name):
    """Largest |V/V0 - 1| of the bubble's volume column of stats.csv, and its final value."""
    path = os.path.join(run, "stats.csv")
    if not os.path.exists(path):
        return np.nan, np.nan
    v = read_csv(path)["volume_" + bubble_name]
    return np.max(np.abs(v / v[0] - 1)), v[-1] / v[0] - 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("--ref", default=DEFAULT_REF)
    ap.add_argument("--curves", default=DEFAULT_CURVES)
    ap.add_argument("--csv")
    ap.add_argument("--tol", type=lambda v: [float(x) for x in v.split(",")])
    ap.add_argument("--curve-tol", type=float)
    ap.add_argument("--smooth", type=float, default=0.2)
    a = ap.parse_args()

    case = read_config(a.run)
    phases = case["phases"]
    bubble = bubble_phase(case)
    dx = float(case["resolution"]["dx"])
    h = dx * float(case["resolution"]["h_over_dx"])
    tanks = [w["box"] for w in case.get("walls", []) if "box" in w and w.get("fluid_side", "inside") == "inside"]
    box = (np.array(case["domain"]["min"], float), np.array(case["domain"]["max"], float))
    obstacles = [w["box"] for w in case.get("walls", []) if "box" in w and w.get("fluid_side") == "outside"]
    if tanks:   # the column: the tank, narrowed by obstacles standing on its sides
        box = (np.array(tanks[0]["min"], float), np.array(tanks[0]["max"], float))
        for o in obstacles:
            if o["max"][0] <= 0.5 * (box[0][0] + box[1][0]):
                box[0][0] = max(box[0][0], o["max"][0])
            else:
                box[1][0] = min(box[1][0], o["min"][0])

    rows = np.array([bubble_row(p, bubble, h, dx, box) for p in sorted(glob.glob(os.path.join(a.run, "snap_*.h5")))])
    t, area, y_c, v_c, circ = rows[:, :5].T
    out = a.csv or os.path.join(a.run, "bubble_rise.csv")
    np.savetxt(out, rows, delimiter=",", fmt="%.8g",
               header="time,area,y_c,v_c,circularity,contour_area,perimeter,contours", comments="")

    c_min, t_c = extremum(t, circ, "min")
    v_max, t_v = extremum(t, v_c, "max")
    drift_max, drift_end = volume_drift(a.run, phases[bubble]["name"])
    print(f"{len(t)} snapshots, t = {t[0]:.3f} to {t[-1]:.3f} s, dx = {dx:g} m; time series in {out}")
    print(f"bubble area: {area[0]:.6f} to {area[-1]:.6f} m^2 (stats.csv volume drift: max {drift_max:.2e}, "
          f"end {drift_end:+.2e}); most closed 0.5 contours in a snapshot: {int(rows[:, 7].max())}")
    got = {"c_min": c_min, "t_c_min": t_c, "v_max": v_max, "t_v_max": t_v, "y_c_end": y_c[-1]}
    ref = read_quantities(a.ref) if os.path.exists(a.ref) else {}
    ok = True
    if a.tol is not None and len(a.tol) not in (1, 3):
        ap.error("--tol takes one bound or three (c_min, v_max, y_c_end)")
    bound = dict(zip(("c_min", "v_max", "y_c_end"), a.tol * 3 if a.tol and len(a.tol) == 1 else a.tol or []))
    for name, label in (("c_min", "minimum circularity"), ("t_c_min", "  at t"), ("v_max", "maximum rise velocity"),
                        ("t_v_max", "  at t"), ("y_c_end", f"centroid y_c at t = {t[-1]:.3f}")):
        line = f"{label:34s} {got[name]:.4f}"
        if name in ref and name.startswith("t_"):
            line += f"   reference {ref[name]:.4f}   difference {got[name] - ref[name]:+.4f}"
        elif name in ref:
            err = got[name] / ref[name] - 1
            line += f"   reference {ref[name]:.4f}   error {100 * err:+.2f} %"
            if name in bound:
                line += f" (bound {100 * bound[name]:g} %)"
                ok = ok and abs(err) <= bound[name]
        print(line)
    pv = probe_rise_velocity(a.run, phases[bubble]["name"], a.smooth)
    if pv:
        line = (f"diagnostic, d(com_y)/dt of probes.csv: max {pv[0]:.4f} at t = {pv[1]:.3f}; averaged over "
                f"{a.smooth:g} s: max {pv[2]:.4f} at t = {pv[3]:.3f}")
        if "v_max" in ref:
            line += f" ({100 * (pv[2] / ref['v_max'] - 1):+.2f} %)"
        print(line)
    if a.curve_tol is not None and not os.path.exists(a.curves):
        ap.error(f"--curve-tol needs the digitised curves, and {a.curves} does not exist")
    if os.path.exists(a.curves):
        v_err = compare_curves(a.curves, t, y_c, v_c)
        if a.curve_tol is not None:
            ok = ok and v_err <= a.curve_tol
            print(f"rise velocity against the digitised curve: {100 * v_err:.2f} % (bound {100 * a.curve_tol:g} %)")
    if a.tol is not None and "t_end" in ref and abs(t[-1] - ref["t_end"]) > 1e-6:
        ok = False
        print(f"the last snapshot is at t = {t[-1]}, not at the reference's end time {ref['t_end']}")
    if a.tol is not None or a.curve_tol is not None:
        print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
