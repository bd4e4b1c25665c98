#!/usr/bin/env bash
# test-cores: 1
# Stability scene 6b (doc/stability.md): density ratio 10000, water (1000, c0 14 m/s) under a gas
# of 0.1 kg/m^3 (c0 340 m/s) at rest, to t = 0.3 s. c_stab = 44.7 c0w = 626 m/s binds the time
# step (asserted at every step). Exit 0, layers kept (overlap at most 3 dx), masses bitwise
# constant, mechanical energy never above E0 + 0.05 M g dx.
source "$(dirname "$0")/stability/run_scene.sh"
scene ratio10000 1 --set time.end=0.3 --set output.stats_interval=1e-9
[ "$status" -eq 0 ] || { echo "FAIL ratio10000: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/ratio10000" --dx 0.025 --tank 0,0,0.2,0.4 \
  --layers water,gas --cstab water:gas --energy-scale mgdx --energy-tol 0.05 || fail=1
exit $fail
