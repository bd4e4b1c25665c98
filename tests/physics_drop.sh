#!/usr/bin/env bash
# Oscillating drop (paper 001 III.B) at R/dx = 25 against the analytic solution: one fluid over a
# full period, two fluids (density ratio 100) over half a period; semi-axis within 2 % of R,
# centre pressure within 5 % of rho_in omega^2 R^2.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
coarse=(--set resolution.dx=0.04 --set output.interval=0.05 --set output.progress_interval=1000)
scripts/mpirun -n 2 build/mpsph run cases/oscillating-drop/case.yaml -o "$out/one" "${coarse[@]}"
"$PYTHON" tests/check_drop.py "$out/one" 0.02 0.05
scripts/mpirun -n 2 build/mpsph run cases/oscillating-drop-2fluid/case.yaml -o "$out/two" "${coarse[@]}" \
  --set time.end=2.42
"$PYTHON" tests/check_drop.py "$out/two" 0.02 0.05
