# mpsph — build, test, run, validate, bench.
# Clusters: make MPICC=mpicc HDF5_DIR=/opt/hdf5 METIS_DIR=/opt/metis [YAML_DIR=...]

MPICC  ?= mpicc
ARCH   ?= native
PYTHON ?= $(shell test -x /usr/bin/python3 && echo /usr/bin/python3 || echo python3)
MPIRUN ?= scripts/mpirun
NP     ?= 2

ifdef HDF5_DIR
  HDF5_CFLAGS := -I$(HDF5_DIR)/include
  HDF5_LIBS   := -L$(HDF5_DIR)/lib -Wl,-rpath,$(HDF5_DIR)/lib -lhdf5
else
  HDF5_CFLAGS := $(shell pkg-config --cflags hdf5-mpi 2>/dev/null)
  HDF5_LIBS   := $(shell pkg-config --libs hdf5-mpi 2>/dev/null)
endif
ifdef METIS_DIR
  METIS_CFLAGS := -I$(METIS_DIR)/include
  METIS_LIBS   := -L$(METIS_DIR)/lib -Wl,-rpath,$(METIS_DIR)/lib -lmetis
else
  METIS_CFLAGS := $(shell pkg-config --cflags metis 2>/dev/null)
  METIS_LIBS   := $(shell pkg-config --libs metis 2>/dev/null || echo -lmetis)
endif
ifdef YAML_DIR
  YAML_CFLAGS := -I$(YAML_DIR)/include
  YAML_LIBS   := -L$(YAML_DIR)/lib -Wl,-rpath,$(YAML_DIR)/lib -lyaml
else
  YAML_CFLAGS := $(shell pkg-config --cflags yaml-0.1 2>/dev/null)
  YAML_LIBS   := $(shell pkg-config --libs yaml-0.1 2>/dev/null || echo -lyaml)
endif

# native (the default): this machine's widest vector units, which the pair loops' kernel evaluation
# uses (include/physics/pair_chunk.h); portable: any x86-64, for a binary shared by unlike nodes.
# -std=c11 keeps floating-point contraction off in both, so a binary gives the same results on any
# rank count; two builds for different machines may differ by rounding.
OPT_portable := -O2 -ftree-vectorize
OPT_native   := -O3 -march=native
VERSION := $(shell git describe --always --dirty 2>/dev/null || echo unknown)

# CFLAGS (the optimisation flags; a user's, from the environment or the command line, replace
# ARCH's) is left as given, so that make test's sub-make, to which it is passed down, builds with
# the same ALL_CFLAGS (and the same flags stamp) as the make that called it.
CFLAGS  ?= $(OPT_$(ARCH)) -g
BASE_CFLAGS := -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -Iinclude \
           -DMPSPH_VERSION='"$(VERSION)"' $(HDF5_CFLAGS) $(METIS_CFLAGS) $(YAML_CFLAGS)
ALL_CFLAGS := $(CFLAGS) $(if $(filter 1,$(SINGLE_PHASE)),-DMPSPH_SINGLE_PHASE) $(BASE_CFLAGS)
LDLIBS  := $(HDF5_LIBS) $(METIS_LIBS) $(YAML_LIBS) -lm
# `make` alone builds everything (the stamp's rule below would otherwise be the first target).
.DEFAULT_GOAL := all

# The compiler flags of the objects in build/ (the version string aside): rewritten when they
# change (another ARCH, CFLAGS), so that every object is compiled again with the new ones.
FLAGS_STAMP := build/cflags.txt
FLAGS_NOW   := $(MPICC) $(filter-out -DMPSPH_VERSION=%,$(ALL_CFLAGS))
ifneq ($(FLAGS_NOW),$(shell cat $(FLAGS_STAMP) 2>/dev/null))
  $(shell mkdir -p build && echo '$(FLAGS_NOW)' > $(FLAGS_STAMP))
endif
$(FLAGS_STAMP):   # again after a clean in the same make command
	@mkdir -p build && echo '$(FLAGS_NOW)' > $@

# The case loader and what `check` runs of it, without MPI: the fuzz target and its replay.
FUZZ_SRC := $(addprefix src/,case/case_load.c case/yaml_tree.c case/init.c case/geometry.c case/motion.c \
              physics/kernel.c base/parts.c base/mem.c) tests/fuzz/fuzz_case_load.c
FUZZ_CFLAGS  = -std=c11 -D_POSIX_C_SOURCE=200809L -g -O1 -Wall -Wextra -Werror -Iinclude $(YAML_CFLAGS)
CLANG    ?= clang
SANITIZE ?= -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_SECONDS ?= 120

# The sources by layer (src/<layer>/, physics/ with a folder per scheme that owns passes; see
# doc/architecture.md); the headers beside them under include/<layer>/, included as "layer/x.h".
SRC      := $(wildcard src/*/*.c src/*/*/*.c)
HDR      := $(wildcard include/*/*.h)
# The sanitizer build of the solver (tests/combinations.sh): its own objects, -O1.
ASAN_CFLAGS = -O1 -g $(SANITIZE) $(BASE_CFLAGS)
ASAN_OBJ := $(patsubst src/%.c,build/asan/obj/%.o,$(SRC))
LIB_OBJ  := $(patsubst src/%.c,build/obj/%.o,$(filter-out src/app/main.c,$(SRC)))
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(patsubst tests/%.c,build/tests/%,$(TEST_SRC))

.PHONY: all deps test run validate bench fuzz clean asan keys-doc
all: build/mpsph $(TEST_BIN) build/tests/fuzz_replay
asan: build/asan/mpsph

deps:
	@scripts/install-deps

build/obj/%.o: src/%.c $(HDR) $(FLAGS_STAMP)
	@echo "CC $<"
	@mkdir -p $(@D)
	@$(MPICC) $(ALL_CFLAGS) -c $< -o $@

build/libmpsph.a: $(LIB_OBJ)
	@ar rcs $@ $^

build/mpsph: build/obj/app/main.o build/libmpsph.a
	@echo "LD $@"
	@$(MPICC) $(ALL_CFLAGS) $^ -o $@ $(LDLIBS)

build/asan/obj/%.o: src/%.c $(HDR)
	@echo "CC (asan) $<"
	@mkdir -p $(@D)
	@$(MPICC) $(ASAN_CFLAGS) -c $< -o $@

build/asan/mpsph: $(ASAN_OBJ)
	@echo "LD $@"
	@$(MPICC) $(ASAN_CFLAGS) $^ -o $@ $(LDLIBS)

build/tests/%: tests/%.c tests/check.h tests/engine_test.h build/libmpsph.a $(FLAGS_STAMP) | build/tests
	@echo "LD $@"
	@$(MPICC) $(ALL_CFLAGS) -Itests $< build/libmpsph.a -o $@ $(LDLIBS)

build/tests/fuzz_replay: tests/fuzz/replay.c $(FUZZ_SRC) $(HDR) | build/tests
	@echo "LD $@"
	@$(CC) $(FUZZ_CFLAGS) $(SANITIZE) tests/fuzz/replay.c $(FUZZ_SRC) -o $@ $(YAML_LIBS) -lm

build/fuzz/fuzz_case_load: $(FUZZ_SRC) $(HDR) | build/fuzz
	@echo "LD $@"
	@$(CLANG) $(FUZZ_CFLAGS) -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
	  $(FUZZ_SRC) -o $@ $(YAML_LIBS) -lm

build/tests build/fuzz:
	mkdir -p $@

# libFuzzer on the case loader for FUZZ_SECONDS; seeds: the cases and the regression inputs;
# dictionary: tests/fuzz/case.dict.
# New inputs go to build/fuzz/corpus, crashes to build/fuzz/crash-*.
fuzz:
	@scripts/install-deps fuzz
	@$(MAKE) --no-print-directory build/fuzz/fuzz_case_load
	@mkdir -p build/fuzz/corpus build/fuzz/seeds
	@for f in cases/*/case.yaml; do cp "$$f" "build/fuzz/seeds/$$(basename $$(dirname $$f)).yaml"; done
	@cp tests/cases/*.yaml tests/fuzz_regressions/* build/fuzz/seeds/
	build/fuzz/fuzz_case_load -max_total_time=$(FUZZ_SECONDS) -timeout=10 -dict=tests/fuzz/case.dict \
	  -artifact_prefix=build/fuzz/ build/fuzz/corpus build/fuzz/seeds

# The case key reference of doc/user-guide.md (section 2.1) rewritten from `mpsph keys`;
# tests/keys_reference.sh fails when it is out of date.
keys-doc: build/mpsph
	@scripts/keys-doc

# The builds run on every core (-j unless make was given one); the benchmark's programs too, so
# that tests/bench_smoke.sh, which runs alone, does not compile them.
TEST_JOBS = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(shell nproc))
test: deps
	@$(MAKE) --no-print-directory $(TEST_JOBS) all asan $(BENCH_TOOLS) build/bench/mpsph-single-phase
	@PYTHON=$(PYTHON) scripts/run-tests

# Two hosts on one machine (tests/multihost/multihost.sh: network namespaces, needs root, else it
# is skipped): the 2D and 3D runs over TCP between the hosts are bitwise identical to one host.
# Not part of `make test` (about 1-2 min on 2 cores).
.PHONY: test-multihost
test-multihost: build/mpsph
	@PYTHON=$(PYTHON) bash tests/multihost/multihost.sh

run: deps
	@$(MAKE) --no-print-directory build/mpsph
	@PYTHON=$(PYTHON) NP=$(NP) scripts/run-default

# Benchmarks (issue 6): doc/performance.md and doc/performance.csv from measured runs only.
# BENCH_QUICK=1: a few-minute smoke version written to build/bench/ instead of doc/.
# DUALSPHYSICS=BIN adds the peer comparison of issue 23 (scripts/bench_peer.py) with that
# DualSPHysics CPU binary; DUALSPHYSICS_SRC=DIR its source tree if not three levels above BIN.
BENCH_TOOLS := build/bench/peak_fma build/bench/bench_hdf5
build/bench/peak_fma: scripts/bench/peak_fma.c $(FLAGS_STAMP) | build/bench
	@$(MPICC) $(ALL_CFLAGS) -ffp-contract=fast $< -o $@
build/bench/bench_hdf5: scripts/bench/bench_hdf5.c build/libmpsph.a | build/bench
	@$(MPICC) $(ALL_CFLAGS) $< build/libmpsph.a -o $@ $(LDLIBS)
build/bench:
	mkdir -p $@
build/bench/mpsph-single-phase: $(SRC) $(HDR) $(FLAGS_STAMP) | build/bench
	@echo "LD $@ (SINGLE_PHASE)"
	@$(MPICC) $(filter-out -DMPSPH_SINGLE_PHASE,$(ALL_CFLAGS)) -DMPSPH_SINGLE_PHASE $(SRC) -o $@ $(LDLIBS)
build/tests/test_no_alloc: tests/test_no_alloc.c tests/check.h tests/engine_test.h build/libmpsph.a | build/tests
	@echo "LD $@"
	@$(MPICC) $(ALL_CFLAGS) -Itests $< build/libmpsph.a -o $@ $(LDLIBS) \
	  -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc
bench: deps
	@$(MAKE) --no-print-directory build/mpsph $(BENCH_TOOLS)
	@$(PYTHON) scripts/bench.py $(if $(BENCH_QUICK),--quick) $(if $(DUALSPHYSICS),--dualsphysics $(DUALSPHYSICS)) \
	  $(if $(DUALSPHYSICS_SRC),--dualsphysics-src $(DUALSPHYSICS_SRC))

# The validation ladder and doc/validation/README.md; QUICK=1: the cheap rungs only (user guide
# 1.8 for their time). Runs go to runs/validate/, as many at once as their ranks fit in JOBS cores
# (default: this machine's); VALIDATE_ARGS passes e.g. --only STUDY (which updates that study's part
# of the report, keeping the others) or --reuse.
JOBS ?= $(shell nproc)
validate: deps
	@$(MAKE) --no-print-directory build/mpsph
	@$(PYTHON) scripts/validate.py $(if $(filter 1,$(QUICK)),--quick) --jobs $(JOBS) $(VALIDATE_ARGS)

clean:
	rm -rf build
