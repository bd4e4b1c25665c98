#!/usr/bin/env bash
# Combination test: the sanitizer build (build/asan/mpsph: AddressSanitizer and
# UndefinedBehaviorSanitizer, `make asan`) runs 3 steps of each combination of the covering design
# of tests/combinations.py (three pairwise covers over scheme x dimension x kernel x h/dx x walls x
# free surface x surface tension x shifting x interface options x scheme model x 1 or 2 ranks x
# re-partitioning, plus six combinations the loader must refuse). Each run must end with exit
# status 0, 1 or 2, with an "mpsph:" message when not 0, never by a signal, a time-out or a
# sanitizer report; a combination the design marks refused must end with 1. Prints each failure
# with the command that reproduces it, then the count per outcome, the time taken and the CPU
# time of the runs.
# Usage: bash tests/combinations.sh [LABEL-PATTERN]   (runs the combinations whose label contains
#   it, e.g. scheme=riemann); COMBINATIONS_SEED=N: another design (tests/combinations.py --seed N)
set -u
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
RUN_SECONDS=${RUN_SECONDS:-120}   # time-out of one run
pattern=${1:-}
# Open MPI's own allocations are never freed before exit and LeakSanitizer reports them as leaks:
# leak detection is off. A sanitizer report ends the run with an exit status outside 0-2.
export ASAN_OPTIONS=detect_leaks=0:exitcode=98
export UBSAN_OPTIONS=print_stacktrace=1:exitcode=99
export OMPI_MCA_rmaps_base_oversubscribe=1
make -s --no-print-directory build/asan/mpsph || exit 1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
design=(tests/combinations.py ${COMBINATIONS_SEED:+--seed "$COMBINATIONS_SEED"})
"$PYTHON" "${design[@]}" > "$tmp/design.tsv" || exit 1

declare -A outcome=([0]=0 [1]=0 [2]=0 [failed]=0)
unexpected_refusals=0
fail=0
start=$SECONDS

# shell_words ARG...: the arguments as a shell command line (single quotes where needed).
shell_words() {
  local a out=""
  for a; do
    if [[ "$a" =~ ^[A-Za-z0-9_./=:,+-]+$ ]]; then out+="$a "; else out+="'${a//\'/\'\\\'\'}' "; fi
  done
  echo "$out"
}

# report LABEL LOG COMMAND...: print the combination, its command line (quoted for a shell) and
# the messages and first stack frames of its log.
report() {
  local label=$1 log=$2
  shift 2
  echo "    $label"
  echo "    command: $(shell_words "$@")"
  grep -E 'mpsph:|ERROR: |runtime error|signal|SUMMARY|^    #[0-9]' "$log" | head -n 20 |
    sed 's/^/    | /'
}

# verdict STATUS LOG EXPECT: empty when the run ended cleanly, else what went wrong.
verdict() {
  local status=$1 log=$2 expect=$3
  if grep -qE 'ERROR: (Address|Leak|UndefinedBehavior)Sanitizer|runtime error:' "$log"; then
    echo "sanitizer report (status $status)"
  elif [ "$status" -gt 2 ] || grep -qE 'exited on signal|Segmentation fault|Aborted|core dumped' "$log"
  then
    echo "signal, time-out or unexpected status $status"
  elif [ "$status" -ne 0 ] && ! grep -q '^mpsph: ' "$log"; then
    echo "status $status without an mpsph: message"
  elif [ "$expect" = refused ] && [ "$status" -ne 1 ]; then
    echo "status $status, expected the loader to refuse it (1)"
  fi
}

n=0
while IFS=$'\t' read -r -a row; do
  label=${row[0]} np=${row[1]} case=${row[2]} expect=${row[3]}
  [[ -n "$pattern" && "$label" != *"$pattern"* ]] && continue
  n=$((n + 1))
  sets=()
  for s in "${row[@]:4}"; do sets+=(--set "$s"); done
  log="$tmp/$n.log"
  cmd=(build/asan/mpsph run "$case" -o "$tmp/out$n" "${sets[@]}")
  [ "$np" -gt 1 ] && cmd=(scripts/mpirun -n "$np" "${cmd[@]}")
  t0=$SECONDS
  timeout -k 5 "$RUN_SECONDS" "${cmd[@]}" </dev/null >"$log" 2>&1
  status=$?
  rm -rf "$tmp/out$n"
  problem=$(verdict "$status" "$log" "$expect")
  if [ -n "$problem" ]; then
    outcome[failed]=$((outcome[failed] + 1))
    fail=1
    echo "FAIL #$n: $problem ($((SECONDS - t0)) s)"
    report "$label" "$log" "${cmd[@]}"
    continue
  fi
  outcome[$status]=$((outcome[$status] + 1))
  [ "$status" -eq 1 ] && [ "$expect" = run ] && unexpected_refusals=$((unexpected_refusals + 1))
  echo "ok #$n: exit $status ($((SECONDS - t0)) s)"
  [ "$status" -ne 0 ] && echo "    $label"$'\n'"    $(grep -m1 '^mpsph: ' "$log")"
done < "$tmp/design.tsv"

echo "$n combinations run (design: $(grep -c $'\trun\t' "$tmp/design.tsv") to run," \
     "$(grep -c $'\trefused\t' "$tmp/design.tsv") to be refused):" \
     "${outcome[0]} exit 0, ${outcome[1]} exit 1 ($unexpected_refusals of them outside the" \
     "design's refused ones), ${outcome[2]} exit 2, ${outcome[failed]} failed;" \
     "$((SECONDS - start)) s"
times > "$tmp/times"   # second line: the children's user and system time
read -r run_user run_sys < <(sed -n 2p "$tmp/times")
echo "CPU time of the runs: user $run_user, system $run_sys"
exit $fail
