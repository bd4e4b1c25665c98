#!/usr/bin/env bash
# test-cores: 2
# The energy check with an elastic solid (doc/theory.md section 6): a rubber block (1.44 kg/m)
# dropped 7 cm into a 5 cm water pool in a closed tank (tests/cases/solid-drop.yaml, delta-plus,
# 2 ranks). Its fall gives the water kinetic energy, more than the case's time.energy_growth
# 0.02 M U_max^2/2 on its own; the check counts the block's kinetic, strain and potential energy,
# so the run ends with status 0 and a largest growth below that threshold.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
case=tests/cases/solid-drop.yaml
status=0
scripts/mpirun -n 2 build/mpsph run "$case" -o "$out/run" > "$out/run.log" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
  cat "$out/run.log"
  echo "FAIL: status $status (want 0)"
  exit 1
fi
"$PYTHON" - "$out/run" "$case" "$out/run.log" <<'PY'
import re
import sys

import yaml

sys.path.insert(0, "scripts/validation")
import metrics  # noqa: E402

run, case_file, log = sys.argv[1:]
with open(case_file) as f:
    case = yaml.safe_load(f)
box = case["fluids"][0]["box"]
mass = case["phases"][0]["rho0"] * (box["max"][0] - box["min"][0]) * (box["max"][1] - box["min"][1])
scale = 0.5 * mass * 1.0 ** 2   # M U_max^2 / 2, u_max 1 (the default)
kinetic = metrics.read_csv(run + "/stats.csv")["kinetic_energy_water"].max() / scale
growth = float(re.search(r"largest growth of the mechanical energy ([-0-9.e+]+)", open(log).read()).group(1))
limit = case["time"]["energy_growth"]
print("the water's kinetic energy peaks at %.4f M U_max^2/2; the largest growth of the checked energy "
      "(water and block) is %.3g; threshold %g" % (kinetic, growth, limit))
ok = kinetic > 2 * limit and growth < limit
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
PY
