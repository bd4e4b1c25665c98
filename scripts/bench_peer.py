"""bench_peer.py - the peer comparison of `make bench` (issue 23): DualSPHysics' 2D dam break
CaseDambreakVal2D against mpsph's case of the same geometry, spacing and sound speed
(scripts/bench/dambreak-val2d.yaml), timed on 1 and 2 cores (DualSPHysics OpenMP threads, mpsph
ranks) in interleaved rounds, and the surge front of both codes against Martin & Moyce (1952).

The user provides the DualSPHysics CPU binary (make bench DUALSPHYSICS=...) and its source tree
(DUALSPHYSICS_SRC=..., by default the folder three levels above the binary, where the source's
own makefile puts it: SRC/bin/linux/DualSPHysics5.4CPU_linux64). DualSPHysics' case generator
GenCase is a closed binary; in its place scripts/bench/peer_case_bi4.cpp, compiled here against
the user's source tree into build/peer/, writes the case's particle file, and this module its XML
(the constants and particle counts GenCase would add, and the <parameters> of the source's
CaseDambreakVal2D_Def.xml; its gauges are left out). Nothing of DualSPHysics is kept in this
repository."""
import math
import os
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts", "validation"))
import metrics  # noqa: E402  (front_position, front_error, snapshots)

MPIRUN = os.path.join(ROOT, "scripts", "mpirun")
CASE = "scripts/bench/dambreak-val2d.yaml"
DEF_XML = "examples/main/01_DamBreak/CaseDambreakVal2D_Def.xml"
NAME = "CaseDambreakVal2D"
# The user's DualSPHysics sources the particle-file writer links (its bi4 writer and what it uses).
WRITER_SOURCES = ("JPartDataBi4", "JBinaryData", "Functions", "JObject", "JException")
REFERENCE = "cases/dambreak-1phase/reference/dambreak_surge_front_martin_moyce1952_table.csv"
SAMPLE_S = 0.01   # time between the front samples of the accuracy runs [s]
FRONT_CORES = 2   # the accuracy runs of both codes use the 2 cores
# mpsph's settings timed against DualSPHysics: (key, what the report calls them, --set overrides
# of CASE). The issue's settings as the case has them, and the same scheme with less work per
# simulated second: CFL 2 (half the steps), and with Wendland C2 (support 2.66 dx: about half the
# pairs) besides. Their validation errors are in the dambreak-front and dambreak-impact studies of
# doc/validation/README.md.
MPSPH_SETTINGS = (("mpsph", "Gaussian (cut at 4 dx), CFL 1", ()),
                  ("mpsph_cfl2", "Gaussian (cut at 4 dx), CFL 2", ("time.cfl=2",)),
                  ("mpsph_wendland_cfl2", "Wendland C2 (support 2.66 dx), CFL 2", ("kernel=wendland-c2", "time.cfl=2")))


def sh(cmd, cwd=ROOT):
    """Run cmd (list); return stdout; raise with its output on failure."""
    r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if r.returncode:
        raise RuntimeError("command failed (%d): %s\n%s%s" % (r.returncode, " ".join(cmd), r.stdout[-3000:], r.stderr[-3000:]))
    return r.stdout


def source_root(binary, src):
    """The DualSPHysics source tree: src, or the folder three levels above the binary."""
    root = src or os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(binary))))
    if not os.path.isfile(os.path.join(root, "src", "source", "JPartDataBi4.cpp")):
        raise RuntimeError("%s is not a DualSPHysics source tree (no src/source/JPartDataBi4.cpp): "
                           "give it as DUALSPHYSICS_SRC=" % root)
    return root


def build_writer(src_root, build_dir):
    """Compile scripts/bench/peer_case_bi4.cpp against the source tree (once); its path."""
    os.makedirs(build_dir, exist_ok=True)
    inc = os.path.join(src_root, "src", "source")
    objects = []
    for name in WRITER_SOURCES:
        obj = os.path.join(build_dir, name + ".o")
        if not os.path.isfile(obj):
            sh(["g++", "-c", "-O1", "-std=c++11", "-I" + inc, os.path.join(inc, name + ".cpp"), "-o", obj])
        objects.append(obj)
    exe = os.path.join(build_dir, "peer_case_bi4")
    sh(["g++", "-O1", "-std=c++11", "-Wall", "-I" + inc, os.path.join(ROOT, "scripts/bench/peer_case_bi4.cpp")]
       + objects + ["-o", exe])
    return exe


def box_size(drawbox):
    """(x, z) size [m] of a <drawbox> of the case definition."""
    size = drawbox.find("size")
    return float(size.get("x")), float(size.get("z"))


def read_definition(path):
    """The case definition (_Def.xml): spacing, the column's and the tank's size (the drawbox
    after setmkfluid and after setmkbound), the constants and the <execution> parameters."""
    root = ET.parse(path).getroot()
    c = root.find("casedef/constantsdef")
    value = {e.tag: float(e.get("value")) for e in c if e.get("value") not in (None, "")}
    boxes, kind = {}, None
    for e in root.find("casedef/geometry/commands/mainlist"):
        kind = {"setmkfluid": "fluid", "setmkbound": "tank"}.get(e.tag, kind)
        if e.tag == "drawbox":
            boxes[kind] = box_size(e)
    g = c.find("gravity")
    return {"dp": float(root.find("casedef/geometry/definition").get("dp")), "fluid": boxes["fluid"],
            "tank": boxes["tank"], "g": math.sqrt(sum(float(g.get(k)) ** 2 for k in "xyz")),
            "gravity": [g.get(k) for k in "xyz"], "rho0": value["rhop0"], "gamma": value["gamma"],
            "coefsound": value["coefsound"], "coefh": value["coefh"], "cfl": value["cflnumber"],
            "fluidcount": int(root.find("casedef/mkconfig").get("fluidcount")),
            "parameters": root.find("execution/parameters")}


def derived_constants(d):
    """What GenCase derives: still-water level (the top fluid node), sound speed coefsound
    sqrt(g hswl), Tait's b = c^2 rho0 / gamma, h = coefh sqrt(2) dp (2D), particle mass."""
    hswl = math.floor(d["fluid"][1] / d["dp"] + 1e-6) * d["dp"]
    c0 = d["coefsound"] * math.sqrt(d["g"] * hswl)
    return {"c0": c0, "b": c0 * c0 * d["rho0"] / d["gamma"], "h": d["coefh"] * math.sqrt(2.0) * d["dp"],
            "mass": d["rho0"] * d["dp"] ** 2}


def case_xml(d, k, nb, nf):
    """The case's XML: constants and particle blocks as GenCase writes them, and the parameters
    of the definition."""
    case = ET.Element("case", app="mpsph scripts/bench_peer.py")
    exe = ET.SubElement(case, "execution")
    ctes = ET.SubElement(exe, "constants")
    ET.SubElement(ctes, "data2d", value="true")
    ET.SubElement(ctes, "data2dposy", value="0")
    ET.SubElement(ctes, "gravity", x=d["gravity"][0], y=d["gravity"][1], z=d["gravity"][2])
    for tag, v in (("cflnumber", d["cfl"]), ("gamma", d["gamma"]), ("rhop0", d["rho0"]), ("dp", d["dp"]),
                   ("h", k["h"]), ("b", k["b"]), ("massbound", k["mass"]), ("massfluid", k["mass"])):
        ET.SubElement(ctes, tag, value=repr(v))
    parts = ET.SubElement(exe, "particles", np=str(nb + nf), nb=str(nb), nbf=str(nb),
                          mkboundfirst=str(d["fluidcount"] + 1), mkfluidfirst="1")
    ET.SubElement(parts, "fixed", mkbound="0", mk=str(d["fluidcount"] + 1), begin="0", count=str(nb))
    ET.SubElement(parts, "fluid", mkfluid="0", mk="1", begin=str(nb), count=str(nf))
    exe.append(d["parameters"])
    return ET.ElementTree(case)


def check_same_case(d, k):
    """Stop unless mpsph's case has the definition's spacing, column, tank and sound speed."""
    with open(os.path.join(ROOT, CASE)) as f:
        c = yaml.safe_load(f)
    ours = [c["resolution"]["dx"]] + c["fluids"][0]["box"]["max"] + c["walls"][0]["box"]["max"] + [c["phases"][0]["c0"]]
    theirs = [d["dp"], *d["fluid"], *d["tank"], k["c0"]]
    if any(abs(float(x) - y) > 1e-4 * abs(y) for x, y in zip(ours, theirs)):
        raise RuntimeError("%s: dx, column, tank and c0 %s differ from DualSPHysics' %s" % (CASE, ours, theirs))


def prepare_case(binary, src, work):
    """Write the DualSPHysics case into work/case/; (case path without extension, definition,
    derived constants, fluid particles)."""
    root = source_root(binary, src)
    d = read_definition(os.path.join(root, DEF_XML))
    k = derived_constants(d)
    check_same_case(d, k)
    writer = build_writer(root, os.path.join(ROOT, "build", "peer"))
    folder = os.path.join(work, "case")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    args = [d["dp"], d["fluid"][0], d["fluid"][1], d["tank"][0], d["tank"][1], d["rho0"], d["gamma"],
            k["b"], k["h"], k["mass"], d["g"]]
    nb, nf = (int(x) for x in sh([writer, folder, NAME] + [repr(a) for a in args]).split()[1:3])
    case_xml(d, k, nb, nf).write(os.path.join(folder, NAME + ".xml"), encoding="UTF-8", xml_declaration=True)
    return os.path.join(folder, NAME), d, k, nf


def run_dsph(binary, case, out, threads, seconds, sample_s=None):
    """One DualSPHysics run of `seconds` of flow; (wall time [s], steps). With sample_s, the
    particles as CSV every sample_s (data/PartCsv_*.csv), else only the initial and final state."""
    shutil.rmtree(out, ignore_errors=True)
    cmd = [os.path.abspath(binary), case, out, "-cpu", "-ompthreads:%d" % threads, "-tmax:%g" % seconds,
           "-tout:%g" % (sample_s or seconds), "-sv:binx" + (",csv" if sample_s else "")]
    t0 = time.perf_counter()
    log = sh(cmd, cwd=os.path.dirname(out))
    wall = time.perf_counter() - t0
    return wall, dsph_steps(log)


def dsph_steps(log):
    """The step count of DualSPHysics' log ('Steps of simulation....: N')."""
    line = next(l for l in log.splitlines() if l.startswith("Steps of simulation"))
    return int(line.split(":")[1].replace(",", "").split()[0])


def run_mpsph(ranks, seconds, out, sample_s=None, sets=()):
    """One mpsph run of `seconds` of flow with the --set overrides `sets`; (wall time [s], steps).
    With sample_s, a snapshot every sample_s, else only the initial and final ones."""
    shutil.rmtree(out, ignore_errors=True)
    cmd = [MPIRUN, "-n", str(ranks), "build/mpsph", "run", CASE, "-o", out] + [a for kv in sets for a in ("--set", kv)] + [
           "--set", "time.end=%g" % seconds,
           "--set", "output.interval=%g" % (sample_s or 0), "--set", "output.stats_interval=1e9",
           "--set", "output.probes_interval=1e9", "--set", "output.progress_interval=1e9"]
    t0 = time.perf_counter()
    sh(cmd)
    wall = time.perf_counter() - t0
    with open(os.path.join(out, "timings.csv")) as f:
        steps = next(int(float(l.split(",")[2])) for l in f if l.startswith("steps,"))
    return wall, steps


def dsph_particles(path):
    """Fluid positions (x, z) of a DualSPHysics PartCsv file (Type 3 = fluid)."""
    with open(path) as f:
        lines = f.read().splitlines()
    head = next(i for i, l in enumerate(lines) if l.startswith("Pos.x"))
    names = [n.split(" ")[0] for n in lines[head].rstrip(";").split(";")]
    ix, iz, it = names.index("Pos.x"), names.index("Pos.z"), names.index("Type")
    rows = [l.split(";") for l in lines[head + 1:] if l.strip()]
    return [(float(r[ix]), float(r[iz])) for r in rows if r[it].strip() == "3"]


def dsph_front(out, dx, a, g):
    """(T, Z) series of DualSPHysics' front, the k-th CSV part at k SAMPLE_S (DualSPHysics writes
    it at the first step past that time: later by less than one step, about 3e-5 s here)."""
    import numpy as np
    parts = sorted(f for f in os.listdir(os.path.join(out, "data")) if f.startswith("PartCsv_"))
    ts, zs = [], []
    for name in parts:
        k = int(name[len("PartCsv_"):-len(".csv")])
        x = np.array(dsph_particles(os.path.join(out, "data", name)))
        ts.append(k * SAMPLE_S * math.sqrt(2 * g / a))
        zs.append(metrics.front_position({"position": x, "phase": np.zeros(len(x))}, dx) / a)
    return ts, zs


def mpsph_front(out, dx, a, g):
    """(T, Z) series of mpsph's front from its snapshots."""
    ts, zs = [], []
    for path in metrics.snapshots(out):
        t, s = metrics.read_snapshot(path)
        ts.append(t * math.sqrt(2 * g / a))
        zs.append(metrics.front_position(s, dx) / a)
    return ts, zs


def front_window_s(d, g):
    """Flow time [s] to the last Martin & Moyce point before the front reaches the far wall
    (Z < tank width / a), rounded up to a sample."""
    ref = metrics.read_reference(os.path.join(ROOT, REFERENCE))
    inside = [float(t) for t, z in zip(ref["T_t_sqrt_2g_over_a"], ref["Z_x_over_a"]) if float(z) < d["tank"][0] / d["fluid"][0]]
    return math.ceil(max(inside) / math.sqrt(2 * g / d["fluid"][0]) / SAMPLE_S - 1e-9) * SAMPLE_S


def fronts(binary, case, d, work, seconds, timed_s):
    """The front errors of DualSPHysics and of each of mpsph's settings against Martin & Moyce over
    `seconds` of flow and over the timed window, from one run each on FRONT_CORES cores."""
    a, g, dx = d["fluid"][0], d["g"], d["dp"]
    ref = os.path.join(ROOT, REFERENCE)
    out = {"seconds": seconds, "timed_s": timed_s, "T_end": seconds * math.sqrt(2 * g / a),
           "T_timed": timed_s * math.sqrt(2 * g / a)}
    runs = [("dualsphysics", lambda o: run_dsph(binary, case, o, FRONT_CORES, seconds, SAMPLE_S), dsph_front)]
    runs += [(key, lambda o, sets=sets: run_mpsph(FRONT_CORES, seconds, o, SAMPLE_S, sets), mpsph_front)
             for key, _, sets in MPSPH_SETTINGS]
    for code, run, series in runs:
        folder = os.path.join(work, "front_" + code)
        run(folder)
        ts, zs = series(folder, dx, a, g)
        out[code] = {"series": (ts, zs),
                     "window": metrics.front_error(ts, zs, ref)[:2],
                     "timed": metrics.front_error(ts, zs, ref, t_last=out["T_timed"])[:2]}
    return out


def measure(binary, src, work, rounds, seconds, front_seconds, say):
    """The comparison: `rounds` interleaved rounds (per core count: DualSPHysics, then mpsph with
    each of MPSPH_SETTINGS) of
    `seconds` of flow on 1 and 2 cores, then the fronts over front_seconds (None: the case's
    window, front_window_s). A dict of the results."""
    case, d, k, nf = prepare_case(binary, src, work)
    res = {"binary": os.path.abspath(binary), "fluid": nf, "c0": k["c0"], "seconds": seconds, "rounds": rounds,
           "times": {}, "settings": [(key, label) for key, label, _ in MPSPH_SETTINGS], "def": {key: d[key] for key in ("dp", "fluid", "tank", "cfl", "coefsound")},
           "parameters": {e.get("key"): e.get("value") for e in d["parameters"] if e.tag == "parameter"}}
    for cores in (1, 2):
        res["times"][cores] = {code: [] for code in ["dualsphysics"] + [key for key, _, _ in MPSPH_SETTINGS]}
    for r in range(rounds):
        for cores in (1, 2):
            say("peer: round %d, %d cores: DualSPHysics, then mpsph with each setting" % (r + 1, cores))
            res["times"][cores]["dualsphysics"].append(run_dsph(binary, case, os.path.join(work, "peer_dsph"), cores, seconds))
            for key, _, sets in MPSPH_SETTINGS:
                res["times"][cores][key].append(run_mpsph(cores, seconds, os.path.join(work, "peer_mpsph"), sets=sets))
    window = front_seconds or front_window_s(d, d["g"])
    say("peer: fronts over %g s of flow on %d cores" % (window, FRONT_CORES))
    res["fronts"] = fronts(binary, case, d, work, window, seconds)
    res["fronts"]["to_far_wall"] = front_seconds is None
    return res
