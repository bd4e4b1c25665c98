#!/usr/bin/env bash
# test-cores: 1
# scripts/slurm/validate-sweep.sh with a stand-in sbatch that records its arguments: the array
# has one task per rung of `scripts/validate.py --list` for the same options, and every task asks
# for the largest rank count among them (the Kleefsman study's fine rungs need 8 and 32 ranks;
# the air-pocket study's 4 and 16), here for the whole ladder, one study, and the quick rungs.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
stand_ins=$out/stand-ins   # a directory put first on PATH
mkdir "$stand_ins"
cat > "$stand_ins/sbatch" <<SH
#!/usr/bin/env bash
printf '%s\n' "\$*" >> "$out/calls"
echo 42
SH
chmod +x "$stand_ins/sbatch"
fail=0
check() {   # check OPTIONS...: one sweep against --list for the same options
  : > "$out/calls"
  PATH="$stand_ins:$PATH" PYTHON=$PYTHON scripts/slurm/validate-sweep.sh "$@" > /dev/null
  local list n ranks array
  list=$("$PYTHON" scripts/validate.py --list "$@")
  n=$(printf '%s\n' "$list" | grep -c .)
  ranks=$(printf '%s\n' "$list" | sed -n 's/.* -n \([0-9][0-9]*\) .*/\1/p' | sort -n | tail -1)
  array=$(head -1 "$out/calls")
  if [[ "$array" == *"--array=0-$((n - 1)) --ntasks=$ranks "* ]]; then
    echo "ok: $* -> $n rungs, --ntasks=$ranks"
  else
    echo "FAIL: $*: want --array=0-$((n - 1)) --ntasks=$ranks in: $array"
    fail=1
  fi
}
check
check --only dambreak-3d-kleefsman
check --quick
[ "$(sed -n 's/.*--ntasks=\([0-9]*\) .*/\1/p' "$out/calls" | head -1)" -gt 1 ] || { echo "FAIL: quick set asks for one rank"; fail=1; }
exit $fail
