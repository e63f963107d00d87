#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, -fsanitize=fuzzer,address,undefined)
# with the project's sources, and a bezcam executable with the same
# sanitizers (run.sh uses it to make seed programs):
#
#   tests/fuzz/build.sh [BUILD_DIR]      (default: build-fuzz, beside the sources)
#
# Environment: JOBS (parallel compile jobs, default 1), CXX (default clang++).
# Needs the Debian packages clang and libclang-rt-14-dev. Fuzzing is not part
# of the test suite; findings are kept as gtest regression tests.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build-fuzz}"
command -v "${CXX:-clang++}" >/dev/null || { echo "build.sh: clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 1; }
cmake -S "$root/tests/fuzz" -B "$build" -DCMAKE_CXX_COMPILER="${CXX:-clang++}" -DCMAKE_BUILD_TYPE=Fuzz >/dev/null
cmake --build "$build" -j"${JOBS:-1}" --target fuzz_job_reader fuzz_gcode_reader fuzz_modbus_frames bezcam
echo "build.sh: fuzzers in $build: fuzz_job_reader fuzz_gcode_reader fuzz_modbus_frames"
