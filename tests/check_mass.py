#!/usr/bin/env python3
"""Mass conservation of a run, per phase. No scheme creates, deletes or re-weighs a fluid particle
(the solver sets m only at the start, src/case/init.c, and for wall ghosts; delta-sph integrates
V = m/rho and riemann re-initialises rho, never m: doc/theory.md sections 9, 10), so every
snapshot, against the first one, must hold
  - per fluid phase: the same number of particles and the same total mass, to round-off
    (relative 1e-12; math.fsum is correctly rounded, so an unchanged set of masses gives the
    same sum exactly);
  - every fluid particle (by id; no id twice in a snapshot) with the same phase and the same
    mass, bit for bit; masses finite and positive;
  - the same wall ghosts (phase -1, by id). Their mass is not compared: a ghost's m = rho0 of
    the phase that dominates at its mirror point times dx^n (theory section 5) changes when
    that phase does (water reaching a wall that stood in air).
and the run advanced: at least two snapshots, the last one's step > 0.

Usage: check_mass.py RUN_DIR"""
import glob
import math
import os
import sys

import h5py
import numpy as np

WALL = -1
REL_TOL = 1e-12


def particles(path):
    """(ids, masses, phases) of a snapshot sorted by id, and its step."""
    with h5py.File(path, "r") as f:
        ids = f["particles/id"][:]
        order = np.argsort(ids, kind="stable")
        return (ids[order], f["particles/mass"][:][order], f["particles/phase"][:][order],
                int(f["header"].attrs["step"]))


def per_phase(ids, m, phase):
    """{phase: (count, total mass)} over the fluid particles."""
    return {int(ph): (int(np.sum(phase == ph)), math.fsum(m[phase == ph]))
            for ph in np.unique(phase) if ph != WALL}


def snapshot_problems(ids, m, phase):
    """What is wrong with a snapshot on its own: repeated ids, bad masses, no fluid."""
    out = []
    if len(np.unique(ids)) != len(ids):
        out.append("%d repeated ids" % (len(ids) - len(np.unique(ids))))
    fluid = phase != WALL
    bad = fluid & ~(np.isfinite(m) & (m > 0))
    if bad.any():
        out.append("%d fluid particles with a mass that is not finite and positive (id %d: %r)"
                   % (bad.sum(), ids[bad][0], m[bad][0]))
    if not fluid.any():
        out.append("no fluid particles")
    return out


def phase_problems(ref, now):
    """Per-phase count and total-mass differences of `now` against `ref`."""
    out = []
    for ph in sorted(set(ref) | set(now)):
        (n0, m0), (n, mass) = ref.get(ph, (0, 0.0)), now.get(ph, (0, 0.0))
        if n != n0:
            out.append("phase %d: %d fluid particles, the first snapshot had %d" % (ph, n, n0))
        if not abs(mass - m0) <= REL_TOL * abs(m0):
            out.append("phase %d: total mass %.17g, the first snapshot had %.17g (relative change %.3g)"
                       % (ph, mass, m0, (mass - m0) / m0 if m0 else math.inf))
    return out


def particle_problems(first, now):
    """Per-particle differences: fluid ids, phases, masses (bitwise) and wall ids."""
    ids0, m0, ph0, _ = first
    ids, m, ph, _ = now
    out = []
    for label, sel0, sel in (("fluid", ph0 != WALL, ph != WALL), ("wall", ph0 == WALL, ph == WALL)):
        lost, new = np.setdiff1d(ids0[sel0], ids[sel]), np.setdiff1d(ids[sel], ids0[sel0])
        if len(lost) or len(new):
            out.append("%s particles: %d of the first snapshot's ids missing (first %s), %d new (first %s)"
                       % (label, len(lost), lost[:5].tolist(), len(new), new[:5].tolist()))
    common, k0, k = np.intersect1d(ids0, ids, return_indices=True)
    fluid = ph0[k0] != WALL
    moved = fluid & (ph[k] != ph0[k0])
    if moved.any():
        out.append("%d fluid particles changed phase (first id %d)" % (moved.sum(), common[moved][0]))
    changed = fluid & (m[k].view(np.uint64) != m0[k0].view(np.uint64))
    if changed.any():
        c = np.flatnonzero(changed)[0]
        out.append("%d fluid particles changed mass (first id %d: %.17g, was %.17g)"
                   % (changed.sum(), common[c], m[k][c], m0[k0][c]))
    return out


def main(run):
    snaps = sorted(glob.glob(os.path.join(run, "snap_*.h5")))
    if len(snaps) < 2:
        print("%s: %d snapshots, need at least two to compare" % (run, len(snaps)))
        return 1
    first = particles(snaps[0])
    ref = per_phase(*first[:3])
    problems = [(snaps[0], p) for p in snapshot_problems(*first[:3])]
    for s in snaps[1:]:
        now = particles(s)
        problems += [(s, p) for p in snapshot_problems(*now[:3]) + phase_problems(ref, per_phase(*now[:3])) +
                     particle_problems(first, now)]
    step = now[3]
    for s, p in problems:
        print("%s: %s" % (os.path.basename(s), p))
    print("%d snapshots, last step %d; per phase (fluid particles, total mass): %s; %d wall ghosts"
          % (len(snaps), step, ", ".join("%d: %d, %.17g" % (ph, n, m) for ph, (n, m) in sorted(ref.items())),
             np.sum(first[2] == WALL)))
    if step == 0:
        print("the run did not advance (last snapshot at step 0)")
    return 1 if problems or step == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
