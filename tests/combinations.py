#!/usr/bin/python3
"""The combination design of tests/combinations.sh: pairwise (all-pairs) covers of the solver's
options, one combination a line.

Factors: scheme, dimension, kernel, h/dx, walls (none, fixed, moving, obstacle), free-surface
detection, surface tension, shifting, the interface options (interface_pressure,
interface_viscosity, interface_mode, interface_sharpness), the scheme-specific model switches
(spc_model, dissipation_form), the number of ranks and re-partitioning every step. Every run
also evaluates every kind of probe and writes stats and probes rows at every step. The word
levels are read from the loader's tables in src/case/case_load.c (the schemes from SCHEME_LIST in
include/case/case.h), so a new scheme, kernel or option
word enters the design by itself.

Every pair of levels that some accepted combination holds is held by an accepted combination
(the cross-key refusals of doc/user-guide.md section 7 are the constraints) in each of COVERS
independent greedy covers (AETG-style, seeds seed, seed + 1, ...), so at least COVERS times in
different company; REFUSED adds a few combinations that must be refused with status 1.

Output: one line per combination, tab-separated: label, ranks, case file, expected outcome
("run" or "refused"), then the --set overrides.
Usage: combinations.py [--seed N]   (another design of the same strength)
"""
import itertools
import os
import random
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
H_OVER_DX = ["1.0", "1.2", "1.33", "1.5", "2.0"]
WALLS = ["none", "fixed", "moving", "obstacle"]
SURFACE_TENSION = ["0", "0.07"]
SHARPNESS = ["0", "0.08"]
RANKS = ["1", "2"]
REPARTITION_EVERY = ["0", "1"]   # parallel.repartition_every: on imbalance only, every step
MAX_STEPS = 3
SEED = 20
CANDIDATES = 30   # greedy candidates tried for each combination (AETG)
COVERS = 3        # independent pairwise covers (seeds seed, seed + 1, ...): every pair 3 times


def loader_words(source, table):
    """The words of the NULL-terminated string table `table` in the loader's source."""
    m = re.search(r"\b%s\[\]\s*=\s*\{(.*?)NULL\s*\}" % table, source, re.S)
    if not m:
        sys.exit("combinations.py: table %s not found in src/case/case_load.c" % table)
    return re.findall(r'"([^"]*)"', m.group(1))


def scheme_words():
    """The spellings of the schemes: the lines X(SCHEME_..., "word") of SCHEME_LIST in
    include/case/case.h (the loader's SCHEME_NAMES is made from it)."""
    with open(os.path.join(ROOT, "include", "case", "case.h")) as f:
        words = re.findall(r'X\(SCHEME_\w+, "([^"]*)"\)', f.read())
    if not words:
        sys.exit("combinations.py: SCHEME_LIST not found in include/case/case.h")
    return words


def loader_range(source, rule):
    """The integers lo..hi of the loader's integer rule `rule` ({"...", lo, open, hi, 1})."""
    m = re.search(r"\b%s\s*=\s*\{\"[^\"]*\",\s*(\d+),\s*0,\s*(\d+),\s*1\}" % rule, source)
    if not m:
        sys.exit("combinations.py: rule %s not found in src/case/case_load.c" % rule)
    return [str(k) for k in range(int(m.group(1)), int(m.group(2)) + 1)]


def factors():
    """The factors and their levels, words read from src/case/case_load.c."""
    with open(os.path.join(ROOT, "src", "case", "case_load.c")) as f:
        src = f.read()
    return [
        ("scheme", scheme_words()),
        ("dimension", ["2", "3"]),
        ("kernel", loader_words(src, "KERNEL_NAMES")),
        ("h_over_dx", H_OVER_DX),
        ("walls", WALLS),
        ("free_surface", loader_words(src, "FREE_SURFACE_NAMES")),
        ("surface_tension", SURFACE_TENSION),
        ("shifting", loader_words(src, "SHIFTING_NAMES")),
        ("interface_pressure", loader_words(src, "IFACE_P_NAMES")),
        ("interface_viscosity", loader_words(src, "IFACE_VISC_NAMES")),
        ("interface_mode", loader_range(src, "R_MODE")),
        ("interface_sharpness", SHARPNESS),
        # the scheme's own model switch: its default, or the non-default word of each
        ("model", ["default", "spc_model=" + loader_words(src, "SPC_MODEL_NAMES")[1],
                   "dissipation_form=" + loader_words(src, "DISSIPATION_NAMES")[1]]),
        ("ranks", RANKS),
        ("repartition_every", REPARTITION_EVERY),
    ]


# What each scheme refuses (doc/user-guide.md section 7): factor -> the levels it accepts.
SCHEME_LIMITS = {
    "riemann": {"walls": {"none", "fixed", "obstacle"}, "interface_viscosity": {"harmonic"},
                "model": {"default"}},
    "same-phase-continuity": {"shifting": {"none"}, "interface_sharpness": {"0"},
                              "interface_pressure": {"sum"}, "interface_viscosity": {"harmonic"}},
    "generalized-dissipation": {"shifting": {"none"}, "interface_sharpness": {"0"},
                                "interface_pressure": {"sum"},
                                "interface_viscosity": {"harmonic"}},
}
# The model switches belong to one scheme each.
MODEL_SCHEME = {"spc_model": "same-phase-continuity", "dissipation_form": "generalized-dissipation"}

# Combinations that must be refused (status 1): each sets a level its scheme refuses.
REFUSED = [
    {"scheme": "riemann", "walls": "moving"},
    {"scheme": "riemann", "interface_viscosity": "none"},
    {"scheme": "same-phase-continuity", "shifting": "consistent"},
    {"scheme": "generalized-dissipation", "interface_pressure": "density-weighted"},
    {"scheme": "delta-plus", "model": "spc_model=conventional"},
    {"scheme": "delta-sph", "model": "dissipation_form=printed"},
]


def accepted(a):
    """False when the partial assignment a (factor -> level) breaks a limit of its scheme."""
    scheme = a.get("scheme")
    if scheme is None:
        return True
    for factor, allowed in SCHEME_LIMITS.get(scheme, {}).items():
        if factor in a and a[factor] not in allowed:
            return False
    model = a.get("model", "default")
    return model == "default" or MODEL_SCHEME[model.split("=")[0]] == scheme


def complete(a, levels, order):
    """a completed over the factors in order (first accepted level, depth first), or None."""
    if not order:
        return dict(a)
    f = order[0]
    if f in a:
        return complete(a, levels, order[1:])
    for v in levels[f]:
        a[f] = v
        if accepted(a):
            full = complete(a, levels, order[1:])
            if full:
                del a[f]
                return full
        del a[f]
    return None


def pairs_of(a, names):
    """The pairs ((f, v), (g, w)) of the full assignment a, f before g in names."""
    return {((f, a[f]), (g, a[g])) for f, g in itertools.combinations(names, 2)}


def required_pairs(levels, names):
    """Every pair of levels that an accepted combination can hold."""
    need = set()
    for f, g in itertools.combinations(names, 2):
        for v in levels[f]:
            for w in levels[g]:
                if complete({f: v, g: w}, levels, names) is not None:
                    need.add(((f, v), (g, w)))
    return need


def ordered_pair(names, p, q):
    """The pair of levels p, q ((factor, level) each) in the order of pairs_of."""
    return (p, q) if names.index(p[0]) < names.index(q[0]) else (q, p)


def candidate(levels, names, uncovered, rng):
    """One accepted combination started from an uncovered pair and filled greedily."""
    (f, v), (g, w) = rng.choice(sorted(uncovered))
    a = {f: v, g: w}
    rest = [n for n in names if n not in a]
    rng.shuffle(rest)
    for n in rest:
        best, best_gain = None, -1
        for x in rng.sample(levels[n], len(levels[n])):
            a[n] = x
            if not accepted(a) or complete(a, levels, names) is None:
                continue
            gain = sum(1 for m in a
                       if m != n and ordered_pair(names, (n, x), (m, a[m])) in uncovered)
            if gain > best_gain:
                best, best_gain = x, gain
        a[n] = best
    return a


def pairwise_cover(levels, names, need, rng):
    """Accepted combinations, chosen greedily, that together hold every pair in need."""
    uncovered = set(need)
    rows = []
    while uncovered:
        tries = [candidate(levels, names, uncovered, rng) for _ in range(CANDIDATES)]
        best = max(tries, key=lambda a: len(pairs_of(a, names) & uncovered))
        uncovered -= pairs_of(best, names)
        rows.append(best)
    return rows


def design(seed):
    """COVERS pairwise covers of the accepted combinations, then the refused ones."""
    fs = factors()
    names = [n for n, _ in fs]
    levels = dict(fs)
    need = required_pairs(levels, names)
    rows = []
    for k in range(COVERS):
        rows += pairwise_cover(levels, names, need, random.Random(seed + k))
    for k, broken in enumerate(REFUSED):
        base = dict(rows[k % len(rows)])
        base.update(broken)
        rows.append(base)
    return rows


# The scenes: a water column over an air pocket in a tank (tests/stability/pocket.yaml, 2D) and
# water under air in a box (tests/cases/hydrostatic-3d.yaml made two-phase, 3D); the domains leave
# room for the ghost layers of the widest kernel support (3h at h = 2 dx).
SCENES = {
    "2": {
        "case": "tests/stability/pocket.yaml",
        "sets": ["resolution.dx=0.015",
                 "domain={min: [-0.6, -0.6], max: [0.8, 1.2]}",
                 "probes=[{name: p_point, position: [0.1, 0.0]}, "
                 "{name: p_mls, position: [0.1, 0.05], interpolation: mls}, "
                 "{name: p_face, position: [0.1, 0.0], diameter: 0.05, axis: [1, 0], "
                 "interpolation: mls}, {name: gauge, kind: elevation, position: [0.1, 0], "
                 "phase: water}, {name: water, kind: integral, phase: water}]"],
        "tank": "{box: {min: [0, 0], max: [0.2, 0.6]}}",
        "moving": "{box: {min: [0, 0], max: [0.2, 0.6]}, motion: {translation: "
                  "{amplitude: [0.02, 0], period: 0.5}}}",
        "obstacle": "{circle: {centre: [0.1, 0.25], radius: 0.04}, fluid_side: outside}",
    },
    "3": {
        "case": "tests/cases/hydrostatic-3d.yaml",
        "sets": ["resolution.dx=0.06",
                 "domain={min: [-1, -1, -1], max: [1.4, 1.5, 1.3]}",
                 "phases=[{name: water, rho0: 1000, c0: 31.3, incompressible: true}, "
                 "{name: air, rho0: 1, c0: 340, gamma: 1.4}]",
                 "fluids=[{phase: water, box: {min: [0, 0, 0], max: [0.42, 0.24, 0.3]}}, "
                 "{phase: air, box: {min: [0, 0.24, 0], max: [0.42, 0.48, 0.3]}}]",
                 "probes=[{name: p_point, position: [0.21, 0.0, 0.15]}, "
                 "{name: p_mls, position: [0.21, 0.1, 0.15], interpolation: mls}, "
                 "{name: gauge, kind: elevation, position: [0.21, 0, 0.15], phase: water}, "
                 "{name: air, kind: integral, phase: air}]"],
        "tank": "{box: {min: [0, 0, 0], max: [0.42, 0.48, 0.3]}}",
        "moving": "{box: {min: [0, 0, 0], max: [0.42, 0.48, 0.3]}, motion: {translation: "
                  "{amplitude: [0.02, 0, 0], period: 0.5}}}",
        "obstacle": "{circle: {centre: [0.21, 0.24, 0.15], radius: 0.07}, fluid_side: outside}",
    },
}


def walls_value(scene, walls):
    """The YAML list of the walls level in the scene."""
    return {"none": "[]", "fixed": "[%s]" % scene["tank"], "moving": "[%s]" % scene["moving"],
            "obstacle": "[%s, %s]" % (scene["tank"], scene["obstacle"])}[walls]


def overrides(a):
    """The --set overrides of combination a on its scene."""
    scene = SCENES[a["dimension"]]
    sets = list(scene["sets"]) + [
        "time.max_steps=%d" % MAX_STEPS, "output.progress_interval=1000",
        "output.stats_interval=1e-9", "output.probes_interval=1e-9",
        "parallel.repartition_every=" + a["repartition_every"],
        "scheme=" + a["scheme"], "kernel=" + a["kernel"],
        "resolution.h_over_dx=" + a["h_over_dx"], "walls=" + walls_value(scene, a["walls"])]
    sets += ["physics.%s=%s" % (k, a[k]) for k in
             ("free_surface", "surface_tension", "shifting", "interface_pressure",
              "interface_viscosity", "interface_mode", "interface_sharpness")]
    if a["model"] != "default":
        sets.append("physics." + a["model"])
    return scene["case"], sets


def main():
    args = sys.argv[1:]
    seed = int(args[1]) if args[:1] == ["--seed"] else SEED
    names = [n for n, _ in factors()]
    rows = design(seed)
    for k, a in enumerate(rows):
        case, sets = overrides(a)
        label = " ".join("%s=%s" % (n, a[n]) for n in names)
        expect = "refused" if k >= len(rows) - len(REFUSED) else "run"
        print("\t".join([label, a["ranks"], case, expect] + sets))


if __name__ == "__main__":
    main()
