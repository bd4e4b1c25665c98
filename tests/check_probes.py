#!/usr/bin/env python3
"""Checks of the probes of tests/cases/hydrostatic-probes.yaml (water depth H = 0.5 m at rest):

* the wave gauge reads H within 0.1 dx in every row;
* the integral probe at t = 0 equals the sums over the particles of the first snapshot
  (volume sum m/rho, kinetic energy, potential energy -sum m g.x, mass-weighted centre), to
  1e-12 relative, and the volume is 0.5 m^2 x 1 m to 1e-6;
* after the start (t > 0, the wall ghosts then hold their pressure) the point, MLS and segment
  sensors at the bottom read rho0 g H within 2 %;
* run2 (another rank count), if given, gives the same interpolated columns to the last printed
  digit and the integrals to 1e-12 relative.

Usage: check_probes.py RUN [RUN2]
"""
import glob
import os
import sys

import h5py
import numpy as np

H, DX, RHO0, G = 0.5, 0.02, 1000.0, 9.81
INTERPOLATED = ["p_point", "p_mls", "p_sensor", "p_mid", "gauge"]
INTEGRAL = ["water_volume", "water_kinetic", "water_potential", "water_com_x", "water_com_y"]


def table(run):
    return np.genfromtxt(os.path.join(run, "probes.csv"), delimiter=",", names=True)


def fail(msg):
    print("check_probes: FAIL:", msg)
    sys.exit(1)


def check_integrals(run, t):
    with h5py.File(sorted(glob.glob(os.path.join(run, "snap_*.h5")))[0], "r") as f:
        part = f["particles"]
        water = part["phase"][:] == 0
        x, v = part["position"][:][water], part["velocity"][:][water]
        m, rho = part["mass"][:][water], part["density"][:][water]
    expected = {"water_volume": np.sum(m / rho), "water_kinetic": 0.5 * np.sum(m * np.sum(v * v, axis=1)),
                "water_potential": np.sum(m * G * x[:, 1]), "water_com_x": np.sum(m * x[:, 0]) / np.sum(m),
                "water_com_y": np.sum(m * x[:, 1]) / np.sum(m)}
    for key, want in expected.items():
        got = t[key][0]
        print(f"check_probes: {key} = {got:.12g}, from the snapshot {want:.12g}")
        if abs(got - want) > 1e-12 * abs(want):
            fail(f"{key} {got} != {want}")
    if abs(t["water_volume"][0] - 0.5) > 1e-6:
        fail(f"volume {t['water_volume'][0]} != 0.5")


def check_values(t):
    err = np.max(np.abs(t["gauge"] - H))
    print(f"check_probes: gauge max |eta - H| = {err:.3g} m = {err / DX:.3g} dx")
    if not err < 0.1 * DX:
        fail(f"gauge off H by {err} m")
    later = t["time"] > 0
    for key in ["p_point", "p_mls", "p_sensor"]:
        rel = np.max(np.abs(t[key][later] / (RHO0 * G * H) - 1))
        print(f"check_probes: {key} max |p/(rho0 g H) - 1| = {rel:.3g} for t > 0")
        if not rel < 0.02:
            fail(f"{key} off rho0 g H by {rel}")


def check_ranks(run, run2):
    a, b = table(run), table(run2)
    for key in INTERPOLATED:
        if not np.array_equal(a[key], b[key]):
            fail(f"{key} differs between {run} and {run2}: {a[key]} {b[key]}")
    for key in INTEGRAL:
        if not np.allclose(a[key], b[key], rtol=1e-12, atol=0):
            fail(f"{key} differs between {run} and {run2} beyond 1e-12")
    print("check_probes: the rank counts agree")


def main(run, run2=None):
    t = table(run)
    if len(t) < 2:
        fail("fewer than 2 rows in probes.csv")
    check_integrals(run, t)
    check_values(t)
    if run2:
        check_ranks(run, run2)
    print("check_probes: ok")


if __name__ == "__main__":
    main(*sys.argv[1:])
