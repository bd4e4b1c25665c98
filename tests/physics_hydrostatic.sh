#!/usr/bin/env bash
# Single-phase hydrostatic tank (H/dx = 25) settles to t sqrt(g/H) = 40 on 2 ranks: bottom
# pressure within 2 % of rho g H, kinetic energy decaying; snapshots pass the contract check.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/mpirun -n 2 build/mpsph run cases/hydrostatic-1phase/case.yaml -o "$out/run" \
  --set output.progress_interval=1000
"$PYTHON" tests/check_hydrostatic.py "$out/run"
"$PYTHON" scripts/check_snapshot.py "$out/run"
