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
# The build's options for a source, from its compile_commands.json (any
# generator): optimisation, debug, defines, standard and machine options.
flags_of() {
  python3 - "$build/compile_commands.json" "$1" <<'PY'
import json, shlex, sys
for e in json.load(open(sys.argv[1])):
    if e["file"].endswith(sys.argv[2]):
        args = e.get("arguments") or shlex.split(e["command"])
        keep = [a for a in args if a[:2] in ("-O", "-g", "-D", "-m", "-f") or a.startswith("-std")]
        print(" ".join(shlex.quote(a) for a in keep))
        sys.exit(0)
sys.exit("flatten_ab.sh: %s is not in %s (build it first)" % (sys.argv[2], sys.argv[1]))
PY
}
# The driver with the benchmarks' options; the variant with those the
# library's copy is compiled with (its own -O3 included). Assigned first,
# so that a source missing from the build stops the script.
driver_flags=$(flags_of bench/flatten_bench.cpp)
variant_flags=$(flags_of src/flatten/flatten_curve.cpp)
eval "flags=($driver_flags)"
eval "own=($variant_flags)"
inc="-I$src/include -I$src/src -I$build/include"
c++ "${own[@]}" $inc -c "$out/variant.cpp" -o "$out/variant.o"
c++ "${flags[@]}" $inc -c "$src/bench/ab/flatten_ab.cpp" -o "$out/driver.o"
libs=("$build"/libbezcam_flatten.a "$build"/libbezcam_kernel.a "$build"/libbezcam_base.a)
c++ "${flags[@]}" "$out/driver.o" "$out/variant.o" -o "$out/flatten_ab" "${libs[@]}" "${libs[@]}"
"$out/flatten_ab" "$corpus" "${4:-10}" "${5:-61}"
