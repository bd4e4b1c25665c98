#!/usr/bin/env bash
# test-cores: 3
# kill -9 in the middle of a write (the test hook MPSPH_TEST_ABORT_IN_WRITE=NAME kills every
# rank by SIGKILL while NAME.tmp is being written) leaves the files written before complete:
#  1. a run with periodic checkpoints (output.checkpoint_interval) killed while writing a
#     snapshot keeps its earlier snapshots and its last checkpoint; --restart on 3 ranks then
#     ends with the snapshots and stats.csv rows (step, time, dt) of an uninterrupted run;
#  2. a run killed while writing its checkpoint keeps the previous checkpoint.h5, bit for bit.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run=(build/mpsph run tests/cases/dambreak-2phase-coarse.yaml --set time.max_steps=100
     --set output.checkpoint_interval=0.004)
# complete OUTDIR FILE...: each file opens and has every dataset with n_particles rows.
complete() {
  local dir=$1
  shift
  "$PYTHON" - "$dir" "$@" <<'PY'
import os, sys
sys.path.insert(0, "scripts")
from check_snapshot import check_checkpoint, check_h5
for name in sys.argv[2:]:
    path = os.path.join(sys.argv[1], name)
    problems = (check_checkpoint if name == "checkpoint.h5" else check_h5)(path)[0]
    assert not problems, f"{name}: {problems}"
    print(f"{name}: complete")
PY
}
killed() {  # killed NAME OUTDIR [args...]: the run must die while writing NAME
  local name=$1 dir=$2 status=0
  shift 2
  MPSPH_TEST_ABORT_IN_WRITE=$name scripts/mpirun -n 2 "${run[@]}" -o "$dir" "$@" > "$dir.kill.log" 2>&1 || status=$?
  [ "$status" -ne 0 ] && [ -e "$dir/$name.tmp" ] || { echo "FAIL: no kill in $name (status $status)"; exit 1; }
  echo "killed in the write of $name (status $status)"
}

scripts/mpirun -n 2 "${run[@]}" -o "$out/ref" > "$out/ref.log" 2>&1

# 1. Killed while writing snap_00005.h5 (t = 0.01 s), after the checkpoint at t = 0.008 s.
killed snap_00005.h5 "$out/crash"
[ ! -e "$out/crash/snap_00005.h5" ]
complete "$out/crash" snap_00000.h5 snap_00004.h5 checkpoint.h5
"$PYTHON" -c "import h5py, sys; t = h5py.File(sys.argv[1], 'r')['header'].attrs['time']; assert 0.008 <= t < 0.01, t" \
  "$out/crash/checkpoint.h5"
scripts/mpirun -n 3 "${run[@]}" -o "$out/crash" --restart > "$out/crash.restart.log" 2>&1
"$PYTHON" tests/compare_snapshots.py "$out/ref" "$out/crash"
"$PYTHON" scripts/check_snapshot.py "$out/crash"
for f in stats.csv probes.csv; do
  cmp <(cut -d, -f1-3 "$out/ref/$f") <(cut -d, -f1-3 "$out/crash/$f")
  echo "$f: the rows of the uninterrupted run, each once"
done

# 2. Killed while writing the checkpoint at the end of an extension to 110 steps.
cp "$out/crash/checkpoint.h5" "$out/before.h5"
killed checkpoint.h5 "$out/crash" --set time.max_steps=110 --restart
cmp "$out/before.h5" "$out/crash/checkpoint.h5"
complete "$out/crash" checkpoint.h5 $(cd "$out/crash" && ls snap_*.h5)
echo "the previous checkpoint.h5 is intact"
