#!/usr/bin/env bash
# test-cores: 1
# The key reference of doc/user-guide.md (section 2.1) is the output of `build/mpsph keys`, so
# it documents the keys, defaults and ranges the loader has; `make keys-doc` regenerates it.
set -u
cd "$(dirname "$0")/.."
scripts/keys-doc --check
