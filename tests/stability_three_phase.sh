#!/usr/bin/env bash
# test-cores: 1
# Stability scene 6a (doc/stability.md): a three-phase column at rest, oil (846) over water (1000)
# with air (1, c0 = 340 m/s) above, 6 rows each (paper 000 section 3.5 layers, with air), to
# t = 0.5 s (t sqrt(g/H) = 2.9 with H = 0.3 m). Exit 0, layers kept (each interface's overlap at
# most 3 dx), masses bitwise constant, mechanical energy never above E0 + 0.05 M g dx.
source "$(dirname "$0")/stability/run_scene.sh"
scene three_phase 1 --set time.end=0.5
[ "$status" -eq 0 ] || { echo "FAIL three_phase: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/three_phase" --dx 0.025 --tank 0,0,0.2,0.45 \
  --layers water,oil,air --energy-scale mgdx --energy-tol 0.05 || fail=1
exit $fail
