#!/usr/bin/env bash
# test-cores: 1
# Stability scene 2 (doc/stability.md): entrapped air. A water column (0.3 m, free surface on top)
# falls at 1 m/s onto a closed air layer (0.1 m, 5 rows) at the bottom of a narrow tank: the air
# is compressed (pressure up to about 16 times its initial value) and re-expands below its
# initial pressure (period about 0.05 s). Exit 0, no particle beyond the walls, masses bitwise
# constant, the pocket stays closed (max y(air) - min y(water) at most 3 dx), the pocket pressure
# rises and falls back, mechanical energy never above E0 + 0.05 M g dx.
# The same column at 2 m/s (to 0.1 s) runs to the end, held off the walls by the wall guard
# (doc/theory.md §5; without it an air particle at the interface-wall corner entered the side
# wall at t = 0.059 s), and passes every check but one. XFAIL: the pocket does not stay closed:
# the interface breaks up as the air re-expands and air particles end up to about 6 dx above the
# lowest water particle (doc/stability.md, scene 2').
source "$(dirname "$0")/stability/run_scene.sh"
scene pocket 1
[ "$status" -eq 0 ] || { echo "FAIL pocket: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/pocket" --dx 0.02 --tank 0,0,0.2,0.6 --layers air,water \
  --pressure-cycle p_pocket --energy-scale mgdx --energy-tol 0.05 || fail=1

rm -rf "$out/pocket"   # the 1 m/s run's snapshots go on to t = 0.25 s
scene pocket 1 --set 'fluids.1.velocity=[0, -2]' --set time.end=0.1
[ "$status" -eq 0 ] || { echo "FAIL pocket at 2 m/s: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/pocket" --dx 0.02 --tank 0,0,0.2,0.6 --layers air,water \
  --pressure-cycle p_pocket --energy-scale mgdx --energy-tol 0.05 >"$out/check2.txt"
cat "$out/check2.txt"
failed=$(grep -c '^FAIL' "$out/check2.txt")
if [ "$failed" -eq 1 ] && grep -q '^FAIL layers' "$out/check2.txt"; then
  xfail "pocket at 2 m/s: runs to the end, but air and water mix beyond 3 dx (known limit, doc/stability.md)"
elif [ "$failed" -eq 0 ]; then
  echo "XPASS pocket at 2 m/s kept the pocket closed: update doc/stability.md and make it a checked scene"
else
  echo "FAIL pocket at 2 m/s: checks other than the layers failed"; fail=1
fi
exit $fail
