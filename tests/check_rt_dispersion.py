#!/usr/bin/env python3
"""check_rt_dispersion.py - the exact viscous interface normal modes of metrics.rt_mode_matrix
against three known limits: the inviscid Rayleigh-Taylor rate sqrt(At g k), the very viscous rate
At g / (2 nu k), and Lamb's damping 2 nu k^2 of a gravity wave under a near-vacuum (a complex
root), whose relative correction vanishes like sqrt(nu). Exit status 1 on a failed check."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

K, G = 2 * math.pi, 1.0
failed = 0


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what))
    failed += not ok


inviscid = metrics.rt_viscous_rate(K, G, (1 / 3, 1.0), (1e-9, 1e-9))
check(abs(inviscid / math.sqrt(0.5 * G * K) - 1) < 1e-4, "inviscid %.6f vs sqrt(At g k) %.6f" % (inviscid, math.sqrt(0.5 * G * K)))
viscous = metrics.rt_viscous_rate(K, G, (1 / 3, 1.0), (1.0, 1.0))
check(abs(viscous / (0.5 * G / (2 * K)) - 1) < 2e-3, "nu = 1: %.6f vs At g / (2 nu k) %.6f" % (viscous, 0.5 * G / (2 * K)))
for nu, tol in ((1e-4, 0.04), (1e-5, 0.012)):
    wave = metrics.newton_root(lambda z: __import__("numpy").linalg.det(
        metrics.rt_mode_matrix(z, K, G, (1.0, 1e-6), (nu, nu))), complex(-2 * nu * K * K, math.sqrt(G * K)))
    check(abs(wave.real / (-2 * nu * K * K) - 1) < tol and abs(wave.imag / math.sqrt(G * K) - 1) < 1e-3,
          "gravity wave nu = %g: n = %.6g%+.6gi vs Lamb -2 nu k^2 = %.6g, omega = %.6g" % (
              nu, wave.real, wave.imag, -2 * nu * K * K, math.sqrt(G * K)))
case = metrics.rt_viscous_rate(K, G, (1 / 3, 1.0), (3.90625e-3, 3.90625e-3))
print("cases/rayleigh-taylor-linear: exact viscous rate %.4f 1/s, estimate %.4f 1/s" % (
    case, metrics.rt_linear_rate(0.5, G, K, 3.90625e-3)))
sys.exit(1 if failed else 0)
