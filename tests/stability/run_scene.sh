# Sourced by tests/stability_*.sh: run a stability scene and check it.
#   scene NAME NP [--set ...]   runs tests/stability/NAME.yaml on NP ranks into $out/NAME;
#                               sets $status (exit status) and prints the run's last lines.
#   xfail MESSAGE               records an expected failure (printed as XFAIL, not an error).
# Each test ends with `exit $fail`.
set -u
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail=0
status=0

scene() {
  local name=$1 np=$2
  shift 2
  local start=$SECONDS
  scripts/mpirun -n "$np" build/mpsph run "tests/stability/$name.yaml" -o "$out/$name" \
    --set output.progress_interval=1000 "$@" >"$out/$name.log" 2>&1
  status=$?
  grep -E '^(mpsph:|summary:|  throughput)' "$out/$name.log"
  echo "$name: exit status $status after $((SECONDS - start)) s"
}

xfail() {
  echo "XFAIL $*"
}
