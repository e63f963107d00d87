#!/usr/bin/env bash
# Times a changed copy of src/flatten/flatten_curve.cpp against the built
# library's, in one process (bench/flatten_ab.cpp says why): the variant's
# public functions get a _v suffix, it is compiled with the build's flags
# and linked, with the driver, against the build's libraries, in a
# temporary directory (the build itself is not touched).
# Usage: bench/flatten_ab.sh BUILD_DIR VARIANT.cpp [CORPUS.json [EVERY [ROUNDS]]]
#        (TOLS="0.1 0.01" to choose the tolerances; default corpus:
#        bench/corpus/cubics-10k.json, every 10th curve, 61 rounds)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:?usage: flatten_ab.sh BUILD_DIR VARIANT.cpp [CORPUS [EVERY [ROUNDS]]]}" && pwd)
variant=${2:?usage: flatten_ab.sh BUILD_DIR VARIANT.cpp [CORPUS [EVERY [ROUNDS]]]}
corpus=${3:-$src/bench/corpus/cubics-10k.json}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
sed -E 's/\bflatten_pieces\b/flatten_pieces_v/g; s/\bflatten_into\b/flatten_into_v/g; s/\bFlattenResult flatten\(/FlattenResult flatten_v(/; s/\bdouble (chord_deviation|band_deviation|estimate_segments)\(/double \1_v(/' \
  "$variant" > "$out/variant.cpp"
source "$src/bench/build_flags.sh"
flatten_flags
inc="-I$src/include -I$src/src -I$build/include"
c++ "${own[@]}" $inc -c "$out/variant.cpp" -o "$out/variant.o"
c++ "${flags[@]}" $inc -c "$src/bench/ab/flatten_ab.cpp" -o "$out/driver.o"
libs=("$build"/libbezcam_flatten.a "$build"/libbezcam_kernel.a "$build"/libbezcam_base.a)
c++ "${flags[@]}" "$out/driver.o" "$out/variant.o" -o "$out/flatten_ab" "${libs[@]}" "${libs[@]}"
"$out/flatten_ab" "$corpus" "${4:-10}" "${5:-61}"
