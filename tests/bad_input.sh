#!/usr/bin/env bash
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
refuses unreadable 'folder\.yaml: cannot read the file: Is a directory' -- \
  build/mpsph run "$tmp/folder.yaml" -o "$tmp/unreadable"
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
# The machine: ranks, output folder, memory.
refuses ranks 'the domain has 1 cells but 3 ranks were started' -- \
  scripts/mpirun -n 3 build/mpsph run "$case" -o "$tmp/ranks" --set 'walls=[]' \
  --set resolution.dx=0.2 --set time.end=0.01
refuses proc "cannot write to the output folder '/proc/mpsph-not-writable'" -- \
  build/mpsph run "$case" -o /proc/mpsph-not-writable
touch "$tmp/file"
refuses through-file "cannot write to the output folder '$tmp/file/out': Not a directory" -- \
  build/mpsph run "$case" -o "$tmp/file/out"
refuses memory-bound 'not enough memory: up to 1e\+10 particles .* need about [0-9.e+]+ GB per rank on 1 rank .* but 16 GB are available per rank' -- \
  env MPSPH_MEMORY_AVAILABLE=16e9 build/mpsph run "$case" -o "$tmp/memory-bound" --set resolution.dx=1e-5
refuses memory-counted 'not enough memory: 258852 particles \(250000 fluid, 8852 wall\) need about 0\.103 GB per rank on 2 ranks .* but 0\.05 GB are available per rank \(the node.s available memory over its 2 ranks\)' -- \
  env MPSPH_MEMORY_AVAILABLE=1e8 scripts/mpirun -n 2 build/mpsph run "$case" -o "$tmp/memory-counted" \
  --set resolution.dx=0.002
refuses memory-variable "MPSPH_MEMORY_AVAILABLE: got '2GB', expected a number of bytes > 0" -- \
  env MPSPH_MEMORY_AVAILABLE=2GB build/mpsph run "$case" -o "$tmp/memory-variable"
exit $fail
