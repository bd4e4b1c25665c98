#!/usr/bin/env bash
# test-cores: 4   (4 restarts at once, mostly waiting)
# Damaged checkpoints: copies of a valid checkpoint, each with one damage made by
# tests/damage_checkpoint.py (a header number, a /run number, the snapshot series, one field of
# one particle row, a dataset of the wrong length, a truncated file), are refused by --restart on
# 1 and on 2 ranks with status 1 and a message naming the file, the field, the row and the
# value, within a time limit (a crash or a hang fails), and create no output folder. A restart whose next
# snapshot number is taken by a snapshot older than the checkpoint (a series that lost rows)
# is refused; one taken by a snapshot written after the checkpoint is replaced, and the
# undamaged checkpoint restarts on 1 and 2 ranks.
# The restarts run 4 at a time: most of their time is mpirun's wait after a rank's status 1.
set -u
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
case=tests/cases/dambreak-2phase-coarse.yaml
fail=0

# The damages and the message each must give after "cannot restart from FILE: ".
declare -A expect=(
  [n_particles_negative]='/header/n_particles: got -1, expected an integer from 1 to [0-9]+'
  [n_particles_huge]='/header/n_particles: got 1000000000000, expected an integer from 1 to [0-9]+ \(at most the lattice nodes'
  [n_particles_more]='/particles/position has [0-9]+ rows, expected [0-9]+'
  [density_rows_short]='/particles/density has [0-9]+ rows, expected [0-9]+'
  [time_nan]='/header/time: got nan, expected a finite number > 0'
  [step_negative]='/header/step: got -3, expected an integer >= 1'
  [dimension_3]='/header/dimension: got 3, expected 2 \(the dimension of its case\)'
  [dt_negative]='/run/dt: got -0.0001, expected a number in \(0, '
  [next_output_nan]='/run/next_output: got nan, expected a number in \['
  [next_stats_past]='/run/next_stats: got -1e\+300, expected a number in \['
  [last_stats_step_future]='/run/last_stats_step: got 1099511627776, expected an integer from 0 to 3 '
  [finished_2]='/run/finished: got 2, expected 1 '
  [series_empty]='/run/snapshot_times: number of rows: got 0, expected an integer from 1 to 4 '
  [series_long]='/run/snapshot_times: number of rows: got 10, expected an integer from 1 to 4 '
  [series_short]='/run/snapshot_times: row 0: got 0, expected [0-9.e-]+ \(the last snapshot was written at'
  [series_after_time]='/run/snapshot_times: row 1: got [0-9.e-]+, expected'
  [phase_out_of_range]='/particles/phase: row [0-9]+ \(id [0-9]+\): got 7, expected an integer from -1 to 1 '
  [wall_out_of_range]='/particles/wall: row [0-9]+ \(id [0-9]+\): got 5, expected 0 '
  [wall_on_fluid]='/particles/wall: row [0-9]+ \(id [0-9]+\): got 0, expected -1 '
  [id_negative]='/particles/id: row [0-9]+ \(id -4\): got -4, expected an integer from 0 to [0-9]+'
  [id_too_large]='/particles/id: row 0 \(id [0-9]+\): got [0-9]+, expected an integer from 0 to'
  [id_duplicate]='/particles/id: rows 0 and [0-9]+: got [0-9]+ in both, expected each id once'
  [density_negative]='/particles/density: row [0-9]+ \(id [0-9]+\): got -1000, expected a finite number > 0'
  [mass_zero]='/particles/mass: row 0 \(id [0-9]+\): got 0, expected a finite number > 0'
  [pressure_inf]='/particles/pressure: row 0 \(id [0-9]+\): got inf, expected a finite number'
  [velocity_nan]='/particles/velocity: row [0-9]+ \(id [0-9]+\), column 1: got nan, expected a finite number'
  [position_outside]='/particles/position: row [0-9]+ \(id [0-9]+\), column 0: got 100, expected a number in \[-0.3, 3.516\]'
  [mirror_nan]='/particles/mirror: row [0-9]+ \(id [0-9]+\), column 0: got nan, expected a finite number'
  [mirror_far]='/particles/mirror: row [0-9]+ \(id [0-9]+\), column 1: got 5, expected a number in \[-[0-9.]+, [0-9.]+\] \(a ghost'"'"'s mirror point'
  [truncated]='cannot open .*/truncated.h5'
)

# attempt TAG NP DIR FILE: in the background (at most 4 at a time), restart from FILE into DIR
# on NP ranks for 3 more steps within 30 s (status 124: a hang); the output goes to
# $out/TAG.npNP, the status to $out/TAG.npNP.status.
attempt() {
  while [ "$(jobs -rp | wc -l)" -ge 4 ]; do wait -n; done
  (status=0
   timeout 30 scripts/mpirun -n "$2" build/mpsph run "$case" -o "$3" --set time.max_steps=6 \
     --restart "$4" > "$out/$1.np$2" 2>&1 || status=$?
   echo "$status" > "$out/$1.np$2.status") &
}
# verdict TAG NP STATUS PATTERN: the attempt ended with STATUS and printed PATTERN.
verdict() {
  local log=$out/$1.np$2 status
  status=$(cat "$log.status")
  if [ "$status" -ne "$3" ] || ! grep -qE -- "$4" "$log"; then
    echo "FAIL $1 on $2 ranks: status $status (want $3), output: $(grep -m 3 'mpsph\|rror' "$log")"
    fail=1
  else
    echo "ok $1 on $2 ranks: $(grep -m 1 "^mpsph: \|^restart from" "$log")"
  fi
}

scripts/mpirun -n 2 build/mpsph run "$case" -o "$out/run" --set time.max_steps=3 > "$out/run.log" 2>&1 ||
  { echo "FAIL: the run that makes the checkpoint"; cat "$out/run.log"; exit 1; }
mkdir "$out/damaged"
"$PYTHON" tests/damage_checkpoint.py "$out/run/checkpoint.h5" "$out/damaged" "${!expect[@]}" || exit 1
# The next snapshot number (snap_00002.h5: the series has 2) taken by a snapshot of step 0: the
# series lost rows, and the restart would overwrite it. The same file with a step after the
# checkpoint's, as a run killed after its checkpoint leaves it: replaced by the restart.
"$PYTHON" - "$out" <<'PY' || exit 1
import shutil, sys, h5py
out = sys.argv[1]
with h5py.File(f"{out}/run/checkpoint.h5", "r") as f:
    assert len(f["run/snapshot_times"]) == 2 and f["header"].attrs["step"] == 3, "not the run expected"
for name in ("older", "later1", "later2"):
    shutil.copytree(f"{out}/run", f"{out}/{name}")
    shutil.copyfile(f"{out}/run/snap_00000.h5", f"{out}/{name}/snap_00002.h5")
    if name != "older":
        with h5py.File(f"{out}/{name}/snap_00002.h5", "r+") as f:
            f["header"].attrs.modify("step", 4)
PY
before=$(cd "$out/older" && md5sum *)

for damage in "${!expect[@]}"; do
  for np in 1 2; do attempt "$damage" "$np" "$out/$damage.np$np.out" "$out/damaged/$damage.h5"; done
done
for np in 1 2; do
  attempt older "$np" "$out/older" "$out/older/checkpoint.h5"
  attempt later "$np" "$out/later$np" "$out/later$np/checkpoint.h5"
done
wait

for damage in "${!expect[@]}"; do
  for np in 1 2; do
    verdict "$damage" "$np" 1 "^mpsph: cannot restart from $out/damaged/$damage.h5: ${expect[$damage]}"
    [ ! -e "$out/$damage.np$np.out" ] || { echo "FAIL: $damage on $np ranks wrote output"; fail=1; }
  done
done
[ "$(cd "$out/older" && md5sum *)" = "$before" ] || { echo "FAIL: a refused restart wrote in its folder"; fail=1; }
for np in 1 2; do
  verdict older "$np" 1 "/run/snapshot_times: got 2 rows, expected at least 3: $out/older/snap_00002.h5 \(step 0\) was written at or before the checkpoint's step 3"
  verdict later "$np" 0 "^restart from $out/later$np/checkpoint.h5: t = .*, step 3"
  "$PYTHON" -c "import h5py, sys; assert h5py.File(sys.argv[1], 'r')['header'].attrs['step'] == 6" \
    "$out/later$np/snap_00002.h5" || { echo "FAIL: snap_00002.h5 not replaced on $np ranks"; fail=1; }
done
exit $fail
