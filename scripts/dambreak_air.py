#!/usr/bin/python3
"""The air of a two-phase dam break run (cases/dambreak-2phase), snapshot by snapshot: the open
air's mean gauge pressure in units of rho_w g H (paper 000 section 3.2: it drifts when the phases'
volumes are not conserved, as with position-only shifting), the enclosed pockets and stray air
particles (regions of air particles connected on a dx grid, scripts/validation/metrics.py), the
largest pocket's volume and pressure; then each phase's volume drift (stats.csv), the first
impact at p1 against Buchner 2002 and the period of the first closed pocket from p1.

usage: dambreak_air.py RUN_DIR DX [--every N]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from validation import metrics  # noqa: E402

REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cases", "dambreak-2phase", "reference",
                         "dambreak_pressure_buchner2002_P1_P2_digitized_trixiparticles.csv")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("dx", type=float)
    ap.add_argument("--every", type=int, default=1, help="print every N-th snapshot")
    a = ap.parse_args()
    series = metrics.dambreak_air_series(a.run, a.dx)
    print("t [s]   open-air p/(rho g H)  pockets  stray  pocket V [m^3]  pocket p [Pa]")
    for k in range(0, len(series["t"]), a.every):
        print("%6.3f  %20.5f  %7d  %5d  %14.5f  %13.1f" % tuple(series[n][k] for n in
              ("t", "open_air_p", "pockets", "stray", "pocket_volume", "pocket_p")))
    drift = metrics.read_csv(os.path.join(a.run, "stats.csv"))
    print("max |open-air p|/(rho g H): %.4f; %s" % (abs(series["open_air_p"]).max(), metrics.volume_drift_text(drift)))
    err, notes, _ = metrics.dambreak_impact(a.run, a.dx, REFERENCE)
    print("first impact at p1: error %.4f; %s" % (err, notes))
    err, notes, _ = metrics.pocket_period(series, metrics.read_csv(os.path.join(a.run, "probes.csv")),
                                          metrics.POCKET_PERIOD_REF)
    print("air pocket: period error %.4f against the regression value; %s" % (err, notes))


if __name__ == "__main__":
    main()
