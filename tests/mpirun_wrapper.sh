#!/usr/bin/env bash
# test-cores: 1
# scripts/mpirun leaves its ranks free to run on any core the caller may use (--bind-to none), so
# runs started side by side (make validate JOBS=N) spread over the cores instead of all sitting on
# the first one, where Open MPI binds the ranks of a small job; MPSPH_BIND=core forces core binding,
# also with more ranks than cores and after a qualifier of its own; the cores are counted as Open
# MPI counts its slots (physical cores, not hardware threads); a bad command line exits with status 1.
set -u
cd "$(dirname "$0")/.."
unset OMPI_MCA_hwloc_base_binding_policy   # scripts/run-tests sets it for its own runs
fail=0
own=$(grep Cpus_allowed_list /proc/self/status | cut -f2)
ranked=$(scripts/mpirun -n 1 grep Cpus_allowed_list /proc/self/status | cut -f2)
if [ "$ranked" = "$own" ]; then
  echo "ok: a rank may run on the caller's cores ($own)"
else
  echo "FAIL: the rank may run on cores $ranked only, the caller on $own"
  fail=1
fi
# count_cpus LIST: the number of CPUs in a list such as 0-3,8 (Cpus_allowed_list)
count_cpus() {
  local n=0 part parts
  IFS=, read -ra parts <<< "$1"
  for part in "${parts[@]}"; do
    if [[ "$part" == *-* ]]; then n=$((n + ${part#*-} - ${part%-*} + 1)); else n=$((n + 1)); fi
  done
  echo "$n"
}
if [ "$(nproc)" -gt 1 ]; then   # a core may hold several hardware threads (e.g. 0,4): fewer CPUs suffice
  bound=$(MPSPH_BIND=core scripts/mpirun -n 1 grep Cpus_allowed_list /proc/self/status | cut -f2)
  if [ -n "$bound" ] && [ "$(count_cpus "$bound")" -lt "$(count_cpus "$own")" ]; then
    echo "ok: MPSPH_BIND=core binds the rank to CPUs $bound (the caller has $own)"
  else
    echo "FAIL: MPSPH_BIND=core gave the CPUs '$bound' (the caller has $own)"
    fail=1
  fi
fi
cores=$(scripts/count-cores)
over=$((cores + 1))
# runs_over POLICY: $over ranks run with MPSPH_BIND=POLICY (empty: the wrapper's default)
runs_over() {
  if MPSPH_BIND=$1 scripts/mpirun -n "$over" true > /dev/null 2>&1; then
    echo "ok: MPSPH_BIND='$1' with $over ranks on $cores cores runs"
  else
    echo "FAIL: MPSPH_BIND='$1' with $over ranks on $cores cores failed"
    fail=1
  fi
}
runs_over ""                 # oversubscribed
runs_over core               # the overload qualifier added
runs_over core:if-supported  # ... after the policy's own
# scripts/count-cores counts physical cores (Open MPI's slots), not hardware threads: four CPUs on
# two cores of one package (one file without a final newline), and CPUs without a readable
# topology each as a core
topo=$(mktemp -d)
for cpu in 0 1 2 3; do
  mkdir -p "$topo/cpu$cpu/topology"
  echo 0 > "$topo/cpu$cpu/topology/physical_package_id"
  echo $((cpu % 2)) > "$topo/cpu$cpu/topology/core_id"
done
printf 1 > "$topo/cpu3/topology/core_id"   # a value without a final newline
for case in "0-3 2" "0,2 1" "0-1,3 2" "0-5 4" "3 1"; do
  set -- $case
  got=$(scripts/count-cores "$1" "$topo")
  if [ "$got" = "$2" ]; then echo "ok: CPUs $1 of 2 cores x 2 threads -> $got cores"
  else echo "FAIL: CPUs $1 of 2 cores x 2 threads -> $got cores, expected $2"; fail=1; fi
done
rm -rf "$topo"
scripts/mpirun true > /dev/null 2>&1
status=$?
if [ "$status" -eq 1 ]; then echo "ok: usage error -> 1"; else echo "FAIL: usage error gave $status"; fail=1; fi
exit $fail
