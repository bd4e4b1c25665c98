#!/usr/bin/env bash
# Smoke test of the benchmark driver (make bench): every benchmark group at the smallest quick
# size, one repeat, into a temporary folder; the report and the CSV must come out with every
# section and target row, so that scripts/bench.py cannot rot unnoticed.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$PYTHON" scripts/bench.py --quick --repeats 1 --sizes 1 --out "$out"
md="$out/performance.md"
for section in "## Targets" "## 1. Throughput" "## 2. Where" "## 3. Floating" "## 4. Memory" \
               "## 5. Parallel" "## 6. Snapshot" "## 7. Cost" "## 8. Single-phase" "## What bounds"; do
  grep -q "^$section" "$md" || { echo "missing section: $section"; exit 1; }
done
[ "$(grep -c '^| .* | \*\*\(met\|missed\)\*\*' "$md")" -eq 5 ] || { echo "expected 5 target rows"; exit 1; }
grep -q "particle_steps_per_s_per_core" "$out/performance.csv"
grep -q "main_pass_fraction_of_peak" "$out/performance.csv"
echo "bench smoke: ok"
