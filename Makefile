# The two commands of the README. Everything else is CMake.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all deps configure build verify test certify bench sanitize fuzz ci clean

all: build

deps:
	scripts/install-deps

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

verify: build
	$(BUILD)/bin/simpson-verify

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The paper scene's claims with their Coq certificates checked by coqc (certificates/*.v in
# reports/out/certify); exit 1 when coqc rejects one. Also ctest's label coq, part of `make test`.
certify: build
	$(BUILD)/bin/simpson-verify --claims all --certify --out reports/out/certify

# Google Benchmark (bench/), not part of `make test`: times measured side by side in one run; the last
# lines printed are the ratios (`ratio <name> <value>`).
bench: build
	$(BUILD)/bin/simpson_bench --benchmark_min_time=0.5 --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (-O1), in build-sanitize/.
# Leak reports from third-party libraries are suppressed in scripts/lsan.supp, each with its reason.
# -g1 (line tables only): reports keep file:line, and the build is about a third faster than with -g.
sanitize: deps
	cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DSIMPSON_SANITIZE=ON
	cmake --build build-sanitize -j $(JOBS)
	cd build-sanitize && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0 \
	  ctest --output-on-failure -j $(JOBS)

# The scene parser under libFuzzer (clang) for 60 s, in build-fuzz/.
fuzz: deps
	cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCMAKE_CXX_COMPILER=clang++ -DSIMPSON_FUZZ=ON
	cmake --build build-fuzz -j $(JOBS) --target scene_parser_fuzz
	scripts/run-fuzz build-fuzz/bin/scene_parser_fuzz 60

# What CI runs (.ci/run): the tests, then the same under sanitizers, then the fuzzer.
ci: test sanitize fuzz

clean:
	rm -rf $(BUILD) build-sanitize build-fuzz
