#!/usr/bin/env bash
# Tries per chord of the band flattener, by kind of search, on every 10th
# corpus curve at 0.1, 0.01 and 0.001 mm: flatten_curve.cpp compiled with
# BEZCAM_FLATTEN_COUNTERS and linked into a copy of flatten_bench (in a
# temporary directory; the build itself is not touched).
# Usage: bench/flatten_tries.sh [BUILD_DIR [CORPUS.json]]  (BUILD_DIR with flatten_bench built)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-build}" && pwd)
corpus=(${2:+"$2"})
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
flags=$(grep -oE '^[^ ]+ .*-O[0-9s]?[^C]*' "$build/bench/CMakeFiles/flatten_bench.dir/link.txt" | head -1 | awk '{for (i = 2; i <= NF; ++i) if ($i ~ /^-O|^-g|^-D/) printf "%s ", $i}')
c++ -std=c++20 $flags -DBEZCAM_FLATTEN_COUNTERS -I"$src/include" -I"$src/src" -c "$src/src/flatten/flatten_curve.cpp" -o "$out/flatten_curve.o"
link=$(cat "$build/bench/CMakeFiles/flatten_bench.dir/link.txt")
link=${link/CMakeFiles\/flatten_bench.dir\/flatten_bench.cpp.o/CMakeFiles/flatten_bench.dir/flatten_bench.cpp.o $out/flatten_curve.o}
link=${link/-o ..\/flatten_bench/-o $out/flatten_bench}
(cd "$build/bench" && eval "$link")
for tol in 0.1 0.01 0.001; do
  echo "tol $tol mm:"
  "$out/flatten_bench" "${corpus[@]}" --quick --only bezcam --tol "$tol" 2>&1 >/dev/null | sed 's/^/  /'
  "$out/flatten_bench" "${corpus[@]}" --quick --only bezcam --tol "$tol" 2>/dev/null | sed 's/^/  /'
done
