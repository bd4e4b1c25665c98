#!/usr/bin/env bash
# test-cores: 1
# The 3D two-phase dam-break (Lobovsky et al. 2014) metric of the validation (scripts/validation/metrics.py) on constructed input.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_lobovsky_metric.py
