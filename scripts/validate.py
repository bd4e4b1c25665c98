#!/usr/bin/env python3
"""Runs the validation studies (scripts/validation/studies.py) on their ladders of resolutions and
rank counts, measures each run's error against its reference and its wall-clock time, and writes
doc/validation/README.md with a table per study, a comparison plot and an error-against-run-time
plot (log-log, one line per scheme), plus results.csv beside it. Every number in the report is
measured by this run (or read back from runs of an earlier invocation with --reuse, or with --only
kept from the report in place).

Usage: scripts/validate.py [--quick] [--only ID[,ID]] [--reuse] [--jobs N] [--runs DIR] [--report DIR]
  --quick   the cheap rungs only (make validate QUICK=1; user guide 1.8 for its time)
  --only    these studies only, and with a report already in --report, update it: their rows of
            results.csv and their sections (with their plots) are replaced, the other studies'
            sections are kept verbatim (in STUDIES order; a new study goes in at its place) and the
            summary table is rebuilt from all rows. The header names the studies measured again, the
            date and the commit; every section names the invocation, date and commit that measured
            it. A chosen study that runs no rung (e.g. a study with fine rungs only, with --quick)
            keeps its section.
  --coarsest  the first rung of each study only (the smoke test of make test)
  --reuse   keep runs that finished in an earlier invocation with the same case file and --set
            overrides (their recorded wall time is used); a rung whose overrides changed since is
            run again (not detected: edits inside the case file, a rebuilt binary)
  --list    print the rungs with their commands and exit
  --rung K  run only the K-th rung of the selection (0-based, as --list orders them), no report:
            for job arrays; a later --reuse invocation writes the report from the runs
  --jobs N  run the selected rungs first, several at once while their ranks fit in N cores (make
            validate JOBS=N; default 1: one after the other), the longest first by the wall times
            the report in --report records (rungs it has no time for before them); each run's wall
            time is its own, taken while the others ran beside it
MPSPH_LAUNCHER (default "scripts/mpirun -n {np}") starts the ranks, e.g. "srun -n {np}".
"""
import argparse
import csv
import datetime
import json
import math
import os
import re
import shlex
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from bench import read_timings  # noqa: E402
from validation import plots  # noqa: E402
from validation.studies import STUDIES, case_path  # noqa: E402



def rung_dir(runs, study, r):
    """Output folder of a rung."""
    tag = re.sub(r"[^A-Za-z0-9.-]+", "_", r["label"]).strip("_")
    return os.path.join(runs, study.get("runs", study["id"]), "%s_dx%g_np%d" % (tag, r["dx"], r["np"]))


def command(study, r, out):
    """The mpsph command line of a rung."""
    launcher = os.environ.get("MPSPH_LAUNCHER", "scripts/mpirun -n {np}").format(np=r["np"]).split()
    cmd = launcher + ["build/mpsph", "run", case_path(study, r), "-o", out,
           "--set", "resolution.dx=%g" % r["dx"]]
    for key, value in r["sets"].items():
        cmd += ["--set", "%s=%s" % (key, value)]
    return cmd


def run_arguments(cmd):
    """The part of an mpsph command line (a list of words) that sets what is computed: from the
    binary on, without the launcher (mpirun or srun) and without the output folder."""
    args = cmd[cmd.index("build/mpsph"):]
    k = args.index("-o")
    return args[:k] + args[k + 2:]


def finished_run(study, r, out):
    """(record, stale) of an earlier run of rung r in out: record None when there is none or when
    it ran other arguments than the study's now (stale True: its case file or --set overrides
    changed since; edits inside the case file or a rebuilt binary are not detected)."""
    record_path = os.path.join(out, "validate.json")
    if not os.path.exists(record_path):
        return None, False
    with open(record_path) as f:
        rec = json.load(f)
    # compared as recorded, a string split at spaces (a --set value may hold one: "[0.3, 0.6]")
    if run_arguments(rec["command"].split()) != run_arguments(" ".join(command(study, r, out)).split()):
        return None, True
    return rec, False


def reusable(study, r, out, reuse, done):
    """The record of a run that need not run again (one of this invocation, which studies may share,
    or with reuse a finished earlier run with the same case file and overrides, finished_run), or
    None."""
    if not (reuse or out in done):
        return None
    rec, stale = finished_run(study, r, out)
    if stale and not rec:
        print("validate: %s ran with other settings than the study's now; running it again" % out, flush=True)
    return rec


class Launched:
    """A rung's run started in the background: its folder, command, process, log and start time."""

    def __init__(self, study, r, out):
        self.np, self.out, self.cmd = r["np"], out, command(study, r, out)
        os.makedirs(out, exist_ok=True)
        timings = os.path.join(out, "timings.csv")
        if os.path.exists(timings):
            os.remove(timings)   # a run that stops before its summary must not show an older one's
        self.log = open(os.path.join(out, "mpsph.log"), "w")
        self.start = time.time()
        self.proc = subprocess.Popen(self.cmd, stdout=self.log, stderr=subprocess.STDOUT)

    def record(self, done):
        """Wait for the run; write and return its record (status, steps, particles, wall time [s])."""
        status = self.proc.wait()
        wall = time.time() - self.start
        self.log.close()
        rec = {"status": status, "wall": wall, "started": self.start, "command": " ".join(self.cmd), "steps": 0,
               "fluid": 0, "wall_particles": 0}
        timings = os.path.join(self.out, "timings.csv")
        if os.path.exists(timings):   # the run's summary (engine_report.c), also after status 2
            value = {row["name"]: row["value"] for row in read_timings(timings)}
            rec.update(steps=int(value["steps"]), fluid=int(value["fluid_particles"]),
                       wall_particles=int(value["wall_particles"]))
        with open(os.path.join(self.out, "validate.json"), "w") as f:
            json.dump(rec, f)
        done.add(self.out)
        return rec


DONE = set()   # the folders of the runs of this invocation


def run_rung(study, r, out, reuse, done=DONE):
    """Run one rung, or reuse its run (reusable). Returns the run record (status, steps, particles,
    wall time [s])."""
    return reusable(study, r, out, reuse, done) or Launched(study, r, out).record(done)


def rung_key(study, r):
    """A rung's identity as results.csv writes it: (study, label, dx, ranks), as strings."""
    return (study["id"], r["label"], "%g" % r["dx"], str(r["np"]))


RUNS_FOLDER = {s["id"]: s.get("runs", s["id"]) for s in STUDIES}   # studies with a "runs" key share a run


def run_key(study_id, label, dx, np_):
    """The key of a run (rung_key's fields): the study replaced by its runs folder, so that studies
    sharing their runs (standing-wave-period and -decay) share it."""
    return (RUNS_FOLDER.get(study_id, study_id), label, dx, np_)


def earlier_seconds(report):
    """The wall time [s] of each run that the report in folder `report` records ({} if none), keyed
    by run_key: whichever of the studies sharing a run the report holds gives its time."""
    return {run_key(*(row[k] for k in CSV_HEADER[:4])): float(row["wall_seconds"]) for row in read_report(report)[1]}


def longest_first(queue, seconds):
    """The rungs of queue [(study, rung, folder)] ordered by their wall time in seconds (earlier_seconds),
    longest first, the rungs it does not know ahead of them (they may be long) in queue order, so that
    short rungs fill the cores at the end (a rung wider than the free cores still lets narrower ones
    behind it start first: run_packed)."""
    def known(item):
        s, r, _ = item
        return seconds.get(run_key(*rung_key(s, r)), math.inf)
    return sorted(queue, key=known, reverse=True)


def run_packed(todo, args, done=DONE):
    """Run the rungs todo [(study, rung)] that are not reusable, as many at once as their ranks fit in
    args.jobs cores (a run with more ranks than that alone), longest first by the wall times of the
    report in args.report (longest_first): whenever cores are free, the first waiting rung that fits
    in them starts; their records go to their folders, where run_study reads them back."""
    running, queue, folders = [], [], set()
    for s, r in todo:   # studies that share their runs (a "runs" key) share a folder: one run each
        out = rung_dir(args.runs, s, r)
        if out not in folders and not reusable(s, r, out, args.reuse, done):
            queue.append((s, r, out))
        folders.add(out)
    queue = longest_first(queue, earlier_seconds(args.report))
    try:
        while queue or running:
            free = args.jobs - sum(run.np for run in running)
            fits = [k for k, (s, r, out) in enumerate(queue) if r["np"] <= free]
            if queue and (fits or not running):
                s, r, out = queue.pop(fits[0] if fits else 0)
                print("%s: %s dx = %g on %d ranks started" % (s["id"], r["label"], r["dx"], r["np"]), flush=True)
                running.append(Launched(s, r, out))
                continue
            time.sleep(0.2)
            for run in [run for run in running if run.proc.poll() is not None]:
                run.record(done)
                running.remove(run)
    finally:   # an exception or a signal here stops the runs still going, as subprocess.call would
        for run in running:
            run.proc.terminate()
            run.proc.wait()
            run.log.close()


def signal_stop(out):
    """The line of the run's log saying that a stop signal ended it at a checkpoint before its end
    time (status 0, user guide section 4.4), or None."""
    path = os.path.join(out, "mpsph.log")
    if not os.path.exists(path):
        return None
    with open(path, errors="replace") as f:
        return next((line.strip() for line in f if line.startswith("stopped by SIG")), None)


def evaluate(study, r, out, rec):
    """Error, notes and curves of a finished rung (error nan with the reason if it failed or was
    stopped by a signal before its end)."""
    if rec["status"] != 0:
        return float("nan"), "run exited with status %d (see %s/mpsph.log)" % (rec["status"], out), None
    stop = signal_stop(out)
    if stop:
        return float("nan"), "run not finished: %s" % stop.split(":")[0], None
    try:
        return study["metric"](out, r["dx"])
    except Exception as exc:  # a metric that cannot be computed is reported, not hidden
        return float("nan"), "metric failed: %s" % exc, None


def verdict(err, threshold):
    """pass / FAIL / n.a. of an error against its threshold."""
    if not math.isfinite(err):
        return "n.a."
    return "pass" if err <= threshold else "FAIL"


def run_study(study, args):
    """Run and evaluate every selected rung of a study; returns the rows."""
    rows = []
    for r in study["rungs"]:
        out = rung_dir(args.runs, study, r)
        if args.quick and not r["quick"]:   # a fine rung: QUICK runs none, and with --reuse reports those run before
            rec, stale = finished_run(study, r, out) if args.reuse else (None, False)
            if stale:
                print("validate: %s ran with other settings than the study's now; left out (a fine rung)" % out,
                      flush=True)
            if not rec:
                continue
        print("%s: %s dx = %g on %d ranks ..." % (study["id"], r["label"], r["dx"], r["np"]), flush=True)
        rec = run_rung(study, r, out, args.reuse)
        err, notes, curves = evaluate(study, r, out, rec)
        print("  status %d, %d steps, %.0f s, error %.4g (%s): %s" % (
            rec["status"], rec["steps"], rec["wall"], err, verdict(err, study["threshold"]), notes), flush=True)
        rows.append({"rung": r, "rec": rec, "err": err, "notes": notes, "curves": curves, "out": out})
    return rows


def table(study, rows):
    """The markdown table of a study."""
    name, length = study["length"]
    lines = ["| label | dx [m] | %s/dx | particles (fluid + wall) | ranks | steps | wall time [s] | "
             "core-seconds | error | verdict | notes |" % name,
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        r, rec = row["rung"], row["rec"]
        lines.append("| %s | %g | %.4g | %d + %d | %d | %d | %.1f | %.0f | %.4g | %s | %s |" % (
            r["label"], r["dx"], length / r["dx"], rec["fluid"], rec["wall_particles"], r["np"], rec["steps"],
            rec["wall"], rec["wall"] * r["np"], row["err"], verdict(row["err"], study["threshold"]),
            row["notes"].replace("|", "/")))
    return "\n".join(lines)


def error_time_plot(study, rows, path):
    """Error against wall-clock time, log-log, one line per label."""
    fig, ax = plt.subplots(figsize=(5.5, 4))
    labels = sorted({row["rung"]["label"] for row in rows})
    for lab in labels:
        pts = sorted((row["rec"]["wall"], row["err"]) for row in rows
                     if row["rung"]["label"] == lab and math.isfinite(row["err"]) and row["err"] > 0)
        if pts:
            ax.loglog(*zip(*pts), "o-", label=lab)
    ax.axhline(study["threshold"], color="k", ls="--", lw=0.8, label="threshold")
    ax.set_xlabel("wall-clock time [s]")
    ax.set_ylabel("error")
    ax.set_title(study["id"], fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def comparison_plot(study, rows, path):
    """The physical comparison of the study (plots.py), every rung against the reference."""
    fig, ax = plt.subplots(figsize=(6, 4))
    getattr(plots, study["plot"])(ax, [(row["rung"], row["curves"]) for row in rows if row["curves"]])
    ax.set_title(study["title"], fontsize=9)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def git_commit():
    """The commit the runs were made with (dirty marked)."""
    try:
        return subprocess.check_output(["git", "describe", "--always", "--dirty"], text=True).strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


CSV_HEADER = ["study", "label", "dx", "np", "fluid", "wall", "steps", "wall_seconds", "error", "threshold", "verdict"]


def csv_rows(study, rows):
    """The results.csv rows (dicts keyed by CSV_HEADER, strings as csv reads them back) of a
    study's measured rows."""
    out = []
    for row in rows:
        r, rec = row["rung"], row["rec"]
        out.append(dict(zip(CSV_HEADER, rung_key(study, r) + tuple(map(str, [
            rec["fluid"], rec["wall_particles"], rec["steps"], "%.2f" % rec["wall"], "%.6g" % row["err"],
            "%g" % study["threshold"], verdict(row["err"], study["threshold"])])))))
    return out


def case_dimension(study):
    """The dimension (2 or 3) the study's case file states."""
    with open(case_path(study)) as f:
        found = re.search(r"^dimension:\s*(\d)", f.read(), re.M)
    return int(found.group(1)) if found else 2


def full_ladder_estimate(studies, table_rows):
    """A sentence with the expected wall time of the rungs of studies not in table_rows (csv_rows),
    each scaled from the finest run with an error of its study and label as dx^-(dim + 1)
    (particles x steps) and 1/ranks."""
    total, missing = 0.0, 0
    for study in studies:
        own = [x for x in table_rows if x["study"] == study["id"]]
        exponent = case_dimension(study) + 1
        for r in study["rungs"]:
            if any((x["label"], x["dx"], x["np"]) == (r["label"], "%g" % r["dx"], str(r["np"])) for x in own):
                continue
            same = [x for x in own if x["label"] == r["label"] and math.isfinite(float(x["error"]))]
            if not same:
                missing += 1
                continue
            m = min(same, key=lambda x: float(x["dx"]))
            total += float(m["wall_seconds"]) * (float(m["dx"]) / r["dx"]) ** exponent * int(m["np"]) / r["np"]
    if total == 0 and missing == 0:
        return "Every rung of the ladder was run."
    return ("Expected wall time of the rungs of the full ladder not run here, scaled from the finest run "
            "of the same study and label as dx^-3 in 2D and dx^-4 in 3D (particles x steps) and 1/ranks on this machine: "
            "about %.1f h%s." % (total / 3600, "" if not missing else
                                 " (plus %d rungs whose coarser runs failed or were not run, not estimated)" % missing))


def summary(table_rows):
    """The summary table of the report: per study, the finest rung of its first label."""
    md = ["| study | finest rung run | error | threshold | verdict |", "|---|---|---|---|---|"]
    for study in STUDIES:
        own = [x for x in table_rows if x["study"] == study["id"]]
        if own:
            last = min((x for x in own if x["label"] == own[0]["label"]), key=lambda x: float(x["dx"]))
            md.append("| [%s](#%s) | %s, dx = %s | %.4g | %s | %s |" % (
                study["id"], study["id"], last["label"], last["dx"], float(last["error"]), last["threshold"],
                last["verdict"]))
    return md


def section(args, study, rows, stamp):
    """The report section of a study from its measured rows (stamp: which invocation measured
    them, when, at which commit); writes its two plots beside the report."""
    comparison_plot(study, rows, os.path.join(args.report, study["id"] + "_comparison.png"))
    error_time_plot(study, rows, os.path.join(args.report, study["id"] + "_cost.png"))
    return "\n".join([
        "## %s" % study["id"], "", study["title"] + ".", "", stamp, "",
        "- case: `%s`" % ", ".join(sorted({case_path(study, row["rung"]) for row in rows})),
        "- reference: %s" % study["reference"], "- error: %s; threshold %g" % (study["error"], study["threshold"]),
        "", table(study, rows), "",
        "![comparison](%s_comparison.png) ![error against run time](%s_cost.png)" % (study["id"], study["id"])])


def read_report(folder):
    """(sections by study id, results.csv rows) of the report in folder ({} and [] if none). A
    section runs from its "## <id>" line to the next "## " heading; one written before sections
    named their provenance gets the line from the report's header (its invocation, date, commit)."""
    md, table_csv = os.path.join(folder, "README.md"), os.path.join(folder, "results.csv")
    if not (os.path.exists(md) and os.path.exists(table_csv)):
        return {}, []
    header, *parts = re.split(r"^## ", open(md).read(), flags=re.M)
    old = re.search(r"Generated by (.*?), on \d+ cores", header)
    sections = {}
    for part in parts:
        lines = ("## " + part.rstrip("\n")).split("\n")
        if old and not any(line.startswith("Measured by ") for line in lines):
            lines[4:4] = ["Measured by %s." % old.group(1), ""]
        sections[lines[0][3:].strip()] = "\n".join(lines)
    with open(table_csv) as f:
        return sections, list(csv.DictReader(f))


def write_report(args, results, seconds):
    """doc/validation/README.md and results.csv from the measured rows. With --only and a report
    in place, only the measured studies' sections and rows are replaced; the other studies'
    (read_report) are kept verbatim, in STUDIES order, and the summary is rebuilt from all rows."""
    os.makedirs(args.report, exist_ok=True)
    measured = {s["id"]: rows for s, rows in results if rows}
    sections, kept = read_report(args.report) if args.only else ({}, [])
    studies = [s for s in STUDIES if sections or any(s["id"] == c["id"] for c, _ in results)]
    invocation = "`scripts/validate.py %s` on %s, commit `%s`" % (
        shlex.join(sys.argv[1:]), datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"), git_commit())
    table_rows, text = [], []
    for study in studies:
        if study["id"] in measured:
            table_rows += csv_rows(study, measured[study["id"]])
            text.append(section(args, study, measured[study["id"]], "Measured by %s." % invocation))
        elif study["id"] in sections:
            table_rows += [x for x in kept if x["study"] == study["id"]]
            text.append(sections[study["id"]])
    runs_wall = sum({row["out"]: row["rec"]["wall"] for rows in measured.values() for row in rows}.values())
    if sections:
        intro = ("Updated by %s, on %d cores (load average at the end %.1f): measured again %s (their runs "
                 "took %.0f s of wall time, this invocation %.0f s); the other studies' sections are kept "
                 "from earlier invocations, each section names the invocation, date and commit that measured "
                 "it." % (invocation, os.cpu_count(), os.getloadavg()[0], ", ".join(measured) or "no study",
                          runs_wall, seconds))
    else:
        intro = ("Generated by %s, on %d cores (load average at the end %.1f). The runs took %.0f s of wall "
                 "time in all (this invocation %.0f s)." % (invocation, os.cpu_count(), os.getloadavg()[0],
                                                            runs_wall, seconds))
    md = ["# Validation report", "",
          intro + " Do not edit by hand: every number below is measured by the runs. Each case folder's "
          "README names its source and reference.", "", full_ladder_estimate(studies, table_rows), "",
          "The error is the study's metric against its reference; *verdict* compares it with the "
          "study's threshold. Wall time is that of `mpirun` including start-up; core-seconds = wall "
          "time x ranks (this machine's ranks share %d cores; this invocation ran up to %d cores' worth of "
          "ranks at once, --jobs)." % (os.cpu_count(), args.jobs), ""] + summary(table_rows)
    for part in text:
        md += ["", part]
    md += ["", "## Commands", "", "Each rung's command line is in `<runs>/<study>/<rung>/validate.json`, <runs> "
           "the `--runs` of the invocation its section names (default `runs/validate`); the full ladder runs "
           "with `make validate` (or `scripts/slurm/validate-sweep.sh` on a cluster)."]
    with open(os.path.join(args.report, "README.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.join(args.report, "results.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, CSV_HEADER, lineterminator="\n")
        writer.writeheader()
        writer.writerows(table_rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", default="")
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--rung", type=int, default=-1)
    ap.add_argument("--coarsest", action="store_true")
    ap.add_argument("--runs", default="runs/validate")
    ap.add_argument("--report", default="doc/validation")
    ap.add_argument("--jobs", type=int, default=1)
    args = ap.parse_args()
    chosen = [s for s in STUDIES if not args.only or s["id"] in args.only.split(",")]
    if args.coarsest:
        chosen = [dict(s, rungs=s["rungs"][:1]) for s in chosen]
    todo = [(s, r) for s in chosen for r in s["rungs"] if not args.quick or r["quick"]]
    if args.list:
        for k, (s, r) in enumerate(todo):
            print(k, " ".join(command(s, r, rung_dir(args.runs, s, r))))
        return 0
    if args.rung >= 0:
        s, r = todo[args.rung]
        return run_rung(s, r, rung_dir(args.runs, s, r), args.reuse)["status"]
    start = time.time()
    if args.jobs > 1:
        run_packed(todo, args)
    results = [(s, run_study(s, args)) for s in chosen]
    write_report(args, results, time.time() - start)
    print("report: %s/README.md" % args.report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
