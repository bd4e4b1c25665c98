#!/usr/bin/env bash
# test-cores: 1
# The inputs on which `make fuzz` found a crash, undefined behaviour or a broken contract, all
# fixed: each goes through the fuzz target (build/tests/fuzz_replay, built with the address and
# undefined-behaviour sanitizers) and through `mpsph check` with the input's "#set" lines as --set
# overrides, which must exit with status 0 or 1 (never a crash).
set -u
cd "$(dirname "$0")/.."
fail=0
files=(tests/fuzz_regressions/*)
build/tests/fuzz_replay "${files[@]}" || fail=1
for f in "${files[@]}"; do
  sets=()
  while IFS= read -r line && [[ "$line" == "#set "* ]]; do sets+=(--set "${line#\#set }"); done < "$f"
  build/mpsph check "$f" "${sets[@]}" > /dev/null 2>&1
  status=$?
  if [ "$status" -gt 1 ]; then
    echo "FAIL: mpsph check $f exited with status $status"
    fail=1
  fi
done
exit $fail
