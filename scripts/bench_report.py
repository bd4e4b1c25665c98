"""bench_report.py - doc/performance.md and doc/performance.csv from the results of bench.py.
Every number written comes from the runs of this invocation; the targets are those of issue 6."""
import csv
import math
import os

TARGET_PEAK, TARGET_EFF, TARGET_BYTES, TARGET_SP, TARGET_IO = 0.25, 0.90, 600.0, 0.05, 0.50
TARGET_GHOST_SHARE, TARGET_3D_COST = 0.10, 3.0   # issue 24: wall-ghost share of a 3D step; 3D / 2D cost per fluid particle-step
GHOST_PASS = "wall ghosts"
EFF_MIN_FLUID = 35000   # the efficiency target is judged on the scenes with at least this many fluid particles



# A trial measured once (not by this suite), kept in the report because it decides the next step.
GHOST_REACH_TRIAL = (
    "Tried and not kept (stop 35; `build/mpsph run scripts/bench/dambreak-3d.yaml --set time.max_steps=20` at "
    "dx 0.04 m, 1 rank, each build 3 times in turn): of the 12073 ghosts with fluid in the lists of their mirror points (within "
    "the cell edge of them), 3351 have no fluid within the support of the ghost itself (mostly the deepest layer, 3.5 dx "
    "behind the wall: the first fluid row is 4.0 dx from it, the Gaussian's cut 3.99 dx), and their Shepard sums "
    "are 32 % of the pass's pairs (138 million over 20 steps, 94 million without them). Leaving them without values (no pair reads "
    "them; an exact test per stage over the mirror point's list, valid in a box tank; the fluid's snapshots "
    "bitwise unchanged) made the interpolation 1.78 -> 1.74 s: the test cost what the pairs saved. A test per "
    "step instead (the nearest fluid at the step's start against the support plus or minus half the cell "
    "skin) finds only 3 % of the ghosts never reached, since the deepest layer's 4.0 dx lies within half a "
    "skin of the support; the list pass grew from 0.61 to 0.86 s and the 20 steps took 11.5, 11.9, 11.0 s against "
    "11.0, 11.6, 11.5 s without it. What the pass costs is its pairs at the mirror points (about 140 per "
    "reached ghost and stage at 10-13 ns each), and the ghosts' share falls with the surface-to-volume ratio "
    "(the rows above).")
GATHER_TRIAL = (
    "Measured (stop 33, `scripts/bench/compare_builds.py` with 5 interleaved rounds against the same commit "
    "without the change, 2D dam break of 20 000 fluid particles and 3D dam break at dx 0.04 m): the rhs pair "
    "terms computed in SIMD lanes over all the pairs of a particle (AVX-512 gathers of the neighbours' "
    "fields, selects for the pair relations, 8 partial sums per term added in a fixed order, so that the "
    "sums stay independent of the rank count and of the vector width) ran the fluid rhs pass at 0.89x the "
    "speed of the scalar pair loop in 2D and 1.01x in 3D. On this CPU a gather of 8 doubles costs about what "
    "8 scalar loads do, so vectorising the arithmetic behind the gathers gains nothing; the trial was not "
    "kept. Contracting multiply-adds into FMA (`-ffp-contract=fast`, which would make results differ "
    "between builds for different CPUs) made the rhs pass 1.07x (2D) and 1.08x (3D) faster and the step "
    "1.02x and 1.04x; not adopted.")

def mmm(values, fmt="%.3g", scale=1.0):
    """'median [min-max]' of a list."""
    v = sorted(x * scale for x in values)
    med = v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])
    return (fmt % med) + " [" + (fmt % v[0]) + "-" + (fmt % v[-1]) + "]"


def med(values):
    v = sorted(values)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])


def spread(values):
    """(max - min) / median [%]."""
    return 100.0 * (max(values) - min(values)) / med(values)


def col(runs, key):
    return [r[key] for r in runs]


def pct(x):
    """A fraction as a percentage, or 'none' when it is not a number."""
    return "%.2f %%" % (100 * x) if math.isfinite(x) else "none"


def peer_case(code):
    """The case column of the peer comparison's CSV rows of `code`: DualSPHysics and mpsph's
    issue settings keep the case's name, mpsph's other settings (bench_peer.MPSPH_SETTINGS keys
    mpsph_<setting>) add theirs."""
    setting = code[len("mpsph_"):] if code.startswith("mpsph_") else ""
    return "dambreak-val2d" + ("-" + setting.replace("_", "-") if setting else "")


def verdict(ok):
    return "**met**" if ok else "**missed**"


class Report:
    """Collects the Markdown lines and the CSV rows."""

    def __init__(self, b, m, peaks, cfg, quick, flops, main_pass):
        self.b, self.m, self.peaks, self.cfg, self.quick = b, m, peaks, cfg, quick
        self.flops_per_pair, self.main_pass = flops, main_pass
        self.md, self.rows, self.targets, self.notes = [], [], [], []
        self.estimate_errors = []   # |estimate / peak - 1| of the runs of section 4
        self.peak = max(peaks)

    def w(self, *lines):
        self.md.extend(lines)

    def row(self, group, case, particles, ranks, steps, metric, values, unit):
        self.rows.append([group, case, int(particles), ranks, steps, metric, "%.6g" % med(values),
                          "%.6g" % min(values), "%.6g" % max(values), len(values), unit])

    def header(self):
        m = self.m
        self.md += ["# mpsph performance", "",
               "Generated by `make bench`%s (scripts/bench.py, scripts/bench_report.py) from the runs of "
               "that invocation only; do not edit by hand. Figures are medians over the repeats with "
               "[min-max] and the spread (max-min)/median. The machine is shared, so prefer the ratios "
               "(fraction of peak, efficiencies, relative costs), which hold better under load than "
               "absolute rates." % (" BENCH_QUICK=1 (smoke sizes: not the issue's sizes)" if self.quick else ""), "",
               "| machine | |", "|---|---|",
               "| CPU | %s, %d cores (os.cpu_count) |" % (m["cpu"], m["cores"]),
               "| load average (1/5/15 min) at start | %.2f / %.2f / %.2f |" % m["load_start"],
               "| load average at end | %.2f / %.2f / %.2f |" % m["load_end"],
               "| commit | `%s` |" % m["commit"],
               "| compiler | %s, flags `%s` (`-std=c11`: no floating-point contraction) |"
               % (m["compiler"], m.get("flags", "-O2 -ftree-vectorize -g")),
               "| date | %s |" % m["date"],
               "| run time of the whole suite | %.1f min |" % (m["seconds"] / 60)]
        self.md += ["| groups run again: %s | commit `%s`%s, %s, load %.2f / %.2f / %.2f at start, %.2f / %.2f / %.2f at end, %.1f min |"
                  % ((r["groups"], r["commit"], ", flags `%s`" % r["flags"] if "flags" in r else "", r["date"])
                     + tuple(r["load_start"]) + tuple(r["load_end"]) + (r["seconds"] / 60,))
                  for r in m.get("reruns", [])]
        self.md += ["",
               "Every run: `scripts/mpirun -n R build/mpsph run CASE --set resolution.dx=DX --set "
               "time.max_steps=STEPS --set output.interval=0` (stats, probes and progress intervals "
               "set beyond the run), so the only output is the initial and final snapshot and the "
               "final checkpoint. The per-run figures come from `OUTDIR/timings.csv` written by "
               "`engine_report.c`: per-operation wall time (max and mean over ranks), pair counts, the "
               "step-loop time without the final output, peak and end resident memory per rank. A "
               "particle-step is one fluid particle advanced through all four RK4 stages; per core "
               "= per rank (one rank per core; 4 ranks on 2 cores are oversubscribed). The load average "
               "above counts other users' jobs on the same 2 cores: with a load near or above 2 the "
               "2-rank runs did not have two cores to themselves.", ""]

    def sizes(self):
        b = self.b
        self.w("## 1. Throughput by size (strong runs)", "",
               "| scene | particles (fluid + wall) | ranks | steps | particle-steps/s per core | spread | pairs per particle-step |",
               "|---|---|---|---|---|---|---|")
        for (kind, case, k, ranks), runs in sorted((key, v) for key, v in b.res.items() if key[0] == "size"):
            ps = col(runs, "psps_core")
            r0 = runs[0]
            self.w("| %s | %d + %d | %d | %d | %s | %.0f %% | %.1f |" % (
                case, r0["fluid"], r0["wall"], ranks, r0["steps"], mmm(ps, "%.4g"), spread(ps),
                med(col(runs, "pairs_per_particle_step"))))
            self.row("size", case, r0["fluid"], ranks, r0["steps"], "particle_steps_per_s_per_core", ps, "1/s")
            for key in r0:
                if key.startswith("pairs/s/core"):
                    self.row("size", case, r0["fluid"], ranks, r0["steps"], key.replace(" ", "_"), col(runs, key), "1/s")
            self.row("size", case, r0["fluid"], ranks, r0["steps"], "bytes_per_particle_peak",
                     col(runs, "bytes_per_particle_peak"), "B")
            self.row("size", case, r0["fluid"], ranks, r0["steps"], "bytes_per_particle_end",
                     col(runs, "bytes_per_particle_end"), "B")
            for name in r0["shares"]:
                self.row("size", case, r0["fluid"], ranks, r0["steps"], "share " + name,
                         [r["shares"][name] for r in runs], "fraction of loop")
        self.w("")

    def largest(self, case, ranks):
        keys = [k for k in self.b.res if k[0] == "size" and k[1] == case and k[3] == ranks]
        return self.b.res[max(keys)] if keys else None

    def shares(self):
        self.w("## 2. Where the step time goes (largest size)", "",
               "Share of the step loop's wall time per operation (operation time averaged over the "
               "ranks, over the loop time of the slowest rank); halo = every halo "
               "update of the stage pipeline, message exchange and waiting included; migration = "
               "migration, re-sort, halo rebuild and re-partition after each step; final output = "
               "the final snapshot and checkpoint inside the loop (the benchmark writes no other); "
               "other = the rest (time step reduction, RK update, checks).", "")
        cols = [(c, r) for c in ("1phase", "2phase") for r in (1, 2) if self.largest(c, r)]
        names = []
        for c, r in cols:
            for n in self.largest(c, r)[0]["shares"]:
                if n not in names:
                    names.append(n)
        self.w("| operation | " + " | ".join("%s, %d rank%s" % (c, r, "s" if r > 1 else "") for c, r in cols) + " |",
               "|---|" + "---|" * len(cols))
        for n in names:
            cells = []
            for c, r in cols:
                runs = self.largest(c, r)
                cells.append("%.1f %%" % (100 * med([x["shares"].get(n, 0.0) for x in runs])) if n in runs[0]["shares"] else "-")
            self.w("| %s | %s |" % (n, " | ".join(cells)))
        self.w("", "Neighbour-pair evaluations per second per core, per pass (pairs within the kernel "
               "support; the neighbour-list pass counts none):", "",
               "| pass | " + " | ".join("%s, %d rank%s" % (c, r, "s" if r > 1 else "") for c, r in cols) + " |",
               "|---|" + "---|" * len(cols))
        keys = []
        for c, r in cols:
            for k in self.largest(c, r)[0]:
                if k.startswith("pairs/s/core") and k not in keys:
                    keys.append(k)
        for k in keys:
            cells = [mmm(col(self.largest(c, r), k), "%.3g") if k in self.largest(c, r)[0] else "-" for c, r in cols]
            self.w("| %s | %s |" % (k[len("pairs/s/core "):], " | ".join(cells)))
        self.w("")

    def flops(self):
        self.w("## 3. Floating-point rate of the main pass", "",
               "Peak: `build/bench/peak_fma` (scripts/bench/peak_fma.c), 32 independent multiply-add "
               "accumulators compiled with the solver's flags and `-ffp-contract=fast`, best rate of "
               "repeated sweeps, run at the start and the end of the run that measured the sizes of section "
               "1 (the suite, or its rerun with `--only sizes`): %s Gflop/s (the larger is used). With the default flags (`ARCH=native`) this is the fused multiply-add peak of one "
               "core in the machine's widest vectors, which the solver itself (no contraction, to keep "
               "its rounding fixed) cannot reach in full: its multiply and add are two instructions."
               % " and ".join("%.3g" % (p / 1e9) for p in self.peaks), "",
               "Flops of the main pass (`%s`): counted by hand from the source of `fluid_sums` in "
               "src/physics/pass_fluid_rhs.c (perf's hardware counters are not available on this virtual "
               "machine: `perf stat -e instructions true` reports `<not supported>`): %d flops per "
               "pair for the single-phase scene and %d for the two-phase scene (same-phase fluid pair "
               "in 2D; the derivation is in scripts/bench.py, FLOPS_PER_PAIR). Wall and other-phase "
               "pairs do fewer and rejected candidates are not counted, so the rate is an estimate."
               % (self.main_pass, self.flops_per_pair["1phase"], self.flops_per_pair["2phase"]), "",
               "| scene | particles | ranks | main-pass Gflop/s per core | fraction of peak |", "|---|---|---|---|---|")
        worst, kmax = None, max(key[2] for key in self.b.res if key[0] == "size")
        for (kind, case, k, ranks), runs in sorted((key, v) for key, v in self.b.res.items() if key[0] == "size"):
            f = col(runs, "main_flops_core")
            frac = [x / self.peak for x in f]
            if k == kmax and ranks == 1:
                worst = med(frac) if worst is None else min(worst, med(frac))
            self.w("| %s | %d | %d | %s | %s |" % (case, runs[0]["fluid"], ranks, mmm(f, "%.3g", 1e-9),
                                                   mmm(frac, "%.3f")))
            self.row("flops", case, runs[0]["fluid"], ranks, runs[0]["steps"], "main_pass_fraction_of_peak", frac, "ratio")
        self.w("", "The verdict uses the 1-rank runs at the largest size (the worse of the two scenes): "
               "on 2 ranks the per-core rate also carries the sharing of the cores with other jobs "
               "(section 5). The rates are from the pass's wall time while the peak is the best sweep, "
               "so where other jobs took part of the core the fraction is underestimated; section 7 "
               "compares CPU and wall time of the same runs.", "")
        self.targets.append(("main pair pass >= 25 % of one core's measured peak (largest size, 1 rank)",
                             "%.1f %%" % (100 * worst), worst >= TARGET_PEAK, "%.1f points below" % (100 * (TARGET_PEAK - worst))))
        self.main_frac = worst

    def size_runs(self, case, ranks):
        """The size runs of a scene and rank count, smallest first."""
        ks = sorted(k[2] for k in self.b.res if k[0] == "size" and k[1] == case and k[3] == ranks)
        return [self.b.res[("size", case, k, ranks)] for k in ks]

    def memory(self):
        self.w("## 4. Memory per particle", "",
               "Per run, over all particles (fluid + wall) and summed over the ranks: the resident "
               "memory at the peak (getrusage ru_maxrss, start-up included) and at the end of the run "
               "(/proc/self/statm, the steady state); the file-backed part of the end figure (RssFile: "
               "the pages of the executable and of the shared libraries, MPI, HDF5 and their "
               "dependencies, which every rank maps and the sum counts once per rank); the proportional "
               "set size at the end (Pss of /proc/self/smaps_rollup: each shared page divided among the "
               "processes that map it, so the sum over the ranks counts the library pages once: the "
               "memory the job holds on the machine); and the "
               "project's own arrays at the end, counted from their capacities (particles, scheme work "
               "arrays, neighbour lists, cell index and sort scratch, halo message buffers; "
               "`project_bytes_rankN` of timings.csv). Resident memory also holds the fixed cost of "
               "every process (the libraries' code and heaps), which is why small runs show more per "
               "particle.", "",
               "| scene | particles | ranks | peak RSS B/particle | end RSS B/particle | of which file-backed | end PSS B/particle | project arrays B/particle | largest rank peak MB | `check --ranks` estimate MB (/ peak) |",
               "|---|---|---|---|---|---|---|---|---|---|")
        for (kind, case, k, ranks), runs in sorted((key, v) for key, v in self.b.res.items() if key[0] == "size"):
            peak = med(col(runs, "rss_peak_max_rank"))
            estimate = self.b.res.get(("estimate", case, k, ranks))
            if estimate:
                self.estimate_errors.append(abs(estimate / peak - 1))
            self.w("| %s | %d | %d | %s | %s | %.0f | %s | %.0f | %.1f | %s |" % (
                case, runs[0]["fluid"] + runs[0]["wall"], ranks, mmm(col(runs, "bytes_per_particle_peak"), "%.0f"),
                mmm(col(runs, "bytes_per_particle_end"), "%.0f"), med(col(runs, "bytes_per_particle_file")),
                mmm(col(runs, "bytes_per_particle_pss"), "%.0f"), med(col(runs, "bytes_per_particle_project")),
                peak / 1e6, "%.1f (%.2f)" % (estimate / 1e6, estimate / peak) if estimate else "-"))
        self.memory_owners()
        self.memory_marginal()
        self.memory_target()

    def memory_owners(self):
        owners = ["particles", "work", "neighbour_lists", "cells", "halo_buffers"]
        self.w("", "The project's arrays by owner at the largest size, B per particle (all ranks; capacity "
               "included): particles = position, velocity, density, pressure, mass, phase, id, cell and "
               "the ghosts' mirror offset and wall index; work = the scheme's per-particle arrays (those "
               "the halo reads sized to owned + halo slots, the RK4 state, sums and derivatives to the "
               "owned ones; optional ones only when their term is on); neighbour lists = one bit per "
               "candidate of the cell stencil; cells = the owner of every top cell, the index of the "
               "fine cells of the rank's region and halo reach, and the sort scratch; halo buffers = the send index and the packed "
               "values of the halo updates and migrations (the halo copies are received in place).", "",
               "| scene | ranks | particles | work | neighbour lists | cells | halo buffers | total | halo copies |",
               "|---|---|---|---|---|---|---|---|---|")
        for case in ("1phase", "2phase"):
            for ranks in (1, 2):
                runs = self.largest(case, ranks)
                if not runs:
                    continue
                by = runs[0]["project_by_owner"]
                n = runs[0]["fluid"] + runs[0]["wall"]
                self.w("| %s | %d | %s | %.0f | %.0f %% |" % (
                    case, ranks, " | ".join("%.0f" % by.get(o, 0) for o in owners), sum(by.values()),
                    100 * runs[0]["halo_particles"] / n))

    def memory_marginal(self):
        self.w("", "Marginal memory per particle (the fixed cost taken out): the growth of the summed "
               "end-of-run resident memory, and of the project's arrays, from the smallest to the largest "
               "size, over the growth of the particle count; and the fixed cost of one process, the "
               "smallest run's end resident memory less its project arrays, per rank:", "")
        fixed = {}
        for case in ("1phase", "2phase"):
            for ranks in (1, 2):
                runs = self.size_runs(case, ranks)
                if len(runs) < 2:
                    continue
                lo, hi = runs[0], runs[-1]
                dn = hi[0]["fluid"] + hi[0]["wall"] - lo[0]["fluid"] - lo[0]["wall"]
                marg = (med(col(hi, "rss_end_sum")) - med(col(lo, "rss_end_sum"))) / dn
                own = (med(col(hi, "project_sum")) - med(col(lo, "project_sum"))) / dn
                fixed[(case, ranks)] = (med(col(lo, "rss_end_sum")) - med(col(lo, "project_sum"))) / ranks
                self.w("- %s, %d rank%s: %.0f B per particle resident, %.0f B of project arrays; fixed cost "
                       "%.1f MB per process" % (case, ranks, "s" if ranks > 1 else "", marg, own,
                                                fixed[(case, ranks)] / 1e6))
                self.row("memory", case, hi[0]["fluid"], ranks, hi[0]["steps"], "marginal_bytes_per_particle", [marg], "B")
                self.row("memory", case, hi[0]["fluid"], ranks, hi[0]["steps"], "marginal_project_bytes_per_particle", [own], "B")

    def memory_target(self):
        worst, where, worst_peak = 0.0, None, 0.0
        for case in ("1phase", "2phase"):
            for ranks in (1, 2):
                runs = self.largest(case, ranks)
                if not runs:
                    continue
                worst_peak = max(worst_peak, med(col(runs, "bytes_per_particle_peak")))
                if med(col(runs, "bytes_per_particle_pss")) > worst:
                    worst, where = med(col(runs, "bytes_per_particle_pss")), (case, ranks, runs)
        self.w("", "The target (issue 6: at most 600 B per particle, all ranks' steady state included) is "
               "read as: at the largest size, the end-of-run proportional set size of every rank summed, "
               "over all particles, for each scene on 1 and on 2 ranks (the worst counts). It includes the "
               "fixed cost of every process (the libraries' heaps, and their code pages counted once, not "
               "once per rank as the sum of resident sizes does). For comparison, the worst peak resident "
               "memory summed over the ranks, with the library pages counted once per rank and the "
               "start-up included, is %.0f B per particle." % worst_peak, "")
        if where and worst > TARGET_BYTES:
            case, ranks, runs = where
            own = med(col(runs, "bytes_per_particle_project"))
            self.w("Missed by %.0f B (%s, %d rank%s: %.0f B): the project's arrays are %.0f B of it, the "
                   "rest is the processes' fixed cost and the libraries' heaps." % (
                       worst - TARGET_BYTES, case, ranks, "s" if ranks > 1 else "", worst, own), "")
        self.targets.append(("<= 600 B per particle, all ranks' steady state (largest size, end-of-run PSS "
                             "summed over the ranks, 1 and 2 ranks)",
                             "worst %.0f B (peak RSS summed: %.0f B)" % (worst, worst_peak),
                             worst <= TARGET_BYTES, "%.0f B over" % (worst - TARGET_BYTES)))

    def scaling(self):
        self.w("## 5. Parallel efficiency", "",
               "Strong: the same problem on 1 and 2 ranks, efficiency = t1 / (2 t2) from the median "
               "step-loop times (without the final output). The spread is from the extreme pairings "
               "of the repeats.", "", "| scene | particles | efficiency 1 -> 2 ranks |", "|---|---|---|")
        worst = None
        for case in ("1phase", "2phase"):
            for k in sorted({key[2] for key in self.b.res if key[0] == "size" and key[1] == case}):
                r1, r2 = self.b.res[("size", case, k, 1)], self.b.res[("size", case, k, 2)]
                t1, t2 = col(r1, "steps_s"), col(r2, "steps_s")
                eff = med(t1) / (2 * med(t2))
                lo, hi = min(t1) / (2 * max(t2)), max(t1) / (2 * min(t2))
                self.w("| %s | %d | %.2f [%.2f-%.2f] |" % (case, r1[0]["fluid"], eff, lo, hi))
                self.row("strong", case, r1[0]["fluid"], 2, r1[0]["steps"], "efficiency_1_to_2", [eff, lo, hi], "ratio")
                if r1[0]["fluid"] >= EFF_MIN_FLUID:
                    worst = eff if worst is None else min(worst, eff)
        self.w("", "Where the 2-rank time goes, against the 1-rank run (largest size): the per-core "
               "pair rate of the main pass on 2 ranks relative to 1 rank (below 1: the pass itself runs "
               "slower per core, from sharing the cores and the memory bandwidth with the other rank and "
               "with other jobs), and the halo exchange and wait share on 2 ranks:", "")
        for case in ("1phase", "2phase"):
            r1, r2 = self.largest(case, 1), self.largest(case, 2)
            key = next((k for k in r1[0] if k.startswith("pairs/s/core " + self.main_pass)), None)
            if r1 and r2 and key:
                rate = med(col(r2, key)) / med(col(r1, key))
                halo = med([x["shares"]["halo exchange and wait"] for x in r2])
                self.w("- %s: main-pass rate per core on 2 ranks %.2f of 1 rank; halo exchange and wait %.1f %% "
                       "of the 2-rank loop" % (case, rate, 100 * halo))
                self.row("strong", case, r1[0]["fluid"], 2, r1[0]["steps"], "main_pass_rate_2_over_1", [rate], "ratio")
        self.w("")
        if worst is not None:
            self.targets.append((">= 90 % efficiency 1 -> 2 ranks at >= 4e4 particles", "worst %.0f %%" % (100 * worst),
                                 worst >= TARGET_EFF, "%.0f points below" % (100 * (TARGET_EFF - worst))))
        self.w("", "Weak: the two-phase scene with about the same particles per rank; efficiency = t1 / tN. "
               "4 ranks on this 2-core machine are **oversubscribed** (two ranks per core), so the "
               "4-rank figure measures time sharing, not scaling.", "",
               "| ranks | particles | particles per rank | step-loop s | weak efficiency |", "|---|---|---|---|---|")
        t1 = med(col(self.b.res[("weak", 1)], "steps_s"))
        for ranks in (1, 2, 4):
            runs = self.b.res[("weak", ranks)]
            t = col(runs, "steps_s")
            label = " (oversubscribed)" if ranks > self.m["cores"] else ""
            self.w("| %d%s | %d | %d | %s | %.2f |" % (ranks, label, runs[0]["fluid"], runs[0]["fluid"] / ranks,
                                                      mmm(t, "%.2f"), t1 / med(t)))
            self.row("weak", "2phase", runs[0]["fluid"], ranks, runs[0]["steps"], "weak_efficiency", [t1 / x for x in t], "ratio")
        self.w("")

    def hdf5(self):
        self.w("## 6. Snapshot write bandwidth", "",
               "`build/bench/bench_hdf5` (scripts/bench/bench_hdf5.c): the project's collective "
               "`hdf5_write_snapshot` (temporary name, rename) of a 2D snapshot against every rank "
               "`pwrite`-ing its share of the same number of bytes into one file in the same folder "
               "(build/bench/work); both end with fsync and a barrier. The first pair of each set is a "
               "warm-up and dropped.", "",
               "| particles | bytes | ranks | HDF5 MB/s | raw MB/s | HDF5 / raw |", "|---|---|---|---|---|---|")
        worst = None
        for key in sorted(k for k in self.b.res if k[0] == "hdf5"):
            nbytes, th, tr = self.b.res[key]
            ratio = [med(tr) / x for x in th]
            r = med(tr) / med(th)
            self.w("| %d | %d | %d | %s | %s | %.2f |" % (key[1], nbytes, key[2], mmm([nbytes / x for x in th], "%.0f", 1e-6),
                                                        mmm([nbytes / x for x in tr], "%.0f", 1e-6), r))
            self.row("hdf5", "snapshot", key[1], key[2], 0, "hdf5_over_raw_bandwidth", ratio, "ratio")
            if key[1] == max(k[1] for k in self.b.res if k[0] == "hdf5"):
                worst = r if worst is None else min(worst, r)
        self.w("", "Ratios above 1 (HDF5 faster than the raw write of the same bytes) show the noise of "
               "this shared virtual disk: the raw write's spread is as wide as the difference.", "")
        self.targets.append(("snapshot writes >= 50 % of raw write bandwidth (largest size, 1 and 2 ranks)",
                             "worst %.0f %%" % (100 * worst), worst >= TARGET_IO, "%.0f points below" % (100 * (TARGET_IO - worst))))

    def terms(self):
        base = [k for k in self.b.res if k[0] == "term"]
        if not base:
            return
        on = self.b.res[("term", "all terms on")]
        t_on = med(col(on, "steps_cpu")) / on[0]["steps"]
        self.w("## 7. Cost of each optional term", "",
               "The two-phase scene (%d fluid particles, 1 rank, %d steps) with every optional term on "
               "(`%s`), then with one switched off. Cost = time per step saved by switching it off, as a "
               "fraction of the all-on step, from the CPU time of the step loop (clock of the process, "
               "which other jobs on the machine disturb far less than the wall time); the variants ran "
               "in turn within each repeat. Terms that are compiled or assembled out of the pipeline "
               "when off show a saving; a parameter set to 0 whose term is still evaluated shows none."
               % (on[0]["fluid"], on[0]["steps"], " ".join(s for s in __import__("bench").TERMS_ON if "domain" not in s)), "",
               "| variant | CPU s per step | wall s per step | saving vs all on (CPU) |", "|---|---|---|---|")
        for label, _ in __import__("bench").TERMS_OFF:
            runs = self.b.res[("term", label)]
            per = [x["steps_cpu"] / x["steps"] for x in runs]
            wall = [x["steps_s"] / x["steps"] for x in runs]
            save = [1 - p / t_on for p in per]
            self.w("| %s | %s | %s | %s |" % (label, mmm(per, "%.4f"), mmm(wall, "%.4f"), mmm([100 * x for x in save], "%.1f %%")))
            self.row("terms", "2phase", runs[0]["fluid"], 1, runs[0]["steps"], "saving " + label, save, "fraction of step")
        self.w("")

    def single_phase(self):
        a, b = self.b.res["sp"]
        ta, tb = col(a, "steps_cpu"), col(b, "steps_cpu")
        pairs = [x / y for x, y in zip(ta, tb)]
        over = med(pairs) - 1
        self.w("## 8. Single-phase scene: multiphase build vs SINGLE_PHASE=1", "",
               "The single-phase dam break (%d fluid particles, 1 rank, %d steps) through `build/mpsph` "
               "and through `build/bench/mpsph-single-phase` (every source compiled with the same flags "
               "plus `-DMPSPH_SINGLE_PHASE`, the multiphase specialisations compiled out), run "
               "alternately. Overhead = t(multiphase) / t(single-phase build) - 1 of each adjacent pair, t "
               "the CPU time of the step loop." %
               (a[0]["fluid"], a[0]["steps"]), "",
               "| build | step-loop CPU s |", "|---|---|",
               "| multiphase (build/mpsph) | %s |" % mmm(ta, "%.3f"),
               "| SINGLE_PHASE=1 | %s |" % mmm(tb, "%.3f"), "",
               "Overhead of the multiphase code on a single-phase scene: %s." % mmm([100 * (x - 1) for x in pairs], "%.1f %%"), "")
        self.row("single_phase", "1phase", a[0]["fluid"], 1, a[0]["steps"], "multiphase_over_single_build", pairs, "ratio")
        self.targets.append(("single-phase scene through the multiphase code within 5 % of SINGLE_PHASE=1",
                             "%+.1f %%" % (100 * over), over <= TARGET_SP, "%.1f points over" % (100 * (over - TARGET_SP))))

    def no_alloc(self):
        self.targets.append(("no allocation inside the time step after the first step",
                             "tests/test_no_alloc.c (make test): 0 project allocations in steps 2..12, 1 and 2 ranks",
                             True, ""))

    def step3d(self):
        """Section 11: the 3D step against its 2D slice (issue 24)."""
        keys = sorted(k for k in self.b.res if k[0] == "step3d")
        if not keys:
            return
        self.w("## 11. The 3D step (issue 24)", "",
               "The 3D dam break of section 9 (`scripts/bench/dambreak-3d.yaml`, 1 m across, closed tank) on "
               "1 rank, against its 2D slice (`scripts/bench/dambreak-3d-slice.yaml`: the same tank and column "
               "in x-y, scheme, kernel, h/dx = 1.33 and terms) at the dx that gives the slice as many fluid "
               "particles, run in turn within each repeat. Cost = step-loop time per fluid particle-step; the "
               "3D/2D ratio is of the medians. Pairs = neighbour pairs of the main pass per fluid particle and "
               "stage.", "",
               "| 3D dx [m] | 3D particles (fluid + wall) | 3D particle-steps/s per core | 3D B per particle (peak) "
               "| wall ghosts' share | 2D dx [m] | 2D particles | 2D particle-steps/s per core | pairs 3D / 2D "
               "| cost 3D / 2D |", "|---|---|---|---|---|---|---|---|---|---|")
        worst_share, worst_ratio = 0.0, 0.0
        for key in keys:
            dx, runs3, dx2, runs2 = self.b.res[key]
            r3, r2 = runs3[0], runs2[0]
            ps3, ps2 = col(runs3, "psps_core"), col(runs2, "psps_core")
            share = med([r["shares"].get(GHOST_PASS, 0.0) for r in runs3])
            ratio = med(ps2) / med(ps3)
            worst_share, worst_ratio = max(worst_share, share), max(worst_ratio, ratio)
            self.w("| %g | %d + %d | %s | %.0f | %.1f %% | %g | %d + %d | %s | %.1f / %.1f | %.2f |" % (
                dx, r3["fluid"], r3["wall"], mmm(ps3, "%.4g"), med(col(runs3, "bytes_per_particle_peak")),
                100 * share, dx2, r2["fluid"], r2["wall"], mmm(ps2, "%.4g"),
                med(col(runs3, "pairs_per_particle_step")), med(col(runs2, "pairs_per_particle_step")), ratio))
            for case, runs in (("3d", runs3), ("3d-slice", runs2)):
                self.row("step3d", case, runs[0]["fluid"], 1, runs[0]["steps"], "particle_steps_per_s_per_core",
                         col(runs, "psps_core"), "1/s")
                self.row("step3d", case, runs[0]["fluid"], 1, runs[0]["steps"], "bytes_per_particle_peak",
                         col(runs, "bytes_per_particle_peak"), "B")
                for name in runs[0]["shares"]:
                    self.row("step3d", case, runs[0]["fluid"], 1, runs[0]["steps"], "share " + name,
                             [r["shares"].get(name, 0.0) for r in runs], "fraction of loop")
        dx, runs3, dx2, runs2 = self.b.res[keys[-1]]
        names = list(runs3[0]["shares"])
        self.w("", "Share of the step loop per operation at the largest size (dx = %g m in 3D, %g m in 2D):" % (dx, dx2), "",
               "| operation | 3D | 2D slice |", "|---|---|---|")
        for n in names + [n for n in runs2[0]["shares"] if n not in names]:
            cells = ["%.1f %%" % (100 * med([r["shares"].get(n, 0.0) for r in runs])) for runs in (runs3, runs2)]
            self.w("| %s | %s |" % (n, " | ".join(cells)))
        self.w("", GHOST_REACH_TRIAL, "")
        self.targets.append(("wall-ghost pass (lists and interpolation) < 10 % of a 3D step (3D dam break, 1 rank, every size)",
                             "worst %.1f %%" % (100 * worst_share), worst_share < TARGET_GHOST_SHARE,
                             "%.1f points over" % (100 * (worst_share - TARGET_GHOST_SHARE))))
        self.targets.append(("3D cost per fluid particle-step <= 3x the 2D one at the same h/dx (3D dam break "
                             "against its 2D slice, equal fluid counts, 1 rank)", "worst %.2fx" % worst_ratio,
                             worst_ratio <= TARGET_3D_COST, "%.2fx over" % (worst_ratio / TARGET_3D_COST)))

    def target_table(self):
        lines = ["## Targets (issue 6 in 2D, double precision; issues 22 and 24 in 3D)", "", "| target | measured | verdict |", "|---|---|---|"]
        for name, value, ok, miss in self.targets:
            lines.append("| %s | %s | %s%s |" % (name, value, verdict(ok), "" if ok else " (" + miss + ")"))
        lines.append("")
        return lines

    def closing(self):
        runs = self.largest("2phase", 1) or self.largest("1phase", 1)
        shares = {n: med([r["shares"][n] for r in runs]) for n in runs[0]["shares"]}
        main = next((n for n in shares if n.startswith(self.main_pass)), None)
        s = shares.get(main, 0.0)
        k = TARGET_PEAK / self.main_frac if self.main_frac > 0 else 1.0
        gain = 1.0 / ((1 - s) + s / k) if k > 1 else 1.0
        top = sorted(shares.items(), key=lambda x: -x[1])[:3]
        name, share = top[0]
        halved = 1.0 / (1 - share / 2)
        self.w("## What bounds it, and the next step", "",
               "The largest shares of the two-phase step at the largest size on 1 rank: %s." %
               ", ".join("%s %.0f %%" % (n, 100 * v) for n, v in top), "",
               "The main pass runs at %.1f %% of the measured peak (target 25 %%, %s). What bounds it, "
               "from the source (no hardware counters on this machine, so this is reasoning, not a "
               "measurement): the separations, the support test and the kernel (its exp()) run in SIMD "
               "lanes over each mask word's 64 candidates (include/physics/pair_chunk.h), but the pair "
               "terms after them stay scalar: each pair gathers its neighbour's fields through the index "
               "list (v, rho, p, grad rho, du: up to 10 scattered loads per pair), branches on the pair "
               "relation (wall, other phase) and pays one division, and the sums are added in list order "
               "(so that the results do not depend on the vector width). The pass is latency and gather "
               "bound rather than bound by the multiply-add units." % (100 * self.main_frac, "met" if self.main_frac >= TARGET_PEAK else "missed"), "",
               GATHER_TRIAL, "")
        if k > 1:
            self.w("Bringing the main pass to the 25 %% target (%.2fx faster) would make the whole step "
                   "%.2fx faster at this size (Amdahl, with its measured %.0f %% share)." % (k, gain, 100 * s), "")
        self.w("Next step: halving the largest share (%s) would make the step %.2fx faster (Amdahl). The "
               "known ways: the neighbours' fields copied into contiguous per-cell blocks (a cell's "
               "particles share their candidates) so that the pair loop reads them with vector loads, "
               "the mask words as lane masks, instead of gathers (which the trial above shows gain "
               "nothing here); kernel values F_ij computed once per pair and kept with the neighbour list "
               "(the gradient and the rhs pass both evaluate the same exp() per pair; at 8 B per pair "
               "this costs memory the lists, now bit masks, no longer take); and the support test moved "
               "into the list build." % (name, halved), "")
        r1, r2 = self.largest("2phase", 1), self.largest("2phase", 2)
        key = next(k for k in r1[0] if k.startswith("pairs/s/core " + self.main_pass))
        rate = med(col(r2, key)) / med(col(r1, key))
        halo = med([x["shares"]["halo exchange and wait"] for x in r2])
        self.w("Parallel efficiency (two-phase, largest size): the main pass runs at %.2f of its 1-rank "
               "per-core rate on 2 ranks, while halo exchange and wait take %.1f %% of the 2-rank loop. "
               "The loss is therefore mostly the slower pass per core, which on this machine (load "
               "average in the header, two cores shared with other jobs) cannot be told apart from "
               "the other jobs' use of the second core; the measurement has to be repeated on an idle "
               "machine before the halo path is optimised. Overlapping halo messages with interior "
               "pairs could recover at most the %.1f %% halo share." % (rate, 100 * halo, 100 * halo), "")

    def cluster(self):
        """Weak scaling to 64 ranks in 3D, the memory estimate against the measured peaks, and the
        model of the parallel efficiency at cluster sizes."""
        runs = {k[1]: v for k, v in self.b.res.items() if k[0] == "cluster"}
        if not runs:
            return
        ranks_list = sorted(runs)
        self.w("## 9. Weak scaling to %d ranks (3D) and the memory model" % ranks_list[-1], "",
               "The 3D dam break of issue 22 (`scripts/bench/dambreak-3d.yaml`: tank 3.22 x 1 m, water "
               "column 1.228 m long and 0.55 m high, single phase) at dx = %g m, extruded across (z) so "
               "that each rank holds about %d particles (fluid and wall ghosts; at least 0.25 m across), "
               "%d steps with a re-partition every 2 steps, once per rank count. Above %d ranks the runs "
               "are **oversubscribed** on this machine's %d cores: their counts and memory hold, their "
               "times do not. The ranks talk over TCP (`OMPI_MCA_btl=self,tcp`), as ranks on separate "
               "nodes: Open MPI's shared-memory transport holds about 0.4 MB per process for every other "
               "rank on the same node, so with all ranks on this one machine the memory would grow with "
               "the rank count as it does not on a cluster with a fixed number of ranks per node (the "
               "estimates below are for one rank per node: `--ranks-per-node 1`). Per rank: the largest "
               "rank's project arrays and peak resident memory, the "
               "estimate of `mpsph check --ranks N` for the same run, the halo particles (mean over "
               "ranks, and the largest), the neighbouring ranks of the rank with the most, and per rank and step the "
               "messages and bytes the halo machinery sent (rebuild, the updates of the 4 RK stages, "
               "migration); the time of one re-partition (METIS on the top cells, redistribution, "
               "halo build)." % (self.cfg["cluster_dx"], self.cfg["cluster_per_rank"], self.cfg["cluster_steps"],
                                 self.m["cores"], self.m["cores"]), "",
               "| ranks | width m | particles | per rank | project arrays MB | peak MB | estimate MB (/ peak) "
               "| halo mean / max | neighbours | messages / step | KB / step | re-partition s |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|")
        for n in ranks_list:
            r = runs[n]
            total, steps = r["fluid"] + r["wall"], r["steps"]
            reps = r.get("repartitions", 0)
            self.w("| %d | %g | %d | %d | %.1f | %.1f | %.1f (%.2f) | %d / %d | %d | %.0f | %.0f | %s |" % (
                n, r["width"], total, total / n, r["project_max_rank"] / 1e6, r["rss_peak_max_rank"] / 1e6,
                r["estimate"] / 1e6, r["estimate"] / r["rss_peak_max_rank"], r["halo_particles"] / n,
                r["halo_particles_max"], r["halo_neighbours_max"], r["halo_messages"] / (n * steps),
                r["halo_bytes"] / (n * steps) / 1e3, "%.3f" % (r["repartition_s"] / reps) if reps else "-"))
            self.row("cluster", "3d", total, n, steps, "project_bytes_max_rank", [r["project_max_rank"]], "B")
            self.row("cluster", "3d", total, n, steps, "estimate_over_peak", [r["estimate"] / r["rss_peak_max_rank"]], "ratio")
        big = [n for n in ranks_list if n >= 8]
        if len(big) > 1:
            proj = [runs[n]["project_max_rank"] / ((runs[n]["fluid"] + runs[n]["wall"]) / n) for n in big]
            peak = [runs[n]["rss_peak_max_rank"] for n in big]
            other = [runs[n]["rss_peak_max_other"] for n in big]
            flat_p, flat_r, flat_o = max(proj) / min(proj) - 1, max(peak) / min(peak) - 1, max(other) / min(other) - 1
            worst = max([abs(runs[n]["estimate"] / runs[n]["rss_peak_max_rank"] - 1) for n in ranks_list] +
                        self.estimate_errors)
            self.w("", "From %d to %d ranks the largest rank's project arrays per particle it owns vary by %.1f %% "
                   "and its peak resident memory by %.1f %% (target: within 15 %% of flat); the peak of the "
                   "largest rank but rank 0 by %.1f %% (%s MB). Rank 0 also runs METIS on the graph of "
                   "the top cells holding particles, whose memory grows with their number, hence with the "
                   "rank count in a weak scaling. The estimate of "
                   "`check --ranks` is within %.1f %% of the measured peak in every run above and in the 2D "
                   "runs of section 4 (target 20 %%)."
                   % (big[0], big[-1], 100 * flat_p, 100 * flat_r, 100 * flat_o,
                      " / ".join("%.1f" % (o / 1e6) for o in other), 100 * worst), "")
            self.targets.append(("per-rank memory flat within 15 % from 8 to 64 ranks (3D weak scaling)",
                                 "%.1f %% (peak resident, rank 0 included; %.1f %% without it)"
                                 % (100 * flat_r, 100 * flat_o), flat_r <= 0.15,
                                 "%.1f %% over" % (100 * (flat_r - 0.15))))
            self.targets.append(("`check --ranks` memory estimate within 20 % of the measured peak "
                                 "(the 3D runs above and the 2D runs of section 4)",
                                 "%.1f %% at worst" % (100 * worst), worst <= 0.20,
                                 "%.1f %% over" % (100 * (worst - 0.20))))
        self.model(runs, ranks_list)

    def model(self, runs, ranks_list):
        """A model (labelled so) of the parallel efficiency at 10^3 and 10^4 ranks."""
        one, last = runs[ranks_list[0]], runs[ranks_list[-1]]
        fluid_s = sum(t for name, t in one["pass_s"].items() if not name.startswith("wall ghosts"))
        t_fluid = fluid_s / (one["fluid"] * one["steps"])
        per_halo = last["halo_bytes"] / last["steps"] / max(last["halo_particles"], 1)
        per_neighbour = last["halo_messages"] / (last["steps"] * ranks_list[-1]) / max(last["halo_neighbours_max"], 1)
        band = 4.6   # one cell layer, in particle spacings: cell edge 1.15 supports of 4 dx (Gaussian, h/dx 1.33)
        latency, bandwidth, reductions = 1.5e-6, 12e9, 10
        self.w("", "**A model, not a measurement** (the parallel efficiency at cluster sizes). Inputs measured "
               "here: the compute time of the passes but the wall ghosts' per fluid particle-step, "
               "%.3g us (%d-rank run); the halo bytes sent per halo particle and step, %.0f B, and "
               "the messages per neighbouring rank and step, %.1f (%d-rank run). Assumed: ranks hold "
               "cubes of n particles deep inside the fluid (no walls, 26 neighbouring ranks), a halo band "
               "of one cell layer (%.1f particle spacings: halo (n^(1/3) + 2 x %.1f)^3 - n), an InfiniBand "
               "network of %.1f us latency and %.0f GB/s per rank, %d global reductions per step as binary "
               "trees (2 log2 P latencies each), perfect load balance. Efficiency = compute / (compute + "
               "communication), without overlap (halo updates and reductions add to the step) and with "
               "the halo updates hidden behind the interior cells (only the reductions add)."
               % (1e6 * t_fluid, ranks_list[0], per_halo, per_neighbour, ranks_list[-1], band, band,
                  1e6 * latency, bandwidth / 1e9, reductions), "",
               "| ranks | particles per rank | compute ms / step | halo particles | halo ms / step | reductions ms / step | efficiency, no overlap | with overlap |",
               "|---|---|---|---|---|---|---|---|")
        for ranks in (1000, 10000):
            for n in (1e5, 1e6):
                comp = n * t_fluid
                halo = (n ** (1 / 3) + 2 * band) ** 3 - n
                t_halo = 26 * per_neighbour * latency + halo * per_halo / bandwidth
                t_red = reductions * 2 * math.log2(ranks) * latency
                self.w("| %d | %.0e | %.0f | %.0f | %.2f | %.3f | %.3f %% | %.4f %% |" % (
                    ranks, n, 1e3 * comp, halo, 1e3 * t_halo, 1e3 * t_red, 100 * comp / (comp + t_halo + t_red),
                    100 * comp / (comp + t_red)))
        frac = [((n ** (1 / 3) + 2 * band) ** 3 - n) / n for n in (1e5, 1e6)]
        self.w("", "The halo band makes the halo %.2f n at 10^5 particles per rank and %.2f n at 10^6. "
               "What the model leaves out: load imbalance (the re-partition's threshold, "
               "10 %% by default, bounds it), the wall ghosts' deeper halo, output (collective HDF5), "
               "network contention, and the re-partitions (their measured time above, every few hundred "
               "steps at most)." % tuple(frac), "")

    def peer(self):
        """Section 10: DualSPHysics against mpsph on the same dam break (bench_peer.py), or the
        note that it was skipped."""
        p = self.b.res.get("peer")
        self.w("## 10. Peer comparison: DualSPHysics on the same dam break (issue 23)", "")
        if not p:
            self.w("Skipped: no DualSPHysics binary was given. `make bench DUALSPHYSICS=/path/to/"
                   "DualSPHysics5.4CPU_linux64` runs it (`DUALSPHYSICS_SRC=` names the binary's source tree "
                   "if it is not three levels above the binary; README.md, `make bench`).", "")
            return
        d, prm = p["def"], p["parameters"]
        self.w("DualSPHysics' 2D dam break CaseDambreakVal2D (column %g x %g m in a tank %g x %g m, dp = %g m, "
               "%d fluid particles, coefsound %g: c0 = %.2f m/s) with the parameters of its source's "
               "`_Def.xml` (StepAlgorithm %s, Kernel %s, ViscoTreatment %s, Visco %s, DensityDT %s, "
               "DensityDTvalue %s, Shifting %s; cflnumber %g), binary `%s`; and mpsph's case of the same "
               "geometry, spacing and sound speed, `scripts/bench/dambreak-val2d.yaml` (delta-plus, "
               "shifting none, artificial viscosity 0.02, no acoustic damper), with three settings "
               "(`scripts/bench_peer.py` MPSPH_SETTINGS): the issue's (Gaussian kernel cut at 3h = 4 dx, "
               "CFL 1.0), the same at CFL 2 (half the steps), and Wendland C2 (support 2h = 2.66 dx, about "
               "half the pairs) at CFL 2; their validation errors are side by side in the dambreak-front "
               "and dambreak-impact studies of `doc/validation/README.md`. Each code runs "
               "%g s of flow on 1 and 2 cores (DualSPHysics `-ompthreads:N`, mpsph N ranks), writing "
               "only the initial and final state; %d interleaved rounds (per round and core count "
               "DualSPHysics, then mpsph with each setting), wall time of the whole process (start-up "
               "included) measured by the bench. Ratio = mpsph / DualSPHysics within each round; "
               "median [min-max]." % (
                   d["fluid"][0], d["fluid"][1], d["tank"][0], d["tank"][1], d["dp"], p["fluid"], d["coefsound"], p["c0"],
                   prm.get("StepAlgorithm"), prm.get("Kernel"), prm.get("ViscoTreatment"), prm.get("Visco"),
                   prm.get("DensityDT"), prm.get("DensityDTvalue"), prm.get("Shifting"), d["cfl"], p["binary"],
                   p["seconds"], p["rounds"]), "",
               "| cores | mpsph setting | DualSPHysics s | its steps | mpsph s | its steps (RK4) | mpsph / DualSPHysics time |",
               "|---|---|---|---|---|---|---|")
        for cores, t in sorted(p["times"].items()):
            dsph = [x[0] for x in t["dualsphysics"]]
            dsph_steps = med([x[1] for x in t["dualsphysics"]])
            for key, label in p["settings"]:
                ratio = [m[0] / q for m, q in zip(t[key], dsph)]
                steps = med([x[1] for x in t[key]])
                self.w("| %d core%s | %s | %s | %d | %s | %d | %s |" % (
                    cores, "s" if cores > 1 else "", label, mmm(dsph, "%.2f"), dsph_steps,
                    mmm([x[0] for x in t[key]], "%.2f"), steps, mmm(ratio, "%.3f")))
                for metric, values in (("mpsph_over_dualsphysics_time", ratio), ("dualsphysics_seconds", dsph),
                                       ("mpsph_seconds", [x[0] for x in t[key]])):
                    self.row("peer", peer_case(key), p["fluid"], cores, steps, metric, values,
                             "ratio" if metric.endswith("time") else "s")
        self.peer_fronts(p)

    def peer_fronts(self, p):
        """The fronts' errors of the peer comparison, over the timed window and the front window."""
        f = p["fronts"]
        self.w("", "Accuracy of the same settings: each code's surge front (largest x of a fluid particle "
               "with at least 2 fluid neighbours within 1.5 dp, from x = 0 at the left wall) every 0.01 s "
               "of one run of %g s of flow on 2 cores, against Martin & Moyce (1952, n^2 = 2, a = %g m: "
               "`%s`): RMS of (Z_SPH - Z_exp) / Z_exp over the experimental points, Z = x / a, T = t "
               "sqrt(2 g / a). The timed window (t <= %g s, T <= %.2f) holds the points up to it; the "
               "longer window ends at %g s (T = %.2f)%s. The time ratios above are at these errors." % (
                   f["seconds"], p["def"]["fluid"][0], "cases/dambreak-1phase/reference/"
                   "dambreak_surge_front_martin_moyce1952_table.csv", f["timed_s"], f["T_timed"], f["seconds"], f["T_end"],
                   ", past the last point before the front reaches the far wall" if f.get("to_far_wall")
                   else " (shortened: not the case's whole window)"), "",
               "| code | front error, t <= %g s | points | front error, t <= %g s | points |" % (f["timed_s"], f["seconds"]),
               "|---|---|---|---|---|")
        codes = [("dualsphysics", "DualSPHysics")] + [(key, "mpsph, " + label) for key, label in p["settings"]]
        for code, label in codes:
            e = f[code]
            self.w("| %s | %s | %s | %s | %s |" % (label, pct(e["timed"][0]), e["timed"][1], pct(e["window"][0]), e["window"][1]))
            for metric, err in (("front_error_timed_window_" + code, e["timed"][0]), ("front_error_window_" + code, e["window"][0])):
                if math.isfinite(err):
                    self.row("peer", peer_case(code), p["fluid"], 2, 0, metric, [err], "fraction")
        self.w("")

    def write(self, out):
        self.header()
        body_start = len(self.md)
        self.sizes()
        self.shares()
        self.flops()
        self.memory()
        self.scaling()
        self.hdf5()
        self.terms()
        self.single_phase()
        self.no_alloc()
        self.cluster()
        self.peer()
        self.step3d()
        self.closing()
        self.md[body_start:body_start] = self.target_table()
        with open(os.path.join(out, "performance.md.tmp"), "w") as f:
            f.write("\n".join(self.md) + "\n")
        os.replace(os.path.join(out, "performance.md.tmp"), os.path.join(out, "performance.md"))
        with open(os.path.join(out, "performance.csv.tmp"), "w", newline="") as f:
            wr = csv.writer(f)
            wr.writerow(["group", "case", "particles", "ranks", "steps", "metric", "median", "min", "max", "repeats", "unit"])
            wr.writerows(self.rows)
        os.replace(os.path.join(out, "performance.csv.tmp"), os.path.join(out, "performance.csv"))


def write(b, m, peaks, cfg, quick, out, flops, main_pass):
    """Write out/performance.md and out/performance.csv."""
    Report(b, m, peaks, cfg, quick, flops, main_pass).write(out)
