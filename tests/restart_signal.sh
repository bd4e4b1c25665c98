#!/usr/bin/env bash
# test-cores: 3
# Stop signals: SIGTERM sent to the ranks (what Slurm and srun deliver) and SIGUSR1 sent to
# mpirun (Open MPI forwards it; on SIGTERM it kills the ranks after 1 s) stop a run at the
# same step on every rank with status 0 and a complete checkpoint.h5, written no snapshot of
# its own; --restart (on 3 and on 2 ranks) then gives bitwise the snapshots of an uninterrupted
# run.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run=(build/mpsph run tests/cases/dambreak-2phase-coarse.yaml --set time.max_steps=120)

scripts/mpirun -n 2 "${run[@]}" -o "$out/ref" > "$out/ref.log" 2>&1

# interrupt OUTDIR SIGNAL WHO: start the run, wait for its second snapshot, signal the ranks
# (WHO=ranks) or mpirun (WHO=mpirun), and check the clean stop.
interrupt() {
  local dir=$1 sig=$2 who=$3 status=0
  scripts/mpirun -n 2 "${run[@]}" -o "$dir" > "$dir.log" 2>&1 &
  local pid=$!
  while [ ! -e "$dir/snap_00001.h5" ] && kill -0 "$pid" 2>/dev/null; do sleep 0.05; done
  if [ "$who" = ranks ]; then kill -s "$sig" $(pgrep -P "$pid"); else kill -s "$sig" "$pid"; fi
  wait "$pid" || status=$?
  [ "$status" -eq 0 ] || { echo "FAIL: status $status after SIG$sig"; cat "$dir.log"; exit 1; }
  grep "stopped by SIG$sig at step" "$dir.log"
  "$PYTHON" scripts/check_snapshot.py "$dir"
  "$PYTHON" -c "import h5py, sys; r = h5py.File(sys.argv[1], 'r')['run'].attrs; assert r['finished'] == 0" \
    "$dir/checkpoint.h5"
}

interrupt "$out/term" TERM ranks
scripts/mpirun -n 3 "${run[@]}" -o "$out/term" --restart > "$out/term2.log" 2>&1
"$PYTHON" tests/compare_snapshots.py "$out/ref" "$out/term"

interrupt "$out/usr1" USR1 mpirun
scripts/mpirun -n 2 "${run[@]}" -o "$out/usr1" --restart > "$out/usr12.log" 2>&1
"$PYTHON" tests/compare_snapshots.py "$out/ref" "$out/usr1"
