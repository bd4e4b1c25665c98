#!/usr/bin/env bash
# Slurm job-script template: run an mpsph case in a chain of jobs, each stopped cleanly shortly
# before its time limit and continued by the next one from OUTDIR/checkpoint.h5, until the run
# reaches time.end (or time.max_steps).
#
#   cd /path/to/mpsph            # the repository: the script finds build/mpsph and itself here
#   sbatch scripts/slurm/restart-job.sh CASE.yaml OUTDIR [--set key.path=value ...]
#
# How it works:
#  1. --signal=TERM@300 below makes Slurm send SIGTERM to every task of the job steps (the mpsph
#     ranks started by srun; not this batch shell) about 300 s before the time limit. mpsph
#     agrees on the signal at the end of the current step, writes OUTDIR/checkpoint.h5
#     (through a temporary file, so a kill during the write leaves the previous one intact)
#     and exits 0. Choose the lead time above the wall time of one step plus one checkpoint
#     write (the log prints both); Slurm may signal up to a minute earlier than asked.
#  2. This script then reads the attribute /run/finished of the checkpoint (written at the end
#     of every run: 1 when time.end or time.max_steps was reached, 0 after a signal) and, while
#     it is 0, submits itself again with the same arguments. The next job sees the checkpoint
#     and adds --restart; it may use a different node or rank count (--nodes, --ntasks): the
#     restart re-partitions the particles, and the result is bitwise that of one long run.
#  3. Any other exit status ends the chain: 1 bad input (e.g. the case was edited in more than
#     time.end, time.max_steps, output.* or parallel.*), 2 unstable run, 3 I/O failure.
#     MPSPH_MAX_JOBS (default 50) bounds the chain.
#
# To stop a chain, scancel the running job: the batch shell is killed with it, so nothing is
# resubmitted, and the ranks still write their checkpoint if KillWait leaves them the time.
# To extend a finished run, submit again with a later --set time.end=...
#
# Options given on the sbatch command line are not repeated by the resubmission: put them in
# the #SBATCH lines below, or export them as SBATCH_* variables (SBATCH_ACCOUNT,
# SBATCH_PARTITION, ...), which the resubmitting sbatch reads from the job's environment.
#
# With Open MPI's mpirun instead of srun, mpirun kills the ranks 1 s after passing SIGTERM
# on, but forwards SIGUSR1, which mpsph also takes as a stop request. Signal the batch shell
# instead and forward the signal as SIGUSR1:
#   #SBATCH --signal=B:USR1@300
#   trap 'kill -USR1 "$pid"' USR1
#   mpirun build/mpsph run ... & pid=$!
#   wait "$pid"; wait "$pid"; status=$?      # the first wait returns when the trap runs
#
#SBATCH --job-name=mpsph
#SBATCH --nodes=1
#SBATCH --ntasks-per-node=32
#SBATCH --time=04:00:00
#SBATCH --signal=TERM@300
#SBATCH --output=%x-%j.out
set -u
if [ $# -lt 2 ]; then
  echo "usage: sbatch scripts/slurm/restart-job.sh CASE.yaml OUTDIR [--set key.path=value ...]" >&2
  exit 1
fi
case_file=$1 outdir=$2
shift 2
cd "${SLURM_SUBMIT_DIR:-.}"
mpsph=${MPSPH:-build/mpsph}                          # the binary, relative to the submit folder
script=${MPSPH_JOB_SCRIPT:-scripts/slurm/restart-job.sh}   # Slurm runs a copy of this file
job=${MPSPH_JOB_NUMBER:-1}
max_jobs=${MPSPH_MAX_JOBS:-50}
checkpoint=$outdir/checkpoint.h5

# finished CHECKPOINT: prints the /run/finished attribute (1 or 0), or nothing if unreadable.
finished() {
  h5dump -a /run/finished "$1" 2>/dev/null | awk '/\(0\):/ { print $2 }'
}

restart=()   # expanded as ${restart[@]+...}: an empty array trips set -u in bash < 4.4
[ -e "$checkpoint" ] && restart=(--restart)
echo "job $job of the chain: $mpsph run $case_file -o $outdir $*${restart[@]+ --restart}"
srun "$mpsph" run "$case_file" -o "$outdir" "$@" ${restart[@]+"${restart[@]}"}
status=$?
if [ "$status" -ne 0 ]; then
  echo "mpsph exited with status $status: the chain ends here"
  exit "$status"
fi
case $(finished "$checkpoint") in
  1) echo "the run has reached its end: the chain is complete"; exit 0 ;;
  0) ;;
  *) echo "cannot read /run/finished from $checkpoint: the chain ends here"; exit 3 ;;
esac
if [ "$job" -ge "$max_jobs" ]; then
  echo "MPSPH_MAX_JOBS = $max_jobs jobs reached: not resubmitting"
  exit 0
fi
echo "stopped before the end: submitting job $((job + 1))"
MPSPH_JOB_NUMBER=$((job + 1)) sbatch "$script" "$case_file" "$outdir" "$@"
