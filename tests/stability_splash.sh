#!/usr/bin/env bash
# test-cores: 1
# Stability scene 5 (doc/stability.md): isolated water particles (four single particles and a 2x2
# drop) thrown at 4-5 m/s through air at rest (density ratio 1000, c0a = 340 m/s) into the walls
# of a closed tank: the same-phase renormalisation falls back to the identity and shifting is off
# for them. Exit 0, no particle beyond the walls, masses bitwise constant, every water particle
# ends within 3 dx of a wall, mechanical energy never above E0 + 0.05 M g dx.
source "$(dirname "$0")/stability/run_scene.sh"
scene splash 1
[ "$status" -eq 0 ] || { echo "FAIL splash: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/splash" --dx 0.02 --tank 0,0,0.4,0.2 \
  --at-wall water --energy-scale mgdx --energy-tol 0.05 || fail=1
exit $fail
