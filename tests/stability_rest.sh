#!/usr/bin/env bash
# test-cores: 1
# Stability scene 4 (doc/stability.md): long-time rest. The two-phase hydrostatic tank of paper
# 000 section 3.1 (water 1 m under air 1 m, c0w = 10 sqrt(g Hw), c0a = 340 m/s) at Hw/dx = 10, to
# t sqrt(g/Hw) = 5 (the paper's 40 does not fit in a test; doc/stability.md has the command of
# the full run). Exit 0, layers kept (overlap at most 3 dx), masses bitwise constant,
# mechanical energy never above E0 + 0.05 M g dx.
source "$(dirname "$0")/stability/run_scene.sh"
scene rest 1
[ "$status" -eq 0 ] || { echo "FAIL rest: exit status $status, want 0"; exit 1; }
"$PYTHON" tests/check_stability.py "$out/rest" --dx 0.1 --tank 0,0,1,2 --layers water,air \
  --energy-scale mgdx --energy-tol 0.05 || fail=1
exit $fail
