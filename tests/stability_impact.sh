#!/usr/bin/env bash
# Stability scene 3 (doc/stability.md): a violent impact. A water block (0.14 m x 0.1 m, c0w =
# 60 m/s) moving at 6 m/s onto a vertical wall through a thin air layer (3 dx) in a closed
# air-filled tank (paper 000 section 3.3 spirit).
# XFAIL: the run stops with status 2 after about 0.0044 s, when an air particle of the cushion,
# squeezed between the water (about 50 kPa) and wall ghosts whose pressure is interpolated from
# the low-pressure air at their mirror points, is pushed through the first ghost layer (the same
# at 1.5 and 3 m/s, with a 5 dx layer, without shifting and without tensile control:
# doc/stability.md, "Light particles pushed into walls"). Asserted instead: the run stops with
# exactly this check, naming an air particle, and the last good state is finite, has every
# particle inside the walls and the initial masses, bit for bit.
source "$(dirname "$0")/stability/run_scene.sh"
scene impact 1
if [ "$status" -eq 0 ]; then
  echo "XPASS impact ran to the end: update doc/stability.md and make it a checked scene"
  "$PYTHON" tests/check_stability.py "$out/impact" --dx 0.01 --tank 0,0,0.3,0.15 \
    --energy-scale mgdx --energy-tol 0.05 || fail=1
  exit $fail
fi
if [ "$status" -eq 2 ] && grep -qE 'unstable at step [0-9]+, t = [-0-9.e+]+ s, after the step: particle [0-9]+ \(phase 1\) .*: entered the solid of walls.0' "$out/impact.log"; then
  xfail "impact at 6 m/s through a 3 dx air layer: exit status 2, an air particle entered the wall (known limit, doc/stability.md)"
else
  echo "FAIL impact: exit status $status, not the known failure"; exit 1
fi
"$PYTHON" - "$out/impact" <<'PY' || fail=1
import sys, h5py, numpy as np
run = sys.argv[1]
def load(name):
    with h5py.File(f"{run}/{name}", "r") as f:
        o = np.argsort(f["particles/id"][:])
        return {k: f["particles/" + k][:][o] for k in ("position", "velocity", "density", "pressure", "mass", "phase")}, f["header"].attrs["time"]
s0, _ = load("snap_00000.h5")
s, t = load("unstable_last_good.h5")
fl = s["phase"] >= 0
ok = all(np.all(np.isfinite(s[k])) for k in s)
x = s["position"][fl]
beyond = np.max(np.maximum(-x, x - np.array([0.3, 0.15]))) / 0.01
same = np.array_equal(s["mass"][fl], s0["mass"][s0["phase"] >= 0]) and np.array_equal(s["phase"], s0["phase"])
water = s["phase"] == 0
print(f"last good state t = {t:.5g} s: finite {ok}, largest distance beyond the walls {beyond:.3f} dx, masses bitwise {same}, "
      f"water max |u| {np.max(np.linalg.norm(s['velocity'][water], axis=1)):.3g} m/s, air max |u| {np.max(np.linalg.norm(s['velocity'][s['phase'] == 1], axis=1)):.3g} m/s, "
      f"water max rho/rho0 - 1 {np.max(s['density'][water] / 1000 - 1):.4f}")
sys.exit(0 if ok and beyond <= 0.5 and same else 1)
PY
exit $fail
