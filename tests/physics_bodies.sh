#!/usr/bin/env bash
# test-cores: 3
# Rigid bodies (doc/theory.md section 5b): free fall in 2D (two bodies) and 3D exact to round-off;
# boxes held under water, one beside a corner of the tank, carry the buoyancy rho g A and no
# torque (1 %); two floating boxes, one beside a wall, moving in the flow give the same bodies.csv
# and particles on 1, 2 and 3 ranks, and across a restart. The floating draft: physics_floating.sh.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run() {  # run NP CASE OUTDIR [args...]
  local np=$1 case=$2 dir=$3
  shift 3
  scripts/mpirun -n "$np" build/mpsph run "$case" -o "$dir" --set output.progress_interval=1000 "$@" > "$dir.log" 2>&1
}

run 2 tests/cases/body-free-fall.yaml "$out/fall"
"$PYTHON" tests/check_bodies.py fall "$out/fall"
run 2 tests/cases/body-free-fall-3d.yaml "$out/fall3"
"$PYTHON" tests/check_bodies.py fall "$out/fall3"

run 2 tests/cases/body-buoyancy.yaml "$out/buoy"
"$PYTHON" tests/check_bodies.py buoyancy "$out/buoy" 0.1

# The moving bodies on 1, 2 and 3 ranks, and 2 ranks stopped half-way and continued on 3: the same
# bits in the last snapshot, the checkpoint and the body's rows (the stopped run's final row at
# step 30, kept by the restart as stats.csv keeps its, aside).
short=(--set time.max_steps=60 --set output.interval=0.01 --set output.stats_interval=0.002)
for np in 1 2 3; do run "$np" tests/cases/floating-boxes.yaml "$out/r$np" "${short[@]}"; done
run 2 tests/cases/floating-boxes.yaml "$out/half" "${short[@]}" --set time.max_steps=30
run 3 tests/cases/floating-boxes.yaml "$out/half" "${short[@]}" --restart
for dir in r2 r3 half; do
  "$PYTHON" tests/compare_snapshots.py "$out/r1/checkpoint.h5" "$out/$dir/checkpoint.h5"
  "$PYTHON" tests/compare_snapshots.py "$(ls "$out"/r1/snap_*.h5 | tail -n 1)" "$(ls "$out"/$dir/snap_*.h5 | tail -n 1)"
  cmp <(awk -F, '$1 != 30' "$out/r1/bodies.csv") <(awk -F, '$1 != 30' "$out/$dir/bodies.csv")
done
echo "bodies.csv, snapshots and checkpoints identical on 1, 2, 3 ranks and across a restart"
