#!/bin/bash
# engine.fence: the claims engine (verify/prove, verify/shapes) cannot include a core header. Builds
# engine_fence_probe (a unit of the engine's include path that includes simpson/simpson_map.hpp) and
# passes only when it fails for that reason, the header not found; any other outcome fails.
build_dir=$1
out=$(cmake --build "$build_dir" --target engine_fence_probe 2>&1)
if [ $? -eq 0 ]; then
  echo "engine_fence_probe compiled: a core header is on the engine's include path (a link to simpson::core in verify/prove or verify/shapes?)"
  exit 1
fi
if grep -Eq "simpson/simpson_map.hpp(: No such file or directory|' file not found)" <<<"$out"; then
  echo "the fence holds: simpson/simpson_map.hpp is not on the engine's include path"
  exit 0
fi
echo "engine_fence_probe failed for another reason than the missing core header:"
echo "$out" | tail -20
exit 1
