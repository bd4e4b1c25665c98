#!/usr/bin/env bash
# Two-phase hydrostatic tank (paper 000 section 3.1) at Hw/dx = 25 to t = 1 s on 2 ranks with the
# delta-plus scheme of the case: bottom pressure (averaged over 0.5-1 s) within 2 % of rho_w g Hw,
# no interpenetration beyond 3 dx, phase volumes within 0.5 %. The centreline criterion belongs to
# the full-length run (t sqrt(g/Hw) = 40, check_hydrostatic2.py --centreline), not to this test.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/mpirun -n 2 build/mpsph run cases/hydrostatic-2phase/case.yaml -o "$out/run" \
  --set resolution.dx=0.04 --set time.end=1.0 --set output.interval=0.5 --set output.progress_interval=1000
"$PYTHON" tests/check_hydrostatic2.py "$out/run" 0.04 0.02
