#!/usr/bin/env bash
# Every refusal of a claims file in one pass: a copy of a corpus note's claims file with faults in
# four records (q no longer declared, which two formulas the records read need; an undeclared
# variable, twice; a label that is not there) is refused with exit 2, one line per refusal, each naming the
# claims file's line, or the document's for a formula that does not read, and nothing is written.
set -u
bin="$1"
notes="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -e "s/real = \['q', 'q_\\\\ell'/real = ['q_\\\\ell'/" \
    -e "s/variable = \['q_m'\], unknowns/variable = ['q_x'], unknowns/" \
    -e 's/relations = \["internal", "pl", "pr"\]/relations = ["internal", "nolabel", "pr"]/' \
    "$notes/simpson-any-lagrangian.toml" >"$work/bad.toml"
[ "$(diff "$notes/simpson-any-lagrangian.toml" "$work/bad.toml" | grep -c '^>')" = 4 ] || { echo "FAIL the edits did not all apply"; exit 1; }
"$bin" --paper "$notes/simpson-any-lagrangian.tex" --claims-file "$work/bad.toml" --no-certify --out "$work/out" 2>"$work/err"
code=$?
cat "$work/err"
[ "$code" = 2 ] || { echo "FAIL exit $code, expected 2"; exit 1; }
[ ! -e "$work/out" ] || { echo "FAIL the output directory was written"; exit 1; }
[ "$(wc -l <"$work/err")" = 4 ] || { echo "FAIL $(wc -l <"$work/err") lines, expected 4 (one per refusal)"; exit 1; }
if grep -v "^simpson-verify: \(claims file '$work/bad.toml', line [0-9]*, field\|document '.*', .*, line [0-9]*: cannot read\)" "$work/err"; then
  echo "FAIL a line above names neither the claims file's line nor the document's"; exit 1
fi
grep -q "inline formula at 'applied to the action of one step', line 32" "$work/err" && grep -q "field 'with.variable'" "$work/err" &&
  grep -q "no \\\\label{nolabel}" "$work/err" && grep -q "label pendulum, line 58" "$work/err" || { echo "FAIL a refusal is missing"; exit 1; }
echo "ok: 4 refusals in one pass"

# An argument only its claim's run can judge (symplectic-step counts its relations against the
# unknowns it finds as it reads them) is bad input too: exit 2, one line naming the record's field,
# nothing written; not "internal error" (exit 3), which would lose the run to a fault of the harness.
sed -e 's/relations = \["internal", "pl", "pr"\]/relations = ["pl", "pr"]/' "$notes/simpson-any-lagrangian.toml" >"$work/short.toml"
[ "$(diff "$notes/simpson-any-lagrangian.toml" "$work/short.toml" | grep -c '^>')" = 1 ] || { echo "FAIL the relations edit did not apply"; exit 1; }
"$bin" --paper "$notes/simpson-any-lagrangian.tex" --claims-file "$work/short.toml" --no-certify --quiet --out "$work/out2" >/dev/null 2>"$work/err2"
code=$?
cat "$work/err2"
[ "$code" = 2 ] || { echo "FAIL exit $code for a relation too few, expected 2"; exit 1; }
[ ! -e "$work/out2" ] || { echo "FAIL the output directory was written"; exit 1; }
[ "$(wc -l <"$work/err2")" = 1 ] && grep -q "^simpson-verify: claims file '$work/short.toml', line 60, field 'with.relations': 2 relations for 3 unknowns" "$work/err2" ||
  { echo "FAIL not one line naming with.relations at line 60"; exit 1; }
echo "ok: a refusal at run time"
