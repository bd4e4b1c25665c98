#!/usr/bin/env bash
# test-cores: 2
# make validate's machinery on its cheapest rungs: scripts/validate.py runs the coarsest rung of
# the one-fluid oscillating drop (R/dx = 12.5) and of the standing wave, computes their errors
# and writes the report. Asserts the report, its CSV and plots exist with a row per study, and
# the drop's semi-axis within its 2 % threshold of the analytic solution (measured 1.66 % of R).
# Then --reuse: a finished run is read back (its recorded wall time reported), also when it ran
# with another launcher, and a run whose recorded case file and overrides are not the study's
# current ones is run again (the dam-break front's rung, whose overrides hold a value with a
# space, is read back), and a run a stop signal ended before its end is not taken as finished. And
# --only with a report in place: only the chosen study's section and
# rows are replaced. And --jobs 2: 1-rank rungs run two at a time (longest first, by the report's
# wall times), with the same results, and a
# folder two studies share runs once.
set -eu
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-/usr/bin/python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$PYTHON" scripts/validate.py --coarsest --only oscillating-drop,standing-wave-period,dambreak-front \
  --runs "$out/runs" --report "$out/report"
for f in README.md results.csv oscillating-drop_comparison.png oscillating-drop_cost.png \
         standing-wave-period_comparison.png standing-wave-period_cost.png; do
  [ -s "$out/report/$f" ] || { echo "FAIL: $f missing"; exit 1; }
done
grep -q "^## oscillating-drop" "$out/report/README.md"
grep -q "^## standing-wave-period" "$out/report/README.md"
"$PYTHON" - "$out/report/results.csv" <<'PY'
import csv, math, sys
rows = {r["study"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"oscillating-drop", "standing-wave-period", "dambreak-front"}, rows
for r in rows.values():
    assert math.isfinite(float(r["error"])) and int(r["steps"]) > 0, r
drop = rows["oscillating-drop"]
assert drop["verdict"] == "pass" and float(drop["error"]) <= 0.02, drop
print("drop error %.4f of R, standing-wave period error %.4f" % (float(drop["error"]), float(rows["standing-wave-period"]["error"])))
PY

# --only updates a report in place: the drop, taken out of a copy of the report, is measured again
# (read back with --reuse) and goes in at its STUDIES place; the other sections and rows are kept
# verbatim, the summary has every study
cp -r "$out/report" "$out/report3"
"$PYTHON" - "$out/report3" <<'PY'
import re, sys
md, table = sys.argv[1] + "/README.md", sys.argv[1] + "/results.csv"
text, lines = open(md).read(), open(table).readlines()
open(md, "w").write(re.sub(r"## oscillating-drop\n.*?(?=## )", "", text, flags=re.S))
open(table, "w").writelines(l for l in lines if not l.startswith("oscillating-drop,"))
PY
"$PYTHON" scripts/validate.py --coarsest --only oscillating-drop --reuse --runs "$out/runs" --report "$out/report3" \
  > "$out/only.log"
"$PYTHON" - "$out/report" "$out/report3" <<'PY'
import csv, re, sys
def parts(folder):
    text = open(folder + "/README.md").read()
    return {p.split("\n", 1)[0]: p for p in re.split(r"^## ", text, flags=re.M)[1:]}, text
(before, _), (after, text) = parts(sys.argv[1]), parts(sys.argv[2])
assert list(after) == ["oscillating-drop", "dambreak-front", "standing-wave-period", "Commands"], list(after)
for kept in ("dambreak-front", "standing-wave-period"):
    assert after[kept] == before[kept], kept
assert "--only oscillating-drop" in after["oscillating-drop"] and "measured again oscillating-drop" in text
rows = lambda folder: sorted(csv.reader(open(folder + "/results.csv")))
assert rows(sys.argv[1]) == rows(sys.argv[2]), "results.csv differs"
assert all("| [%s](#%s)" % (s, s) in text for s in after if s != "Commands")
print("--only: the drop's section and rows put back in place, the others kept verbatim")
PY

# --reuse: the drop's record, given a marker wall time, is read back, not run again
reuse() {
  "$PYTHON" scripts/validate.py --coarsest --only oscillating-drop,dambreak-front --reuse \
    --runs "$out/runs" --report "$out/report2" > "$out/reuse.log" || { echo "FAIL: validate --reuse" >&2; return 1; }
  "$PYTHON" - "$out/report2/results.csv" <<'PY'
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
assert row["verdict"] == "pass" and int(row["steps"]) > 0, row
print(row["wall_seconds"])
PY
}
record=$(ls "$out"/runs/oscillating-drop/*/validate.json)
mark() {
  "$PYTHON" - "$record" "$1" <<'PY'
import json, sys
rec = json.load(open(sys.argv[1]))
rec["wall"] = 12345.0
if sys.argv[2] == "stale":
    rec["command"] += " --set time.end=0"
elif sys.argv[2] == "launcher":   # another launcher and runs folder: the same run
    rec["command"] = rec["command"].replace("scripts/mpirun -n 1", "srun -n 1").replace(" -o ", " -o ./")
json.dump(rec, open(sys.argv[1], "w"))
PY
}
mark same
wall=$(reuse) && [ "$wall" = "12345.00" ] || { echo "FAIL: --reuse ran a finished run again"; exit 1; }
! grep -q "running it again" "$out/reuse.log" || { echo "FAIL: --reuse ran the dam-break front again"; exit 1; }
mark launcher
wall=$(reuse) && [ "$wall" = "12345.00" ] || { echo "FAIL: --reuse ran again a run made with another launcher"; exit 1; }
mark stale
wall=$(reuse) && [ "$wall" != "12345.00" ] || { echo "FAIL: --reuse kept a run made with other settings"; exit 1; }
grep -q "running it again" "$out/reuse.log" || { echo "FAIL: the stale run is not reported"; exit 1; }
again=$(reuse) && [ "$again" = "$wall" ] && ! grep -q "running it again" "$out/reuse.log" ||
  { echo "FAIL: the re-run's record is not read back"; exit 1; }
echo "reuse: a finished run read back (also with another launcher), a stale one run again (wall $wall s)"

# a run that a stop signal ended at its checkpoint (status 0, the log's "stopped by SIG..." line) is
# not finished: --reuse reads it back with no error (n.a.), not as a result
log=$(dirname "$record")/mpsph.log
echo "stopped by SIGTERM at step 9, t = 0.1 s: the checkpoint is CKPT; continue with the same command and --restart" >> "$log"
"$PYTHON" scripts/validate.py --coarsest --only oscillating-drop --reuse --runs "$out/runs" --report "$out/report4" \
  > "$out/stopped.log"
"$PYTHON" - "$out/report4/results.csv" <<'PY'
import csv, math, sys
row = next(csv.DictReader(open(sys.argv[1])))
assert row["verdict"] == "n.a." and not math.isfinite(float(row["error"])), row
PY
grep -q "run not finished: stopped by SIGTERM at step 9" "$out/stopped.log" ||
  { echo "FAIL: a signal-stopped run is not reported as unfinished"; exit 1; }
echo "reuse: a run stopped by a signal is reported as not finished"

# --jobs 2: the 1-rank rungs run two at a time (the first two overlap in time, from their records)
# and give the errors and steps of the runs made one after the other; the standing wave's two
# studies share one folder, which runs once
"$PYTHON" scripts/validate.py --coarsest --only oscillating-drop,dambreak-front,standing-wave-period,standing-wave-decay \
  --jobs 2 --runs "$out/runs_jobs" --report "$out/report_jobs" > "$out/jobs.log"
[ "$(grep -c " started$" "$out/jobs.log")" = 3 ] || { echo "FAIL: --jobs 2 did not run 3 folders once each"; exit 1; }
"$PYTHON" - "$out/report/results.csv" "$out/report_jobs/results.csv" "$out/runs_jobs" <<'PY'
import csv, glob, json, sys
rows = [{r["study"]: (r["error"], r["steps"]) for r in csv.DictReader(open(f))} for f in sys.argv[1:3]]
for study in ("oscillating-drop", "dambreak-front", "standing-wave-period"):
    assert rows[0][study] == rows[1][study], (study, rows[0][study], rows[1][study])
assert rows[1]["standing-wave-decay"][1] == rows[1]["standing-wave-period"][1], rows[1]
recs = sorted((json.load(open(f)) for f in glob.glob(sys.argv[3] + "/*/*/validate.json")), key=lambda r: r["started"])
assert len(recs) == 3 and all(r["status"] == 0 for r in recs), recs
assert recs[1]["started"] < recs[0]["started"] + recs[0]["wall"], "the first two runs did not overlap"
PY
echo "jobs: two rungs at a time, the same errors and steps as one after the other; a shared folder run once"

# --jobs again, with the report just written: the rungs start longest first by its wall times
cp "$out/report_jobs/results.csv" "$out/jobs_times.csv"
"$PYTHON" scripts/validate.py --coarsest --only oscillating-drop,dambreak-front,standing-wave-period,standing-wave-decay \
  --jobs 2 --runs "$out/runs_jobs2" --report "$out/report_jobs" > "$out/jobs2.log"
"$PYTHON" - "$out/jobs_times.csv" "$out/jobs2.log" <<'PY'
import csv, sys
wall = {r["study"]: float(r["wall_seconds"]) for r in csv.DictReader(open(sys.argv[1]))}
started = [line.split(":")[0] for line in open(sys.argv[2]) if line.rstrip().endswith(" started")]
times = [wall[s] for s in started]
assert len(started) == 3 and times == sorted(times, reverse=True), (started, times)
PY
echo "jobs: the rungs start longest first by the report's wall times"
