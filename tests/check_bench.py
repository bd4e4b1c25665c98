#!/usr/bin/env python3
"""Sanity of the benchmark's outputs (scripts/bench.py): OUT/performance.csv and
OUT/performance.md exist; the CSV has bench_report.py's columns, every number is finite, min <=
median <= max, and each metric has the sign and range its definition allows; particle-steps/s
per core is in a plausible range, agrees with the same run's main-pass figures, and no pass runs
above the measured peak; every benchmark of the suite (scenes x ranks, weak scaling, each
optional term, the single-phase build, the HDF5 sizes, the 3D weak-scaling rank counts, the 3D
step's sizes against their 2D slices) has its rows in the CSV and in the report, whose sections
and target verdicts are all there; the peer comparison (DualSPHysics) is either marked skipped
with no rows, or has its time ratios on 1 and 2 cores (the report's table holding the CSV's
medians) and both codes' front errors. Prints each problem and exits 1 if
there is one.

Usage: check_bench.py OUT [--quick] [--sizes N]   (the options bench.py ran with)"""
import argparse
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
import bench  # noqa: E402  (the suite's configuration: scenes, sizes, terms, HDF5 sizes)
import bench_report  # noqa: E402

COLUMNS = ["group", "case", "particles", "ranks", "steps", "metric", "median", "min", "max", "repeats", "unit"]
SECTIONS = ["## Targets", "## 1. Throughput", "## 2. Where", "## 3. Floating", "## 4. Memory",
            "## 5. Parallel", "## 6. Snapshot", "## 7. Cost", "## 8. Single-phase", "## 9. Weak scaling",
            "## 10. Peer comparison", "## 11. The 3D step", "## What bounds"]
PEER_SKIPPED = "Skipped: no DualSPHysics binary was given."
# Target verdicts: seven (five of issue 6, the 3D step's two), the efficiency target's when a
# scene has bench_report.EFF_MIN_FLUID fluid particles (not at the quick sizes), and the cluster
# group's two when it ran on 8 ranks or more at two rank counts (not at the quick sizes).
N_TARGETS = 7
# Particle-steps/s per core. A particle-step is four RK stages over about 45 neighbours with at
# least 62 flops per pair in the main pass alone (bench.FLOPS_PER_PAIR): over 1e4 flops, so
# 1e7/s would take 1e11 flop/s, six times this machine's measured one-core peak (16.5 Gflop/s).
# 1e3/s is 50-80 times below the 1-rank rates measured here at the quick sizes (4.7e4-7.9e4/s;
# 6.5e3/s on 2 ranks with the 2 cores shared by other jobs): a rate below it is a broken run or
# formula.
PSPS_RANGE = (1e3, 1e7)


def read_csv(path, problems):
    """The rows of performance.csv as dicts, or None if its header is not COLUMNS."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0] != COLUMNS:
        problems.append("%s: header %s, expected %s" % (path, rows[0] if rows else "none", COLUMNS))
        return None
    out = []
    for k, r in enumerate(rows[1:], 2):
        if len(r) != len(COLUMNS):
            problems.append("%s line %d: %d fields, expected %d" % (path, k, len(r), len(COLUMNS)))
            continue
        out.append(dict(zip(COLUMNS, r)))
    return out


def metric_range(metric):
    """(low, high, low inclusive) a value of this metric may take: a saving and the remainder
    share 'other' are differences of measured times (noise can make them negative), the other
    shares fractions of the loop, everything else a positive rate, size or ratio."""
    if metric.startswith("saving ") or metric.startswith("share other"):
        return -1.0, 1.0, True
    if metric.startswith("share "):
        return 0.0, 1.0, True
    if metric == "particle_steps_per_s_per_core":
        return PSPS_RANGE[0], PSPS_RANGE[1], True
    if metric == "main_pass_fraction_of_peak":
        return 0.0, 1.0, False
    return 0.0, math.inf, False


def row_problems(r):
    """Problems of one CSV row: integer columns, finite ordered values in the metric's range."""
    where = "%s/%s/%s ranks/%s" % (r["group"], r["case"], r["ranks"], r["metric"])
    try:
        ints = [int(r[c]) for c in ("particles", "ranks", "steps", "repeats")]
        med, lo, hi = (float(r[c]) for c in ("median", "min", "max"))
    except ValueError as err:
        return ["%s: not a number (%s)" % (where, err)]
    out = []
    if ints[0] <= 0 or ints[1] < 1 or ints[2] < 0 or ints[3] < 1:
        out.append("%s: particles %d, ranks %d, steps %d, repeats %d" % (where, *ints))
    if not all(math.isfinite(v) for v in (med, lo, hi)) or not lo <= med <= hi:
        return out + ["%s: median %r, min %r, max %r: not finite, or not min <= median <= max" % (where, med, lo, hi)]
    low, high, closed = metric_range(r["metric"])
    if not ((lo >= low if closed else lo > low) and hi <= high):
        out.append("%s: [%g, %g] outside %s%g, %g]" % (where, lo, hi, "[" if closed else "(", low, high))
    return out


def expected_rows(cfg, n_sizes):
    """{(group, case, ranks, metric): number of rows} the suite must write (bench.py,
    bench_report.py): per scene, one row per size of each per-size metric."""
    want = {}
    for case in bench.CASES:
        sizes = min(n_sizes, len(cfg["dx"][case]))
        for ranks in (1, 2):
            for group, metric in (("size", "particle_steps_per_s_per_core"), ("size", "bytes_per_particle_end"),
                                  ("flops", "main_pass_fraction_of_peak")):
                want[(group, case, ranks, metric)] = sizes
        want[("strong", case, 2, "efficiency_1_to_2")] = sizes
    want.update({("weak", "2phase", ranks, "weak_efficiency"): 1 for ranks in (1, 2, 4)})
    want.update({("hdf5", "snapshot", ranks, "hdf5_over_raw_bandwidth"): len(cfg["hdf5_particles"]) for ranks in (1, 2)})
    want.update({("terms", "2phase", 1, "saving " + label): 1 for label, _ in bench.TERMS_OFF})
    want[("single_phase", "1phase", 1, "multiphase_over_single_build")] = 1
    for ranks in cfg["cluster_ranks"]:
        for metric in ("project_bytes_max_rank", "estimate_over_peak"):
            want[("cluster", "3d", ranks, metric)] = 1
    sizes3d = min(n_sizes, len(cfg["step3d_dx"]))
    for case in ("3d", "3d-slice"):
        for metric in ("particle_steps_per_s_per_core", "bytes_per_particle_peak", "share wall ghosts"):
            want[("step3d", case, 1, metric)] = sizes3d
    return want


def csv_problems(rows, cfg, n_sizes):
    """Every row's own problems, then the rows the suite must have written and did not."""
    out = [p for r in rows for p in row_problems(r)]
    have = {}
    for r in rows:
        key = (r["group"], r["case"], int(r["ranks"]), r["metric"])
        have[key] = have.get(key, 0) + 1
    for key, n in expected_rows(cfg, n_sizes).items():
        if have.get(key, 0) != n:
            out.append("performance.csv: %d rows %s, expected %d" % (have.get(key, 0), "/".join(map(str, key)), n))
    return out


def throughput_problems(r, rows, md):
    """The report's throughput row of CSV row r (particle-steps/s per core of one run) holds r's
    value, and the value agrees with the same run's main-pass figures: by their definitions
    (bench.derive) particle-steps/s per core = main-pass pairs/s per core x the pass's share of the
    loop / (4 x pairs per particle-step x (1 - the final output's share)), an identity up to the
    rounding of pairs per particle-step to 0.1 in the report (< 0.2 % at about 40) and of the CSV
    to 6 digits: a rate computed with the wrong time, rank count or stage count breaks it. Checked
    with one repeat only (the smoke test): with more, each median may come from another repeat."""
    what = "%s, %s particles, %s ranks" % (r["case"], r["particles"], r["ranks"])
    m = re.search(r"^\| %s \| %s \+ \d+ \| %s \| %s \| (\S+) .* \| (\S+) \|$" % (r["case"], r["particles"], r["ranks"], r["steps"]),
                  md, re.M)
    psps = float(r["median"])
    if not m or abs(float(m.group(1)) / psps - 1) > 1e-3:
        return ["performance.md: throughput row of %s: %s, the CSV has %s" % (what, m.group(1) if m else "missing", psps)]
    if int(r["repeats"]) != 1:
        return []
    run = {x["metric"]: float(x["median"]) for x in rows
           if x["group"] == "size" and (x["case"], x["particles"], x["ranks"]) == (r["case"], r["particles"], r["ranks"])}
    main = bench.MAIN_PASS.replace(" ", "_")
    try:
        implied = (run["pairs/s/core_" + main] * run["share " + bench.MAIN_PASS] /
                   (4 * float(m.group(2)) * (1 - run["share final output (snapshot + checkpoint)"])))
    except (KeyError, ValueError, ZeroDivisionError) as err:
        return ["%s: cannot recompute particle-steps/s from the main pass (%r)" % (what, err)]
    if abs(implied / psps - 1) > 5e-3:
        return ["%s: particle-steps/s per core %g, but the main pass's pairs/s, share and pairs per "
                "particle-step give %g" % (what, psps, implied)]
    return []


def peer_problems(md, rows):
    """The peer comparison: skipped with no rows, or per core count (1, 2) a time-ratio row for
    each of mpsph's settings whose medians the report's table shows in the same order, and a
    front-error row of each code."""
    peer = [r for r in rows if r["group"] == "peer"]
    if PEER_SKIPPED in md:
        return ["performance.csv: %d peer rows, but the report says the comparison was skipped" % len(peer)] if peer else []
    out = []
    for cores in (1, 2):
        ratio = [float(r["median"]) for r in peer if r["metric"] == "mpsph_over_dualsphysics_time" and int(r["ranks"]) == cores]
        shown = [float(x) for x in re.findall(
            r"^\| %d cores? \| [^|]+ \| [^|]+ \| \d+ \| [^|]+ \| \d+ \| (\S+) \[[^]]*\] \|$" % cores, md, re.M)]
        if not ratio or len(shown) != len(ratio) or any(abs(a / b - 1) > 5e-3 for a, b in zip(shown, ratio)):
            out.append("peer comparison on %d cores: ratio rows %s, report rows %s" % (cores, ratio, shown))
    for code in ("dualsphysics", "mpsph"):
        if not any(r["metric"] == "front_error_window_" + code for r in peer):
            out.append("performance.csv: no front error of %s in the peer comparison" % code)
    return out


def report_problems(md, rows, cfg, n_sizes):
    """Sections, target verdicts and one row per benchmark in the report; the throughput table
    holds the CSV's particle-steps/s."""
    out = ["performance.md: missing section %r" % s for s in SECTIONS if not re.search("^" + re.escape(s), md, re.M)]
    verdicts = len(re.findall(r"^\| .* \| \*\*(met|missed)\*\*", md, re.M))
    targets = N_TARGETS + any(r["group"] == "size" and int(r["particles"]) >= bench_report.EFF_MIN_FLUID for r in rows)
    targets += 2 * (sum(n >= 8 for n in cfg["cluster_ranks"]) > 1)
    if verdicts != targets:
        out.append("performance.md: %d target verdicts, expected %d" % (verdicts, targets))
    if re.search(r"\b(nan|inf)\b", md, re.I):
        out.append("performance.md: holds nan or inf")
    out += [p for r in rows if r["group"] == "size" and r["metric"] == "particle_steps_per_s_per_core"
            for p in throughput_problems(r, rows, md)]
    rows_wanted = [("weak scaling on %d ranks" % n, r"%d( \(oversubscribed\))? \| \d+ \| \d+" % n) for n in (1, 2, 4)]
    rows_wanted += [("term variant %r" % label, re.escape(label)) for label, _ in bench.TERMS_OFF]
    rows_wanted += [("build %r" % b, re.escape(b)) for b in ("multiphase (build/mpsph)", "SINGLE_PHASE=1")]
    rows_wanted += [("snapshot bandwidth, %d particles on %d ranks" % (n, ranks), r"%d \| \d+ \| %d" % (n, ranks))
                    for n in cfg["hdf5_particles"] for ranks in (1, 2)]
    rows_wanted += [("3D weak scaling on %d ranks" % n, r"%d \| [0-9.]+ \| \d+ \| \d+" % n) for n in cfg["cluster_ranks"]]
    rows_wanted += [("3D step at dx %g" % dx, r"%g \| \d+ \+ \d+" % dx) for dx in cfg["step3d_dx"][:n_sizes]]
    for what, pattern in rows_wanted:
        if not re.search(r"^\| %s \|" % pattern, md, re.M):
            out.append("performance.md: no table row for %s" % what)
    return out + peer_problems(md, rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--sizes", type=int, default=3)
    a = ap.parse_args()
    cfg = bench.QUICK if a.quick else bench.FULL
    csv_path, md_path = (os.path.join(a.out, n) for n in ("performance.csv", "performance.md"))
    problems = ["%s: missing or empty" % p for p in (csv_path, md_path) if not os.path.isfile(p) or not os.path.getsize(p)]
    if not problems:
        rows = read_csv(csv_path, problems)
        if rows is not None:
            problems += csv_problems(rows, cfg, a.sizes)
            with open(md_path) as f:
                problems += report_problems(f.read(), rows, cfg, a.sizes)
    for p in problems:
        print(p)
    print("bench outputs: %s" % ("%d problems" % len(problems) if problems else "ok"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
