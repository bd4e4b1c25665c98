#!/usr/bin/env bash
# Static bubble in 3D (tests/cases/static-bubble-3d.yaml: R/dx = 10, sigma of cases/static-bubble,
# both fluids the liquid's, a liquid shell with a free outer surface) on 2 ranks to t = 6 ms: the
# pressure jump averaged over t = 1-6 ms is 2 sigma/R within 5 % and the phases stay apart
# (tests/check_static_bubble.py). The bubble starts at the Laplace pressure: a curvature that is
# wrong in 3D (sigma/R) sends it to the other equilibrium within the bubble's acoustic time.
# Measured +1.4 %; with sigma halved in the run and the case's sigma in the check, -54 %: FAIL.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/mpirun -n 2 build/mpsph run tests/cases/static-bubble-3d.yaml -o "$out/bubble"
"$PYTHON" tests/check_static_bubble.py "$out/bubble" 0.05 0.001
