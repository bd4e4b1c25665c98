#!/usr/bin/env bash
# The probes on water at rest (tests/cases/hydrostatic-probes.yaml) on 1 and 2 ranks: wave gauge
# at the still level, integrals equal to the snapshot's sums, bottom sensors at rho0 g H, the
# same values on both rank counts (tests/check_probes.py).
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scripts/mpirun -n 1 build/mpsph run tests/cases/hydrostatic-probes.yaml -o "$out/r1" >/dev/null
scripts/mpirun -n 2 build/mpsph run tests/cases/hydrostatic-probes.yaml -o "$out/r2" >/dev/null
"${PYTHON:-/usr/bin/python3}" tests/check_probes.py "$out/r2" "$out/r1"
