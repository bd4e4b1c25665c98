#!/usr/bin/env bash
# Rayleigh-Taylor growth in the linear regime (cases/rayleigh-taylor-linear) at W/dx = 25: the
# exact viscous dispersion relation is checked against its limits, then the fitted growth rate of
# the run must be within 10 % of it (the validation study's metric and threshold).
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$PYTHON" tests/check_rt_dispersion.py
scripts/mpirun -n 2 build/mpsph run cases/rayleigh-taylor-linear/case.yaml -o "$out/rt" \
  --set resolution.dx=0.04 --set time.end=1.2 --set output.progress_interval=1000
"$PYTHON" - "$out/rt" <<'PY'
import os, sys
sys.path.insert(0, os.path.join("scripts", "validation"))
import metrics
err, notes, _ = metrics.rt_growth(sys.argv[1], 0.04)
print("growth-rate error %.4f: %s" % (err, notes))
sys.exit(0 if err <= 0.10 else 1)
PY
