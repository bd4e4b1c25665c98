#!/usr/bin/env bash
# test-cores: 3
# parallel.balance: work (section 6.3 of the user guide): a re-partition that balances particle
# work alone gives the same partition on every run, whatever the timings. A coarse 3D hydrostatic
# box on 3 ranks, re-partitioned every 5 steps, run twice: each rank owns as many particles of each
# kind at the end of both runs (with the default, `time`, the counts differ from run to run), and
# the particle data are those of the one-rank run.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
three=(tests/cases/hydrostatic-3d.yaml --set time.max_steps=20 --set output.interval=0.02
       --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${three[@]}" -o "$out/one"
for run in a b; do
  scripts/mpirun -n 3 build/mpsph run "${three[@]}" -o "$out/$run" --set parallel.repartition_every=5 \
    --set parallel.balance=work
  "$PYTHON" tests/compare_snapshots.py "$out/one" "$out/$run"
done
grep '^owned_' "$out/a/timings.csv" > "$out/a.owned"
grep '^owned_' "$out/b/timings.csv" > "$out/b.owned"
test "$(wc -l < "$out/a.owned")" -ge 3
cmp "$out/a.owned" "$out/b.owned"
# The repartitions happened: 20 steps, every 5 (steps 5, 10, 15, 20 or the first three of them).
grep -Eq '^repartition,time,[34],' "$out/a/timings.csv"
echo "repartition_balance: same partition on both runs"
