#!/usr/bin/env bash
# Exit codes and output of simpson-verify: 0 as expected, 1 a verdict differs, 2 bad input with
# one line on stderr and nothing written.
#   cli_test.sh BIN               every check but the beyond scene's
#   cli_test.sh BIN beyond-scene  the embedded beyond scene, whole (its nonlinear section takes most
#                                 of the time): a ctest test of its own, so that it runs beside the rest
#   cli_test.sh BIN interruption  SIGINT and SIGTERM at every moment of a run, the process group's
#                                 Ctrl-C included: a ctest test of its own (cli.interruption)
#   cli_test.sh BIN interruption-reduced  the same with each kind of moment once (the sanitizer suite's)
#   cli_test.sh BIN beyond-scene-reduced  its claims but family-symplectic (tested on its own) in every
#                                 precision with 4 samples, and its nonlinear section at a small size
#                                 (every problem and table): the sanitizer suite's
#   cli_test.sh BIN main-reduced  every check but the beyond scene's, the family scene to s = 2 (its
#                                 table, plot and order line; s = 3, 4 are 90% of its time), no coqc,
#                                 the corrected paper without its claims on Gamma, the quick scene
#                                 without its table1 and work_precision, no changed Table 1, and a
#                                 fuller report of two claims: the sanitizer suite's
set -u
bin="$(realpath "$1")"
part="${2:-main}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
# Runs check coqc only where they test it (--certify): coqc is the default wherever it is installed,
# and coq_certificates_test.sh checks the certificates once.
certify_flag() { case " $* " in *" --certify "*|*" --no-certify "*) ;; *) echo --no-certify ;; esac; }
check() {  # check NAME EXPECTED_CODE ARGS...
  local name="$1" want="$2"
  shift 2
  local start=$EPOCHREALTIME
  "$bin" $(certify_flag "$@") "$@" >"$work/out" 2>"$work/err"
  local got=$?
  # CLI_TEST_TIMES=1: each check's seconds, to see where the script's time goes.
  [ -n "${CLI_TEST_TIMES:-}" ] && printf 'time %6.2f s  %s\n' "$(echo "$EPOCHREALTIME - $start" | bc)" "$name"
  if [ "$got" != "$want" ]; then
    echo "FAIL $name: exit $got, expected $want"; sed 's/^/  stderr: /' "$work/err" | head -5
    failures=$((failures + 1))
  elif [ "$want" = 2 ] && { [ ! -s "$work/err" ] || grep -qv '^simpson-verify: ' "$work/err" || [ "$(sort "$work/err" | uniq -d | wc -l)" != 0 ]; }; then
    echo "FAIL $name: expected one line on stderr per refusal, each after 'simpson-verify: '"; cat "$work/err"
    failures=$((failures + 1))
  else
    echo "ok   $name"
    passes=$((passes + 1))
  fi
}

fail() { echo "FAIL $1"; failures=$((failures + 1)); }

if [ "$part" = beyond-scene ] || [ "$part" = beyond-scene-reduced ]; then
  if [ "$part" = beyond-scene ]; then
    check "beyond scene" 0 --scene beyond --quiet --out "$work/beyond"
  else
    # Every claim of the beyond scene but family-symplectic: 41 s under the sanitizers, and its own
    # test there, Ledger/ClaimVerdict.IsAsExpected/family_symplectic, runs the same code.
    cat >"$work/beyond-reduced.json" <<'JSON'
{"name": "beyond-reduced", "claims": ["nonlinear-step-derivation", "nonlinear-lobatto-equivalence", "nonlinear-symplectic", "nonlinear-order-4",
 "internal-node-solvability", "ndof-symplectic", "ndof-energy", "ndof-stability", "fpu-second-band-invariant"],
 "precisions": ["double", "long double", "float128", "bin50", "mpfr:50", "mpfr:100"],
 "samples": 4, "seed": 20230830,
 "nonlinear": {"pendulum_N": [10, 20], "energy_steps": 100, "brouwer_steps": 1000, "problems": ["pendulum", "kepler", "henon-heiles", "fpu"],
               "N": [64, 128], "double_pendulum_N": [10, 20], "max_runs": 1}}
JSON
    check "beyond scene, reduced" 0 --scene "$work/beyond-reduced.json" --quiet --out "$work/beyond"
  fi
  claims_held=12
  [ "$part" = beyond-scene ] || claims_held=9
  grep -q "^$claims_held claims: $claims_held held, 0 errata, 0 failed; all verdicts as expected" "$work/out" ||
    { echo "FAIL beyond scene: $(cat "$work/out")"; failures=$((failures + 1)); }
  echo "$passes passed, $failures failed"
  [ "$failures" = 0 ]
  exit
fi

if [ "$part" = interruption ] || [ "$part" = interruption-reduced ]; then
# Interruption: a long run (10000 samples per recheck) stopped after one second.
for sig in INT TERM; do
  "$bin" ${SIMPSON_VERIFY_ARGS:-} --samples 10000 --out "$work/stopped-$sig" >"$work/out" 2>"$work/err" &
  pid=$!
  sleep 1
  kill -"$sig" "$pid"
  wait "$pid"
  got=$?
  want=$([ "$sig" = INT ] && echo 130 || echo 143)
  if [ "$got" != "$want" ] || ! grep -q "interrupted (SIG$sig)" "$work/err" || [ -n "$(ls -A "$work/stopped-$sig" 2>/dev/null)" ]; then
    echo "FAIL SIG$sig: exit $got (expected $want), stderr: $(tail -1 "$work/err"), files: $(ls -A "$work/stopped-$sig")"
    failures=$((failures + 1))
  else
    echo "ok   SIG$sig stops the run with $got and writes nothing"
    passes=$((passes + 1))
  fi
done
# The same during an experiment section (work_precision in mpfr:1000, minutes long), stopped within
# seconds: interruption is checked every 1024 steps and points (interruption.hpp), about 0.01 s of
# work at mpfr:1000 in Release; the limit is 10 s so that the sanitizer build, ten times slower,
# passes too. The exact solution's 10^5 points at 1000 digits once ignored the signal for 37 s.
echo '{"name": "slow", "work_precision": {"precisions": ["mpfr:1000"], "N": [100000]}}' >"$work/slow.json"
"$bin" ${SIMPSON_VERIFY_ARGS:-} --scene "$work/slow.json" --allow-expensive --out "$work/stopped-section" >"$work/out" 2>"$work/err" &
pid=$!
sleep 1
kill -INT "$pid"
signalled=$SECONDS
wait "$pid"
got=$?
latency=$((SECONDS - signalled))
if [ "$got" != 130 ] || [ -n "$(ls -A "$work/stopped-section" 2>/dev/null)" ] || [ "$latency" -gt 10 ]; then
  echo "FAIL SIGINT in a section: exit $got after $latency s, files: $(ls -A "$work/stopped-section")"; failures=$((failures + 1))
else
  echo "ok   SIGINT during an experiment section stops it with 130 and writes nothing"
  passes=$((passes + 1))
fi
# A terminal's Ctrl-C goes to the whole process group (gnuplot included). Each moment below, the
# run is its own group (setsid) and the group gets SIGINT: the run exits 130 and leaves the previous
# report byte-identical, or, when the signal came after the report was swapped into place, exits 0
# with the new report complete. One moment is while gnuplot draws (waited for with pgrep).
"$bin" ${SIMPSON_VERIFY_ARGS:-} --scene quick --sections stability,long_time --out "$work/group" >/dev/null 2>&1 || fail "process group: the first run failed"
snapshot() { (cd "$work/group" && find . -type f | sort | xargs sha256sum); }
before=$(snapshot)
group_interrupt() {  # group_interrupt WHEN: a delay in seconds; "gnuplot" (while it draws); "staging" (once the report is staged)
  setsid "$bin" ${SIMPSON_VERIFY_ARGS:-} --scene quick --sections stability,long_time --samples 1000 --seed 7 --out "$work/group" >"$work/out" 2>"$work/err" &
  local pid=$!
  case "$1" in
    # gnuplot runs while its <plot>.log exists in the staging directory (made before exec, removed after)
    gnuplot|gnuplot-alone) while kill -0 "$pid" 2>/dev/null && ! compgen -G "$work/.group.*.staging/*.log" >/dev/null; do sleep 0.005; done
             compgen -G "$work/.group.*.staging/*.log" >/dev/null || fail "process group: gnuplot never seen running" ;;
    staging) while kill -0 "$pid" 2>/dev/null && ! compgen -G "$work/.group.*.staging" >/dev/null; do sleep 0.005; done ;;
    *) sleep "$1" ;;
  esac
  if [ "$1" = gnuplot-alone ]; then kill -INT "$pid" 2>/dev/null; else kill -INT -- "-$pid" 2>/dev/null; fi
  wait "$pid"
  local got=$?
  if [ "$got" = 130 ]; then
    [ "$(snapshot)" = "$before" ] && grep -q "interrupted (SIGINT)" "$work/err" && ! ls -A "$work" | grep -q 'staging\|\.old$' &&
      { echo "ok   SIGINT to the process group ($1): 130, previous report byte-identical"; passes=$((passes + 1)); } ||
      fail "SIGINT to the process group ($1): exit 130 but the previous report changed or staging left: $(ls -A "$work" | grep 'staging\|old')"
  elif [ "$got" = 0 ] && [ "${1#gnuplot}" = "$1" ] && grep -q '"seed": 7' "$work/group/report.json" && [ -f "$work/group/truncation_digits.png" ]; then
    echo "ok   SIGINT to the process group ($1): came after the swap, new report complete"; passes=$((passes + 1))
    before=$(snapshot)
  else
    fail "SIGINT to the process group ($1): exit $got, stderr: $(tail -2 "$work/err")"
  fi
}
moments="0.3 staging gnuplot 0.6 gnuplot gnuplot-alone"
[ "$part" = interruption-reduced ] && moments="0.3 staging gnuplot gnuplot-alone"  # each kind of moment once
for moment in $moments; do group_interrupt "$moment"; done
  echo "$passes passed, $failures failed"
  [ "$failures" = 0 ]
  exit
fi

# The family scene's fast subset (s = 1 … 4, a few seconds; the embedded scene goes to 6): the paper's
# scheme, Newmark, Lobatto's order 2s and the plot. Its claim, family-symplectic, runs in the beyond scene.
family_degree=4
orders='s = 1: order 2, s = 2: order 4, s = 3: order 6, s = 4: order 8\.'
if [ "$part" = main-reduced ]; then family_degree=2; orders='s = 1: order 2, s = 2: order 4\.'; fi
echo "{\"name\": \"family-fast\", \"family\": {\"max_degree\": $family_degree}}" >"$work/family.json"
check "family scene" 0 --scene "$work/family.json" --quiet --out "$work/family"
grep -q '^| s = 2, Simpson | 3 | yes | yes | yes | 4 | yes | 1/1440 | (0, 2 sqrt(2)) ∪ (2 sqrt(3), 2 sqrt(6)) | Φ₃' "$work/family/report.md" ||
  fail "family scene: the row of Φ₃ (s = 2, Simpson)"
grep -q '^| s = 1, midpoint | 1 | yes | yes | yes | 2 | yes | -1/6 | (0, ∞) | Newmark' "$work/family/report.md" ||
  fail "family scene: the row of Newmark (s = 1, midpoint)"
grep -q "$orders" "$work/family/report.md" ||
  fail "family scene: Lobatto s + 1 of order 2s"
if command -v gnuplot >/dev/null; then [ -s "$work/family/family_bands.png" ] || fail "family scene: the stability-band plot is missing"; fi

# Under the sanitizers the quick scene's claims and its two cheapest sections (its table1, with the
# convention search, and the rest run in process there: Report.*, ChangedTable.*, Experiments.*).
quick_sections=()
[ "$part" = main-reduced ] && quick_sections=(--sections stability,long_time)
check "quick scene" 0 --scene quick "${quick_sections[@]}" --out "$work/quick"
[ -f "$work/quick/report.json" ] && [ -f "$work/quick/report.md" ] || { echo "FAIL quick: reports missing"; failures=$((failures + 1)); }
grep -q 'seed 20230830' "$work/out" || { echo "FAIL quick: seed not printed"; failures=$((failures + 1)); }
check "claims filter" 0 --scene quick --claims phi3-det,hd-invariance --precisions double,rational --out "$work/filter"
grep -q '^2 claims' "$work/out" || { echo "FAIL claims filter: not 2 claims"; failures=$((failures + 1)); }

cat >"$work/override.json" <<'JSON'
{"name": "override", "claims": ["phi3-det"], "precisions": ["double"], "expected_overrides": {"phi3-det": "fails"}}
JSON
check "unexpected verdict" 1 --scene "$work/override.json" --out "$work/override"
grep -q 'phi3-det: verdict holds, expected fails' "$work/err" || { echo "FAIL unexpected verdict: not named"; failures=$((failures + 1)); }

check "unknown flag" 2 --bogus
check "unknown scene" 2 --scene no-such-scene --out "$work/none1"
check "unknown claim" 2 --scene quick --claims phi4-det --out "$work/none2"
check "unknown precision" 2 --scene quick --precisions quad --out "$work/none3"
check "mpfr digits" 2 --scene quick --precisions mpfr:5 --out "$work/none4"
check "bad seed" 2 --scene quick --seed -4 --out "$work/none5"
check "bad samples" 2 --scene quick --samples 0 --out "$work/none6"
check "bad enclosure budget" 2 --scene quick --enclosure-budget 39 --out "$work/none6b"
grep -q -- "--enclosure-budget '39'" "$work/err" || { echo "FAIL bad enclosure budget: not named: $(cat "$work/err")"; failures=$((failures + 1)); }
check "enclosure budget" 0 --scene quick --claims peer-schemes --enclosure-budget 80 --out "$work/budget"
grep -q '"enclosure_budget_digits": 80' "$work/budget/report.json" || { echo "FAIL enclosure budget: not in report.json"; failures=$((failures + 1)); }
grep -q '"decision": "holds"' "$work/budget/report.json" || { echo "FAIL enclosure budget: no enclosure decision"; failures=$((failures + 1)); }
echo '{"name": "x", "claims": [,]}' >"$work/malformed.json"
check "malformed scene" 2 --scene "$work/malformed.json" --out "$work/none7"
grep -q 'line 1, column' "$work/err" || { echo "FAIL malformed scene: no line and column"; failures=$((failures + 1)); }
: >"$work/empty.json"
check "empty scene file" 2 --scene "$work/empty.json" --out "$work/none9"
printf '{"name": "x", "claims": "all", "precisions": ["dou' >"$work/truncated.json"
check "truncated scene file" 2 --scene "$work/truncated.json" --out "$work/none10"
echo '{"name": "x", "claims": "all", "precisions": "double"}' >"$work/wrongtype.json"
check "wrong type" 2 --scene "$work/wrongtype.json" --out "$work/none11"
echo '{"name": "x", "claims": "all", "precisions": ["double"], "extra": 1}' >"$work/unknown.json"
check "unknown key" 2 --scene "$work/unknown.json" --out "$work/none8"
touch "$work/a-file"
check "unwritable out" 2 --scene quick --out "$work/a-file/sub"
# Experiment parameters (each section's fields are validated before anything runs).
bad_section() {  # bad_section NAME K JSON-MEMBERS EXPECTED-TEXT
  echo "{\"name\": \"x\", $3}" >"$work/section$2.json"
  check "$1" 2 --scene "$work/section$2.json" --out "$work/none$2"
  grep -q -- "$4" "$work/err" || { echo "FAIL $1: stderr lacks '$4': $(cat "$work/err")"; failures=$((failures + 1)); }
}
bad_section "m <= 0" 12 '"table1": {"m": -1}' "'table1.m' must be a number greater than 0"
bad_section "N = 0" 13 '"table1": {"N": [10, 0]}' "'table1.N'\[1\] must be an integer from 1"
bad_section "absurd N" 14 '"work_precision": {"precisions": ["double"], "N": [1e15]}' "'work_precision.N'\[0\]"
bad_section "NaN literal" 15 '"table1": {"m": NaN}' "malformed JSON at line 1, column"
bad_section "infinite omega h" 16 '"stability": {"precisions": ["double"], "omega_h": [1e999]}' "malformed JSON"
bad_section "h = 0" 17 '"stability": {"precisions": ["double"], "omega_h": [0]}' "'stability.omega_h'\[0\] must be a number greater than 0"
bad_section "stiff ratio < 2" 18 '"stability": {"precisions": ["double"], "stiff_ratios": [1]}' "'stability.stiff_ratios'\[0\]"
bad_section "rational in experiments" 19 '"work_precision": {"precisions": ["rational"]}' "has no cos or sin"
bad_section "unknown scheme" 20 '"work_precision": {"precisions": ["double"], "schemes": ["euler"]}' "unknown scheme 'euler'"
bad_section "digits > 100000" 21 '"long_time": {"mpfr_digits": 200000}' "'long_time.mpfr_digits' must be an integer from 30 to 100000"
bad_section "unknown section key" 22 '"long_time": {"step": 5}' "unknown key 'long_time.step'"
bad_section "section wrong type" 23 '"stability": []' "'stability' must be an object"
bad_section "run for days" 24 '"long_time": {"steps_double": 100000000000}' "estimated cost .* exceeds the budget .* --allow-expensive"
bad_section "unknown problem" 25 '"nonlinear": {"problems": ["lorenz"]}' "'nonlinear.problems'\[0\]: unknown name 'lorenz' (known: oscillator, pendulum, kepler, henon-heiles, fpu)"
bad_section "pendulum over the top" 26 '"nonlinear": {"pendulum_q0": 4}' "'nonlinear.pendulum_q0' must be a number greater than 0 and at most 3.14159"
bad_section "absurd nonlinear N" 27 '"nonlinear": {"N": [1e12]}' "'nonlinear.N'\[0\] must be an integer from 1 to 100000000"
for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27; do
  [ -e "$work/none$k" ] && { echo "FAIL: bad input wrote $work/none$k"; failures=$((failures + 1)); }
done

# The quick scene's report: every format, and plots in both SVG and PNG.
quick_files=(report.json report.md report.html table1.csv work_precision.csv figure1.svg figure1.png work_precision_time.svg)
[ "$part" = main-reduced ] && quick_files=(report.json report.md report.html long_time_energy.svg truncation_digits.png)
for f in "${quick_files[@]}"; do
  [ -s "$work/quick/$f" ] || { echo "FAIL quick: $f missing or empty"; failures=$((failures + 1)); }
done
# --out: a second, smaller run into the same directory replaces the report whole, so no file of
# the first run survives; no staging directory is left beside it.
echo '{"name": "small", "stability": {"precisions": ["double"], "omega_h": [1], "masses": [1], "stiff_ratios": [100], "stiff_doublings": 10, "steps": 10}}' >"$work/small.json"
check "second run into the same --out" 0 --scene "$work/small.json" --out "$work/quick"
for f in figure1.png work_precision.csv table1.csv long_time_energy.svg; do
  [ -e "$work/quick/$f" ] && fail "second run: $f of the first run survived"
done
[ -f "$work/quick/truncation_digits.png" ] || fail "second run: its own plot missing"
ls -A "$work" | grep -q 'staging\|\.old$' && fail "second run: staging left behind: $(ls -A "$work" | grep 'staging\|old')"
# A directory holding files that are not a report is refused, and nothing in it is touched.
mkdir "$work/notes" && echo keep >"$work/notes/notes.txt"
check "--out holding other files" 2 --scene "$work/small.json" --out "$work/notes"
grep -q "not a simpson-verify report" "$work/err" || fail "--out holding other files: reason not given"
[ "$(ls -A "$work/notes")" = notes.txt ] && [ "$(cat "$work/notes/notes.txt")" = keep ] || fail "--out holding other files: touched"
# ωh = 3 and 3.3 lie between 2√2 and 2√3: every run there leaves its orbit and is reported unstable, with its step.
echo '{"name": "unstable", "stability": {"precisions": ["double", "mpfr:40"], "stiff_ratios": [1e4], "stiff_doublings": 12, "omega_h": [1, 3.0, 3.3], "masses": [1], "steps": 1000}}' >"$work/unstable.json"
check "omega h = 3 is unstable" 0 --scene "$work/unstable.json" --out "$work/unstable"
[ "$(grep -c 'unstable (step' "$work/unstable/report.md")" -ge 4 ] || fail "omega h = 3: not reported unstable: $(grep -c 'unstable (step' "$work/unstable/report.md")"
# No bare NaN, infinity or null in any file of any report this script wrote.
# A JSON value, a Markdown table cell or a CSV field that is nan, inf or null; prose may name them.
bad=$( (grep -rliE ': (null|-?nan|-?inf|NaN|-?Infinity)\b|"-?(nan|inf)"' --include='report.json' "$work"
        grep -rliE '\| *-?(nan|inf|null) *\|' --include='*.md' "$work"
        grep -rliE '(^|,)-?(nan|inf|null)(,|$)' --include='*.csv' "$work") 2>/dev/null)
[ -z "$bad" ] || fail "bare NaN/inf/null in: $bad"
# Claims files (--claims-file): one that does not read is bad input, named with its line and field;
# one that reads is the ledger of the run (here: phi3-det expected to be an erratum, so exit 1).
claims_src="$(dirname "$0")/../../claims/paper.toml"
check "claims file missing" 2 --claims-file "$work/no-such.toml" --scene quick --out "$work/none-claims1"
grep -q "claims file '$work/no-such.toml': cannot be read" "$work/err" || fail "claims file missing: not named: $(cat "$work/err")"
sed '0,/expected = "holds"/s//expected = "hold"/' "$claims_src" >"$work/bad-verdict.toml"
check "claims file, bad verdict" 2 --claims-file "$work/bad-verdict.toml" --scene quick --out "$work/none-claims2"
grep -q "claims file '$work/bad-verdict.toml', line [0-9]*, field 'expected': 'hold' is not a verdict" "$work/err" ||
  fail "claims file, bad verdict: line and field not named: $(cat "$work/err")"
sed '0,/check = "scaling"/s//check = "no-such-check"/' "$claims_src" >"$work/bad-check.toml"
check "claims file, unknown check" 2 --claims-file "$work/bad-check.toml" --scene quick --out "$work/none-claims3"
printf '[[claim]]\nid = "a"\n[[claim]]\nid = "a"\n' >"$work/incomplete.toml"
check "claims file, incomplete record" 2 --claims-file "$work/incomplete.toml" --scene quick --out "$work/none-claims4"
sed '0,/observes = "table1.printed-orders"/s//observes = "table1.printed-order"/' "$claims_src" >"$work/bad-fact.toml"
check "claims file, unknown fact" 2 --claims-file "$work/bad-fact.toml" --scene quick --out "$work/none-claims5"
grep -q "claims file '$work/bad-fact.toml', line [0-9]*, field 'observes': no experiment publishes a fact named 'table1.printed-order'" "$work/err" ||
  fail "claims file, unknown fact: line and field not named: $(cat "$work/err")"
for k in 1 2 3 4 5; do [ -e "$work/none-claims$k" ] && fail "bad claims file wrote $work/none-claims$k"; done
awk 'BEGIN{p=0} /^id = "phi3-det"/{p=1} p && /^expected = "holds"/{sub(/holds/, "erratum\"\nfinding = \"erratum"); p=0} {print}' "$claims_src" >"$work/phi3-erratum.toml"
check "claims file read" 1 --claims-file "$work/phi3-erratum.toml" --scene quick --claims phi3-det --out "$work/claims-file"
grep -q "phi3-det: fixed: recorded as erratum, now holds" "$work/err" || fail "claims file read: expectation not from the file: $(cat "$work/err")"
# A record that observes a published fact is judged by it: Table 1's printed orders hold, so a file
# that expects them to fail fails the run.
awk 'BEGIN{p=0} /^id = "table-orders"/{p=1} p && /^expected = "holds"/{sub(/holds/, "fails\"\nfinding = \"erratum"); p=0} {print}' "$claims_src" >"$work/orders-fail.toml"
check "claims file, an observation" 1 --claims-file "$work/orders-fail.toml" --scene quick --claims table-orders --out "$work/claims-observed"
grep -q "table-orders: fixed: recorded as fails, now holds" "$work/err" || fail "claims file, an observation: not judged by its fact: $(cat "$work/err")"
# The exact solution at a node, q(t_n), in a note whose claims file does not say which q it is: bad
# input, naming the construct and how to declare it, nothing written.
sed "s/^solutions = \['q'\]$/functions = ['q']/" "$(dirname "$0")/notes/exact-solution-nodes.toml" >"$work/nodes-undeclared.toml"
grep -q "^functions = \['q'\]$" "$work/nodes-undeclared.toml" || fail "exact solution undeclared: the copy still declares it"
check "exact solution undeclared" 2 --paper "$(dirname "$0")/notes/exact-solution-nodes.tex" --claims-file "$work/nodes-undeclared.toml" --out "$work/nodes-undeclared"
grep -q "q(t_n) is read, but nothing says which q it is: when q(t) is the exact solution, declare it (\[symbols\] solutions = \['q'\]" "$work/err" ||
  fail "exact solution undeclared: not named: $(cat "$work/err")"
[ -e "$work/nodes-undeclared" ] && fail "exact solution undeclared: a report was written"
# A note the harness has never seen, checked from its claims file alone: its four deliberate
# errors are errata with corrections (exit 0: as the file expects); --validate judges them failures.
note_dir="$(dirname "$0")/notes"
check "a note from its claims file" 0 --paper "$note_dir/trapezoidal-note.tex" --claims-file "$note_dir/trapezoidal-note.toml" --out "$work/note"
grep -q '^13 claims: 7 held, 6 errata (1 following from another'"'"'s), 0 failed' "$work/out" || fail "a note: summary: $(cat "$work/out")"
grep -q '"correction": "stable exactly for 0 < h\*omega < 2"' "$work/note/report.json" || fail "a note: the stability correction is not in the report"
grep -q "^Exit code 0: every verdict is the expected one, the claims file's expected verdicts for its document" "$work/note/report.md" ||
  fail "a note: the exit line speaks of the paper"
ls "$work/note"/*.csv >/dev/null 2>&1 && fail "a note: a section of the paper's experiments ran"
grep -q "headline claims" "$work/note/timing.md" && fail "a note: timing.md speaks of the paper's headline claims (a note's records name none)"
grep -q "^What each kernel proved, of (map)^T J (map) = J:" "$work/note/report.md" || fail "a note: a shape's two kernels are not in report.md"
grep -q '"file": "certificates/stability_condition.v"' "$work/note/report.json" || fail "a note: the stability band has no Coq certificate"
# Every certificate the shapes export, checked by coqc: in the Release suite only (coqc is the same
# program in either build; the run above writes the same certificates under the sanitizers).
if [ "$part" = main ] && command -v coqc >/dev/null 2>&1; then
  check "a note, certified" 0 --certify --paper "$note_dir/trapezoidal-note.tex" --claims-file "$note_dir/trapezoidal-note.toml" --out "$work/note-certified"
  grep -q '"status": "failed"' "$work/note-certified/report.json" && fail "a note: a Coq certificate did not check"
  cat "$work/out" "$work/err" | grep -q "^\[coqc\] 11 certificate files checked" || fail "a note, certified: $(cat "$work/out" "$work/err" | grep coqc)"
fi
check "a note, validated" 1 --validate --paper "$note_dir/trapezoidal-note.tex" --claims-file "$note_dir/trapezoidal-note.toml" --out "$work/note-validated"
check "a note without --paper" 2 --claims-file "$note_dir/trapezoidal-note.toml" --out "$work/none-note1"
grep -q "give its LaTeX with --paper" "$work/err" || fail "a note without --paper: $(cat "$work/err")"
sed 's/matrix = "map", equals = "det"/matrix = "no-such-label", equals = "det"/' "$note_dir/trapezoidal-note.toml" >"$work/note-label.toml"
check "a note, label missing" 2 --paper "$note_dir/trapezoidal-note.tex" --claims-file "$work/note-label.toml" --out "$work/none-note2"
grep -q "claims file '$work/note-label.toml', line [0-9]*, field 'with.matrix': no .label{no-such-label}" "$work/err" ||
  fail "a note, label missing: not named: $(cat "$work/err")"
sed 's/shape = "symplectic"/shape = "simplectic"/' "$note_dir/trapezoidal-note.toml" >"$work/note-shape.toml"
check "a note, unknown shape" 2 --paper "$note_dir/trapezoidal-note.tex" --claims-file "$work/note-shape.toml" --out "$work/none-note3"
sed "s/'p_0', //" "$note_dir/trapezoidal-note.toml" >"$work/note-symbol.toml"
check "a note, undeclared symbol" 2 --paper "$note_dir/trapezoidal-note.tex" --claims-file "$work/note-symbol.toml" --out "$work/none-note4"
grep -q "the symbol 'p_0' is not declared" "$work/err" || fail "a note, undeclared symbol: $(cat "$work/err")"
for k in 1 2 3 4; do [ -e "$work/none-note$k" ] && fail "a bad note run wrote $work/none-note$k"; done
# The paper's source as an input (--paper, or the scene key "paper"): bad sources are bad input.
paper_src="$(dirname "$0")/../ledger/text/simpson-symplectic-gsi2023.tex"
source "$(dirname "$0")/paper_copies.sh"
check "paper missing" 2 --claims phi3-det --paper "$work/no-such.tex" --out "$work/none-paper1"
grep -q "paper '$work/no-such.tex': missing or unreadable" "$work/err" || fail "paper missing: not named"
echo 'Some other paper.' >"$work/other.tex"
check "not the paper" 2 --claims phi3-det --paper "$work/other.tex" --out "$work/none-paper2"
sed 's/\\label{moment-ordre-3}/\\label{moment-3}/' "$paper_src" >"$work/nolabel.tex"
check "label missing" 2 --claims momentum-order-3 --paper "$work/nolabel.tex" --out "$work/none-paper3"
grep -q "claims file 'claims/paper.toml', line [0-9]*, field 'with.printed': no .label{moment-ordre-3} in a formula of '$work/nolabel.tex'" "$work/err" ||
  fail "label missing: not named: $(cat "$work/err")"
# What the selected claims do not read is not judged: phi3-det reads (Phi3) alone.
check "label missing, not read" 0 --claims phi3-det --paper "$work/nolabel.tex" --quiet --out "$work/not-read"
sed 's/{11\\over24} \\,  \\omega^2  h^2 +  {{\\omega^4  h^4}\\over48}  $/{11\\over24} \\foo/' "$paper_src" >"$work/unparsable.tex"
check "formula does not parse" 2 --claims phi3-det --paper "$work/unparsable.tex" --out "$work/none-paper4"
grep -qF "document '$work/unparsable.tex', label Phi3, line 490: the command \\foo is not one the reader knows" "$work/err" || fail "formula does not parse: label, line, construct not named: $(cat "$work/err")"
grep -q "claims file" "$work/err" && fail "formula does not parse: a claims file blamed for the paper's TeX: $(cat "$work/err")"
for k in 1 2 3 4; do [ -e "$work/none-paper$k" ] && fail "bad paper wrote $work/none-paper$k"; done
# A paper cut short (no \end{document}) is bad input, named with its file, its last line and the
# likely cause, before anything runs; a ')' missing from a display names the document and its line,
# never the embedded claims file (none was given).
head -600 "$paper_src" >"$work/cut.tex"
check "paper cut short" 2 --claims all --sections none --paper "$work/cut.tex" --out "$work/none-paper5"
grep -q "paper '$work/cut.tex', line 600: the document ends without .end{document}: truncated?" "$work/err" ||
  fail "paper cut short: not named: $(cat "$work/err")"
# Cut before \label{Phi3}: the paper cut short, said so (before: "not the symplectic Simpson paper"); a
# LaTeX file of another paper: not this one.
head -300 "$paper_src" >"$work/cut-early.tex"
check "paper cut before Phi3" 2 --claims all --sections none --paper "$work/cut-early.tex" --out "$work/none-paper7"
grep -q "paper '$work/cut-early.tex': truncated: it ends at line 300 without .end{document}, before .label{Phi3}" "$work/err" ||
  fail "paper cut before Phi3: not named: $(cat "$work/err")"
printf '\\documentclass{article}\n\\begin{document}\nAnother paper.\n\\end{document}\n' >"$work/other-paper.tex"
check "another paper" 2 --claims all --sections none --paper "$work/other-paper.tex" --out "$work/none-paper8"
grep -q "paper '$work/other-paper.tex': not the symplectic Simpson paper" "$work/err" || fail "another paper: not named: $(cat "$work/err")"
# --baseline that is no report: its own name, not compare's.
check "baseline missing" 2 --claims phi3-det --baseline "$work/no-such-baseline" --out "$work/none-paper9"
grep -q "^simpson-verify: --baseline: '$work/no-such-baseline': no report.json there" "$work/err" || fail "baseline missing: not named: $(cat "$work/err")"
sed '423s/(\\omega^2 \\, h^2 - 8 )/(\\omega^2 \\, h^2 - 8 /' "$paper_src" >"$work/paren.tex"
cmp -s "$paper_src" "$work/paren.tex" && fail "missing paren: sed changed nothing"
check "a ( never closed" 2 --claims all --sections none --paper "$work/paren.tex" --out "$work/none-paper6"
grep -q "document '$work/paren.tex', anchor 'can be factorized', line 423: .*a '(' that is never closed" "$work/err" ||
  fail "a ( never closed: not named: $(cat "$work/err")"
grep -q "claims file" "$work/err" && fail "a ( never closed: a claims file blamed for the paper's TeX: $(cat "$work/err")"
for k in 5 6 7 8 9; do [ -e "$work/none-paper$k" ] && fail "bad paper wrote $work/none-paper$k"; done

# A copy with one coefficient of p_r changed (omega^4 -> omega^6) turns momentum-order-3 into an erratum: exit 1.
new_error_copy "$paper_src" "$work/altered.tex" || fail "altered copy: sed changed nothing"
check "altered paper" 1 --claims momentum-order-3,phi3-det --precisions double,rational --paper "$work/altered.tex" --out "$work/altered"
grep -q "momentum-order-3: verdict erratum, expected holds" "$work/err" || fail "altered paper: claim not named: $(cat "$work/err")"
echo "{\"name\": \"altered\", \"claims\": [\"momentum-order-3\"], \"precisions\": [\"double\"], \"paper\": \"$work/altered.tex\"}" >"$work/altered.json"
check "scene key paper" 1 --scene "$work/altered.json" --out "$work/altered-scene"
# A copy with the errata corrected: those claims now hold, so they differ from their expected verdicts (exit 1, named).
corrected_copy "$paper_src" "$work/corrected.tex" || fail "corrected copy: sed did not change six lines"
# Under the sanitizers the four claims on Gamma are left out here (about 12 s there): the same
# corrections make them hold in PaperReading.ACopyWithTheErrataCorrectedMakesThemHold, which runs there too.
corrected_claims=(taylor-display classical-action-range simpson-action-range)
[ "$part" = main ] && corrected_claims+=(gamma-system gamma-determinant)
# gamma-singular and conserved-form hold on both copies, with no remark (their printed conclusions
# are the corrected Gamma's): run beside the fixes, and named by none.
check "corrected paper" 1 --claims "$(IFS=,; echo "${corrected_claims[*]}"),phi3-det$([ "$part" = main ] && echo ,gamma-singular,conserved-form)" \
    --precisions double,rational --paper "$work/corrected.tex" --out "$work/corrected"
for id in "${corrected_claims[@]}"; do
  grep -Eq "$id: fixed: recorded as erratum, now holds" "$work/err" || fail "corrected paper: $id not named: $(cat "$work/err")"
done
grep -Eq "(phi3-det|gamma-singular|conserved-form): " "$work/err" && fail "corrected paper: a claim that holds on both copies named"
# An author's pipeline accepts the fixes: the same run passes.
check "corrected paper, fixes accepted" 0 --accept-fixes --claims "$(IFS=,; echo "${corrected_claims[*]}"),phi3-det" \
    --precisions double,rational --paper "$work/corrected.tex" --quiet --out "$work/corrected-accepted"
grep -q "fixes accepted" "$work/out" || fail "corrected paper, fixes accepted: not said: $(cat "$work/out")"
# Judged by whether each claim holds (--validate), the corrected copy passes: a correct fix is exit 0,
# and the printed paper's errata are exit 1. (The typos whose claims are cheap: each run here costs a
# few seconds under the sanitizers; the corrected Gamma is checked by "corrected paper" above.)
check "corrected paper, validated" 0 --validate --claims 'taylor-display,*-action-range' --precisions double \
    --paper "$work/corrected.tex" --out "$work/corrected-validated"
check "printed paper, validated" 1 --validate --claims '*-action-range' --precisions double --out "$work/printed-validated"
grep -q "^simpson-verify: simpson-action-range: erratum: the claim does not hold as written$" "$work/err" || fail "printed paper, validated: simpson-action-range not named: $(cat "$work/err")"
grep -q "^Exit code 1: 2 claims do not hold as written (classical-action-range, simpson-action-range); see Failures" "$work/out" ||
  fail "printed paper, validated: the exit line speaks of expected verdicts: $(grep '^Exit code' "$work/out")"
grep -q '"mode": "validation"' "$work/printed-validated/report.json" || fail "printed paper, validated: summary.mode is not validation"
grep -q '"validate": true' "$work/printed-validated/report.json" || fail "printed paper, validated: report.json does not say so"
check "claims pattern" 0 --scene quick --claims '*-action-range,phi3-d*' --precisions double --out "$work/pattern"
grep -q '"simpson-action-range"' "$work/pattern/report.json" && grep -q '"phi3-det"' "$work/pattern/report.json" || fail "claims pattern: a matching claim not run"
check "claims pattern matching nothing" 2 --scene quick --claims 'zzz-*' --out "$work/none-pattern"
[ -e "$work/none-pattern" ] && fail "claims pattern matching nothing wrote a report"
"$bin" --list-claims --format json >"$work/claims.json" || fail "--list-claims --format json: exit $?"
/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert len(d) > 60 and all('statement' in c and 'check' in c for c in d)" "$work/claims.json" ||
  fail "--list-claims --format json: not a list of records with statements"
# A prose sentence changed: the claim that quotes it judges the new words ("degree five": erratum), and
# a sentence whose words no longer parse is text-changed (exit 1, a JUnit failure of that type).
sed 's/polynomials of  degree three/polynomials of degree five/' "$paper_src" >"$work/prose.tex"
check "prose changed" 1 --claims simpson-exactness,midpoint-exactness --paper "$work/prose.tex" --out "$work/prose"
grep -q "simpson-exactness: verdict erratum, expected holds" "$work/err" || fail "prose changed: not named: $(cat "$work/err")"
grep -q '"degree": 5' "$work/prose/report.json" || fail "prose changed: the parsed degree is not in report.json"
sed 's/polynomials of  degree three/polynomials of degree trois/' "$paper_src" >"$work/prose2.tex"
check "prose unparsable" 1 --claims simpson-exactness --paper "$work/prose2.tex" --out "$work/prose2"
grep -q "simpson-exactness: verdict text-changed, expected holds" "$work/err" || fail "prose unparsable: not named: $(cat "$work/err")"
grep -q 'type="text-changed"' "$work/prose2/report.junit.xml" || fail "prose unparsable: no text-changed JUnit failure"
grep -q "do not parse as a number" "$work/prose2/report.md" || fail "prose unparsable: report.md does not say why"
# A changed Table 1 is judged as printed, by the claim and by the table1 section alike.
sed 's/\$ 4.11  \\,\\, 10^{-4} \$/$ 4.11  \\,\\, 10^{-3} $/' "$paper_src" >"$work/table.tex"
cmp -s "$paper_src" "$work/table.tex" && fail "changed table: sed changed nothing"
# Ten times the printed Simpson state entry: no convention of the family reproduces it any more.
# (Release only: two convention searches, 29 s under the sanitizers; ChangedTable.* run the same
# reading and search in process there.)
if [ "$part" = main ]; then
  check "changed table" 1 --claims table-values --sections table1 --paper "$work/table.tex" --out "$work/table"
  grep -q "table-values: verdict fails, expected holds" "$work/err" || fail "changed table: not named: $(cat "$work/err")"
  grep -q '^Symplectic Simpson,state,10,[^,]*,[^,]*,4.1099999999999999e-03,' "$work/table/table1.csv" || fail "changed table: the section shows the embedded value"
  grep -q '"printed": "4.11e-03"' "$work/table/report.json" || fail "changed table: the claim did not read the changed value"
fi
# Selection: --claims alone runs no section, --sections alone no claim; the title and report.json say so.
check "claims only" 0 --claims "phi3-det, hd-invariance" --out "$work/claims-only"
grep -q '"sections": \[\]' "$work/claims-only/report.json" || fail "claims only: overrides.sections not empty"
grep -q '^# simpson-verify report: scene `paper`: claims phi3-det, hd-invariance only; no sections' "$work/claims-only/report.md" \
  || fail "claims only: title does not say so"
ls "$work/claims-only"/*.csv >/dev/null 2>&1 && fail "claims only: a section ran"
# The earlier Phi_3 of the source's comments is judged for the run's claims only (phi3-det and
# hd-invariance, not the other claims that read Phi3), against the verdict the run gave them.
/usr/bin/python3 -c "import json,sys; p=json.load(open(sys.argv[1]))['provenance']; rows=[c for e in p['earlier_text'] for c in e['claims']]
assert p['earlier_text_checked'] and [(c['claim'], c['live'], c['earlier']) for c in rows] == [('phi3-det', 'holds', 'fails'), ('hd-invariance', 'holds', 'fails')], rows" \
  "$work/claims-only/report.json" || fail "claims only: the earlier text was judged for claims the run did not ask for"
check "sections only" 0 --scene quick --sections stability --out "$work/sections-only"
grep -q '^0 claims' "$work/out" || fail "sections only: claims ran"
[ -f "$work/sections-only/truncation_digits.dat" ] || fail "sections only: no stability files"
check "unknown section" 2 --sections bogus --out "$work/none-section"
check "quiet" 0 --claims phi3-det --precisions double --quiet --out "$work/quiet"
[ "$(wc -l <"$work/out")" = 1 ] && [ ! -s "$work/err" ] || fail "quiet: more than the summary line: $(cat "$work/out" "$work/err")"
# A selection's report says what was selected, and speaks only for it.
grep -q '^\*\*A selection\*\*: claims phi3-det only; no sections\. This report judges only what was selected' "$work/quiet/report.md" ||
  fail "quiet: the selection's report does not say it is one"
grep -q '^No finding among the 1 claim of this selection; the paper.s other claims were not run\.' "$work/quiet/report.md" ||
  fail "quiet: the selection's referee summary speaks for the whole paper"
# An internal error (a check that throws) is exit 3, named, with the report still written.
# simpson-verify with phi3-det's check made to throw, through the run's seam (simpson-verify-with-fault).
fault_bin="$(dirname "$bin")/simpson-verify-with-fault"
real_bin="$bin"
bin="$fault_bin"
check "internal error" 3 --fault-claim phi3-det --claims phi3-det,hd-invariance --precisions double --out "$work/fault"
bin="$real_bin"
grep -q 'internal error (a bug in the harness) in phi3-det: a fault made by the test' "$work/err" || fail "internal error: not named: $(cat "$work/err")"
# ... and never counted, or announced, as a verdict on the paper.
grep -q 'phi3-det: verdict fails' "$work/err" && fail "internal error: announced as a failed claim: $(cat "$work/err")"
grep -q '\] phi3-det  *fails' "$work/err" && fail "internal error: its progress line says fails: $(cat "$work/err")"
grep -q '\] phi3-det  *threw' "$work/err" || fail "internal error: its progress line does not say threw: $(cat "$work/err")"
grep -q '^2 claims: 1 held, 0 errata, 0 failed, 1 without a verdict (a harness fault' "$work/out" ||
  fail "internal error: the summary counts it as a verdict: $(tail -3 "$work/out")"
grep -q 'without a verdict (a harness fault: the check threw); no verdict on the run: a harness fault' "$work/out" ||
  fail "internal error: the summary line calls the run green: $(grep '^2 claims' "$work/out")"
[ -f "$work/fault/report.json" ] || fail "internal error: no report"
# compare: the committed reference against itself, against an altered copy, and bad input.
reference="$(dirname "$0")/../../reports/reference/paper"
check "compare equal" 0 compare "$reference" "$reference"
grep -q '^the reports agree$' "$work/out" || fail "compare equal: no agreement line"
mkdir -p "$work/altered-report"
sed 's/"verdict": "erratum"/"verdict": "holds"/' "$reference/report.json" >"$work/altered-report/report.json"
check "compare altered" 1 compare "$reference" "$work/altered-report"
grep -q '^claim gamma-system: verdict: "erratum" → "holds"$' "$work/out" || fail "compare altered: claim not named: $(head -12 "$work/out")"
check "compare missing" 2 compare "$reference" "$work/no-such-report"
# compare for a CI's test view: --junit writes a failing testcase per difference, --format json the
# differences as data; a JUnit file that cannot be written is bad input, and nothing is left behind.
check "compare --junit" 1 compare "$reference" "$work/altered-report" --junit "$work/compare.junit.xml" --format json
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert not d['agree'] and any(x['where'] == 'claim gamma-system' and x['what'][0].startswith('verdict:') for x in d['differences'])" "$work/out" ||
  fail "compare --format json: not the differences: $(head -5 "$work/out")"
grep -q 'testcase classname="compare" name="claim gamma-system"><failure type="difference" message="verdict: ' "$work/compare.junit.xml" ||
  fail "compare --junit: no failing testcase for the changed verdict"
check "compare --junit, cannot write" 2 compare "$reference" "$reference" --junit "$work/no-such-dir/compare.xml"
[ -e "$work/no-such-dir/compare.xml.partial" ] && fail "compare --junit left a partial file"
check "list claims" 0 --list-claims
check "version" 0 --version
grep -Eq '^simpson-verify [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{40}|unknown), ' "$work/out" || fail "version: no commit: $(cat "$work/out")"

# A selection never replaces a fuller report by default: without --out it writes a directory named
# after it; an explicit --out holding a fuller report is refused, naming --out; an empty --out too.
(cd "$work" && "$bin" --no-certify --claims phi3-det --precisions double --quiet >/dev/null 2>&1) || fail "selection default out: run failed"
[ -f "$work/reports/out/paper-claims-phi3-det/report.json" ] || fail "selection default out: not in reports/out/paper-claims-phi3-det: $(ls "$work/reports/out" 2>&1)"
# The fuller report: the quick scene's claims and two of its sections (its table1 and work_precision
# would add time and nothing to what is checked here).
# (Under the sanitizers two of its claims: all seven took about 17 s there.)
fuller_claims=all fuller_count="7 claims"
[ "$part" = main-reduced ] && fuller_claims=phi3-det,hd-invariance fuller_count="2 claims"
check "selection onto a fuller report (setup)" 0 --scene quick --claims "$fuller_claims" --sections stability,long_time --no-timing --quiet --out "$work/quick-full"
before=$(cd "$work/quick-full" && find . -type f | sort | xargs sha256sum)
check "selection onto a fuller report" 2 --scene quick --claims phi3-det --out "$work/quick-full"
grep -q -- "--out '$work/quick-full': holds a fuller report ($fuller_count, 2 sections)" "$work/err" || fail "fuller report: not named: $(cat "$work/err")"
[ "$(cd "$work/quick-full" && find . -type f | sort | xargs sha256sum)" = "$before" ] || fail "fuller report: touched"
check "empty --out" 2 --claims phi3-det --out ""
grep -q -- "--out '': an empty directory name" "$work/err" || fail "empty --out: not named: $(cat "$work/err")"
# compare --subset: the headline claims against the committed reference.
# Certified in the Release suite; under the sanitizers coqc's part is noted by compare, not compared.
headline_certify=--certify
[ "$part" = main ] || headline_certify=--no-certify
check "headline claims" 0 --claims phi3-det,discriminant-factorization,stability-condition,hd-invariance,truncation-1440 $headline_certify --no-timing --quiet --out "$work/headline"
check "compare --subset" 0 compare --subset "$reference" "$work/headline"
grep -q '^the reports agree$' "$work/out" || fail "compare --subset: $(tail -5 "$work/out")"
check "compare without --subset" 2 compare "$reference" "$work/headline"
grep -q "is a selection (--claims or --sections: 5 claims, 0 sections) .* compare --subset" "$work/err" || fail "compare without --subset: no hint: $(cat "$work/err")"
sed 's/"verdict": "holds"/"verdict": "fails"/' "$work/headline/report.json" >"$work/headline-altered.json"
check "compare --subset altered" 1 compare --subset "$reference" "$work/headline-altered.json"
# compare's own mistakes in our words: a missing directory, and --subset's two reports swapped.
check "compare one argument" 2 compare "$reference"
grep -q "compare needs two report directories: OLD, the reference" "$work/err" || fail "compare one argument: not named: $(cat "$work/err")"
check "compare --subset swapped" 2 compare --subset "$work/headline" "$reference"
grep -q "must be the fuller report (the reference) .* the two look swapped" "$work/err" || fail "compare --subset swapped: not named: $(cat "$work/err")"
# The console: an erratum's correction, and what exit 0 with errata means. Two cheap errata (the
# table's, with its convention search, took 10 s of this test under the sanitizers, and
# gamma-determinant's 8 s; their places in the report are guarded by
# ReferenceReport.PaperSceneReproducesTheCommittedReport).
check "errata on the console" 0 --claims classical-action-range,simpson-action-range --precisions double --out "$work/console"
grep -q '^           corrected: S_d = \\sum_{j=0}^{N-1}' "$work/out" || fail "errata on the console: no corrected line: $(cat "$work/out")"
grep -q '^Exit code 0: every verdict is the expected one, the ledger.s recorded judgment.*2 errata (false as printed' "$work/out" ||
  fail "console: exit 0 with errata not explained: $(tail -4 "$work/out")"
grep -q 'Phi3 at the paper' "$work/out" && fail "console: a selection printed the Phi3 table"
sed -n '/^## Errata/,/^## /p' "$work/console/report.md" | grep -q '^### simpson-action-range' || fail "report: simpson-action-range not under Errata"
grep -q '^## Failures' "$work/console/report.md" || fail "report: no Failures section"
sed -n '/^## Notes on claims that hold/,/^## /p' "$work/console/report.md" | grep -q 'simpson-action-range' && fail "report: simpson-action-range filed under claims that hold"
# --paper: what the report calls printed comes from the file read (1440 changed to 1400 there).
sed 's/\\over1440}/\\over1400}/' "$paper_src" >"$work/p1400.tex"
cmp -s "$paper_src" "$work/p1400.tex" && fail "1400 copy: sed changed nothing"
check "paper 1400" 1 --claims truncation-1440 --precisions double,rational --paper "$work/p1400.tex" --out "$work/p1400"
grep -q '^- Printed ('"$work"'/p1400.tex, line.*1400' "$work/p1400/report.md" || fail "paper 1400: Printed does not quote the file: $(grep -m2 'Printed' "$work/p1400/report.md")"
grep -q 'Printed ('"$work"'/p1400.tex.*1400' "$work/p1400/report.junit.xml" || fail "paper 1400: JUnit does not quote the file"
grep -q '1440}' "$work/p1400/report.junit.xml" && fail "paper 1400: JUnit quotes the embedded 1440"
# An empty paper, a directory: bad input that says what is wrong.
: >"$work/empty.tex"
check "empty paper" 2 --claims phi3-det --paper "$work/empty.tex" --out "$work/none-paper5"
grep -q "the file is empty" "$work/err" || fail "empty paper: $(cat "$work/err")"
check "paper is a directory" 2 --claims phi3-det --paper "$work" --out "$work/none-paper6"
grep -q "is a directory" "$work/err" || fail "paper directory: $(cat "$work/err")"
# A read-only mount: named as such in one line, before anything runs, whether --out is the mount
# point or a directory inside it. Needs a mount namespace (unshare, as root, as CI runs).
if unshare -m true 2>/dev/null; then
  mkdir -p "$work/ro1" "$work/ro2"
  unshare -m bash -c "mount -t tmpfs -o ro tmpfs '$work/ro1' && mount -t tmpfs tmpfs '$work/ro2' &&
    '$bin' --claims phi3-det --precisions double --quiet --out '$work/ro2/inside' >/dev/null && mount -o remount,ro '$work/ro2' &&
    { '$bin' --claims phi3-det --precisions double --out '$work/ro1' 2>'$work/err-ro1'; echo \$? >'$work/rc-ro1';
      '$bin' --claims phi3-det --precisions double --out '$work/ro2/inside' 2>'$work/err-ro2'; echo \$? >'$work/rc-ro2'; }"
  [ "$(cat "$work/rc-ro1" 2>/dev/null)" = 2 ] && [ "$(wc -l <"$work/err-ro1")" = 1 ] && grep -q "is a mount point (read-only)" "$work/err-ro1" &&
    { echo "ok   read-only mount point as --out"; passes=$((passes + 1)); } || fail "read-only mount point: $(cat "$work/rc-ro1" "$work/err-ro1" 2>&1)"
  [ "$(cat "$work/rc-ro2" 2>/dev/null)" = 2 ] && [ "$(wc -l <"$work/err-ro2")" = 1 ] && grep -q "Read-only file system" "$work/err-ro2" &&
    ! grep -q "filesystem error" "$work/err-ro2" &&
    { echo "ok   directory on a read-only mount as --out"; passes=$((passes + 1)); } || fail "read-only mount: $(cat "$work/rc-ro2" "$work/err-ro2" 2>&1)"
else
  echo "skip read-only mount (no mount namespace here: unshare -m refused)"
fi
# --help: every embedded scene, integers typed as such.
check "help" 0 --help
grep -q 'Exit codes: 0 every verdict as expected .* 2 bad input .* 3 a bug in the harness; 130 or 143 interrupted' "$work/out" ||
  fail "help: exit codes not listed"
grep -q 'embedded scene name (beyond, family, floating, inseparable, paper, quick, stiff)' "$work/out" || fail "help: scenes not all listed"
grep -q -- '--samples UINT' "$work/out" || fail "help: --samples not typed UINT"

# --precisions reaches the sections that have precisions, or is refused with the reason.
check "precisions to sections" 0 --scene quick --sections work_precision,stability --precisions double,mpfr:30 --no-timing --out "$work/prec"
grep -q '"precisions_applied_to": \[' "$work/prec/report.json" && grep -q '"precision": "mpfr:30"' "$work/prec/report.json" ||
  fail "precisions to sections: not applied or not recorded"
grep -q '"precision": "float128"' "$work/prec/report.json" && fail "precisions to sections: a scene precision survived"
check "precisions with long_time" 2 --scene quick --precisions double --out "$work/none-prec1"
grep -q 'long_time' "$work/err" || fail "precisions with long_time: the section is not named"
check "rechecks over the budget" 2 --claims peer-schemes --precisions mpfr:100000 --samples 10000 --out "$work/none-prec5"
grep -q 'numeric rechecks: .* (1 claim x 10000 samples x 1 precision)' "$work/err" || fail "rechecks over the budget: $(cat "$work/err")"
# --certify without coqc on PATH: bad input, named, nothing written.
# (PATH only for the binary: the checks below need wc and grep.)
PATH=/nonexistent "$bin" --claims phi3-det --certify --out "$work/none-coq" >"$work/out" 2>"$work/err"
got=$?
if [ "$got" = 2 ] && [ "$(wc -l <"$work/err")" = 1 ] && grep -q -- "--certify: coqc was not found" "$work/err"; then
  echo "ok   certify without coqc"
  passes=$((passes + 1))
else
  fail "certify without coqc: exit $got, stderr: $(head -3 "$work/err")"
fi
[ -e "$work/none-coq" ] && fail "certify without coqc wrote $work/none-coq"
check "precisions with nonlinear" 2 --scene beyond --precisions double --out "$work/none-prec4"
grep -q 'nonlinear' "$work/err" || fail "precisions with nonlinear: the section is not named"
check "rational in a section" 2 --scene quick --sections stability --precisions rational --out "$work/none-prec2"
check "bad precision" 2 --claims phi3-det --precisions double,mpfr:3 --out "$work/none-prec3"
# Timing: --timing-runs N, --no-timing, never both.
check "timing runs" 0 --scene quick --sections work_precision --timing-runs 1 --out "$work/runs"
grep -q '"max_runs": 1' "$work/runs/timing.json" || fail "timing runs: not in timing.json"
check "timing runs 0" 2 --scene quick --timing-runs 0 --out "$work/none-t1"
check "timing both" 2 --scene quick --timing-runs 3 --no-timing --out "$work/none-t2"
check "timing runs, nothing timed" 2 --claims phi3-det --timing-runs 3 --out "$work/none-t3"
for d in none-prec1 none-prec2 none-prec3 none-t1 none-t2 none-t3; do [ -e "$work/$d" ] && fail "$d: written"; done

echo "$passes passed, $failures failed"
[ "$failures" = 0 ]
