#!/usr/bin/env bash
# test-cores: 1
# `make` alone builds the solver and the test programs (README, "Other targets"): the Makefile's
# default goal is `all`, whatever rule comes first in it (a rule for the compiler-flags stamp
# once did, and `make` built nothing). Read from a copy of the Makefile in a scratch folder, so
# that the parse does not touch build/ (it rewrites the flags stamp when the flags differ).
set -u
cd "$(dirname "$0")/.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp Makefile "$scratch/"
goal=$(make -C "$scratch" -pnq 2>/dev/null | sed -n 's/^\.DEFAULT_GOAL := //p')
echo "make's default goal: ${goal:-(none)}"
[ "$goal" = all ] && echo PASS || { echo FAIL; exit 1; }
