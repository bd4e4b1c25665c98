#!/usr/bin/env bash
# Static bubble (cases/static-bubble, 2D, density ratio 100, surface tension only) at R/dx = 10:
# the pressure jump averaged over t = 0.01-0.03 s is sigma/R within 5 % and the phases stay apart
# (tests/check_static_bubble.py, which also reports the spurious currents); and 40 steps give
# bitwise-identical particles on 1 and 2 ranks (the interface normals' halo update).
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
quiet=(--set output.progress_interval=1000)
build/mpsph run cases/static-bubble/case.yaml -o "$out/bubble" "${quiet[@]}" --set time.end=0.03 \
  --set output.interval=0.0005
"$PYTHON" tests/check_static_bubble.py "$out/bubble" 0.05 0.01
short=(cases/static-bubble/case.yaml "${quiet[@]}" --set time.max_steps=40 --set output.interval=0.0001)
scripts/mpirun -n 1 build/mpsph run "${short[@]}" -o "$out/np1"
scripts/mpirun -n 2 build/mpsph run "${short[@]}" -o "$out/np2"
"$PYTHON" tests/compare_snapshots.py "$out/np1" "$out/np2"
