#!/usr/bin/env bash
# Exit codes and output of simpson-verify: 0 as expected, 1 a verdict differs, 2 bad input with
# one line on stderr and nothing written.
set -u
bin="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME EXPECTED_CODE ARGS...
  local name="$1" want="$2"
  shift 2
  "$bin" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [ "$got" != "$want" ]; then
    echo "FAIL $name: exit $got, expected $want"; sed 's/^/  stderr: /' "$work/err" | head -5
    failures=$((failures + 1))
  elif [ "$want" = 2 ] && [ "$(wc -l <"$work/err")" != 1 ]; then
    echo "FAIL $name: expected exactly one line on stderr"; cat "$work/err"
    failures=$((failures + 1))
  else
    echo "ok   $name"
  fi
}

check "quick scene" 0 --scene quick --out "$work/quick"
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
for k in 1 2 3 4 5 6 7 8 9 10 11; do
  [ -e "$work/none$k" ] && { echo "FAIL: bad input wrote $work/none$k"; failures=$((failures + 1)); }
done
# Interruption: a long run (10000 samples per recheck) stopped after one second.
for sig in INT TERM; do
  "$bin" --samples 10000 --out "$work/stopped-$sig" >"$work/out" 2>"$work/err" &
  pid=$!
  sleep 1
  kill -"$sig" "$pid"
  wait "$pid"
  got=$?
  want=$([ "$sig" = INT ] && echo 130 || echo 143)
  if [ "$got" != "$want" ] || ! grep -q "interrupted (SIG$sig)" "$work/err" || [ -n "$(ls -A "$work/stopped-$sig")" ]; then
    echo "FAIL SIG$sig: exit $got (expected $want), stderr: $(tail -1 "$work/err"), files: $(ls -A "$work/stopped-$sig")"
    failures=$((failures + 1))
  else
    echo "ok   SIG$sig stops the run with $got and writes nothing"
  fi
done
check "list claims" 0 --list-claims
check "version" 0 --version

total=25
echo "$((total - failures)) passed, $failures failed"
[ "$failures" = 0 ]
