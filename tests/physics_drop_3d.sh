#!/usr/bin/env bash
# Oscillating drop in 3D (cases/oscillating-drop-3d: one fluid, R/dx = 10, A(0) = omega (1, -1/2,
# -1/2)) on 2 ranks over one period against the affine solution (doc/theory.md section 7b): the
# three semi-axes within 3 % of R in every snapshot, the centre pressure within 5 % of
# rho omega^2 R^2 after the acoustic filter (tests/check_drop.py).
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/mpirun -n 2 build/mpsph run cases/oscillating-drop-3d/case.yaml -o "$out/drop" --set output.progress_interval=1000
"$PYTHON" tests/check_drop.py "$out/drop" 0.03 0.05
