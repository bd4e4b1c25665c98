#!/usr/bin/env bash
# test-cores: 1
# Stability scene 1 (doc/stability.md): a closed water-air dam break, density ratio 1000, the
# physical air sound speed 340 m/s beside c0w = 28 m/s = 10 x 2 sqrt(gH). The c_stab limit of the
# time step (14.1 c0w = 396 m/s > 340 m/s) binds at every step; asserted from stats.csv written
# after every step. Exit 0, fluid inside the tank, masses bitwise constant, no air particle inside
# the water (all its neighbours within 3 dx water), mechanical energy never above E0 + 0.05 M g dx.
source "$(dirname "$0")/stability/run_scene.sh"
scene cstab 1 --set output.stats_interval=1e-9
[ "$status" -eq 0 ] || { echo "FAIL cstab: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/cstab" --dx 0.025 --tank 0,0,0.5,0.3 \
  --cstab water:air --no-isolated air:water --energy-scale mgdx --energy-tol 0.05 || fail=1
exit $fail
