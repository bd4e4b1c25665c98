#!/usr/bin/env bash
# test-cores: 1
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
expect 0 "^\| \`physics.delta\` \| number" -- build/mpsph keys
expect 0 "# particles: 625 fluid" -- build/mpsph check "$case"
expect 0 "# memory: about [0-9.]+ MB per rank on 1 rank, 1 per node \(the rank needing the most: 625 fluid, 492 wall and 0 halo" -- build/mpsph check "$case"
# --ranks N: the estimate per rank for N ranks (a share and its halo), check only, N a whole number;
# --ranks-per-node K: how many share a node (default N, at most this machine's processors).
expect 0 "# memory: about [0-9.]+ MB per rank on 8 ranks, 1 per node \(the rank needing the most: 0 fluid, 154 wall and 310 halo" -- \
  build/mpsph check "$case" --ranks 8 --ranks-per-node 1
expect 0 "# memory: about [0-9.]+ MB per rank on 4 ranks, 4 per node \(the rank needing the most: 8410 fluid, 3572 wall and 1026 halo" -- \
  build/mpsph check "$case" --set resolution.dx=0.005 --ranks 4 --ranks-per-node 4
expect 1 "^mpsph: --ranks-per-node: got 5, expected at most the 4 ranks of --ranks" -- \
  build/mpsph check "$case" --ranks 4 --ranks-per-node 5
expect 1 "^mpsph: --ranks-per-node: only with check" -- build/mpsph run "$case" --ranks-per-node 2
expect 1 "^mpsph: --ranks: got '0', expected a whole number of ranks from 1" -- build/mpsph check "$case" --ranks 0
expect 1 "^mpsph: --ranks: got '2x'" -- build/mpsph check "$case" --ranks 2x
expect 1 "^mpsph: --ranks: given twice" -- build/mpsph check "$case" --ranks 2 --ranks 3
expect 1 "^mpsph: --ranks: only with check" -- build/mpsph run "$case" --ranks 2
expect 0 "# particles: up to 1e\+10 .*not counted" -- \
  env MPSPH_MEMORY_AVAILABLE=16e9 build/mpsph check "$case" --set resolution.dx=1e-5
expect 1 "usage" -- build/mpsph
expect 1 "unknown command" -- build/mpsph frobnicate "$case"
expect 1 "unexpected argument '--frobnicate'" -- build/mpsph check "$case" --frobnicate
expect 1 "^mpsph: -o: needs a value after it, none given" -- build/mpsph run "$case" -o
expect 1 "^mpsph: --set: needs a value after it, none given" -- build/mpsph check "$case" --set
expect 1 "^mpsph: --restart: got an empty file name" -- build/mpsph run "$case" --restart ''
expect 1 "^mpsph: -o: only with run" -- build/mpsph check "$case" -o "$tmp/check-out"
# As many --set as the command line holds (here 300; the last one wins).
sets=()
for k in $(seq 300); do sets+=(--set "time.cfl=0.$((k % 9 + 1))"); done
check_300_sets() { build/mpsph check "$case" "${sets[@]}"; }
expect 0 "^  cfl: 0\.4$" -- check_300_sets
# A case path that is not a regular file is refused before it is opened: opening a FIFO would wait
# for a writer (and SIGTERM would not end the wait).
mkfifo "$tmp/fifo.yaml"
expect 1 "^mpsph: $tmp/fifo\.yaml: cannot read the file: it is a FIFO \(named pipe\), expected a regular file" -- \
  timeout -k 2 10 build/mpsph check "$tmp/fifo.yaml"
expect 1 "^mpsph: /dev/zero: cannot read the file: it is a character device" -- timeout -k 2 10 build/mpsph check /dev/zero
# SIGTERM ends a check that takes long (counting 4e8 particles, about 13 s on one core) at once:
# timeout's status is 124 when the signal ended it, 137 when it had to kill it 10 s later.
expect 124 "^$" -- timeout -k 10 1 env MPSPH_MEMORY_AVAILABLE=1e12 build/mpsph check "$case" --set resolution.dx=0.00005
exit $fail
