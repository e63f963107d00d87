#!/usr/bin/env bash
# Runs one fuzzer for a given time, on its corpus (kept in the build
# directory, grown across runs) and its seeds:
#
#   tests/fuzz/run.sh TARGET SECONDS [BUILD_DIR]
#
# TARGET: fuzz_job_reader | fuzz_gcode_reader | fuzz_modbus_frames | fuzz_drawing_reader (or job,
# gcode, modbus). BUILD_DIR as given to build.sh (default build-fuzz).
# Seeds: job files from samples/ and tests/bad/; G-code from tests/golden/
# and tests/bad/ and the samples converted for every dialect; Modbus frames
# from the worked example of docs/modbus-register-map.md. Each input gets
# TIMEOUT seconds (default 20; 60 for the job reader, which converts what
# it reads in this instrumented -O1 build, 30 times slower than a release
# build): slower is a hang.
# A finding is written to BUILD_DIR/artifacts/TARGET/ and the run stops;
# reproduce it with BUILD_DIR/TARGET FILE, fix it, and keep it as a gtest
# regression test (tests/<layer>/fuzz_regressions_test.cpp).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -ge 2 ] || { echo "usage: $0 TARGET SECONDS [BUILD_DIR]" >&2; exit 2; }
target="$1" secs="$2" build="${3:-$root/build-fuzz}"
case "$target" in
  job) target=fuzz_job_reader ;;
  gcode) target=fuzz_gcode_reader ;;
  modbus) target=fuzz_modbus_frames ;;
  drawing) target=fuzz_drawing_reader ;;
esac
exe="$build/$target"
[ -x "$exe" ] || { echo "run.sh: $exe not found; build it with tests/fuzz/build.sh $build" >&2; exit 2; }
seeds="$build/seeds/$target" corpus="$build/corpus/$target" artifacts="$build/artifacts/$target"
mkdir -p "$corpus" "$artifacts"

if [ ! -d "$seeds" ]; then
  mkdir -p "$seeds"
  case "$target" in
    fuzz_drawing_reader)
      cp "$root"/samples/*.svg "$root"/samples/*.dxf "$seeds"/
      for f in "$root"/tests/bad/drawing-*; do case "$f" in *.expect) ;; *) cp "$f" "$seeds/bad-$(basename "$f")" ;; esac; done ;;
    fuzz_job_reader)
      cp "$root"/samples/*.json "$seeds"/
      for f in "$root"/tests/bad/*.json; do cp "$f" "$seeds/bad-$(basename "$f")"; done ;;
    fuzz_gcode_reader)
      for f in "$root"/tests/golden/*.nc "$root"/tests/bad/*.nc; do
        [ -f "$f" ] && cp "$f" "$seeds/$(basename "$(dirname "$f")")-$(basename "$f")"
      done
      bezcam="$build/bezcam/bezcam"
      if [ -x "$bezcam" ]; then
        for s in "$root"/samples/*.json; do
          for pm in generic:lines generic:arcs fanuc:nurbs fanuc-g063:nurbs linuxcnc:nurbs linuxcnc:arcs; do
            "$bezcam" convert "$s" --machine "${pm%%:*}" --output "${pm##*:}" -q \
              -o "$seeds/$(basename "$s" .json).${pm%%:*}.${pm##*:}.nc" 2>/dev/null || true
          done
        done
      fi ;;
    fuzz_modbus_frames)
      # The worked example's requests: the whole transfer as one stream, and
      # each request alone.
      sed -n '/^## 8\. Worked example/,/^## 9/p' "$root/docs/modbus-register-map.md" | grep '^> ' | sed 's/^> //' \
        > "$seeds/.frames"
      n=0
      while read -r line; do
        n=$((n + 1))
        echo "$line" | xxd -r -p > "$seeds/frame-$n"
        echo "$line" | xxd -r -p >> "$seeds/transfer"
      done < "$seeds/.frames"
      rm "$seeds/.frames" ;;
    *) echo "run.sh: unknown target $target" >&2; exit 2 ;;
  esac
fi

dict=()
case "$target" in
  fuzz_job_reader) dict=(-dict="$root/tests/fuzz/job.dict") ;;
  fuzz_gcode_reader) dict=(-dict="$root/tests/fuzz/gcode.dict") ;;
esac
timeout=20
[ "$target" = fuzz_job_reader ] && timeout=60
# Inputs of at most MAX_LEN bytes (default 8192: a few hundred G-code lines
# or a job of many entities). The golden programs reach 140 KB; mutating
# those runs at about 30 inputs a second instead of thousands, and what
# only a long input reaches (the line, program and file limits) is tested
# directly in tests/*/limits_test.cpp.
exec "$exe" -max_total_time="$secs" -timeout="${TIMEOUT:-$timeout}" -rss_limit_mb=2048 -print_final_stats=1 \
  -max_len="${MAX_LEN:-8192}" -artifact_prefix="$artifacts/" "${dict[@]}" "$corpus" "$seeds"
