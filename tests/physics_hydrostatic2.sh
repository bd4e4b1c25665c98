#!/usr/bin/env bash
# Two-phase hydrostatic tank (paper 000 section 3.1) at Hw/dx = 25 to t = 1 s on 2 ranks with the
# delta-plus scheme of the case: bottom pressure (averaged over 0.5-1 s) within 2 % of rho_w g Hw,
# no interpenetration beyond 3 dx, phase volumes within 0.5 %. The centreline criterion belongs to
# the full-length run (t sqrt(g/Hw) = 40, check_hydrostatic2.py --centreline), not to the paper's
# pair sum here (its interface error is of first order in h: 6 % at this resolution, doc/theory.md
# section 4b). The same tank with physics.interface_pressure: density-weighted (theory section 4,
# "Interface pressure") must also hold the centreline pressure within 2 % at t = 1 s (measured
# 1.26 % with its wall ghosts of theory section 5 and divergence weight of section 3, 1.49 %
# before them; acoustic transient included). Last, delta-sph with consistent shifting: its bottom
# pressure.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run=(cases/hydrostatic-2phase/case.yaml --set resolution.dx=0.04 --set time.end=1.0 --set output.interval=0.5
     --set output.progress_interval=1000)
scripts/mpirun -n 2 build/mpsph run "${run[@]}" -o "$out/sum"
"$PYTHON" tests/check_hydrostatic2.py "$out/sum" 0.04 0.02
scripts/mpirun -n 2 build/mpsph run "${run[@]}" -o "$out/weighted" --set physics.interface_pressure=density-weighted
"$PYTHON" tests/check_hydrostatic2.py "$out/weighted" 0.04 0.02 --centreline
# delta-sph with the case's consistent shifting (doc/theory.md section 9): its outputs carry the
# Shepard pressure its forces use; with the integrated density's EOS written instead, the bottom
# read 4.4 % off at Hw/dx = 20 (0.8 % with the Shepard pressure)
scripts/mpirun -n 2 build/mpsph run cases/hydrostatic-2phase/case.yaml -o "$out/dsph" --set scheme=delta-sph \
  --set resolution.dx=0.05 --set time.end=1.0 --set output.interval=0.5 --set output.progress_interval=1000
"$PYTHON" tests/check_hydrostatic2.py "$out/dsph" 0.05 0.02
