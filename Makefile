# The two commands of the README. Everything else is CMake.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
SANITIZE_BUILD ?= build-sanitize

.PHONY: all deps configure build verify test certify bench sanitize-build sanitize fuzz ci clean

all: build

deps:
	scripts/install-deps

# Ninja for a new build directory (finer-grained parallelism than make: a library's units compile
# while the libraries it links are still being built); a directory configured earlier keeps its generator.
configure: deps
	cmake -S . -B $(BUILD) $(if $(wildcard $(BUILD)/CMakeCache.txt),,-G Ninja) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# Only what it runs: the CLI and the libraries it links, not the tests and benchmarks. With coqc
# installed (scripts/install-deps installs it), the claims' Coq certificates are checked too
# (--certify, about 30 s on 2 cores), so the counts the report shows are checked counts.
verify: configure
	cmake --build $(BUILD) -j $(JOBS) --target simpson-verify
	$(BUILD)/bin/simpson-verify $(if $(shell command -v coqc),--certify,)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The paper scene's claims with their Coq certificates checked by coqc (certificates/*.v in
# reports/out/certify); exit 1 when coqc rejects one. Also ctest's label coq, part of `make test`.
certify: configure
	cmake --build $(BUILD) -j $(JOBS) --target simpson-verify
	$(BUILD)/bin/simpson-verify --claims all --certify --out reports/out/certify

# Google Benchmark (bench/), not part of `make test`: times measured side by side in one run; the last
# lines printed are the ratios (`ratio <name> <value>`).
bench: configure
	cmake --build $(BUILD) -j $(JOBS) --target simpson_bench
	$(BUILD)/bin/simpson_bench --benchmark_min_time=0.5 --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

# The sanitizer build, in $(SANITIZE_BUILD)/: clang with AddressSanitizer and UndefinedBehaviorSanitizer
# on every unit (-g1: line tables only, so reports keep file:line at a third less build time). The
# code whose runs are long (the core's steppers in the experiments) at -O1; the rest, the "light" code
# of CMakeLists.txt (ledger, paper reader, reports, CLI, tests), at -O0: clang with ASan compiles
# it 2.5 to 3.3 times faster than at -O1, and the suite runs long either way (scripts/build-profile).
# It is the one other compile of the suite, and each of its two uses needs it:
#   - `make sanitize` runs every test of `make test` in it;
#   - `make fuzz` runs the scene parser's libFuzzer target, built in the same tree (libFuzzer needs
#     clang): only scene.cpp gets libFuzzer's coverage instrumentation, the rest is reused as it is.
# The Release build of `make test` is not replaced by it: that is what users build (GCC, -O2, whose
# warnings differ from clang's), so CI compiles the suite twice, once per compiler and purpose.
# Leak reports from third-party libraries are suppressed in scripts/lsan.supp, each with its reason.
sanitize-build: deps
	cmake -S . -B $(SANITIZE_BUILD) $(if $(wildcard $(SANITIZE_BUILD)/CMakeCache.txt),,-G Ninja) -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DSIMPSON_LIGHT_OPTIMIZATION=-O0 -DCMAKE_CXX_COMPILER=clang++ \
	  -DSIMPSON_SANITIZE=ON -DSIMPSON_FUZZ=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)

sanitize: sanitize-build
	cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0 \
	  ctest --output-on-failure -j $(JOBS)

# The scene parser under libFuzzer for 60 s (the target is built by sanitize-build).
fuzz: sanitize-build
	scripts/run-fuzz $(SANITIZE_BUILD)/bin/scene_parser_fuzz 60

# What CI runs (.ci/run): the tests, then the same under sanitizers, then the fuzzer.
ci: test sanitize fuzz

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD)
