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
source "$src/bench/build_flags.sh"
flatten_flags
inc="-I$src/include -I$src/src -I$build/include"
c++ "${own[@]}" -DBEZCAM_FLATTEN_COUNTERS $inc -c "$src/src/flatten/flatten_curve.cpp" -o "$out/flatten_curve.o"
c++ "${flags[@]}" $inc $(pkg-config --cflags cairo 2>/dev/null) -c "$src/bench/flatten_bench.cpp" -o "$out/flatten_bench.o"
libs=("$build"/libbezcam_*.a)
c++ "${flags[@]}" "$out/flatten_bench.o" "$out/flatten_curve.o" -o "$out/flatten_bench" "${libs[@]}" "${libs[@]}" \
  $(pkg-config --libs cairo 2>/dev/null)
for tol in 0.1 0.01 0.001; do
  echo "tol $tol mm:"
  "$out/flatten_bench" "${corpus[@]}" --quick --only bezcam --tol "$tol" 2>&1 >/dev/null | sed 's/^/  /'
  "$out/flatten_bench" "${corpus[@]}" --quick --only bezcam --tol "$tol" 2>/dev/null | sed 's/^/  /'
done
