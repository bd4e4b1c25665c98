#!/usr/bin/env bash
# test-cores: 1
# A box of half the liquid's density released at rest above its draft (tests/cases/floating-box.yaml,
# B/dx = 20) heaves, settles, and floats at the analytic draft M / (rho0 B) below the liquid's level
# (mean of the two elevation probes) within 2 %, its weight carried by the fluid within 1 %
# (tests/check_bodies.py draft; doc/theory.md section 5b).
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
build/mpsph run tests/cases/floating-box.yaml -o "$out/float" --set time.end=2.0 \
  --set output.progress_interval=100000 > "$out/float.log" 2>&1 || { cat "$out/float.log"; exit 1; }
"${PYTHON:-/usr/bin/python3}" tests/check_bodies.py draft "$out/float" 1.5
