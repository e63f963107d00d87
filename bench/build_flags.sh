# Sourced by the scripts that compile a copy of a source beside a build
# (bench/flatten_ab.sh, bench/flatten_tries.sh): flags_of SOURCE prints the
# build's options for SOURCE, from "$build/compile_commands.json" (any
# generator): optimisation, debug, defines, standard and machine options.
flags_of() {
  python3 - "$build/compile_commands.json" "$1" "$(basename "$0")" <<'PY'
import json, shlex, sys
for e in json.load(open(sys.argv[1])):
    if e["file"].endswith(sys.argv[2]):
        args = e.get("arguments") or shlex.split(e["command"])
        keep = [a for a in args if a[:2] in ("-O", "-g", "-D", "-m", "-f") or a.startswith("-std")]
        print(" ".join(shlex.quote(a) for a in keep))
        sys.exit(0)
sys.exit("%s: %s is not in %s (build it first)" % (sys.argv[3], sys.argv[2], sys.argv[1]))
PY
}
# Sets the arrays `flags` (the benchmarks' options) and `own` (those the
# library's copy of src/flatten/flatten_curve.cpp is compiled with, its
# own -O3 included); stops the script when either source is not built.
flatten_flags() {
  local driver variant
  driver=$(flags_of bench/flatten_bench.cpp)
  variant=$(flags_of src/flatten/flatten_curve.cpp)
  eval "flags=($driver)"
  eval "own=($variant)"
}
