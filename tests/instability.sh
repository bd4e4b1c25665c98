#!/usr/bin/env bash
# Instability checks (exit status 2): each check is tripped on purpose in the hydrostatic tank (the
# energy check in issue 25's reproducer). The run must stop with status 2, print the step, time,
# particle, phase, position and the check, and leave unstable_failing.h5 and
# unstable_last_good.h5 readable, in the snapshot layout.
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
PYTHON=${PYTHON:-/usr/bin/python3}
case=cases/hydrostatic-1phase/case.yaml
where='unstable at step [0-9]+, t = [-0-9.e+]+ s, (RK stage [1-4]|after the step): particle [0-9]+ \(phase [0-9]\) at \([-0-9.e+]+, [-0-9.e+]+\) with density .* kg/m\^3, pressure .* Pa: '
fail=0

# trips NAME NP PATTERN -- ARGS...: run the case on NP ranks into $tmp/NAME and check the result.
trips() {
  local name=$1 np=$2 pattern=$3
  shift 4
  local out status
  out=$(scripts/mpirun -n "$np" build/mpsph run "$case" -o "$tmp/$name" --set output.progress_interval=1000 "$@" 2>&1)
  status=$?
  if [ "$status" -ne 2 ] || ! grep -qE -- "$where$pattern" <<<"$out"; then
    echo "FAIL $name: status $status (want 2), output:"
    echo "$out"
    fail=1
    return
  fi
  grep -E "unstable at" <<<"$out"
  "$PYTHON" - "$tmp/$name" <<'PY' || { echo "FAIL $name: the two files are missing or unreadable"; fail=1; }
import sys, h5py
for name in ("unstable_failing.h5", "unstable_last_good.h5"):
    with h5py.File(f"{sys.argv[1]}/{name}", "r") as f:
        assert f["particles/position"].shape[0] == f["header"].attrs["n_particles"] > 0, name
PY
  echo "ok $name"
}

# A non-finite value: gravity so large that the hydrostatic start overflows.
trips nonfinite 1 'drho/dt$' -- --set 'gravity=[0, -1e308]'
# A density band narrower than the hydrostatic compression (about 1 % at the bottom).
trips band 1 'density 1\.0[0-9]* rho0 outside phases\.0\.density_band \[0\.999, 1\.001\]$' -- \
  --set 'phases.0.density_band=[0.999, 1.001]'
# Water thrown into the tank bottom at 100 m/s (Mach 3), with a density band wide enough not to
# trip first, the energy check off (the Mach-3 impact's energy error, 4.6 M U_max^2/2 at step 4,
# trips it first) and the wall guard off (with it the water is stopped at the wall: doc/theory.md §5):
# the motion limit of the time step keeps it from jumping the wall, but it is driven into the
# wall's solid within a few steps; on two ranks, which must stop at the same step.
trips solid 2 'entered the solid of walls\.0, [0-9.]+ dx beyond its boundary$' -- \
  --set 'fluids.0.velocity=[0, -100]' --set 'phases.0.density_band=[0.01, 100]' --set physics.wall_guard=0 \
  --set time.energy_growth=0
# The same without walls: the water leaves the domain.
trips domain 1 'left the domain$' -- --set 'walls=[]' --set 'fluids.0.velocity=[0, -100]'
# A time-step floor above the acoustic step.
trips dt 1 'time step 0\.0017 s below time\.dt_min 0\.01 s, set by the acoustic limit; this particle has the largest acceleration, [0-9.]+ m/s\^2$' -- \
  --set time.dt_min=0.01
# A configuration that is really unstable (the difference-form damper at alpha2 = 10,
# doc/theory.md) is stopped by one of the checks.
trips damper 1 '' -- --set physics.acoustic_damper=10 --set physics.damper_form=difference \
  --set time.end=0.5
# The energy check (time.energy_growth): issue 25's reproducer, a water column oscillating between
# two air layers in a closed channel without gravity, blows up at the interface-wall corners with
# every density in its band (the symmetric damper form at alpha2 = 100, consistent shifting); the
# same column with acoustic_damper 0 runs to its end with status 0 (the check does not trip on a
# clean run).
case=tests/cases/air-water-air-column.yaml
trips energy 2 'the mechanical energy grew by [0-9.e+]+ M U_max\^2/2 since the start, above time\.energy_growth 1; this particle is the fastest, [0-9.e+]+ m/s$' --
out=$(scripts/mpirun -n 2 build/mpsph run "$case" -o "$tmp/control" --set physics.acoustic_damper=0 2>&1)
status=$?
if [ "$status" -ne 0 ] || ! grep -qE 'energy check: largest growth of the mechanical energy' <<<"$out"; then
  echo "FAIL energy control (acoustic_damper 0): status $status (want 0), output:"
  echo "$out"
  fail=1
else
  grep -E "energy check" <<<"$out"
fi
exit $fail
