#!/usr/bin/env bash
# test-cores: 1
# The air-pocket sloshing metric of the validation (scripts/validation/metrics.py, study
# air-pocket-sloshing) on synthetic runs with known errors.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_air_pocket_metric.py
