#!/usr/bin/env bash
# test-cores: 3
# The single-phase dam break (2D, 300 steps), a coarse 3D hydrostatic box (40 steps), the
# two-phase dam break with every delta-plus term (100 steps), a tank shaken by a prescribed
# wall motion (150 steps), and the two-phase dam break with scheme riemann (60 steps; also with
# the air at twice the spacing, 1 and 3 ranks), under
# scheme same-phase-continuity (100 steps) and with scheme generalized-dissipation (60 steps) give
# bitwise-identical particle data (sorted by id) on
# 1, 2 and 3 ranks, also with forced re-partitions; on the re-partitioned runs of every scheme the
# mass of each phase is conserved (tests/check_mass.py: per-phase counts and total masses, every
# fluid particle keeps its phase and its mass bit for bit, none is lost).
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
common=(cases/dambreak-1phase/case.yaml --set resolution.dx=0.02 --set time.max_steps=300
        --set output.interval=0.02 --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${common[@]}" -o "$out/np1"
scripts/mpirun -n 2 build/mpsph run "${common[@]}" -o "$out/np2"
scripts/mpirun -n 3 build/mpsph run "${common[@]}" -o "$out/np3"
scripts/mpirun -n 2 build/mpsph run "${common[@]}" -o "$out/np2r" --set parallel.repartition_every=70
scripts/mpirun -n 3 build/mpsph run "${common[@]}" -o "$out/np3r" --set parallel.repartition_every=70
for run in np2 np3 np2r np3r; do
  "$PYTHON" tests/compare_snapshots.py "$out/np1" "$out/$run"
done
"$PYTHON" tests/check_mass.py "$out/np3r"
# 3D: a coarse hydrostatic box, 40 steps, 1 and 3 ranks with a forced re-partition, and 3 ranks
# with top cells of 2^3 cells.
three=(tests/cases/hydrostatic-3d.yaml --set time.max_steps=40 --set output.interval=0.02
       --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${three[@]}" -o "$out/3d1"
scripts/mpirun -n 3 build/mpsph run "${three[@]}" -o "$out/3d3" --set parallel.repartition_every=15
scripts/mpirun -n 3 build/mpsph run "${three[@]}" -o "$out/3d3b" --set parallel.repartition_every=15 \
  --set parallel.top_cells_per_rank=4 > "$out/3d3b.log"
grep -q "top cells of 2^3" "$out/3d3b.log"
"$PYTHON" tests/compare_snapshots.py "$out/3d1" "$out/3d3"
"$PYTHON" tests/compare_snapshots.py "$out/3d1" "$out/3d3b"
# The two-phase dam break with every delta-plus pass forced on (shifting with the delta-u terms,
# acoustic damper, tensile control, free-surface detection and band), 100 steps, 1, 2 and 3 ranks;
# its pressure probes (with the damper's stress, computed before each row) identical too.
two=(cases/dambreak-2phase/case.yaml --set resolution.dx=0.04 --set time.max_steps=100
     --set 'domain.min=[-0.2,-0.2]' --set 'domain.max=[3.416,2.0]' --set physics.acoustic_damper=10
     --set physics.free_surface=on --set output.interval=0.002 --set output.progress_interval=1000
     --set output.probes_interval=0.0005)
scripts/mpirun -n 1 build/mpsph run "${two[@]}" -o "$out/2p1"
scripts/mpirun -n 2 build/mpsph run "${two[@]}" -o "$out/2p2"
scripts/mpirun -n 3 build/mpsph run "${two[@]}" -o "$out/2p3" --set parallel.repartition_every=40
# Top cells of several cells (issue 22): 16 per rank give blocks of 2^2 cells (partial blocks at the
# domain's edges), with re-partitions.
scripts/mpirun -n 3 build/mpsph run "${two[@]}" -o "$out/2p3b" --set parallel.repartition_every=40 \
  --set parallel.top_cells_per_rank=16 > "$out/2p3b.log"
grep -q "top cells of 2^2" "$out/2p3b.log"
"$PYTHON" tests/compare_snapshots.py "$out/2p1" "$out/2p2"
"$PYTHON" tests/compare_snapshots.py "$out/2p1" "$out/2p3"
"$PYTHON" tests/compare_snapshots.py "$out/2p1" "$out/2p3b"
for run in 2p2 2p3 2p3b; do cmp "$out/2p1/probes.csv" "$out/$run/probes.csv"; done
"$PYTHON" tests/check_mass.py "$out/2p3"

# Scheme generalized-dissipation (its own passes and the Gamma/<grad p> halo field) on the same
# coarse two-phase dam break, 60 steps, 1 and 2 ranks with re-partitions.
gd=(cases/dambreak-2phase/case.yaml --set resolution.dx=0.04 --set time.max_steps=60
    --set 'domain.min=[-0.2,-0.2]' --set 'domain.max=[3.416,2.0]' --set scheme=generalized-dissipation
    --set physics.shifting=none --set output.interval=0.002 --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${gd[@]}" -o "$out/gd1"
scripts/mpirun -n 2 build/mpsph run "${gd[@]}" -o "$out/gd2" --set parallel.repartition_every=20
"$PYTHON" tests/compare_snapshots.py "$out/gd1" "$out/gd2"
"$PYTHON" tests/check_mass.py "$out/gd2"

# Moving walls: the shaken tank (ghosts carried across cells and ranks by the prescribed motion),
# 150 steps on 1 and 3 ranks with re-partitions.
shaken=(tests/cases/shaken-tank.yaml --set time.max_steps=150 --set output.interval=0.05
        --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${shaken[@]}" -o "$out/sh1"
scripts/mpirun -n 3 build/mpsph run "${shaken[@]}" -o "$out/sh3" --set parallel.repartition_every=50
"$PYTHON" tests/compare_snapshots.py "$out/sh1" "$out/sh3"
"$PYTHON" tests/check_mass.py "$out/sh3"

# Scheme riemann (dual time stepping, density re-initialisation, transport velocity, one-sided
# walls): the two-phase dam break with the paper's EOS, 60 advection steps, 1, 2 and 3 ranks.
riemann=(cases/dambreak-2phase/case.yaml --set scheme=riemann --set kernel=wendland-c2
         --set resolution.h_over_dx=1.3 --set resolution.dx=0.04 --set 'domain.min=[-0.2,-0.2]'
         --set 'domain.max=[3.416,2.0]' --set phases.0.gamma=1 --set phases.1.c0=48.5
         --set phases.1.gamma=1 --set physics.u_max=4.85 --set time.cfl=0.6 --set time.max_steps=60
         --set output.interval=0.02 --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${riemann[@]}" -o "$out/ri1"
scripts/mpirun -n 2 build/mpsph run "${riemann[@]}" -o "$out/ri2"
scripts/mpirun -n 3 build/mpsph run "${riemann[@]}" -o "$out/ri3" --set parallel.repartition_every=25
"$PYTHON" tests/compare_snapshots.py "$out/ri1" "$out/ri2"
"$PYTHON" tests/compare_snapshots.py "$out/ri1" "$out/ri3"
"$PYTHON" tests/check_mass.py "$out/ri3"
# The same with the air at twice the spacing (multi-resolution: two kernels, lists by phase, cells
# and wall layers at the air's support), 1 rank against 3 with re-partitions.
riemann_mr=("${riemann[@]}" --set phases.1.dx_ratio=2 --set 'domain.min=[-0.3,-0.3]' --set 'domain.max=[3.516,2.1]')
scripts/mpirun -n 1 build/mpsph run "${riemann_mr[@]}" -o "$out/mr1"
scripts/mpirun -n 3 build/mpsph run "${riemann_mr[@]}" -o "$out/mr3" --set parallel.repartition_every=25
"$PYTHON" tests/compare_snapshots.py "$out/mr1" "$out/mr3"
"$PYTHON" tests/check_mass.py "$out/mr3"
# Scheme same-phase-continuity (its own pair passes and the two-stage predictor-corrector): the
# two-phase dam break, 100 steps, 1, 2 and 3 ranks with re-partitions.
spc=(cases/dambreak-2phase/case.yaml --set resolution.dx=0.04 --set time.max_steps=100
     --set 'domain.min=[-0.2,-0.2]' --set 'domain.max=[3.416,2.0]' --set scheme=same-phase-continuity
     --set physics.shifting=none --set output.interval=0.002 --set output.progress_interval=1000)
scripts/mpirun -n 1 build/mpsph run "${spc[@]}" -o "$out/spc1"
scripts/mpirun -n 2 build/mpsph run "${spc[@]}" -o "$out/spc2"
scripts/mpirun -n 3 build/mpsph run "${spc[@]}" -o "$out/spc3" --set parallel.repartition_every=40
"$PYTHON" tests/compare_snapshots.py "$out/spc1" "$out/spc2"
"$PYTHON" tests/compare_snapshots.py "$out/spc1" "$out/spc3"
"$PYTHON" tests/check_mass.py "$out/spc3"
