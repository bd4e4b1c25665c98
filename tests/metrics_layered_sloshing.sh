#!/usr/bin/env bash
# test-cores: 1
# The linear layered sloshing theory and the metric of the three-liquid 3D sloshing
# (sloshing-3liquid-3d; scripts/validation/metrics.py) against closed forms and constructed input.
set -eu
cd "$(dirname "$0")/.."
"${PYTHON:-/usr/bin/python3}" tests/check_layered_sloshing.py
