#!/usr/bin/env bash
# The steppers' one-step round-off (the floating scene, ctest label coq): every stepper in float32
# and double proved by Gappa, its Coq proof checked by coqc, and the bound within 4 times the largest
# error seen on random states (never below it). Without gappa or coqc the test is skipped (exit 77,
# shown as skipped), never passed.
set -u
bin="$1"
for program in gappa coqc; do
  if ! command -v "$program" >/dev/null 2>&1; then
    echo "SKIP coq.roundoff: $program not found (scripts/install-deps installs gappa, libcoq-gappa and coq); nothing checked"
    exit 77
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" --scene floating --quiet --out "$work/floating" >"$work/out" 2>"$work/err"
code=$?
if [ "$code" != 0 ]; then
  echo "FAIL floating scene: exit $code: $(head -5 "$work/err")"
  exit 1
fi
/usr/bin/python3 - "$work/floating/report.json" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))["experiments"]["floating"]["one_step"]
bad = 0
pairs = {(r["stepper"], r["format"]) for r in rows}
for stepper in ["phi3-matrix", "phi3-shear", "newmark-matrix", "leapfrog-verinum"]:
    for fmt in ["float32", "double"]:
        if (stepper, fmt) not in pairs:
            print(f"FAIL {stepper} {fmt}: no row"); bad += 1
for r in rows:
    name = f'{r["stepper"]} {r["format"]}'
    if r["gappa"] != "proved" or r["coq"] != "checked":
        print(f"FAIL {name}: gappa {r['gappa']!r}, coq {r['coq']!r}"); bad += 1
        continue
    ratio = r["bound_over_seen"]
    if not (1 <= ratio <= 4):
        print(f"FAIL {name}: bound/seen {ratio}"); bad += 1
    print(f"ok {name}: bounds {r['bound_p']}, {r['bound_q']}; seen {r['seen_p']}, {r['seen_q']}; coq checked")
# Over n steps: every lifting lemma checked by coqc, every bound at least the error seen, and at
# VeriNum's setting (n = 1000) the total bound within twice the error made.
report = json.load(open(sys.argv[1]))["experiments"]["floating"]
checked = 0
for r in report["global"]:
    name = f'{r["stepper"]} {r["format"]} n = {r["n"]}'
    if r.get("coq") != "checked":
        print(f"FAIL {name}: lifting lemma {r.get('coq')!r}"); bad += 1
    else:
        checked += 1
    if r.get("roundoff_seen", "not run") != "not run" and float(r["roundoff_bound"]) < float(r["roundoff_seen"]):
        print(f"FAIL {name}: round-off bound {r['roundoff_bound']} below the round-off seen {r['roundoff_seen']}"); bad += 1
# VerifiedLeapfrog's bound holds at every n <= 1000: it stands beside the row uniform over n <= 1000
# (and beside no other), whose bound is within twice the largest error made.
verinum = [r for r in report["global"] if r["stepper"] == "leapfrog-verinum" and r.get("verinum_bound")]
if len(verinum) != 1 or verinum[0]["n"] != "≤ 1000" or not (1 <= verinum[0]["total_bound_over_seen"] <= 2):
    print(f"FAIL VeriNum's setting over n <= 1000: {verinum}"); bad += 1
else:
    print(f"ok VeriNum's setting, n <= 1000: total bound {verinum[0]['total_bound']}, largest seen {verinum[0]['total_seen']}, VeriNum {verinum[0]['verinum_bound']}")
rows = rows + report["global"]
print(f"{len(rows) - bad} passed, {bad} failed")
sys.exit(1 if bad else 0)
PY
