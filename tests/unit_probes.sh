#!/usr/bin/env bash
# The unit test of the probes' interpolation (tests/test_probes.c). scripts/run-tests lists the
# unit tests by name and does not know it yet; once it does, this wrapper can go.
set -eu
cd "$(dirname "$0")/.."
build/tests/test_probes
