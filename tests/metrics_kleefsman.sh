#!/usr/bin/env bash
# test-cores: 1
# The 3D dam-break (Kleefsman et al. 2005) metric of the validation (scripts/validation/metrics.py) on constructed input.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_kleefsman_metric.py
