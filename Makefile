# The two commands of the README. Everything else is CMake.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
SANITIZE_BUILD ?= build-sanitize

.PHONY: all deps configure build verify test certify reference bench sanitize-configure sanitize-build sanitize sanitize-smoke-build sanitize-smoke fuzz ci clean

all: build

# Each command installs what it needs (scripts/install-deps verify|test|ci): `make verify` neither
# chromium nor clang. A target's profile holds for the targets it depends on.
DEPS_PROFILE ?= test
verify certify: DEPS_PROFILE = verify
sanitize-configure sanitize-build sanitize sanitize-smoke-build sanitize-smoke fuzz ci: DEPS_PROFILE = ci

deps:
	scripts/install-deps $(DEPS_PROFILE)

# A new build directory gets Ninja (finer-grained parallelism than make: a library's units compile
# while the libraries it links are still being built) and one unit per target (the fastest build from
# scratch; cmake/unity_groups.cmake); a directory configured earlier keeps both. A developer who
# edits and rebuilds wants one unit per named group: cmake -DSIMPSON_UNITY_GROUPING=groups $(BUILD).
NEW_BUILD_DIRECTORY = -G Ninja -DSIMPSON_UNITY_GROUPING=targets
# The tests are on for every target but those of the verify profile (verify, certify), for which a new
# build directory is configured without them (CMake's SIMPSON_TESTS): `make test` after them
# reconfigures with them.
TESTS_SETTING = $(if $(filter verify,$(DEPS_PROFILE)),$(if $(wildcard $(BUILD)/CMakeCache.txt),,-DSIMPSON_TESTS=OFF),-DSIMPSON_TESTS=ON)
configure: deps
	cmake -S . -B $(BUILD) $(if $(wildcard $(BUILD)/CMakeCache.txt),,$(NEW_BUILD_DIRECTORY)) -DCMAKE_BUILD_TYPE=Release $(TESTS_SETTING)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# Only what it runs: the CLI and the libraries it links, not the tests and benchmarks (nor the
# packages only they need). coqc checks the claims' Coq certificates by default wherever it is
# installed (scripts/install-deps installs it), so the counts the report shows are checked counts.
# Each phase is timed (install, configure, build, scene): scripts/make-verify.
verify:
	scripts/make-verify $(BUILD) $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The committed reference report, regenerated whole by one run, from a clean tree at a commit (the
# report records it; ReferenceReport.IsOneRunFromACleanTree checks it), and README's generated counts.
reference: configure
	@test -z "$$(git status --porcelain)" || \
	  { echo "make reference: the tree has uncommitted changes; commit them first (the report records its commit)"; exit 2; }
	cmake --build $(BUILD) -j $(JOBS) --target simpson-verify
	$(BUILD)/bin/simpson-verify --out reports/reference/paper
	$(BUILD)/bin/simpson-verify --scene stiff --out reports/reference/stiff
	scripts/readme-counts --write

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
# on every unit (our code instrumented, the third-party libraries' header templates not:
# scripts/sanitize-ignorelist.txt says which and why), all at -O0 (-g1: line tables only, so
# reports keep file:line at a third less build time), linked by lld (the test binary's link: 14 s with GNU ld, 3.4 s with lld). clang with ASan
# compiles at -O0 2.5 to 3.3 times faster than at -O1 (scripts/build-profile),
# and the suite there runs no long scene (see `sanitize` below), so optimising would cost more build
# time than it saves run time.
# It is the one other compile of the suite, and each of its two uses needs it:
#   - `make sanitize` runs the tests of `make test` in it;
#   - `make fuzz` runs the libFuzzer targets of the TeX reader, the scene parser and the claims-file reader, built in
#     the same tree (libFuzzer needs clang): only scene.cpp and claims_file.cpp get libFuzzer's
#     coverage instrumentation, the rest is reused as it is.
# The Release build of `make test` is not replaced by it: that is what users build (GCC, -O2, whose
# warnings differ from clang's), so CI compiles the suite twice, once per compiler and purpose.
# Leak reports from third-party libraries are suppressed in scripts/lsan.supp, each with its reason.
sanitize-configure: deps
	cmake -S . -B $(SANITIZE_BUILD) $(if $(wildcard $(SANITIZE_BUILD)/CMakeCache.txt),,$(NEW_BUILD_DIRECTORY)) -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_CXX_FLAGS_DEBUG="-O0 -g1" -DSIMPSON_LIGHT_OPTIMIZATION=-O0 -DCMAKE_CXX_COMPILER=clang++ \
	  -DSIMPSON_SANITIZE=ON -DSIMPSON_FUZZ=ON -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld

sanitize-build: sanitize-configure
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)

# Every test of `make test` runs under the sanitizers except these (none runs code of ours that the
# tests kept there do not run too):
#   - label external (coq.certificates, coq.roundoff, report.html_render): coqc, gappa and chromium are
#     the same programs in either build, so they run once, in the Release suite; the sanitized runs of
#     the CLI pass --no-certify (SIMPSON_VERIFY_ARGS, verify/tests/CMakeLists.txt);
#   - the test cases that call coqc themselves (SANITIZE_SKIP): coqc again, on files our code wrote;
#     the code that writes them runs in the cases kept;
#   - label docs (docs.readme_counts, docs.ci_recipes): Python on the committed report, and the docs'
#     CI recipes as written (the full paper scene with coqc); compare's code runs in ReferenceReport.Compare*;
#   - ReferenceReport.PaperSceneReproducesTheCommittedReport: the full paper scene (10^7 steps of
#     long_time) compared with the committed report; its claims run in Ledger/ClaimVerdict and its
#     sections, at a small size, in the quick scene (cli.exit_codes, report.*).
#   - report.schema and report.reproducible: the quick scene again (four runs of it in
#     report.reproducible, 46 s under ASan), to check properties of the files it writes (their schema,
#     the same bytes for the same seed). Its code runs under the sanitizers in cli.exit_codes' quick
#     scene; the two properties are checked in the Release suite.
#   - PaperReading.EveryFormulaOfTheEmbeddedPaperParsesAndKeepsItsVerdict: every claim of the paper
#     again (37 s under ASan), each of which runs in Ledger/ClaimVerdict.IsAsExpected/*, one test per claim.
#   - PaperReading.AChangedCoefficientInTheTextChangesTheVerdict: the paper's claims again, on 21
#     altered copies; the reading of an altered copy and the verdicts that differ (errata, failures)
#     run in the cases kept: the altered papers of cli.exit_codes, the errata of the paper itself in
#     PaperReading.EveryFormula*, each shape's breaking input in ShapesOnADocument.*.
# Reduced: cli.exit_codes runs the family scene to s = 2, the corrected paper's claims without the four
# on Gamma (PaperReading.ACopyWithTheErrataCorrected* has them), the quick scene without table1 and
# work_precision (Report.* run them), no changed Table 1 (ChangedTable.*), and no coqc
# (cli_test.sh main-reduced); cli.beyond_scene runs the beyond scene's claims with 4 samples, but family-symplectic
# (41 s there; Ledger/ClaimVerdict.IsAsExpected/family_symplectic runs it), and its nonlinear section
# at a small size (every problem and table; cli_test.sh beyond-scene-reduced); cli.interruption
# interrupts the process group at each kind of moment once (cli_test.sh interruption-reduced);
# ConventionSearch.RandomHiddenConventionsOverTheWholeFamilyAreAllRecovered draws 2 hidden conventions
# instead of 20 (SIMPSON_SANITIZED: each search is the same code, several seconds at -O0 under ASan).
# The inseparable section's three numeric runs (25-32 s each at -O0 under ASan, measured 2026-12-02)
# run in the Release suite; its refusals and a Newton failure inside a run (the input paths) stay here.
# Two families more, each run under the sanitizers by a shorter sibling (measured 2026-12-02: 1018 s
# of the suite's first 1276 s of CPU were its 38 tests over 10 s, the suite 25 minutes in all):
#   - whole runs whose files are what they check (SANITIZE_SKIP_RUNS): the quick scene, or the paper
#     and its copies, run end to end (13-102 s each under ASan) to check the bytes of report.json,
#     report.md, the JUnit file and the plots (the same bytes the Release suite checks); the code
#     that writes them runs here in cli.exit_codes' runs, the claims' in Ledger/ClaimVerdict.*, and
#     a fix, a baseline and a changed premise in FixOrChange.APremiseThatBrokeIsNoFix and
#     ErratumContent.ASecond*;
#   - convergence runs (SANITIZE_SKIP_CONVERGENCE): an order, a Lyapunov exponent, an energy bound or
#     a covering fitted from many steps (14-25 s each), where the step they repeat runs here in its own
#     tests (DiscreteLagrangian.*, DiscreteLagrangianNoether.*, EnclosedLagrangianStep.Contains*,
#     HamiltonianPrk.LobattoIs*, Vprk.WithTheNullVector*, DoublePendulum.*, ConventionSearch.* but one);
#     the two records that observe the inseparable section's facts (39-40 s each) among them: the
#     section's step, its Newton failure and its refusals run here in Inseparable.* and
#     DiscreteLagrangian*, the facts' code in the Release suite. With both families out: the suite
#     504 s on the two cores, 997 s of CPU (2026-12-02), before these two records;
#   - a general L's symplectic identity (SANITIZE_SKIP_GRIDS): our kernel's 3645-point grid of
#     rational functions over cpp_rational, 66 and 84 s of CPU under ASan (2026-12-03), in the
#     symplectic-step fixture and the simpson-any-lagrangian note; their siblings
#     *_without_the_general_grid run every other claim of both here, and the same step with L defined
#     (simpson-det-oscillator), the grid's code in every other kernel decision; and Table 1's
#     convention search on three altered copies (ChangedTable.*, 17-22 s of CPU each under ASan): the
#     search runs here in ConventionSearch.* and Ledger/ClaimVerdict.IsAsExpected/table_values, the
#     altered copies' reading in cli.exit_codes.
SANITIZE_SKIP_GRIDS = shapes\.symplectic-step$$|notes\.simpson-any-lagrangian$$|ChangedTable\.(ATableComputedWithSimpleValuesIsExplainedByThem|AnotherConsistentStatedSolutionIsSearchedNotFailed|AnEntryIsJudgedToTheDigitsItIsPrintedWith)
SANITIZE_SKIP_RUNS = Report\.(SameSceneAndSeedGiveIdenticalReportsApartFromTheirRunTimes|WritesEveryFileAtomically|HasTheRequiredFieldsAndAnErrataSection|ADirectoryHoldingOtherFilesIsRefusedAndKept)|JUnit\.(ParsesAndCountsEveryClaimAndTable|FailuresAreExactlyWhatMakesTheExitCodeNonZero|AValidationFailsWhatDoesNotHoldAndNamesACauseOnce)|PlotStyle\.|ErratumContent\.(AFixIsReportedAsFixedAndPassesWhenAccepted|NothingMayGetWorseThanABaseline|OneMoreChangedEntryOfTable1IsAChangedVerdict)|FixOrChange\.AFixOfTheTextItReadsIsAFix|RefereesCases\.|ChangedTable\.(TheStatedConventionsAreJudgedByWhetherTheyReproduceTheTable|TableOneIsJudgedAsPrinted)|GappaClaims\.TableOnesDigitsAreAboveTheProvedRoundoffAndTooManyDigitsFail|Experiments\.OnlyTheSectionsAskedForAreComputed
SANITIZE_SKIP_CONVERGENCE = DoublePendulumLyapunov\.|DoublePendulumReference\.|DiscreteLagrangianOrders\.|DiscreteLagrangianEnergy\.|Vprk\.Lobatto3IsOfOrderFour|HamiltonianPrk\.LobattoAndRk4AreOfOrderFour|EnclosedLagrangianStep\.ABoxOfStarts|HighPrecision\.EverySectionAtMpfr3000|Inseparable\.MomentaMoveOnlyWithinTheBound|ConventionSearch\.AHiddenConventionIsRecoveredWithItsParameters|Ledger/ClaimVerdict\.IsAsExpected/inseparable_(simpson_order|top_momenta)
SANITIZE_SKIP = $(SANITIZE_SKIP_RUNS)|$(SANITIZE_SKIP_CONVERGENCE)|$(SANITIZE_SKIP_GRIDS)|Inseparable\.(OrderFactProvesFourAndTwo|APerturbedExactSolutionFails|SectionMeetsItsExpectationsAtASmallSize)|report\.schema|report\.reproducible|PaperReading\.EveryFormulaOfTheEmbeddedPaperParsesAndKeepsItsVerdict|ReferenceReport\.PaperSceneReproducesTheCommittedReport|PaperReading\.AChangedCoefficientInTheTextChangesTheVerdict|Gappa\.TheBoundsCoqProofIsCheckedByCoqc|GappaGlobal\.TheLiftingLemmaIsCheckedByCoqc|CoqBatch\.OneProcess
SANITIZE_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:symbolize=$(1) UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:symbolize=$(1) \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0
# Stacks are symbolized only for the tests that failed, in a second run of those alone. Symbolizing
# costs 0.45 s in every process that links GiNaC, whatever it tests: LeakSanitizer symbolizes the
# stack of CLN's suppressed leak (scripts/lsan.supp) to match it, and llvm-symbolizer loads the
# 270 MB test binary's line tables for that (0.78 s against 0.33 s for verify_tests running no test;
# about 300 such processes in ctest and 100 in cli_test.sh). Module names are matched without it,
# so the suppression holds, and UBSan names its file and line from its own data either way.
# A run that fails before any test does (no LastTestsFailed.log) reruns nothing. The failed tests
# are rerun by name, not by number (ctest --rerun-failed): the tests gtest_discover_tests lists at
# test time (PRE_TEST) are numbered anew in each run, and a number of the first run named another
# test in the second.
SANITIZE_CTEST = cd $(SANITIZE_BUILD) && rm -f Testing/Temporary/LastTestsFailed.log && \
	  $(call SANITIZE_ENV,0) ctest --output-on-failure -j $(JOBS) $(1) || \
	  { if [ -s Testing/Temporary/LastTestsFailed.log ]; then echo "sanitize: the failed tests again, with symbolized stacks:"; \
	      failed=$$(sed 's/^[0-9]*://; s/[][\\.*^$$+?(){}|/]/\\&/g' Testing/Temporary/LastTestsFailed.log | paste -sd'|'); \
	      $(call SANITIZE_ENV,1) ctest --output-on-failure -j $(JOBS) -R "^($$failed)\$$"; fi; exit 1; }
sanitize: sanitize-build
	$(call SANITIZE_CTEST,-LE 'external|docs' -E '$(SANITIZE_SKIP)')

# CI's sanitizer phase (`make ci`): what the 20-minute budget leaves room for beside `make test`.
# The whole suite above takes 322 s to build and 353 s to run (2026-12-03, measured in CI's phases:
# 1634 s for `.ci/run` with it); this phase builds only the CLI, the engine's runner, the TeX dump
# and the three fuzz targets (193 s of the 322: the libraries are most of it) and runs, under ASan
# and UBSan, each note of the corpus and each proof shape's fixture end to end (the reader, the
# shapes, both kernels, the consequences), the TeX refusal corpus, every refusal of a claims file,
# and the CLI on the quick scene (its claims, the experiments' steppers, the report writers); the
# grid runs and skips of `make sanitize` apply. It compiles the benchmarks too (never
# run here), which `make build` leaves to `make bench`. Run `make sanitize`, the whole
# suite, before landing a change to memory-handling code (the reader, the kernels, the steppers).
SANITIZE_SMOKE_TARGETS = simpson-verify engine-runner tex_support_dump tex_reader_fuzz scene_parser_fuzz claims_file_fuzz simpson_bench
SANITIZE_SMOKE = ^(notes\.|shapes\.|engine\.|tex\.refusals|cli\.refusals_in_one_pass|cli\.sanitized_quick_scene)
sanitize-smoke-build: sanitize-configure
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target $(SANITIZE_SMOKE_TARGETS)

sanitize-smoke: sanitize-smoke-build
	$(call SANITIZE_CTEST,-R '$(SANITIZE_SMOKE)' -E '$(SANITIZE_SKIP)')

# The TeX reader under libFuzzer for 25 s on one core, beside the scene parser and then the
# claims-file reader for 12 s each on the other; the targets are built by sanitize-smoke-build. Each
# one's report is printed whole after all have stopped, in that order.
fuzz: sanitize-smoke-build
	@scripts/run-fuzz $(SANITIZE_BUILD)/bin/tex_reader_fuzz 25 >$(SANITIZE_BUILD)/fuzz-tex.out 2>&1 & tex=$$!; \
	  scripts/run-fuzz $(SANITIZE_BUILD)/bin/scene_parser_fuzz 12 >$(SANITIZE_BUILD)/fuzz-scene.out 2>&1; scene=$$?; \
	  scripts/run-fuzz $(SANITIZE_BUILD)/bin/claims_file_fuzz 12 >$(SANITIZE_BUILD)/fuzz-claims.out 2>&1; claims=$$?; \
	  wait $$tex; tex=$$?; \
	  echo "fuzz: TeX reader (exit $$tex):"; cat $(SANITIZE_BUILD)/fuzz-tex.out; \
	  echo "fuzz: scene parser (exit $$scene):"; cat $(SANITIZE_BUILD)/fuzz-scene.out; \
	  echo "fuzz: claims-file reader (exit $$claims):"; cat $(SANITIZE_BUILD)/fuzz-claims.out; \
	  [ $$tex = 0 ] && [ $$scene = 0 ] && [ $$claims = 0 ]

# What CI runs (.ci/run, which times each phase): the tests, then the sanitizers' smoke run, then the fuzzer.
ci: test sanitize-smoke fuzz

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD)
