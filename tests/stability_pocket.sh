#!/usr/bin/env bash
# Stability scene 2 (doc/stability.md): entrapped air. A water column (0.3 m, free surface on top)
# falls at 1 m/s onto a closed air layer (0.1 m, 5 rows) at the bottom of a narrow tank: the air
# is compressed (pressure up to about 16 times its initial value) and re-expands below its
# initial pressure (period about 0.05 s). Exit 0, no particle beyond the walls, masses bitwise
# constant, the pocket stays closed (max y(air) - min y(water) at most 3 dx), the pocket pressure
# rises and falls back, mechanical energy never above E0 + 0.05 M g dx.
# XFAIL: the same column at 2 m/s stops with status 2 after about 0.06 s: an air particle at the
# interface-wall corner is pushed through the first ghost layer (doc/stability.md, "Light
# particles pushed into walls").
source "$(dirname "$0")/stability/run_scene.sh"
scene pocket 1
[ "$status" -eq 0 ] || { echo "FAIL pocket: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/pocket" --dx 0.02 --tank 0,0,0.2,0.6 --layers air,water \
  --pressure-cycle p_pocket --energy-scale mgdx --energy-tol 0.05 || fail=1

scene pocket 1 --set 'fluids.1.velocity=[0, -2]' --set time.end=0.1
if [ "$status" -eq 2 ] && grep -q 'entered the solid of walls.0' "$out/pocket.log"; then
  xfail "pocket at 2 m/s: exit status 2, an air particle entered the wall (known limit, doc/stability.md)"
elif [ "$status" -eq 0 ]; then
  echo "XPASS pocket at 2 m/s ran to the end: update doc/stability.md and make it a checked scene"
else
  echo "FAIL pocket at 2 m/s: exit status $status, not the known failure"; fail=1
fi
exit $fail
