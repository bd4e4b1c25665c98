#!/usr/bin/env bash
# A failed allocation on one rank ends the whole job with status 3 and the message of mem.h, even
# with an HDF5 file open through MPI-IO on every rank (tests/test_mem_abort.c); a hang fails the
# test at the timeout.
set -u
cd "$(dirname "$0")/.."
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
timeout 60 scripts/mpirun -n 2 build/tests/test_mem_abort "$dir" > "$dir/log" 2>&1 || status=$?
cat "$dir/log"
[ "$status" -eq 3 ] || { echo "FAIL: status $status, expected 3 (124: hung)"; exit 1; }
grep -q "mpsph: out of memory: test block on rank 1 ([0-9]* bytes)" "$dir/log" || { echo "FAIL: no message"; exit 1; }
echo "one rank out of memory with a file open: the job ended with status 3 and the message"
