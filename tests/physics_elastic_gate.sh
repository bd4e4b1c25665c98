#!/usr/bin/env bash
# test-cores: 3
# Elastic solids coupled to the fluid (scheme riemann; doc/theory.md section 14), on the gate case
# (cases/elastic-gate-antoci):
#  - the gate clamped whole holds the water column with the hydrostatic thrust rho g H^2 / 2 (mean
#    over 0.05-0.08 s, after two acoustic periods 4H/c0, within 2 %, every sample within 3 %);
#  - the free gate follows Antoci's measured free end over t <= 0.1 s within 15 % of its maximum
#    (notes seed-002 section 2.4, acceptance 4);
#  - the snapshots' /solids group (displacement, stress) agrees with solids.csv and the particles;
#  - 1, 2 and 3 ranks with re-partitions, and 2 ranks stopped half-way and continued on 3, give the
#    same solids.csv and particles, bit for bit (the stopped run's final row at step 29 aside).
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
gate=cases/elastic-gate-antoci/case.yaml
run() {  # run NP OUTDIR [args...]
  local np=$1 dir=$2
  shift 2
  scripts/mpirun -n "$np" build/mpsph run "$gate" -o "$dir" --set output.progress_interval=1000 "$@" > "$dir.log" 2>&1
}

run 2 "$out/clamped" --set time.end=0.08 --set 'solids.0.clamp_min=[0.39,-0.01]' --set output.interval=0 \
  --set output.stats_interval=0.0005
"$PYTHON" tests/check_gate.py hydrostatic "$out/clamped" 0.05
run 2 "$out/early" --set time.end=0.1 --set output.interval=0
"$PYTHON" tests/check_gate.py early "$out/early"
short=(--set time.end=0.01 --set output.interval=0.005 --set parallel.repartition_every=20)
for np in 1 2 3; do run "$np" "$out/r$np" "${short[@]}"; done
run 2 "$out/half" "${short[@]}" --set time.max_steps=29
run 3 "$out/half" "${short[@]}" --restart
"$PYTHON" tests/check_gate.py snapshot "$out/r1"
for dir in r2 r3 half; do
  "$PYTHON" tests/compare_snapshots.py "$out/r1" "$out/$dir"
  "$PYTHON" tests/compare_snapshots.py "$out/r1/checkpoint.h5" "$out/$dir/checkpoint.h5"
  cmp <(awk -F, '$1 != 29' "$out/r1/solids.csv") <(awk -F, '$1 != 29' "$out/$dir/solids.csv")
done
echo "solids.csv, snapshots and checkpoints identical on 1, 2 and 3 ranks and across a restart"
# A checkpoint whose solid state is damaged (a NaN in F) is refused with status 1.
"$PYTHON" -c "
import sys, h5py
with h5py.File(sys.argv[1], 'r+') as f:
    a = f['run/solid0_F'][:]; a[5] = float('nan'); f['run/solid0_F'][...] = a" "$out/half/checkpoint.h5"
status=0
run 1 "$out/half" "${short[@]}" --set time.end=0.02 --restart || status=$?
[ "$status" -eq 1 ] && grep -q "/run/solid0_F\[5\] is nan" "$out/half.log"
echo "a damaged solid state in the checkpoint is refused"
