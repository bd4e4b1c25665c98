#!/usr/bin/env bash
# The energy check (time.energy_growth, status 2): issue 25's reproducer, a water column
# oscillating between two air layers in a closed channel without gravity, blows up at the
# interface-wall corners with every density in its band (acoustic damper alpha2 = 100, consistent
# shifting). The check must stop it with status 2, the "unstable at" line naming the energy, and
# the two failure files; the same column with acoustic_damper 0 must run to its end with status 0
# (negative control: the check does not trip on a clean run).
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
PYTHON=${PYTHON:-/usr/bin/python3}
case=tests/cases/air-water-air-column.yaml
fail=0

out=$(scripts/mpirun -n 2 build/mpsph run "$case" -o "$tmp/blowup" 2>&1)
status=$?
line='unstable at step [0-9]+, t = [0-9.e+-]+ s, after the step: particle [0-9]+ \(phase [01]\) at .*: the mechanical energy grew by [0-9.e+]+ M U_max\^2/2 since the start, above time\.energy_growth 1; this particle is the fastest, [0-9.e+]+ m/s$'
if [ "$status" -ne 2 ] || ! grep -qE -- "$line" <<<"$out"; then
  echo "FAIL blow-up: status $status (want 2), output:"
  echo "$out"
  fail=1
else
  grep -E "unstable at" <<<"$out"
  "$PYTHON" - "$tmp/blowup" <<'PY' || { echo "FAIL blow-up: the two files are missing or unreadable"; fail=1; }
import sys, h5py
for name in ("unstable_failing.h5", "unstable_last_good.h5"):
    with h5py.File(f"{sys.argv[1]}/{name}", "r") as f:
        assert f["particles/position"].shape[0] == f["header"].attrs["n_particles"] > 0, name
PY
fi

out=$(scripts/mpirun -n 2 build/mpsph run "$case" -o "$tmp/control" --set physics.acoustic_damper=0 2>&1)
status=$?
if [ "$status" -ne 0 ] || ! grep -qE 'energy check: largest growth of the mechanical energy' <<<"$out"; then
  echo "FAIL control (acoustic_damper 0): status $status (want 0), output:"
  echo "$out"
  fail=1
else
  grep -E "energy check" <<<"$out"
fi
[ "$fail" -eq 0 ] && echo "ok energy check"
exit $fail
