#!/usr/bin/env bash
# Slurm job-script template: the validation ladder as a job array, one rung per array task,
# then one dependent job that computes the errors and writes doc/validation/README.md.
#
#   cd /path/to/mpsph && make            # build/mpsph first
#   scripts/slurm/validate-sweep.sh [--quick] [--only STUDY[,STUDY]]      (on the login node)
#
# The rungs and their numbering are those of `scripts/validate.py --list [same options]`; each
# task runs `scripts/validate.py --rung K` with MPSPH_LAUNCHER="srun -n {np}", so each rung gets
# the rank count of its study; every task asks for the largest rank count of the selection
# (--ntasks below, read from the --list commands). The report job
# re-reads the runs with --reuse, so the wall times in it are those measured in the array tasks.
set -euo pipefail
cd "$(dirname "$0")/../.."
PYTHON=${PYTHON:-python3}
rungs=$("$PYTHON" scripts/validate.py --list "$@")
n=$(printf '%s\n' "$rungs" | grep -c .) || true
[ "$n" -gt 0 ] || { echo "validate-sweep: no rung selected" >&2; exit 1; }
ranks=$(printf '%s\n' "$rungs" | sed -n 's/.* -n \([0-9][0-9]*\) .*/\1/p' | sort -n | tail -1)
array=$(sbatch --parsable --job-name=mpsph-validate --array=0-$((n - 1)) --ntasks="${ranks:-2}" \
        --time=${MPSPH_RUNG_TIME:-12:00:00} --output=runs/validate-%A_%a.out \
        --wrap="MPSPH_LAUNCHER='srun -n {np}' $PYTHON scripts/validate.py --rung \$SLURM_ARRAY_TASK_ID $*")
sbatch --job-name=mpsph-report --dependency=afterany:"$array" --ntasks=1 --time=01:00:00 \
       --output=runs/validate-report-%j.out --wrap="$PYTHON scripts/validate.py --reuse $*"
echo "validate-sweep: $n rungs in array job $array, report after it"
