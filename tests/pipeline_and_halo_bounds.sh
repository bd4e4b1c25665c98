#!/usr/bin/env bash
# Issue 20, items 1 and 2: input that assembles the longest pipeline, or needs a wide halo, runs.
#  1. delta-sph with walls, free surface, shifting, surface tension and the wall guard assembles
#     all 18 operations of the RK stage (ENGINE_MAX_OPS); it used to write past e->ops and crash,
#     or drop the wall guard silently.
#  2. a 3D case with walls and a halo reach of 4 cell layers (Wendland C2, h/dx 1.2) has a 9^3 stencil;
#     the halo's cell marking used to write it into a 343-entry stack buffer.
# Each on 1 and 2 ranks: exit 0, and the pipeline printed has every operation.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for n in 1 2; do
  timeout 120 scripts/mpirun -n $n build/mpsph run tests/stability/pocket.yaml --set scheme=delta-sph \
    --set physics.surface_tension=0.07 --set time.max_steps=3 -o "$out/pocket$n" > "$out/pocket$n.log" 2>&1 \
    || { cat "$out/pocket$n.log"; echo "FAIL: pocket delta-sph + surface tension on $n ranks"; exit 1; }
  grep -q "pipeline per RK stage (18 operations)" "$out/pocket$n.log"
  grep -q "18. wall guard" "$out/pocket$n.log"
  echo "pocket, delta-sph, surface tension, $n ranks: 18 operations, wall guard last"
  timeout 300 scripts/mpirun -n $n build/mpsph run tests/cases/hydrostatic-3d.yaml --set kernel=wendland-c2 \
    --set resolution.h_over_dx=1.2 --set resolution.dx=0.03 --set time.max_steps=2 -o "$out/h3d$n" \
    > "$out/h3d$n.log" 2>&1 || { cat "$out/h3d$n.log"; echo "FAIL: 3D halo of 4 layers on $n ranks"; exit 1; }
  grep -q "halo 1 layer, 4 toward wall ghosts' mirror points, $n ranks" "$out/h3d$n.log"
  echo "hydrostatic 3D, wendland-c2, h/dx 1.2, $n ranks: halo reach 4 layers, ran"
done
