#!/usr/bin/env bash
# docs/ci.md's CI recipes, run as written: each recipe's `…bin/simpson-verify …` commands, in order,
# the first that fails stopping the job as a CI's would, from a directory laid out as the recipe
# expects (this build's binary at build/bin/simpson-verify, or harness/build/bin/ for the author's
# pipeline; the committed reference at reports/reference; the paper, or an altered copy, where the
# recipe reads it).
#   the guard's pipeline: GitHub Actions and GitLab run the same commands; it passes on the paper as
#     printed and fails (exit 1) on a copy with the recorded errata corrected;
#   the author's pipeline: it passes on the paper as printed and on the corrected copy (fixes
#     accepted), and fails (exit 1) on the corrected copy with one coefficient changed.
set -u
bin="$(realpath "$1")"
source_dir="$(realpath "$2")"
doc="$source_dir/docs/ci.md"
paper="$source_dir/verify/ledger/text/simpson-symplectic-gsi2023.tex"
source "$source_dir/verify/tests/paper_copies.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

commands() {  # commands GUARD-GITLAB|GUARD-GITHUB|AUTHOR: the simpson-verify commands of that recipe, one per line
  awk -v want="$1" '
    /^```yaml/ { inside = 1; kind = ""; next }
    /^```/ { inside = 0; next }
    inside && /^# GitLab CI \(/ { kind = "GUARD-GITLAB" }
    inside && /^# GitHub Actions \(/ { kind = "GUARD-GITHUB" }
    inside && /^# GitLab CI, the authors/ { kind = "AUTHOR" }
    inside && kind == want && /bin\/simpson-verify/ { sub(/^ *- (run: )?/, ""); print }
  ' "$doc"
}
guard=$(commands GUARD-GITLAB)
github=$(commands GUARD-GITHUB | sed 's/ && /\n/g')
author=$(commands AUTHOR)
[ -n "$guard" ] || { echo "FAIL no GitLab guard recipe found in $doc"; exit 1; }
[ -n "$author" ] || { echo "FAIL no author's recipe found in $doc"; exit 1; }
if [ "$guard" != "$github" ]; then
  fail "the GitHub Actions and GitLab guard recipes run different commands:"
  diff <(echo "$guard") <(echo "$github")
fi

run_recipe() {  # run_recipe NAME DIR EXPECTED_CODE COMMANDS: run them in DIR until one fails
  local name="$1" dir="$2" want="$3" code=0 line
  rm -rf "$dir/out"
  while IFS= read -r line; do
    (cd "$dir" && bash -c "$line") >"$work/log" 2>&1
    code=$?
    [ "$code" = 0 ] || break
  done <<<"$4"
  if [ "$code" = "$want" ]; then
    echo "ok   $name: exit $code$([ "$code" = 0 ] || echo " at: $line")"
  else
    fail "$name: exit $code, expected $want$([ "$code" = 0 ] || echo " at: $line")"
    sed 's/^/  /' "$work/log" | grep -v '^  *- ' | tail -8
  fi
}

# The guard's layout: this repository.
mkdir -p "$work/guard/build/bin" "$work/guard/reports" "$work/guard/verify/ledger/text"
ln -s "$bin" "$work/guard/build/bin/simpson-verify"
ln -s "$source_dir/reports/reference" "$work/guard/reports/reference"
guard_paper="$work/guard/verify/ledger/text/simpson-symplectic-gsi2023.tex"
# The author's layout: their repository, the paper at its root, this harness as harness/.
mkdir -p "$work/author/harness/build/bin"
ln -s "$bin" "$work/author/harness/build/bin/simpson-verify"
draft="$work/author/simpson-symplectic-gsi2023.tex"

corrected_copy "$paper" "$work/corrected.tex" || fail "corrected copy: sed did not change six lines"
new_error_copy "$work/corrected.tex" "$work/corrected-new-error.tex" || fail "new error: sed changed nothing"

cp "$paper" "$guard_paper"
run_recipe "guard, the paper as printed" "$work/guard" 0 "$guard"
cp "$work/corrected.tex" "$guard_paper"
run_recipe "guard, errata corrected (a fix is news)" "$work/guard" 1 "$guard"
grep -q "gamma-system: fixed: recorded as erratum, now holds" "$work/log" || fail "guard, errata corrected: the fix is not named"

cp "$paper" "$draft"
run_recipe "author, the paper as printed" "$work/author" 0 "$author"
cp "$work/corrected.tex" "$draft"
run_recipe "author, errata corrected (fixes accepted)" "$work/author" 0 "$author"
grep -q "fixes accepted" "$work/author/out/draft/report.md" || fail "author, errata corrected: report.md does not say fixes accepted"
cp "$work/corrected-new-error.tex" "$draft"
run_recipe "author, errata corrected and a new error" "$work/author" 1 "$author"
grep -q "momentum-order-3: verdict erratum, expected holds" "$work/log" || fail "author, a new error: not named"

echo "$failures failed"
[ "$failures" = 0 ]
