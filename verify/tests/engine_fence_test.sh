#!/bin/bash
# engine.fence: the claims engine (verify/prove, verify/shapes) is a library apart from the book.
#   1. It cannot include a core header: builds engine_fence_probe (a unit of the engine's include
#      path that includes simpson/simpson_map.hpp) and passes only when that fails for that reason,
#      the header not found; any other outcome fails.
#   2. engine-runner (a note checked by the engine alone) holds none of the book's code: no function
#      that the ledger or the experiments define is defined in it.
build_dir=$1
runner=$2
out=$(cmake --build "$build_dir" --target engine_fence_probe 2>&1)
if [ $? -eq 0 ]; then
  echo "engine_fence_probe compiled: a core header is on the engine's include path (a link to simpson::core in verify/prove or verify/shapes?)"
  exit 1
fi
if ! grep -Eq "simpson/simpson_map.hpp(: No such file or directory|' file not found)" <<<"$out"; then
  echo "engine_fence_probe failed for another reason than the missing core header:"
  echo "$out" | tail -20
  exit 1
fi
echo "the fence holds: simpson/simpson_map.hpp is not on the engine's include path"

defined() { nm --defined-only "$@" 2>/dev/null | awk '$2 == "T" { print $3 }' | sort -u; }
runner_symbols=$(defined "$runner")
if [ -z "$runner_symbols" ]; then
  echo "engine-runner '$runner': no symbols read (stripped, or not built?)"
  exit 1
fi
for lib in ledger/libsimpson_verify_ledger.a experiments/libsimpson_verify_experiments.a; do
  archive="$build_dir/verify/$lib"
  if [ ! -f "$archive" ]; then
    echo "$archive: not built"
    exit 1
  fi
  book_symbols=$(defined "$archive")
  [ -n "$book_symbols" ] || { echo "$archive: no symbols read"; exit 1; }
  shared=$(comm -12 <(echo "$runner_symbols") <(echo "$book_symbols"))
  if [ -n "$shared" ]; then
    echo "engine-runner links the book's code ($lib): $(echo "$shared" | head -5 | c++filt | tr '\n' ' ')"
    exit 1
  fi
done
echo "the engine runs alone: engine-runner defines $(echo "$runner_symbols" | wc -l) functions, none of the ledger's or the experiments'"
