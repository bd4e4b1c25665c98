#!/usr/bin/env bash
# Command line: --help, --version and check succeed (check prints the counts and the memory
# estimate); a bad command line exits with status 1 and the usage. Bad case files:
# tests/bad_input.sh.
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
expect 0 "# memory: about [0-9.]+ MB on one rank \(450 bytes per particle" -- build/mpsph check "$case"
expect 0 "# particles: up to 1e\+10 .*not counted" -- \
  env MPSPH_MEMORY_AVAILABLE=16e9 build/mpsph check "$case" --set resolution.dx=1e-5
expect 1 "usage" -- build/mpsph
expect 1 "unknown command" -- build/mpsph frobnicate "$case"
expect 1 "unexpected argument '--frobnicate'" -- build/mpsph check "$case" --frobnicate
exit $fail
