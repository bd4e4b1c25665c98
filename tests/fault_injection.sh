#!/usr/bin/env bash
# test-cores: 3
# Output faults (issue 20). Every run is under `timeout`, so that a hang fails the test.
#  1. A full disk (a small tmpfs) while writing a snapshot, a checkpoint, and a stats.csv or
#     probes.csv row, each on 1 and 2 ranks: every rank ends with status 3, the message names the
#     file and says "No space left on device", the files written before are complete (snapshots
#     and checkpoint read back, the XDMF index lists the snapshots), no .tmp file is left, and the
#     CSV tables hold complete rows only.
#     These runs have the free-space check before each HDF5 file off
#     (MPSPH_TEST_NO_ROOM_CHECK=1), so that the write itself meets the full disk; on 3 ranks,
#     where Open MPI's ompio can lose a failed collective write and hang, the check is on and
#     refuses the snapshot before its write.
#  2. The test hook MPSPH_TEST_NO_SPACE: a write that fails on the last of 2 ranks only ends the
#     same way on every rank.
#  3. The output folder's lock: a second run into the folder of a running one is refused with
#     status 1, naming the holder; after kill -9 of the first (which also cut a stats.csv row in
#     half, as a kill during a write would), --restart in that folder works and the torn row is
#     dropped.
# The tmpfs needs root, or else a user and mount namespace (unshare -rm); without either, part 1
# is skipped with a message and parts 2 and 3 still run.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
if [ "$(id -u)" -ne 0 ] && [ -z "${MPSPH_FAULT_NS:-}" ] && unshare -rm true 2>/dev/null; then
  MPSPH_FAULT_NS=1 exec unshare -rm bash "$0" "$@"   # root in a namespace of our own: tmpfs
fi
out=$(mktemp -d)
[ -z "${MPSPH_FAULT_NS:-}" ] || export TMPDIR=$out   # Open MPI's session folder: ours, not root's
disk=$out/disk
mkdir "$disk"
trap 'umount "$disk" 2>/dev/null || true; rm -rf "$out"' EXIT
LIMIT=120   # seconds for any one run: more means it hangs
case=tests/cases/dambreak-2phase-coarse.yaml
base=(--set output.progress_interval=1000)

# mpsph NP OUTDIR ARGS...: run on NP ranks under the time limit, output in OUTDIR, log in
# OUTDIR.log with a line "rank status S" per rank (Open MPI told not to end the other ranks when
# one exits non-zero, so that each shows its own). Sets $status: the ranks' status when they
# all agree, else "mixed".
mpsph() {
  local np=$1 dir=$2 code=0
  shift 2
  OMPI_MCA_orte_abort_on_non_zero_status=0 timeout "$LIMIT" scripts/mpirun -n "$np" \
    bash -c 'build/mpsph "$@"; s=$?; echo "rank status $s"; exit $s' \
    _ run "$case" -o "$dir" "${base[@]}" "$@" > "$dir.log" 2>&1 || code=$?
  [ "$code" -ne 124 ] || { echo "FAIL: $dir: no end within $LIMIT s (a hang)"; tail -20 "$dir.log"; exit 1; }
  local each all
  each=$(grep -o 'rank status [0-9]*' "$dir.log" | wc -l)
  all=$(grep -o 'rank status [0-9]*' "$dir.log" | sort -u)
  status=mixed
  if [ "$each" = "$np" ] && [ "$(echo "$all" | wc -l)" = 1 ]; then status=${all##* }; fi
}

# failed NP OUTDIR FILE: the run ended with status 3 on every rank, the message names
# OUTDIR/FILE and the full disk, no .tmp is left and what is there is complete.
failed() {
  local np=$1 dir=$2 file=$3
  [ "$status" = 3 ] ||
    { echo "FAIL: $dir: status $status: $(grep -o 'rank status [0-9]*' "$dir.log" | tr '\n' ' ')"; tail -20 "$dir.log"; exit 1; }
  echo "$dir: status 3 on the $np ranks"
  grep -F "mpsph: cannot write $dir/$file: No space left on device" "$dir.log" ||
    { echo "FAIL: $dir: no message naming $file and the reason"; grep mpsph: "$dir.log"; exit 1; }
  "$PYTHON" scripts/check_snapshot.py "$dir"   # snapshots, index, checkpoint; no .tmp left
  "$PYTHON" - "$dir" <<'PY'
import os, sys
d = sys.argv[1]
for name in ("stats.csv", "probes.csv"):
    text = open(os.path.join(d, name)).read()
    lines = text.split("\n")
    assert text.endswith("\n") and len(lines) > 2, f"{name}: a row cut short"
    n = lines[0].count(",")
    assert all(l.count(",") == n for l in lines[1:-1]), f"{name}: a row glued to another"
    steps = [int(l.split(",")[0]) for l in lines[1:-1]]
    assert steps == sorted(set(steps)), f"{name}: steps out of order"
print(f"{d}: stats.csv and probes.csv hold whole rows, in order")
PY
}

# tmpfs KIB: a fresh, empty tmpfs of KIB kB at $disk; 1 if none can be mounted.
tmpfs() {
  umount "$disk" 2>/dev/null || true
  mount -t tmpfs -o "size=${1}k" tmpfs "$disk" 2>/dev/null
}

# Sizes [kB] of a snapshot and a checkpoint of the case, rounded up to whole pages, from a
# one-step run.
mpsph 1 "$out/ref" --set time.max_steps=1 --set output.interval=1
[ "$status" = 0 ] || { echo "FAIL: the reference run ended with status $status"; cat "$out/ref.log"; exit 1; }
kib() { echo $(( ($(stat -c %s "$1") + 4095) / 4096 * 4 )); }
snap=$(kib "$out/ref/snap_00000.h5")
ckpt=$(kib "$out/ref/checkpoint.h5")
small=32   # config.yaml, snapshots.xdmf, stats.csv and probes.csv: a page or two each
echo "snapshot $snap kB, checkpoint $ckpt kB"

# 1. A full disk.
if tmpfs 64; then
  for np in 1 2; do
    # snapshots at t = 0, 0.002, 0.004 s: room for two and a half
    tmpfs $((5 * snap / 2 + small))
    MPSPH_TEST_NO_ROOM_CHECK=1 mpsph "$np" "$disk/snap$np" --set time.max_steps=40
    failed "$np" "$disk/snap$np" snap_00002.h5
    # checkpoints every 0.001 s after one snapshot: room for one and a half (the second is
    # written beside the first until it is complete)
    tmpfs $((snap + 3 * ckpt / 2 + small))
    MPSPH_TEST_NO_ROOM_CHECK=1 mpsph "$np" "$disk/ckpt$np" --set time.max_steps=40 \
      --set output.interval=1 --set output.checkpoint_interval=0.001
    failed "$np" "$disk/ckpt$np" checkpoint.h5
    # a row every step after one snapshot, with two pages to spare
    tmpfs $((snap + small / 2 + 8))
    MPSPH_TEST_NO_ROOM_CHECK=1 mpsph "$np" "$disk/csv$np" --set time.max_steps=300 --set output.interval=1 \
      --set output.stats_interval=1e-9 --set output.probes_interval=1e-9
    table=$(sed -n "s|^mpsph: cannot write $disk/csv$np/\([a-z]*\.csv\): .*|\1|p" "$disk/csv$np.log" | head -n 1)
    failed "$np" "$disk/csv$np" "${table:-stats.csv or probes.csv}"
  done
  tmpfs $((5 * snap / 2 + small))
  mpsph 3 "$disk/snap3" --set time.max_steps=40
  failed 3 "$disk/snap3" snap_00002.h5
  grep -E "needs about [0-9.]+ MB, [0-9.]+ MB are free" "$disk/snap3.log"
  umount "$disk"
else
  echo "SKIP part 1 (a full disk): cannot mount a tmpfs (needs root, or unshare -rm: user namespaces)"
fi

# 2. The hook: only the last of 2 ranks fails, while writing a snapshot, then a checkpoint.
MPSPH_TEST_NO_SPACE=snap_00001 mpsph 2 "$out/hook_snap" --set time.max_steps=40
failed 2 "$out/hook_snap" snap_00001.h5
MPSPH_TEST_NO_SPACE=checkpoint mpsph 2 "$out/hook_ckpt" --set time.max_steps=20 \
  --set output.checkpoint_interval=0.001
failed 2 "$out/hook_ckpt" checkpoint.h5

# 3. The lock. The first run writes a checkpoint every 0.001 s until it is killed.
lock=$out/lock
timeout "$LIMIT" scripts/mpirun -n 2 build/mpsph run "$case" -o "$lock" "${base[@]}" \
  --set time.max_steps=100000 --set output.checkpoint_interval=0.001 > "$lock.first.log" 2>&1 &
first=$!
while [ ! -e "$lock/checkpoint.h5" ] && kill -0 "$first" 2>/dev/null; do sleep 0.1; done
[ -e "$lock/checkpoint.h5" ] || { echo "FAIL: the first run wrote no checkpoint"; cat "$lock.first.log"; exit 1; }
mpsph 1 "$lock" --set time.max_steps=10
[ "$status" = 1 ] || { echo "FAIL: a second run into a folder in use: status $status"; tail "$lock.log"; exit 1; }
grep -E "mpsph: the output folder '$lock' is in use by another run \(pid [0-9]+ on host " "$lock.log"
ranks=$(pgrep -P "$(pgrep -P "$first")")
kill -KILL $ranks
wait "$first" || true
echo "first run killed by SIGKILL (ranks $(echo $ranks))"
printf '1,0.00' >> "$lock/stats.csv"   # a row cut short, as by a kill during its write
step=$("$PYTHON" -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r')['header'].attrs['step'])" "$lock/checkpoint.h5")
mpsph 2 "$lock" --set output.checkpoint_interval=0.001 --set time.max_steps=$((step + 10)) --restart
[ "$status" = 0 ] || { echo "FAIL: --restart after kill -9: status $status"; tail -20 "$lock.log"; exit 1; }
"$PYTHON" - "$lock/stats.csv" "$step" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
assert lines[-1] == "" and all(l.count(",") == lines[0].count(",") for l in lines[1:-1]), "a torn row"
steps = [int(l.split(",")[0]) for l in lines[1:-1]]
assert steps == sorted(set(steps)) and steps[-1] == int(sys.argv[2]) + 10, steps[-5:]
print(f"--restart from step {sys.argv[2]} after kill -9: stats.csv whole rows, in order")
PY
