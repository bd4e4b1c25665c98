#!/usr/bin/env bash
# scripts/slurm/restart-job.sh with stand-ins for srun and sbatch: srun runs scripts/mpirun -n 2
# and, as Slurm's --signal=TERM@... does before a time limit, sends SIGTERM to the ranks once
# the run has written two more snapshots; sbatch queues the resubmitted job, which this test
# then runs. The chain continues from the checkpoint job after job until the run is finished,
# and its snapshots are bitwise those of an uninterrupted run.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mkdir "$out/bin"
cat > "$out/bin/srun" <<'SH'
#!/usr/bin/env bash
args=("$@")
for ((k = 0; k < $#; k++)); do [ "${args[k]}" = -o ] && dir=${args[k + 1]}; done
count() { ls "$dir"/snap_*.h5 2>/dev/null | wc -l; }
limit=$(($(count) + 2))
scripts/mpirun -n 2 "$@" &
pid=$!
while kill -0 "$pid" 2>/dev/null && [ "$(count)" -lt "$limit" ]; do sleep 0.05; done
kill -TERM $(pgrep -P "$pid") 2>/dev/null
wait "$pid"
SH
cat > "$out/bin/sbatch" <<SH
#!/usr/bin/env bash
{ printf 'MPSPH_JOB_NUMBER=%q bash' "\$MPSPH_JOB_NUMBER"; printf ' %q' "\$@"; } > "$out/queue"
SH
chmod +x "$out/bin/srun" "$out/bin/sbatch"
args=(tests/cases/dambreak-2phase-coarse.yaml "$out/chain" --set time.max_steps=100)

scripts/mpirun -n 2 build/mpsph run "${args[0]}" -o "$out/ref" "${args[@]:2}" > "$out/ref.log" 2>&1
echo "bash scripts/slurm/restart-job.sh $(printf ' %q' "${args[@]}")" > "$out/queue"
jobs=0
while [ -s "$out/queue" ]; do
  job=$(cat "$out/queue")
  : > "$out/queue"
  jobs=$((jobs + 1))
  PATH="$out/bin:$PATH" eval "$job" > "$out/job$jobs.log" 2>&1
  grep -E "^(job|stopped|the run|mpsph exited)" "$out/job$jobs.log"
done
[ "$jobs" -ge 3 ] || { echo "FAIL: only $jobs jobs"; exit 1; }
grep -q "the chain is complete" "$out/job$jobs.log"
"$PYTHON" tests/compare_snapshots.py "$out/ref" "$out/chain"
