#!/usr/bin/env bash
# The pressure probes read the acoustic damper's stress (tests/cases/probe-damper.yaml): water
# compressed uniformly, div u = -2 1/s, at rest density, so at t = 0 the EOS pressure is 0 and a
# probe inside must read -rho0 alpha2 c0 h div u = 2 rho0 alpha2 c0 h (10 640 Pa) within 1 %
# (the lattice sum of the kernel), the same on 1 and 2 ranks; 0 with the damper off.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
case=tests/cases/probe-damper.yaml
scripts/mpirun -n 1 build/mpsph run $case -o "$out/r1" >/dev/null
scripts/mpirun -n 2 build/mpsph run $case -o "$out/r2" >/dev/null
scripts/mpirun -n 1 build/mpsph run $case -o "$out/off" --set physics.acoustic_damper=0 >/dev/null
"${PYTHON:-/usr/bin/python3}" - "$out" <<'PY'
import csv, sys
out = sys.argv[1]
def first_row(run):
    with open(f"{out}/{run}/probes.csv") as f:
        row = next(csv.DictReader(f))
    assert float(row["time"]) == 0, row
    return row
expect = 2 * 1000 * 10 * 20 * 1.33 * 0.02   # 2 rho0 alpha2 c0 h [Pa]
r1, r2, off = first_row("r1"), first_row("r2"), first_row("off")
bad = 0
for name in ("p_centre", "p_off"):
    err = float(r1[name]) / expect - 1
    ok = abs(err) <= 0.01 and r1[name] == r2[name] and abs(float(off[name])) <= 1e-6 * expect
    print(f"{name}: {float(r1[name]):.6g} Pa (2 rho0 alpha2 c0 h = {expect:.6g}, {100 * err:+.3f} %), "
          f"2 ranks {r2[name]}, damper off {off[name]}: {'ok' if ok else 'FAIL'}")
    bad += not ok
sys.exit(1 if bad else 0)
PY
