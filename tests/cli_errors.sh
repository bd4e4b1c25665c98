#!/usr/bin/env bash
# Command line and bad input: exit status 1 with a message naming file, line and key; nothing is
# written for bad input; --help/--version/check succeed.
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {  # expect STATUS PATTERN -- command...
  local want=$1 pattern=$2
  shift 3
  local out status
  out=$("$@" 2>&1)
  status=$?
  if [ "$status" -ne "$want" ] || ! grep -qE -- "$pattern" <<<"$out"; then
    echo "FAIL: '$*' gave status $status (want $want), output: $out"
    fail=1
  else
    echo "ok: $* -> $status"
  fi
}
case=cases/hydrostatic-1phase/case.yaml
expect 0 "usage" -- build/mpsph --help
expect 0 "^mpsph " -- build/mpsph --version
expect 0 "# particles: 625 fluid" -- build/mpsph check "$case"
expect 1 "usage" -- build/mpsph
expect 1 "unknown command" -- build/mpsph frobnicate "$case"
expect 1 "cannot open" -- build/mpsph check "$tmp/missing.yaml"
sed 's/^physics: {delta/physics: {deltaa/' "$case" > "$tmp/unknown.yaml"
expect 1 "unknown.yaml:[0-9]+: physics.deltaa: unknown key" -- build/mpsph check "$tmp/unknown.yaml"
expect 1 "resolution.dx.*> 0" -- build/mpsph check "$case" --set resolution.dx=-1
expect 1 "kernel.*gaussian, wendland-c2" -- build/mpsph check "$case" --set kernel=cubic
sed 's/max: \[1, 1\]}}$/max: [1, 1]}}\n  - {phase: water, box: {min: [0.5, 0.5], max: [0.9, 0.9]}}/' "$case" > "$tmp/overlap.yaml"
expect 1 "fluids.1 overlaps fluids.0" -- build/mpsph check "$tmp/overlap.yaml"
expect 1 "walls.0.*ghost layers.*outside the domain" -- build/mpsph check "$case" --set domain.min=[-0.05,-0.05]
expect 1 "1 cells but 3 ranks|cells but 3 ranks" -- scripts/mpirun -n 3 build/mpsph run "$case" -o "$tmp/ranks" \
  --set "walls=[]" --set resolution.dx=0.2 --set time.end=0.01
expect 1 "scheme: only delta-plus" -- build/mpsph run "$case" -o "$tmp/scheme" --set scheme=riemann
expect 1 "cannot write to the output folder" -- build/mpsph run "$case" -o /proc/mpsph-not-writable
for d in ranks scheme; do
  if [ -e "$tmp/$d" ] && [ -n "$(ls -A "$tmp/$d")" ]; then echo "FAIL: bad input wrote $tmp/$d"; fail=1; fi
done
exit $fail
