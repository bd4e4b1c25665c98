#!/usr/bin/env bash
# Slurm job-script template: one mpsph case on one allocation.
#
#   cd /path/to/mpsph
#   sbatch scripts/slurm/run-case.sh CASE.yaml OUTDIR [--set key.path=value ...]
#
# Adjust the #SBATCH lines (or pass them to sbatch); the ranks are started by srun, one per task.
# A run that may outlast the time limit is better served by scripts/slurm/restart-job.sh, which
# checkpoints before the limit and resubmits itself.
#SBATCH --job-name=mpsph
#SBATCH --ntasks=4
#SBATCH --time=04:00:00
#SBATCH --output=mpsph-%j.out
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: sbatch $0 CASE.yaml OUTDIR [--set key=value ...]" >&2; exit 1; }
case_file=$1
outdir=$2
shift 2
srun build/mpsph run "$case_file" -o "$outdir" "$@"
