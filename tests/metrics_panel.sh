#!/usr/bin/env bash
# test-cores: 1
# The panel-slamming smoke-test metric of the validation (scripts/validation/metrics.py) on constructed input.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_panel_metric.py
