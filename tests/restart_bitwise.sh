#!/usr/bin/env bash
# test-cores: 3
# Restart: a coarse two-phase dam break run for 120 steps on 2 ranks, and the same run stopped
# at step 60 and continued with --restart on 2 ranks and on 3 ranks (with forced
# re-partitions), end in bitwise-identical particle data, and so do their checkpoints (also with
# scheme riemann, 1 rank against 2 continued on 3). The
# continued runs number their snapshots on and keep one stats.csv. A finished run extended with
# a later time.end continues from its last step. A missing or corrupt checkpoint, or a case that
# differs in more than time.end/output/parallel, is refused with status 1.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
case=tests/cases/dambreak-2phase-coarse.yaml
run() {  # run NP OUTDIR [args...]
  local np=$1 dir=$2
  shift 2
  scripts/mpirun -n "$np" build/mpsph run "$case" -o "$dir" "$@" > "$dir.log" 2>&1
}
last_snap() { ls "$1"/snap_*.h5 | tail -n 1; }

run 2 "$out/ref" --set time.max_steps=120
run 2 "$out/half" --set time.max_steps=60
cp -r "$out/half" "$out/half3"
run 2 "$out/half" --set time.max_steps=120 --restart
run 3 "$out/half3" --set time.max_steps=120 --restart "$out/half/../half3/checkpoint.h5" \
  --set parallel.repartition_every=25
grep -q "restart from .*checkpoint.h5: t = .*, step 60" "$out/half3.log"
for dir in half half3; do
  "$PYTHON" tests/compare_snapshots.py "$(last_snap "$out/ref")" "$(last_snap "$out/$dir")"
  "$PYTHON" tests/compare_snapshots.py "$out/ref/checkpoint.h5" "$out/$dir/checkpoint.h5"
  "$PYTHON" scripts/check_snapshot.py "$out/$dir" > "$out/$dir.check"
done
# The stop at step 60 adds one snapshot (the final one of that run) and numbering goes on; one
# stats.csv with every step once, in order, and the same rows as the reference from step 61.
"$PYTHON" - "$out" <<'PY'
import csv, glob, os, sys
out = sys.argv[1]
n_ref, n_half = (len(glob.glob(os.path.join(out, d, "snap_*.h5"))) for d in ("ref", "half3"))
assert n_half == n_ref + 1, (n_ref, n_half)
def rows(d):
    with open(os.path.join(out, d, "stats.csv")) as f:
        return [r[:3] for r in csv.reader(f)][1:]
ref, half = rows("ref"), rows("half3")
steps = [int(r[0]) for r in half]
assert steps == sorted(set(steps)), steps
assert [r for r in half if int(r[0]) > 60] == [r for r in ref if int(r[0]) > 60]
print(f"snapshots {n_ref} + 1, stats.csv rows in order: ok")
PY

# Scheme riemann (dual time stepping): 60 advection steps of the two-phase tank on 1 rank, and
# 30 on 2 ranks continued on 3, end in the same checkpoint bit for bit; with the air at 2 dx too.
riemann=(build/mpsph run cases/hydrostatic-2phase/case.yaml --set scheme=riemann --set kernel=wendland-c2
         --set resolution.h_over_dx=1.3 --set resolution.dx=0.05 --set phases.0.c0=62.6 --set phases.0.gamma=1
         --set phases.1.c0=62.6 --set phases.1.gamma=1 --set physics.u_max=6.26 --set time.cfl=0.6
         --set output.interval=0 --set output.progress_interval=1000)
scripts/mpirun -n 1 "${riemann[@]}" -o "$out/ri_ref" --set time.max_steps=60 > "$out/ri_ref.log" 2>&1
scripts/mpirun -n 2 "${riemann[@]}" -o "$out/ri_half" --set time.max_steps=30 > "$out/ri_half.log" 2>&1
scripts/mpirun -n 3 "${riemann[@]}" -o "$out/ri_half" --set time.max_steps=60 --restart > "$out/ri_half2.log" 2>&1
"$PYTHON" tests/compare_snapshots.py "$out/ri_ref/checkpoint.h5" "$out/ri_half/checkpoint.h5"
# The same with the air at twice the spacing (multi-resolution), 1 rank against 2 continued on 1.
mr=(--set phases.1.dx_ratio=2 --set 'domain.min=[-0.4,-0.4]' --set 'domain.max=[1.4,2.4]')
scripts/mpirun -n 1 "${riemann[@]}" "${mr[@]}" -o "$out/mr_ref" --set time.max_steps=60 > "$out/mr_ref.log" 2>&1
scripts/mpirun -n 2 "${riemann[@]}" "${mr[@]}" -o "$out/mr_half" --set time.max_steps=30 > "$out/mr_half.log" 2>&1
scripts/mpirun -n 1 "${riemann[@]}" "${mr[@]}" -o "$out/mr_half" --set time.max_steps=60 --restart > "$out/mr_half2.log" 2>&1
"$PYTHON" tests/compare_snapshots.py "$out/mr_ref/checkpoint.h5" "$out/mr_half/checkpoint.h5"

# A finished run extended with a later time.end.
run 2 "$out/ext" --set time.end=0.004
run 2 "$out/ext" --set time.end=0.006 --restart
"$PYTHON" - "$out/ext" <<'PY'
import glob, os, sys, h5py
out = sys.argv[1]
with h5py.File(os.path.join(out, "checkpoint.h5"), "r") as f:
    assert f["header"].attrs["time"] == 0.006 and f["run"].attrs["finished"] == 1
snaps = sorted(glob.glob(os.path.join(out, "snap_*.h5")))
times = [h5py.File(s, "r")["header"].attrs["time"] for s in snaps]
assert times == sorted(times) and 0.004 in times and times[-1] == 0.006, times
print(f"extended to t = 0.006 s: {len(snaps)} snapshots in order: ok")
PY
grep -q "end: 0.006" "$out/ext/config.yaml"

# Refusals: status 1, a message, and nothing written.
fail=0
expect_refusal() {  # expect_refusal PATTERN -- command...
  local pattern=$1 status=0 msg
  shift 2
  msg=$("$@" 2>&1) || status=$?
  if [ "$status" -ne 1 ] || ! grep -qE -- "$pattern" <<<"$msg"; then
    echo "FAIL: $* gave status $status: $msg"
    fail=1
  else
    echo "ok: refused: $(grep 'mpsph:' <<<"$msg" | head -n 1)"
  fi
}
restart=(scripts/mpirun -n 2 build/mpsph run "$case" --set time.max_steps=130 --restart)
before=$(md5sum < "$out/ref/checkpoint.h5")
expect_refusal "cannot restart from $out/none/checkpoint.h5: cannot open" -- "${restart[@]}" -o "$out/none"
echo "not HDF5" > "$out/bad.h5"
expect_refusal "cannot restart from $out/bad.h5: cannot open" -- "${restart[@]}" "$out/bad.h5" -o "$out/ref"
expect_refusal "case differs.*under 'physics'.*delta: 0.1.*delta: 0.2" -- "${restart[@]}" -o "$out/ref" \
  --set physics.delta=0.2
expect_refusal "case differs.*under 'resolution'" -- "${restart[@]}" -o "$out/ref" --set resolution.dx=0.05
expect_refusal "cannot restart from .*snap_00000.h5: .*no group /run" -- "${restart[@]}" \
  "$out/ref/snap_00000.h5" -o "$out/ref"
expect_refusal "--restart: only with run" -- build/mpsph check "$case" --restart
[ "$(md5sum < "$out/ref/checkpoint.h5")" = "$before" ] || { echo "FAIL: a refusal changed the checkpoint"; fail=1; }
[ ! -e "$out/none" ] || { echo "FAIL: a refused restart created its output folder"; fail=1; }
exit $fail
