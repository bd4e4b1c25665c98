#!/usr/bin/env python3
"""compare_builds.py - two or more mpsph binaries timed side by side on the benchmark's 2D and 3D
dam breaks, in interleaved rounds (each round runs every binary on a case before the next case),
one rank each: the median over the rounds of the step loop and of the pair passes from each run's
timings.csv, and the ratio of the first binary's to each other's. For a change of code or flags
(e.g. a build of the commit before a change against one after it, or ARCH=portable against
ARCH=native): the shared machine's load moves all binaries of a round alike.

Usage: scripts/bench/compare_builds.py [--rounds N] [--out DIR] NAME=BINARY NAME=BINARY [...]
  --rounds  interleaved rounds (default 3)
  --out     where the runs go (default build/bench/compare)
Prints one markdown table per case."""
import argparse
import csv
import os
import statistics
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = {
    "2D, scripts/bench/dambreak-val2d.yaml (dx 0.01 m, 20 000 fluid), 60 steps":
        ["scripts/bench/dambreak-val2d.yaml", "--set", "time.max_steps=60", "--set", "time.end=1"],
    "3D, scripts/bench/dambreak-3d.yaml at dx 0.04 m (10 850 fluid), 8 steps":
        ["scripts/bench/dambreak-3d.yaml", "--set", "resolution.dx=0.04", "--set", "time.max_steps=8",
         "--set", "output.interval=0"],
}
# timings.csv rows by the start of their name: the step loop and the passes with pairs
OPERATIONS = ["loop", "wall ghosts: Shepard", "free surface: eigen", "gradients", "fluid rhs"]


def seconds_of(path):
    """The max-over-ranks seconds of each operation of OPERATIONS in a run's timings.csv."""
    with open(path) as f:
        rows = list(csv.reader(f))
    return {op: float(r[3]) for op in OPERATIONS for r in rows if r[0].startswith(op)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(ROOT, "build/bench/compare"))
    ap.add_argument("binaries", nargs="+", help="NAME=BINARY")
    a = ap.parse_args()
    binaries = dict(b.split("=", 1) for b in a.binaries)
    times = {}
    for _ in range(a.rounds):
        for case, args in CASES.items():
            for name, binary in binaries.items():
                out = os.path.join(a.out, name)
                subprocess.run([binary, "run", os.path.join(ROOT, args[0]), "-o", out] + args[1:],
                               check=True, capture_output=True)
                for op, s in seconds_of(os.path.join(out, "timings.csv")).items():
                    times.setdefault((case, op, name), []).append(s)
    names = list(binaries)
    for case in CASES:
        print("\n%s, median of %d rounds [s]\n" % (case, a.rounds))
        print("| operation | %s | %s |" % (" | ".join(names), " | ".join("%s / %s" % (names[0], n) for n in names[1:])))
        print("|---" * (2 * len(names)) + "|")
        for op in OPERATIONS:
            med = [statistics.median(times[(case, op, n)]) for n in names]
            print("| %s | %s | %s |" % (op, " | ".join("%.3f" % m for m in med),
                                        " | ".join("%.2f" % (med[0] / m) for m in med[1:])))


if __name__ == "__main__":
    main()
