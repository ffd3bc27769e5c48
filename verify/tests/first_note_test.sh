#!/usr/bin/env bash
# docs/first-note.md's runs, as written: each ```console block's command is run from the source
# directory (build/bin/simpson-verify being this build's binary, the report written to a temporary
# directory), and each line the block shows must begin a line the run prints (white space folded;
# the block leaves out the timings and the report's paths). Exit 0 when every line is there.
set -u
bin="$(realpath "$1")"
source_dir="$(realpath "$2")"
doc="$source_dir/docs/first-note.md"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Each ```console block on its own: its command run, its other lines looked for in that run.
awk -v dir="$work" '/^```console/ { inside = 1; n++; next } /^```/ { inside = 0 } inside { print > (dir "/block" n) }' "$doc"
ls "$work"/block* >/dev/null 2>&1 || { echo "FAIL no console block in $doc"; exit 1; }
fold() { sed -E 's/[[:space:]]+/ /g; s/^ //; s/ $//'; }
failures=0
for block in "$work"/block*; do
  command=$(grep '^\$ ' "$block" | head -1 | sed 's/^\$ //')
  [ -n "$command" ] || { echo "FAIL no command in a console block of $doc"; exit 1; }
  case "$command" in build/bin/simpson-verify\ *) ;; *) echo "FAIL the block's command is not build/bin/simpson-verify: $command"; exit 1 ;; esac
  rm -rf "$work/out"
  (cd "$source_dir" && bash -c "'$bin'${command#build/bin/simpson-verify} --out '$work/out'") >"$work/run" 2>&1
  echo "exit $? from: $command"
  fold <"$work/run" >"$work/actual"
  missing=0
  while IFS= read -r line; do
    want=$(printf '%s\n' "$line" | fold)
    [ -z "$want" ] && continue
    if awk -v want="$want" 'index($0, want) == 1 { found = 1 } END { exit !found }' "$work/actual"; then
      echo "ok   $want"
    else
      echo "FAIL the run prints no line beginning: $want"
      missing=$((missing + 1))
    fi
  done < <(grep -v '^\$ ' "$block")
  [ "$missing" = 0 ] || { echo "the run printed:"; cat "$work/run"; }
  failures=$((failures + missing))
done
[ "$failures" = 0 ]
