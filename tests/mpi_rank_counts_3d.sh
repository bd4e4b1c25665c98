#!/usr/bin/env bash
# test-cores: 16
# 3D two-phase with walls on many rank counts: the coarse 3D water-air dam break
# (tests/cases/dambreak-3d-2phase.yaml, 1440 fluid + 5712 wall particles on 6 x 4 x 3 cells; some
# particles change cells within the run) for 20 steps gives bitwise-identical particle data
# (sorted by id) on 1, 2, 4 and 8 ranks, and on 4, 8 and 16 ranks (oversubscribed) re-partitioned
# at steps 7 and 14 by particle work (parallel.balance: work, so the partitions do not follow noisy
# timings); the re-partitions happened (timings.csv) and conserve each phase's mass. On 24 ranks
# those re-partitions would leave a rank without a cell (72 occupied cells): they are skipped with
# a warning, the first partition stays, the run ends with status 0 and the same particle data.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
args=(tests/cases/dambreak-3d-2phase.yaml --set time.max_steps=20)
run() {  # run NP NAME [args...]
  local np=$1 name=$2
  shift 2
  scripts/mpirun -n "$np" build/mpsph run "${args[@]}" -o "$out/$name" "$@" > "$out/$name.log" 2>&1 \
    || { cat "$out/$name.log"; return 1; }
}

run 1 np1
for np in 2 4 8; do
  run "$np" "np$np"
  "$PYTHON" tests/compare_snapshots.py "$out/np1" "$out/np$np"
done
for np in 4 8 16; do
  run "$np" "np${np}r" --set parallel.repartition_every=7 --set parallel.balance=work
  grep -qx "migration,time,2,.*" "$out/np${np}r/timings.csv" || {
    echo "np${np}r: expected 2 re-partitions in timings.csv"; exit 1; }
  "$PYTHON" tests/compare_snapshots.py "$out/np1" "$out/np${np}r"
  "$PYTHON" tests/check_mass.py "$out/np${np}r"
done
run 24 np24r --set parallel.repartition_every=7 --set parallel.balance=work
[ "$(grep -c 'the re-partition at step .* is skipped' "$out/np24r.log")" = 2 ] || {
  cat "$out/np24r.log"; echo "np24r: expected the 2 re-partitions skipped with a warning"; exit 1; }
grep -qx "migration,time,0,.*" "$out/np24r/timings.csv" || { echo "np24r: expected no re-partition"; exit 1; }
"$PYTHON" tests/compare_snapshots.py "$out/np1" "$out/np24r"
