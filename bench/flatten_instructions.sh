#!/usr/bin/env bash
# Instructions executed by bezcam's flattener and by cairo's over the same
# curves (every 10th corpus curve), counted by callgrind: a speed comparison
# that the load of a shared machine does not change.
# Usage: bench/flatten_instructions.sh [BUILD_DIR [CORPUS.json]]  (default corpus:
# flatten_bench's own, bench/corpus/cubics-10k.json)
set -euo pipefail
build=${1:-build}
corpus=(${2:+"$2"})
command -v valgrind >/dev/null || { echo "valgrind is not installed" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| tol mm | bezcam instructions | cairo instructions | cairo / bezcam |"
echo "|---:|---:|---:|---:|"
for tol in 0.1 0.01 0.001; do
  declare -A n
  for m in bezcam cairo; do
    valgrind --tool=callgrind --callgrind-out-file="$out/$m" --toggle-collect='run_only*' \
      "$build/flatten_bench" "${corpus[@]}" --quick --only "$m" --tol "$tol" >/dev/null 2>"$out/$m.log"
    n[$m]=$(grep -oE 'Collected : [0-9]+' "$out/$m.log" | grep -oE '[0-9]+')
  done
  awk -v t="$tol" -v a="${n[bezcam]}" -v b="${n[cairo]}" 'BEGIN { printf "| %s | %d | %d | %.2fx |\n", t, a, b, b / a }'
done
