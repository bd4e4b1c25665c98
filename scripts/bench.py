#!/usr/bin/env python3
"""bench.py - the benchmark suite of issue 6 (`make bench`).

Runs the single- and two-phase dam breaks at three sizes on 1 and 2 ranks (repeated), weak
scaling 1 -> 2 -> 4 ranks, weak scaling of a 3D dam break to 64 ranks (oversubscribed: counts,
memory, and the memory estimate of `check --ranks`), the 3D dam break on 1 rank at three sizes
against its 2D slice (the 3D step of issue 24), the scene with each optional term switched
off, the single-phase scene
through the multiphase and the SINGLE_PHASE=1 builds, one core's multiply-add peak and the HDF5
snapshot bandwidth against a raw write, and, given a DualSPHysics binary, the peer comparison
of issue 23 (scripts/bench_peer.py); then writes doc/performance.md and doc/performance.csv
from the measured numbers only (nothing in the report is typed in by hand).

Usage: scripts/bench.py [--quick] [--repeats N] [--sizes N] [--out DIR] [--dualsphysics BIN [--dualsphysics-src DIR]]
  --quick    small sizes and few steps (a few minutes); writes to build/bench/ unless --out
  --sizes N  only the first N sizes of each scene (the smoke test uses 1)
  --dualsphysics BIN  run the peer comparison with this DualSPHysics CPU binary (without it the
             comparison is skipped); --dualsphysics-src: its source tree (default: three levels
             above BIN)
Needs build/mpsph, build/bench/peak_fma and build/bench/bench_hdf5 (make bench builds them)."""
import argparse
import csv
import os
import pickle
import shutil
import statistics
import subprocess
import sys
import time

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MPIRUN = os.path.join(ROOT, "scripts", "mpirun")
# The cluster group's transport: TCP between all ranks. Open MPI's shared-memory transport holds
# about 0.4 MB per rank for every other rank on the same node (measured: 2 to 64 ranks here), so
# with every rank on this one machine the per-rank memory would grow with the rank count, as it
# does not on a cluster with a fixed number of ranks per node; TCP connects only the ranks that
# exchange messages.
CLUSTER_ENV = dict(os.environ, OMPI_MCA_btl="self,tcp")
CASES = {"1phase": "cases/dambreak-1phase/case.yaml", "2phase": "cases/dambreak-2phase/case.yaml"}
CASE_FILES = dict(CASES, **{"3d": "scripts/bench/dambreak-3d.yaml",   # the cluster and step3d groups' scene
                            "3d-slice": "scripts/bench/dambreak-3d-slice.yaml"})   # its 2D slice (step3d)

# Floating-point operations per neighbour pair of the main pass (pass_fluid_rhs.c, fluid_sums),
# counted by hand from the source for a same-phase fluid pair in 2D (the most frequent kind):
# each +, -, *, / counts 1 (an FMA would count 2), loop-invariant products hoisted.
#   distance and u_ji.r_ji 12, kernel F (inline exp 21, scaling 2) and V_j 24, pressure
#   gradient 7, viscosity pi_ij 2 + 6, density diffusion psi_ij 6 + 5: 62 (single-phase scene,
#   no shifting); with the delta-u terms (consistent shifting) the interface coefficients 5,
#   du.gW sums 12 + 4 and the momentum delta-u term 14 add 35: 97 (two-phase scene).
# Wall and other-phase pairs skip terms and rejected candidates (r >= support, 12 flops) are not
# counted, so the flop rate derived from it is an estimate, not a hardware count.
FLOPS_PER_PAIR = {"1phase": 62, "2phase": 97}
MAIN_PASS = "fluid rhs"

FULL = {"dx": {"1phase": [0.0085, 0.00424, 0.00212], "2phase": [0.024, 0.012, 0.006]},
        "steps": [100, 40, 12], "weak_dx": [0.012, 0.0085, 0.006], "weak_steps": 20,
        "term_dx": 0.012, "term_steps": 20, "sp_dx": 0.00424, "sp_steps": 60,
        "hdf5_particles": [160000, 2000000], "repeats": 3, "peak_seconds": 2.0,
        "cluster_ranks": [1, 2, 4, 8, 16, 32, 64], "cluster_per_rank": 50000, "cluster_dx": 0.02,
        "cluster_steps": 4, "peer_seconds": 0.1, "peer_front_seconds": None,
        "step3d_dx": [0.04, 0.03, 0.02], "step3d_steps": [20, 12, 6]}
QUICK = {"dx": {"1phase": [0.02, 0.0142, 0.01], "2phase": [0.024, 0.017, 0.012]},
         "steps": [10, 8, 6], "weak_dx": [0.024, 0.017, 0.012], "weak_steps": 6,
         "term_dx": 0.04, "term_steps": 6, "sp_dx": 0.01, "sp_steps": 10,
         "hdf5_particles": [100000], "repeats": 2, "peak_seconds": 0.3,
         "cluster_ranks": [1, 2, 4], "cluster_per_rank": 10000, "cluster_dx": 0.04, "cluster_steps": 2,
         "peer_seconds": 0.01, "peer_front_seconds": 0.1, "step3d_dx": [0.08, 0.06], "step3d_steps": [4, 3]}

# The two-phase scene with every optional term on, and each term switched off in turn.
TERMS_ON = ["physics.acoustic_damper=10", "physics.free_surface=on", "physics.tensile_control=true",
            "physics.shifting=consistent", "domain.min=[-0.2,-0.2]", "domain.max=[3.416,2.0]"]
TERMS_OFF = [("all terms on", []),
             ("acoustic damper off", ["physics.acoustic_damper=0"]),
             ("free-surface detection off", ["physics.free_surface=off"]),
             ("tensile control off", ["physics.tensile_control=false"]),
             ("delta-u terms off (position shifting)", ["physics.shifting=position"]),
             ("shifting off", ["physics.shifting=none"]),
             ("density diffusion delta = 0", ["physics.delta=0"]),
             ("artificial viscosity = 0", ["physics.artificial_viscosity=0"])]


def sh(cmd, **kw):
    """Run cmd (list), return stdout; raise with its output on failure."""
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, **kw)
    if r.returncode:
        raise RuntimeError("command failed (%d): %s\n%s%s" % (r.returncode, " ".join(cmd), r.stdout[-3000:], r.stderr[-3000:]))
    return r.stdout


def read_timings(path):
    """OUTDIR/timings.csv (engine_report.c) as a list of row dicts."""
    with open(path) as f:
        return list(csv.DictReader(f))


def num(x):
    return float(x) if x not in ("", None) else 0.0


def run_case(exe, case, dx, steps, ranks, work, sets=(), env=None):
    """One run (with the environment env, default this one's); returns the derived figures of its
    timings.csv."""
    out = os.path.join(work, "run")
    shutil.rmtree(out, ignore_errors=True)
    cmd = [MPIRUN, "-n", str(ranks), exe, "run", CASE_FILES[case], "-o", out,
           "--set", "resolution.dx=%g" % dx, "--set", "time.max_steps=%d" % steps,
           "--set", "output.interval=0", "--set", "output.stats_interval=1e9",
           "--set", "output.probes_interval=1e9", "--set", "output.progress_interval=1e9"]
    for s in sets:
        cmd += ["--set", s]
    sh(cmd, env=env)
    return derive(read_timings(os.path.join(out, "timings.csv")), case)


def memory_estimate(case, ranks, sets, per_node=None):
    """The bytes per rank `mpsph check --ranks` estimates for the run (its '# memory' line), with
    per_node ranks on a node (default: check's)."""
    cmd = ["build/mpsph", "check", CASE_FILES[case], "--ranks", str(ranks)]
    if per_node:
        cmd += ["--ranks-per-node", str(per_node)]
    for x in sets:
        cmd += ["--set", x]
    for line in sh(cmd).splitlines():
        if line.startswith("# memory: about "):
            value, unit = line.split()[3:5]
            return float(value) * {"MB": 1e6, "GB": 1e9}[unit]
    raise RuntimeError("no memory line from " + " ".join(cmd))


def tank_sets(width):
    """The 3D scene extruded to `width` m across (z): tank, column and domain."""
    return ["fluids.0.box.max=[1.228,0.55,%g]" % width, "walls.0.box.max=[3.22,1.0,%g]" % width,
            "domain.max=[3.52,1.3,%g]" % (width + 0.3)]


def slice_fluid_area():
    """The water column's area of the 3D step's 2D slice, from its case file [m^2]: the slice's dx
    for a given fluid count."""
    with open(os.path.join(ROOT, CASE_FILES["3d-slice"])) as f:
        box = yaml.safe_load(f)["fluids"][0]["box"]
    return (box["max"][0] - box["min"][0]) * (box["max"][1] - box["min"][1])


def particles_of(case, dx, sets):
    """Fluid plus wall particles of a case (mpsph check)."""
    cmd = ["build/mpsph", "check", CASE_FILES[case], "--set", "resolution.dx=%g" % dx]
    for x in sets:
        cmd += ["--set", x]
    for line in sh(cmd).splitlines():
        if line.startswith("# particles: "):
            w = line.split()
            return int(w[2]) + int(w[w.index("wall") - 1])
    raise RuntimeError("no particle line from " + " ".join(cmd))


def derive(rows, case):
    """Per-run figures from the timings rows: rates per core, shares of the loop, memory."""
    by = {r["name"]: r for r in rows}
    ranks, steps = int(num(by["ranks"]["value"])), int(num(by["steps"]["value"]))
    fluid, wall = num(by["fluid_particles"]["value"]), num(by["wall_particles"]["value"])
    loop = num(by["loop"]["seconds_max"])
    t_steps = num(by["steps_without_final_output"]["seconds_max"])
    cpu = by.get("steps_without_final_output_cpu")
    d = {"steps_cpu": num(cpu["seconds_mean"]) if cpu else t_steps, "ranks": ranks, "steps": steps, "fluid": fluid, "wall": wall, "loop_s": loop, "steps_s": t_steps,
         "psps_core": fluid * steps / t_steps / ranks}
    shares, halo, by_pass = {}, 0.0, {}
    for r in rows:   # the operations of one pass (the text before ':', e.g. the wall ghosts' lists and interpolation) add up
        if r["kind"] == "pass":
            short = r["name"].split(":")[0].split(" (")[0]
            seconds, pairs = by_pass.get(short, (0.0, 0.0))
            by_pass[short] = (seconds + num(r["seconds_mean"]), pairs + num(r["pairs"]))
        elif r["kind"] == "halo":
            halo += num(r["seconds_mean"])
    for short, (seconds, pairs) in by_pass.items():
        shares[short] = seconds / loop
        if pairs:
            d["pairs/s/core " + short] = pairs / (seconds * ranks)
            if short.startswith(MAIN_PASS):
                d["pairs_per_particle_step"] = pairs / (fluid * steps * 4)
                if case in FLOPS_PER_PAIR:
                    d["main_flops_core"] = pairs * FLOPS_PER_PAIR[case] / (seconds * ranks)
    shares["halo exchange and wait"] = halo / loop
    shares["migration, sort, re-partition"] = num(by["migration"]["seconds_mean"]) / loop
    shares["operations dropped after step 1 (free surface auto: none found)"] = (
        num(by["dropped_operations"]["seconds_mean"]) / loop if "dropped_operations" in by else 0.0)
    shares["final output (snapshot + checkpoint)"] = (loop - t_steps) / loop
    shares["other (time step, RK update, checks)"] = 1.0 - sum(shares.values())
    d["shares"] = shares
    peaks = [num(r["value"]) for r in rows if r["name"].startswith("rss_peak_rank")]
    ends = [num(r["value"]) for r in rows if r["name"].startswith("rss_end_rank")]
    d["bytes_per_particle_peak"] = sum(peaks) / (fluid + wall)
    d["bytes_per_particle_end"] = sum(ends) / (fluid + wall)
    d["rss_peak_max_rank"] = max(peaks)
    d["rss_peak_max_other"] = max(peaks[1:] or peaks)   # the largest of the ranks but rank 0 (the partitioner)
    d["rss_end_sum"] = sum(ends)
    pss = [num(r["value"]) for r in rows if r["name"].startswith("pss_end_rank")]
    d["bytes_per_particle_pss"] = sum(pss) / (fluid + wall)
    files = [num(r["value"]) for r in rows if r["name"].startswith("rss_file_end_rank")]
    own = [num(r["value"]) for r in rows if r["name"].startswith("project_bytes_rank")]
    d["bytes_per_particle_file"] = sum(files) / (fluid + wall)
    d["bytes_per_particle_project"] = sum(own) / (fluid + wall)
    d["project_sum"] = sum(own)
    d["project_by_owner"] = {r["name"][len("bytes_"):]: num(r["value"]) / (fluid + wall)
                             for r in rows if r["name"].startswith("bytes_")}
    d["halo_particles"] = num(by["halo_particles"]["value"])
    for key in ("halo_particles_max", "halo_neighbours_max", "halo_messages", "halo_bytes"):
        d[key] = num(by[key]["value"]) if key in by else 0.0
    if "repartition" in by:
        d["repartitions"] = num(by["repartition"]["value"])
        d["repartition_s"] = num(by["repartition"]["seconds_max"])
    d["project_max_rank"] = max(own)
    d["pass_s"] = {r["name"]: num(r["seconds_mean"]) for r in rows if r["kind"] == "pass"}
    return d


def repeat(n, fn):
    """fn() n times; list of results."""
    return [fn() for _ in range(n)]


def stat(values):
    """(median, min, max) of a list."""
    return statistics.median(values), min(values), max(values)


def machine():
    """CPU model, cores, load average, commit, compiler."""
    model = "unknown"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    commit = sh(["git", "describe", "--always", "--dirty"]).strip()
    cc = sh(["mpicc", "--version"]).splitlines()[0]
    with open("build/cflags.txt") as f:   # the flags the Makefile built the binaries with
        flags = f.read().split()
    flags = " ".join(a for a in flags[1:] if a.startswith(("-O", "-m", "-f", "-g", "-D")))
    return {"cpu": model, "cores": os.cpu_count(), "load_start": os.getloadavg(), "commit": commit,
            "compiler": cc, "flags": flags, "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())}


class Bench:
    """Runs the benchmark groups and collects their results."""

    def __init__(self, cfg, repeats, n_sizes, work, log, peer=(None, None)):
        self.cfg, self.repeats, self.n_sizes, self.work, self.log = cfg, repeats, n_sizes, work, log
        self.peer_binary, self.peer_src = peer
        self.res = {}

    def say(self, msg):
        self.log.write(msg + "\n")
        self.log.flush()

    def peak(self):
        out = sh([os.path.join(ROOT, "build/bench/peak_fma"), str(self.cfg["peak_seconds"])])
        return float(out.split()[1])

    def sizes(self):
        """Strong-scaling runs: every case and size on 1 and 2 ranks."""
        cfg = self.cfg
        for case in CASES:
            for k, dx in enumerate(cfg["dx"][case][:self.n_sizes]):
                for ranks in (1, 2):
                    self.say("sizes: %s dx=%g ranks=%d" % (case, dx, ranks))
                    runs = repeat(self.repeats, lambda: run_case("build/mpsph", case, dx, cfg["steps"][k], ranks, self.work))
                    self.res[("size", case, k, ranks)] = runs
                    self.res[("estimate", case, k, ranks)] = memory_estimate(case, ranks, ["resolution.dx=%g" % dx])

    def weak(self):
        """Two-phase scene with about the same particles per rank on 1, 2 and 4 ranks."""
        for ranks, dx in zip((1, 2, 4), self.cfg["weak_dx"]):
            self.say("weak: ranks=%d dx=%g" % (ranks, dx))
            self.res[("weak", ranks)] = repeat(self.repeats, lambda: run_case(
                "build/mpsph", "2phase", dx, self.cfg["weak_steps"], ranks, self.work))

    def cluster(self):
        """Weak scaling to 64 ranks (oversubscribed): the 3D dam break extruded across (z) so that
        every rank holds about cluster_per_rank particles at a fixed dx (at least 0.25 m across),
        with a re-partition every 2 steps that balances particle work alone (parallel.balance=work: the
        measured timings of oversubscribed ranks would make the partition, hence the memory of the
        largest rank, differ from run to run); once each (its counts do not depend on the load), with
        the memory `check --ranks` estimates. Over TCP (CLUSTER_ENV): the ranks stand for ranks on
        separate nodes, as a weak scaling on a cluster has a fixed number of ranks per node."""
        cfg, dx = self.cfg, self.cfg["cluster_dx"]
        n1, n2 = particles_of("3d", dx, tank_sets(1.0)), particles_of("3d", dx, tank_sets(2.0))
        for ranks in cfg["cluster_ranks"]:
            width = max(0.25, round(1.0 + (ranks * cfg["cluster_per_rank"] - n1) / (n2 - n1), 3))
            sets = tank_sets(width) + ["parallel.repartition_every=2", "parallel.balance=work"]
            self.say("cluster: ranks=%d width=%g m" % (ranks, width))
            run = run_case("build/mpsph", "3d", dx, cfg["cluster_steps"], ranks, self.work, sets, CLUSTER_ENV)
            run["width"] = width
            run["estimate"] = memory_estimate("3d", ranks, sets + ["resolution.dx=%g" % dx], per_node=1)
            self.res[("cluster", ranks)] = run

    def step3d(self):
        """The 3D step (issue 24): the 3D dam break at each step3d_dx on 1 rank, each against its 2D
        slice (same scheme, kernel, h/dx and terms) with as many fluid particles and 3 times the
        steps, the two in turn within each repeat so that a change of the load hits both alike."""
        cfg = self.cfg
        for k, dx in enumerate(cfg["step3d_dx"][:self.n_sizes]):
            runs3, runs2, dx2 = [], [], None
            for rep in range(self.repeats):
                self.say("step3d: dx=%g (repeat %d)" % (dx, rep + 1))
                runs3.append(run_case("build/mpsph", "3d", dx, cfg["step3d_steps"][k], 1, self.work))
                dx2 = dx2 or round((slice_fluid_area() / runs3[0]["fluid"]) ** 0.5, 6)
                runs2.append(run_case("build/mpsph", "3d-slice", dx2, 3 * cfg["step3d_steps"][k], 1, self.work))
            self.res[("step3d", k)] = (dx, runs3, dx2, runs2)

    def terms(self):
        """The two-phase scene with every term on, then each switched off (1 rank); the variants
        in turn within each repeat, so that a change of the machine's load hits all alike."""
        for label, _ in TERMS_OFF:
            self.res[("term", label)] = []
        for rep in range(self.repeats):
            for label, sets in TERMS_OFF:
                self.say("terms: %s (repeat %d)" % (label, rep + 1))
                self.res[("term", label)].append(run_case(
                    "build/mpsph", "2phase", self.cfg["term_dx"], self.cfg["term_steps"], 1, self.work,
                    TERMS_ON + sets))

    def single_phase(self):
        """Single-phase scene through the multiphase build and the SINGLE_PHASE=1 build,
        interleaved so that load changes hit both alike."""
        sp = os.path.join(ROOT, "build/bench/mpsph-single-phase")
        a, b = [], []
        for _ in range(self.repeats + 1):
            self.say("single-phase variant")
            a.append(run_case("build/mpsph", "1phase", self.cfg["sp_dx"], self.cfg["sp_steps"], 1, self.work))
            b.append(run_case(sp, "1phase", self.cfg["sp_dx"], self.cfg["sp_steps"], 1, self.work))
        self.res["sp"] = (a, b)

    def hdf5(self):
        """Snapshot write through io_hdf5 vs raw write of the same bytes, 1 and 2 ranks."""
        tool = os.path.join(ROOT, "build/bench/bench_hdf5")
        for n in self.cfg["hdf5_particles"]:
            for ranks in (1, 2):
                self.say("hdf5: n=%d ranks=%d" % (n, ranks))
                out = sh([MPIRUN, "-n", str(ranks), tool, self.work, str(n), str(self.repeats + 2)])
                t = {"hdf5": [], "raw": []}
                nbytes = 0
                for line in out.splitlines():
                    kind, b, s = line.split()
                    nbytes = int(b)
                    t[kind].append(float(s))
                # the first pair warms the file system up; it is dropped
                self.res[("hdf5", n, ranks)] = (nbytes, t["hdf5"][1:], t["raw"][1:])

    def peer(self):
        """DualSPHysics against mpsph on the same dam break (scripts/bench_peer.py): the repeats
        as interleaved rounds of peer_seconds of flow on 1 and 2 cores, then both fronts against
        Martin & Moyce over peer_front_seconds (None: the case's window). Skipped, with a message
        in the log and the report, without a binary."""
        if not self.peer_binary:
            self.say("peer: skipped (no DualSPHysics binary: make bench DUALSPHYSICS=...)")
            self.res["peer"] = None
            return
        import bench_peer
        self.res["peer"] = bench_peer.measure(self.peer_binary, self.peer_src, self.work, self.repeats,
                                              self.cfg["peer_seconds"], self.cfg["peer_front_seconds"], self.say)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeats", type=int)
    ap.add_argument("--sizes", type=int, default=3)
    ap.add_argument("--out")
    ap.add_argument("--dualsphysics", help="DualSPHysics CPU binary for the peer comparison")
    ap.add_argument("--dualsphysics-src", help="its source tree (default: three levels above the binary)")
    ap.add_argument("--only", help="comma-separated groups (sizes,weak,terms,single_phase,hdf5,cluster,step3d,peer) to run "
                    "again into the results saved by the last run; the report names them")
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the report from the results saved by the last run into the same --out "
                    "(build/bench/work/results_<out>.pickle)")
    a = ap.parse_args()
    cfg = QUICK if a.quick else FULL
    out = a.out or os.path.join(ROOT, "build/bench" if a.quick else "doc")
    os.makedirs(out, exist_ok=True)
    work = os.path.join(ROOT, "build/bench/work")
    os.makedirs(work, exist_ok=True)
    saved = os.path.join(work, "results_%s.pickle" % os.path.abspath(out).strip("/").replace("/", "_"))
    if a.report_only:
        with open(saved, "rb") as f:
            b, m, peaks, cfg, quick = pickle.load(f)
        report(b, m, peaks, cfg, quick, out)
        return
    if a.only:
        rerun(a, saved, out)
        return
    sh(["make", "--no-print-directory", "build/mpsph", "build/bench/peak_fma", "build/bench/bench_hdf5",
        "build/bench/mpsph-single-phase"])
    t0 = time.time()
    m = machine()
    b = Bench(cfg, a.repeats or cfg["repeats"], a.sizes, work, sys.stdout, (a.dualsphysics, a.dualsphysics_src))
    peaks = [b.peak()]
    b.sizes()
    b.weak()
    b.terms()
    b.single_phase()
    b.hdf5()
    b.cluster()
    b.step3d()
    b.peer()
    peaks.append(b.peak())
    m["load_end"] = os.getloadavg()
    m["seconds"] = time.time() - t0
    b.log = None
    with open(saved, "wb") as f:
        pickle.dump((b, m, peaks, cfg, a.quick), f)
    report(b, m, peaks, cfg, a.quick, out)


def rerun(a, saved, out):
    """Run the groups named by --only again into the saved results, then rewrite the report."""
    with open(saved, "rb") as f:
        b, m, peaks, cfg, quick = pickle.load(f)
    cfg = b.cfg = dict(QUICK if quick else FULL, **cfg)   # with the settings of groups added since
    sh(["make", "--no-print-directory", "build/mpsph", "build/bench/peak_fma", "build/bench/bench_hdf5",
        "build/bench/mpsph-single-phase"])
    b.log = sys.stdout
    b.peer_binary, b.peer_src = a.dualsphysics, a.dualsphysics_src
    t0, info = time.time(), machine()
    remeasure_peak = "sizes" in a.only.split(",")   # section 3 sets the sizes' main pass against it
    if remeasure_peak:
        peaks = [b.peak()]
    for group in a.only.split(","):
        getattr(b, group)()
    if remeasure_peak:
        peaks.append(b.peak())
    info["load_end"] = os.getloadavg()
    info["seconds"] = time.time() - t0
    info["groups"] = a.only
    m.setdefault("reruns", []).append(info)
    b.log = None
    with open(saved, "wb") as f:
        pickle.dump((b, m, peaks, cfg, quick), f)
    report(b, m, peaks, cfg, quick, out)


def report(b, m, peaks, cfg, quick, out):
    """Write out/performance.md and out/performance.csv."""
    import bench_report
    bench_report.write(b, m, peaks, cfg, quick, out, FLOPS_PER_PAIR, MAIN_PASS)
    print("wrote %s/performance.md and performance.csv (suite run time %.0f s)" % (out, m["seconds"]))


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
