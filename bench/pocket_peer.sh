#!/bin/bash
# bezcam's pockets beside FreeCAD's Adaptive, in one run, every program
# measured by the same check (build/pocket_peer: bezcam's pocket
# certificate read from the program's text). Prints a Markdown table.
#
#   bench/pocket_peer.sh [BUILD_DIR]
#
# Needs Debian's freecad package (not installed by .ci/packages: the
# comparison is run by hand, docs/benchmarks.md gives its figures).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
cases=$here/pocket_peer/cases.json
[ -f /usr/lib/freecad-python3/lib/area.so ] || {
  echo "pocket_peer.sh: FreeCAD is not installed (apt-get install freecad)" >&2
  exit 3
}
out=$(mktemp -d /tmp/pocket_peer.XXXXXX)
trap 'rm -rf "$out"' EXIT

/usr/bin/python3 "$here/pocket_peer/freecad_adaptive.py" "$cases" "$out" 2>/dev/null | grep "^{" > "$out/freecad.jsonl"
n=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['cases']))" "$cases")

row() {  # case, program, seconds, who
  local fig
  fig=$("$build/pocket_peer" check "$cases" "$1" "$2")
  python3 - "$cases" "$1" "$3" "$4" "$fig" <<'EOF'
import json, sys
cases = json.load(open(sys.argv[1]))["cases"]
c, secs, who, f = cases[int(sys.argv[2])], float(sys.argv[3]), sys.argv[4], json.loads(sys.argv[5])
walls = "yes" if f["wall_distance_mm"] >= f["wall_distance_needed_mm"] else "NO (%.3f)" % f["wall_distance_mm"]
covered = "yes" if f["uncut_mm2"] <= f["uncut_limit_mm2"] else "NO"
kept = "" if f["engagement_deg"] <= f["engagement_bound_deg"] else " (over %.1f)" % f["engagement_bound_deg"]
print("| %s | %s | %.3f | %.0f | %.1f | %.1f%s at %.2f, %.2f | %.2f (limit %.2f) %s | %s | %d |" % (
    c["name"], who, secs, f["length_mm"], f["cycle_s_linuxcnc"], f["engagement_deg"], kept, f["engagement_at"][0],
    f["engagement_at"][1], f["uncut_mm2"], f["uncut_limit_mm2"], covered, walls, f["rapids_below_top"]))
EOF
}

echo "| pocket | program | s | length mm | linuxcnc s | largest engagement deg | uncut mm^2 | walls kept | G0 below top |"
echo "|---|---|---:|---:|---:|---|---|---|---:|"
for ((i = 0; i < n; ++i)); do
  secs=$(python3 -c "import json,sys
for l in open(sys.argv[1]):
    d = json.loads(l)
    if d['case'] == int(sys.argv[2]): print(d['seconds'])" "$out/freecad.jsonl" "$i")
  row "$i" "$out/$i.freecad.ngc" "$secs" "FreeCAD Adaptive (Execute)"
  for pattern in adaptive offset; do
    "$build/pocket_peer" job "$cases" "$i" "$pattern" > "$out/$i.$pattern.json"
    t0=$(date +%s.%N)
    if "$build/bezcam" convert "$out/$i.$pattern.json" -o "$out/$i.$pattern.ngc" -q 2> "$out/$i.$pattern.err"; then
      t1=$(date +%s.%N)
      row "$i" "$out/$i.$pattern.ngc" "$(echo "$t1 - $t0" | bc)" "bezcam $pattern (whole command)"
    else
      echo "| $(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['cases'][int(sys.argv[2])]['name'])" "$cases" "$i") | bezcam $pattern | refused: $(head -c 150 "$out/$i.$pattern.err" | tr '\n|' '  ') | | | | | | |"
    fi
  done
done
