#!/usr/bin/env bash
# test-cores: 1
# The 3D resonant-sloshing (sloshing-3d-liu-lin) metric of the validation (scripts/validation/metrics.py) on constructed input.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_sloshing3d_metric.py
