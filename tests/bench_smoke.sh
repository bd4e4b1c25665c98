#!/usr/bin/env bash
# test-alone: it measures speeds and the one-core peak
# Smoke test of the benchmark driver (make bench): every benchmark group at the smallest quick
# size, one repeat, into a temporary folder; tests/check_bench.py then checks that the CSV and
# the report came out whole and sane (columns, finite numbers in each metric's range, a plausible
# particle-steps/s, a row for every benchmark, every section and target verdict), so that
# scripts/bench.py and scripts/bench_report.py cannot rot unnoticed.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$PYTHON" scripts/bench.py --quick --repeats 1 --sizes 1 --out "$out"
"$PYTHON" tests/check_bench.py "$out" --quick --sizes 1
