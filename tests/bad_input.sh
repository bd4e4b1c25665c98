#!/usr/bin/env bash
# test-cores: 1   (the refusals on 2 and 3 ranks stop at start-up)
# Bad input: `run` stops with exit status 1 and a message naming the file, line and key (or the
# numbers), before any computation, and the output folder is not created.
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
case=cases/hydrostatic-1phase/case.yaml

# refuses NAME PATTERN -- COMMAND...: COMMAND (which writes to $tmp/NAME) exits 1 with a message
# matching PATTERN and leaves no $tmp/NAME.
refuses() {
  local name=$1 pattern=$2
  shift 3
  local out status
  out=$("$@" 2>&1)
  status=$?
  if [ "$status" -ne 1 ] || ! grep -qE -- "^mpsph: .*$pattern" <<<"$out"; then
    echo "FAIL $name: status $status (want 1), output: $out"
    fail=1
  elif [ -e "$tmp/$name" ]; then
    echo "FAIL $name: the output folder was created"
    fail=1
  else
    echo "ok $name: $(grep '^mpsph: ' <<<"$out" | head -n 1)"
  fi
}
# run NAME [ARGS...]: mpsph run of the case into $tmp/NAME.
run() { local name=$1; shift; build/mpsph run "$case" -o "$tmp/$name" "$@"; }

# The case file.
sed 's/^time: {end: 12.77, cfl: 1.0}/time: {end: 12.77, cfl: 1.0/' "$case" > "$tmp/malformed.yaml"
refuses malformed 'malformed\.yaml:9: time: malformed YAML: .*expected valid YAML' -- \
  build/mpsph run "$tmp/malformed.yaml" -o "$tmp/malformed"
head -c 64 /dev/urandom > "$tmp/binary.yaml"
refuses binary 'binary\.yaml:1: malformed YAML' -- build/mpsph run "$tmp/binary.yaml" -o "$tmp/binary"
refuses missing-file 'missing\.yaml: cannot open the file: No such file' -- \
  build/mpsph run "$tmp/missing.yaml" -o "$tmp/missing-file"
mkdir "$tmp/folder.yaml"
refuses unreadable 'folder\.yaml: cannot read the file: it is a directory, expected a regular file' -- \
  build/mpsph run "$tmp/folder.yaml" -o "$tmp/unreadable"
# YAML that the loader would otherwise read without saying: an unused anchor, a tag, UTF-16. (The
# new refusals below stop after one step if they go missing.)
sed 's/^dimension: 2/dimension: \&d 2/' "$case" > "$tmp/anchor.yaml"
refuses anchor 'anchor\.yaml:3: dimension: got the anchor &d, expected none' -- \
  build/mpsph run "$tmp/anchor.yaml" -o "$tmp/anchor" --set time.max_steps=1
sed 's/^dimension: 2/dimension: !!str 2/' "$case" > "$tmp/tag.yaml"
refuses tag 'tag\.yaml:3: dimension: got the tag !!str, expected none' -- \
  build/mpsph run "$tmp/tag.yaml" -o "$tmp/tag" --set time.max_steps=1
iconv -f UTF-8 -t UTF-16 "$case" > "$tmp/utf16.yaml"
refuses utf16 'utf16\.yaml:1: the text is UTF-16(LE|BE) \(it starts with its byte-order mark\), expected UTF-8' -- \
  build/mpsph run "$tmp/utf16.yaml" -o "$tmp/utf16" --set time.max_steps=1
sed 's/^physics: {delta/physics: {deltaa/' "$case" > "$tmp/unknown.yaml"
refuses unknown-key 'unknown\.yaml:19: physics\.deltaa: unknown key, allowed keys: delta, ' -- \
  build/mpsph run "$tmp/unknown.yaml" -o "$tmp/unknown-key"
refuses unknown-set '--set:1: physics\.colour: unknown key' -- run unknown-set --set physics.colour=red
sed '/^time:/d' "$case" > "$tmp/no_time.yaml"
refuses missing-key 'no_time\.yaml:1: time\.end: missing required key, expected a number > 0' -- \
  build/mpsph run "$tmp/no_time.yaml" -o "$tmp/missing-key"
# Values.
refuses type-list 'resolution\.dx: got a list of 2 items, expected a number > 0' -- \
  run type-list --set 'resolution.dx=[1, 2]'
refuses type-bool 'phases\.0\.incompressible: got .yes., allowed values: false, true' -- \
  run type-bool --set phases.0.incompressible=yes
refuses type-word 'kernel: got .cubic., allowed values: gaussian, wendland-c2' -- \
  run type-word --set kernel=cubic
refuses dx-zero 'resolution\.dx: got .0., expected a number > 0' -- run dx-zero --set resolution.dx=0
refuses dx-negative 'resolution\.dx: got .-1., expected a number > 0' -- \
  run dx-negative --set resolution.dx=-1
refuses sigma-negative 'physics\.surface_tension: got .-0\.07., expected a number >= 0' -- \
  run sigma-negative --set physics.surface_tension=-0.07
refuses h-large 'resolution\.h_over_dx: got .20., expected a number > 0 and <= 10' -- \
  run h-large --set resolution.h_over_dx=20
refuses band 'phases\.0\.density_band: got \[1\.1, 2\], expected a list \[min_ratio, max_ratio\]' -- \
  run band --set 'phases.0.density_band=[1.1, 2]'
refuses spc-shifting 'physics\.shifting: only none with scheme same-phase-continuity' -- \
  run spc-shifting --set scheme=same-phase-continuity --set physics.shifting=consistent
refuses dissform 'physics\.dissipation_form: only scheme generalized-dissipation has one' -- \
  run dissform --set physics.dissipation_form=printed
refuses gdshift 'physics\.shifting: not part of scheme generalized-dissipation' -- \
  run gdshift --set scheme=generalized-dissipation --set physics.shifting=consistent
refuses dissvalue 'physics\.dissipation_form: got .literal., allowed values: consistent, printed' -- \
  run dissvalue --set physics.dissipation_form=literal
refuses ivisc-riemann 'physics\.interface_viscosity: none is not available with scheme riemann' -- \
  run ivisc-riemann --set scheme=riemann --set physics.interface_viscosity=none
refuses ivisc-spc 'physics\.interface_viscosity: none is not available with scheme same-phase-continuity' -- \
  run ivisc-spc --set scheme=same-phase-continuity --set physics.interface_viscosity=none
refuses ivisc-gd 'physics\.interface_viscosity: none is not available with scheme generalized-dissipation' -- \
  run ivisc-gd --set scheme=generalized-dissipation --set physics.interface_viscosity=none
refuses ivisc-value 'physics\.interface_viscosity: got .arithmetic., allowed values: none, harmonic' -- \
  run ivisc-value --set physics.interface_viscosity=arithmetic
# Elastic solids (the gate case): schemes riemann and delta-plus only, their keys, a solid the
# elastic module cannot set up, a fluid region over a solid.
gate=cases/elastic-gate-antoci/case.yaml
refuses solid-scheme 'solids: elastic solids are not available with scheme delta-sph' -- \
  build/mpsph run "$gate" -o "$tmp/solid-scheme" --set scheme=delta-sph
refuses solid-scheme-gd 'solids: elastic solids are not available with scheme generalized-dissipation' -- \
  build/mpsph run "$gate" -o "$tmp/solid-scheme-gd" --set scheme=generalized-dissipation
refuses solid-poisson 'solids\.0\.poisson_ratio: got 0\.5, expected a number > -1 and < 0\.5' -- \
  build/mpsph run "$gate" -o "$tmp/solid-poisson" --set solids.0.poisson_ratio=0.5
sed 's/, clamp_max: \[[^]]*\]//' "$gate" > "$tmp/one-corner.yaml"
refuses solid-clamp 'one-corner\.yaml:[0-9]+: solids\.0\.clamp_min: got one corner of the clamp box' -- \
  build/mpsph run "$tmp/one-corner.yaml" -o "$tmp/solid-clamp"
refuses solid-probe "solids\.0\.probe: got a point outside the solid's box" -- \
  build/mpsph run "$gate" -o "$tmp/solid-probe" --set 'solids.0.probe=[0.3,0]'
refuses solid-layers 'solids\.0: the elastic solid cannot be set up' -- \
  build/mpsph run "$gate" -o "$tmp/solid-layers" --set resolution.dx=0.0025
refuses solid-overlap "solids\.0: a fluid particle lies inside the solid's box" -- \
  scripts/mpirun -n 2 build/mpsph run "$gate" -o "$tmp/solid-overlap" --set 'fluids.0.box.min=[0.39,0]'
refuses solid-spacing 'solids\.0\.max: got a box 30\.6667 particle spacings wide along axis 1, expected a whole number' -- \
  build/mpsph run cases/elastic-plate-walhorn/case.yaml -o "$tmp/solid-spacing" --set resolution.dx=0.003
# Multi-resolution (the two-phase tank): scheme riemann only, a light phase only, no surface tension.
tank2=cases/hydrostatic-2phase/case.yaml
refuses mr-ratio "phases\.1\.dx_ratio: got '3', expected 1 or 2" -- \
  build/mpsph run "$tank2" -o "$tmp/mr-ratio" --set phases.1.dx_ratio=3
refuses mr-scheme 'phases\.1\.dx_ratio: multi-resolution is not available with scheme delta-plus' -- \
  build/mpsph run "$tank2" -o "$tmp/mr-scheme" --set phases.1.dx_ratio=2
refuses mr-heavy 'phases\.0\.dx_ratio: only a light phase .* may be coarser' -- \
  build/mpsph run "$tank2" -o "$tmp/mr-heavy" --set scheme=riemann --set phases.0.dx_ratio=2
refuses mr-tension 'physics\.surface_tension: not available with multi-resolution' -- \
  build/mpsph run "$tank2" -o "$tmp/mr-tension" --set scheme=riemann --set phases.1.dx_ratio=2 \
  --set physics.surface_tension=0.07
# Geometry.
sed 's/max: \[1, 1\]}}$/max: [1, 1]}}\n  - {phase: water, box: {min: [0.5, 0.5], max: [0.9, 0.9]}}/' \
  "$case" > "$tmp/overlap.yaml"
refuses overlap 'overlap\.yaml: fluids\.1 overlaps fluids\.0 \(both contain the point' -- \
  build/mpsph run "$tmp/overlap.yaml" -o "$tmp/overlap"
refuses region-outside 'fluids\.0\.box: got bounding box min \[0, 0\] max \[1, 2\] outside the domain' -- \
  run region-outside --set 'fluids.0.box.max=[1, 2]'
refuses probe-outside 'probes\.0\.position: got \[0\.5, 3\] outside the domain' -- \
  run probe-outside --set 'probes.0.position=[0.5, 3]'
refuses wall-layers 'walls\.0: its 4 ghost layers .* outside the domain' -- \
  run wall-layers --set 'domain.min=[-0.05,-0.05]'
refuses polygon-crossing 'fluids\.0\.polygon: edges 0 \(\[0, 0\] to \[1, 1\]\) and 2 \(\[1, 0\] to \[0, 1\]\) cross or touch' -- \
  run polygon-crossing --set time.max_steps=1 --set 'fluids.0={phase: water, polygon: [[0, 0], [1, 1], [1, 0], [0, 1]]}'
refuses polygon-flat 'fluids\.0\.polygon: edges 0 .* cross or touch' -- \
  run polygon-flat --set time.max_steps=1 --set 'fluids.0={phase: water, polygon: [[0, 0], [0.5, 0], [1, 0]]}'
refuses polygon-repeated 'walls\.0\.polygon: vertices 1 and 3 are the same point \[1, 0\]' -- \
  run polygon-repeated --set time.max_steps=1 --set 'walls.0={polygon: [[0, 0], [1, 0], [1, 1.2], [1, 0], [0, 1.2]]}'
# The command line's paths. An output folder whose files' paths MPI-IO cannot take (Open MPI's
# lockedfile component aborts with "buffer overflow detected" beyond 244 characters on 1 rank).
long="$tmp/long-outdir/$(printf 'd%.0s' {1..200})/$(printf 'e%.0s' {1..200})/$(printf 'f%.0s' {1..200})"
long="$long/$(printf 'g%.0s' {1..200})/$(printf 'h%.0s' {1..200})"
long=${long:0:1000}
refuses long-outdir '-o: the output folder has 1000 characters, at most 218 allowed on 1 rank: .* unstable_last_good\.h5\.tmp would have 1026' -- \
  build/mpsph run "$case" -o "$long" --set time.max_steps=1
refuses long-restart "--restart: the checkpoint's path has 1000 characters, at most 244 allowed on 1 rank" -- \
  run long-restart --restart "$long"
# -o '' wrote every file into /: the bad time.end keeps a build without the refusal from running.
mkfifo "$tmp/fifo.h5"   # MPI-IO waited for a writer, and SIGTERM did not end the wait
refuses restart-fifo "--restart: cannot read '$tmp/fifo\.h5': it is a FIFO \(named pipe\), expected a checkpoint file" -- \
  timeout -k 2 20 build/mpsph run "$case" -o "$tmp/restart-fifo" --restart "$tmp/fifo.h5"
refuses empty-outdir '-o: got an empty folder name, expected a path' -- \
  build/mpsph run "$case" -o '' --set time.end=-1
refuses two-outdirs "-o: given twice \('$tmp/two-outdirs' and '$tmp/two-outdirs-b'\)" -- \
  run two-outdirs -o "$tmp/two-outdirs-b" --set time.max_steps=1
# The folder of 218 characters, the longest allowed on 1 rank, takes every file a run writes: the
# unstable run's unstable_last_good.h5 has the longest path.
edge="$tmp/edge/$(printf 'x%.0s' {1..250})"
edge=${edge:0:218}
out=$(build/mpsph run "$case" -o "$edge" --set 'gravity=[0, -1e308]' 2>&1)
status=$?
if [ "$status" -ne 2 ] || [ ! -s "$edge/unstable_last_good.h5" ]; then
  echo "FAIL edge-outdir: status $status (want 2, with $edge/unstable_last_good.h5), output: $out"
  fail=1
else
  echo "ok edge-outdir: an unstable run into a folder of ${#edge} characters wrote its files"
fi
# The machine: ranks, output folder, memory.
refuses ranks 'the particles fill 1 cells but 3 ranks were started' -- \
  scripts/mpirun -n 3 build/mpsph run "$case" -o "$tmp/ranks" --set 'walls=[]' \
  --set resolution.dx=0.2 --set time.end=0.01
refuses proc "cannot write to the output folder '/proc/mpsph-not-writable'" -- \
  build/mpsph run "$case" -o /proc/mpsph-not-writable
touch "$tmp/file"
refuses through-file "cannot write to the output folder '$tmp/file/out': Not a directory" -- \
  build/mpsph run "$case" -o "$tmp/file/out"
refuses memory-bound 'not enough memory: up to 1e\+10 particles .* need about [0-9.e+]+ GB per rank on 1 rank .* but 16 GB are available per rank' -- \
  env MPSPH_MEMORY_AVAILABLE=16e9 build/mpsph run "$case" -o "$tmp/memory-bound" --set resolution.dx=1e-5
refuses memory-counted 'not enough memory: 258852 particles \(250000 fluid, 8852 wall\) need about 0\.0747 GB per rank on 2 ranks .* but 0\.05 GB are available per rank \(the node.s available memory over its 2 ranks\)' -- \
  env MPSPH_MEMORY_AVAILABLE=1e8 scripts/mpirun -n 2 build/mpsph run "$case" -o "$tmp/memory-counted" \
  --set resolution.dx=0.002
refuses memory-variable "MPSPH_MEMORY_AVAILABLE: got '2GB', expected a number of bytes > 0" -- \
  env MPSPH_MEMORY_AVAILABLE=2GB build/mpsph run "$case" -o "$tmp/memory-variable"
exit $fail
