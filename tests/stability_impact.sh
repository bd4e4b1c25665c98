#!/usr/bin/env bash
# test-cores: 1
# Stability scene 3 (doc/stability.md): a violent impact. A water block (0.14 m x 0.1 m, c0w =
# 60 m/s) moving at 6 m/s onto a vertical wall through a thin air layer (3 dx) in a closed
# air-filled tank (paper 000 section 3.3 spirit), to 0.03 s.
# Asserted: exit 0; every value finite, no fluid particle beyond the walls by more than dx/2 or
# outside the domain, masses bitwise constant, mechanical energy never above E0 + 0.05 M g dx
# (tests/check_stability.py); the wall guard (physics.wall_guard, doc/theory.md §5) acted.
# Negative control: with the guard off (physics.wall_guard: 0) the run stops with status 2 when an
# air particle of the cushion, squeezed between the water and the wall, enters the wall, and the
# last good state is finite, inside the walls, with the initial masses bit for bit.
source "$(dirname "$0")/stability/run_scene.sh"
scene impact 1
[ "$status" -eq 0 ] || { echo "FAIL impact: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/impact" --dx 0.01 --tank 0,0,0.3,0.15 \
  --energy-scale mgdx --energy-tol 0.05 || fail=1
hits=$(tail -n 1 "$out/impact/stats.csv" | awk -F, '{print $NF}')
echo "wall guard corrections: $hits"
[ "${hits:-0}" -gt 0 ] || { echo "FAIL impact: the wall guard never acted (wall_guard_hits $hits)"; fail=1; }

scene impact 1 --set physics.wall_guard=0
if [ "$status" -eq 2 ] && grep -qE 'unstable at step [0-9]+, t = [-0-9.e+]+ s, after the step: particle [0-9]+ \(phase 1\) .*: entered the solid of walls.0' "$out/impact.log"; then
  echo "ok   without the guard: exit status 2, an air particle entered the wall (the negative control)"
else
  echo "FAIL impact without the guard: exit status $status, not the known failure"; exit 1
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
