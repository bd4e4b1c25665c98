#!/usr/bin/env bash
# test-cores: 1
# The air-pocket period metric of the validation (scripts/validation/metrics.py) on analytic input.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_pocket_spectrum.py
