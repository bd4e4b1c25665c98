#!/usr/bin/env python3
"""check_lobovsky_metric.py - metrics.lobovsky_dambreak on constructed input: a run folder whose
probes.csv (every 0.5 ms, to 1.1 s) holds gauges offset from a constructed water-level record
(every 1 ms, to 1.25 s) by known amounts, a gauge dry (nan) at the start, a deviation after H4's
second-jump window, and pressures with flat-topped pulses (the 5 ms running mean leaves their tops
as they are), a one-sample spike (the running mean takes it down) and an unscored sensor far off.
The heights are piecewise linear with kinks on both grids, so the interpolation is exact and the
RMS is known. Exit status 1 on a failed check."""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

results = []   # (passed, what) of each check, printed at the end
check = lambda ok, what: results.append((bool(ok), what))  # noqa: E731

H = 0.3
SCALE = math.sqrt(metrics.G / H)   # t* = t SCALE
T_RUN = 1.1


def levels(t):
    """The constructed record [m]: H1 falling, H2 rising, H3 dry until 0.3 s, H4 constant."""
    return {"H1": 0.3 - 0.1 * t, "H2": 0.03 + 0.05 * t, "H3": np.where(t < 0.3, 0.0, 0.2 * (t - 0.3)),
            "H4": 0.05 + 0.0 * t}


def run_levels(t):
    """The run's gauges [m]: H2 0.006 m high (0.02 H), H3 0.009 m low once wet (0.03 H) and nan
    while dry, H4 0.1 m high after 0.95 s only (after its window, t* = 5.4 or 0.944 s)."""
    h = levels(t)
    return {"H1": h["H1"], "H2": h["H2"] + 0.006, "H3": np.where(h["H3"] > 0, h["H3"] - 0.009, np.nan),
            "H4": h["H4"] + np.where(t > 0.95, 0.1, 0.0)}


def plateau(t, t0, t1, top, ramp=0.02):
    """A pulse [p*]: 0 until t0 - ramp, linear up to top at t0, flat to t1, linear down by t1 + ramp."""
    return top * np.clip(np.minimum((t - (t0 - ramp)) / ramp, ((t1 + ramp) - t) / ramp), 0, 1)


def pressures(t, run):
    """p* of sensors 1-4 (and 2L in the record): the record's and the run's pulses."""
    if not run:
        return {"1": plateau(t, 0.42, 0.44, 3.0), "2": plateau(t, 0.45, 0.46, 2.0), "2L": 0 * t,
                "3": plateau(t, 0.46, 0.48, 1.5), "4": plateau(t, 0.64, 0.66, 0.6) + plateau(t, 1.03, 1.05, 0.8)}
    spike = np.where(np.abs(t - 0.8) < 1e-6, 3.0, 0.0)   # one sample: 3.0 / 11 after the running mean
    return {"1": plateau(t, 0.43, 0.44, 2.0), "2": plateau(t, 0.45, 0.46, 6.0),
            "3": plateau(t, 0.46, 0.48, 1.8), "4": plateau(t, 0.64, 0.66, 0.5) + plateau(t, 1.03, 1.05, 0.6) + spike}


def write(path, header, cols):
    with open(path, "w") as f:
        f.write("# constructed\n" + header + "\n")
        np.savetxt(f, np.column_stack(cols), delimiter=",", fmt="%.12g")


def write_inputs(run):
    t = np.round(np.arange(0, 1.25005, 0.001), 6)
    h = levels(t)
    write(os.path.join(run, "levels.csv"), "t_star,h_over_H_H1_2,h_over_H_H2_3,h_over_H_H2_4,h_over_H_H3_3,"
          "h_over_H_H3_4,h_over_H_H4_4,h_over_H_H4_5",
          [t * SCALE] + [h[g] / H for g in ("H1", "H2", "H2", "H3", "H3", "H4", "H4")])
    t = np.round(np.arange(0.00005, 1.25, 0.00005), 7)
    p = pressures(t, False)
    write(os.path.join(run, "pressures.csv"), "t_star,p_star_sensor_1,p_star_sensor_2,p_star_sensor_2L,"
          "p_star_sensor_3,p_star_sensor_4", [t * SCALE] + [p[s] for s in ("1", "2", "2L", "3", "4")])
    t = np.round(np.arange(0, T_RUN + 0.00005, 0.0005), 6)
    h, p = run_levels(t), pressures(t, True)
    with open(os.path.join(run, "probes.csv"), "w") as f:
        f.write("step,time,P1,P2,P3,P4,H1,H2,H3,H4\n")
        np.savetxt(f, np.column_stack([np.arange(len(t)), t] + [p[s] * 1000 * metrics.G * H for s in "1234"] +
                                      [h[g] for g in ("H1", "H2", "H3", "H4")]), delimiter=",", fmt="%.12g")
    with open(os.path.join(run, "config.yaml"), "w") as f:
        f.write("phases:\n  - {name: water, p_background: 0}\n")


with tempfile.TemporaryDirectory() as run:
    write_inputs(run)
    err, notes, curves = metrics.lobovsky_dambreak(run, 0.03, os.path.join(run, "levels.csv"),
                                                   os.path.join(run, "pressures.csv"))
print(notes)
h3 = 0.03 * math.sqrt(800 / 1101)   # 301 dry samples (0-0.3 s) of 1101 to the run's end
check(abs(err - 0.25 / 0.30) < 1e-6, "error %.9f: the worst, sensor 4's peak 0.6 against 0.8 (0.25 of 0.30; "
      "the heights' 0.03 of 0.10 at most), expected %.9f" % (err, 0.25 / 0.3))
check("H1 0.000 (0.0000) to t* %.2f" % (T_RUN * SCALE) in notes and "H2 0.020 (0.0200)" in notes,
      "H1 exact, H2 0.006 m high: max and RMS 0.02 H, to the run's end")
check("H3 0.030 (%.4f)" % h3 in notes, "H3: dry samples (nan) read as 0 and equal to the record's 0, then 0.03 H low")
check("H4 0.000 (0.0000) to t* 5.40" in notes, "H4: the 0.1 m after t* = 5.4 (its second jump) left out")
check("P3 peak p* 1.80 at t* 2.6" in notes and "(exp. 1.50 at 2.6" in notes,
      "P3: the flat tops 1.8 and 1.5 (0.2 of 0.3 of the score)")
check("P4 peak p* 0.60 at t* 5." in notes and "(exp. 0.80 at 5." in notes,
      "P4: the one-sample spike 3.0 averaged to 0.27 does not count; 0.6 against 0.8 at t = 1.03-1.05 s")
check("P2 peak p* 6.00" in notes, "P2 (three times the record's peak) reported, not scored")
t1 = (0.41 + 0.02 * 0.5 / 2.0) * SCALE, (0.40 + 0.02 * 0.5 / 3.0) * SCALE
check("P1 through p* 0.5 at t* %.3f (exp. %.3f)" % t1 in notes, "P1's rise through p* = 0.5 on both ramps")
check(len(curves["t_ref"]) == 1251 and np.isnan(curves["H3"][0]), "curves: the whole record, the run's columns as written")
for ok, what in results:
    print("%s %s" % ("ok  " if ok else "FAIL", what))
sys.exit(0 if all(ok for ok, _ in results) else 1)
