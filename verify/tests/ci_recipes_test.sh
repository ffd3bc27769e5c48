#!/usr/bin/env bash
# docs/ci.md's CI recipes, run as written against the committed reference: every
# `build/bin/simpson-verify …` command of its GitLab recipe, in order, from a directory where
# build/bin/simpson-verify is this build's binary and reports/reference is the committed one. The
# GitHub Actions recipe must run the same commands. Exit 0 when every command exits 0.
set -u
bin="$(realpath "$1")"
source_dir="$(realpath "$2")"
doc="$source_dir/docs/ci.md"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
commands() {  # commands GITLAB|GITHUB: the simpson-verify commands of that recipe, one per line
  awk -v want="$1" '
    /^```yaml/ { inside = 1; kind = ""; next }
    /^```/ { inside = 0; next }
    inside && /^# GitLab/ { kind = "GITLAB" }
    inside && /^# GitHub/ { kind = "GITHUB" }
    inside && kind == want && /build\/bin\/simpson-verify/ { sub(/^ *- (run: )?/, ""); print }
  ' "$doc"
}
gitlab=$(commands GITLAB)
github=$(commands GITHUB | sed 's/ && /\n/g')
[ -n "$gitlab" ] || { echo "FAIL no GitLab recipe found in $doc"; exit 1; }
if [ "$gitlab" != "$github" ]; then
  echo "FAIL the GitHub Actions and GitLab recipes run different commands:"
  diff <(echo "$gitlab") <(echo "$github")
  exit 1
fi
mkdir -p "$work/build/bin" "$work/reports"
ln -s "$bin" "$work/build/bin/simpson-verify"
ln -s "$source_dir/reports/reference" "$work/reports/reference"
failures=0
while IFS= read -r line; do
  (cd "$work" && bash -c "$line") >"$work/log" 2>&1
  code=$?
  if [ "$code" = 0 ]; then
    echo "ok   $line"
  else
    echo "FAIL exit $code: $line"; sed 's/^/  /' "$work/log" | grep -v '^  *- ' | tail -8
    failures=$((failures + 1))
  fi
done <<<"$gitlab"
echo "$(echo "$gitlab" | wc -l) commands, $failures failed"
[ "$failures" = 0 ]
