// libFuzzer target: job JSON text -> parse_job -> convert, as `bezcam
// convert` runs them: curves as lines and arcs (generic) and as NURBS blocks
// (fanuc), surfaces as lines.
//
// A refusal (bezcam::Error: InputError naming the place) is a correct
// answer. Anything else is a finding: another exception escaping (an
// internal error), a crash, a sanitizer report, a leak, a program whose
// proven or measured deviation exceeds its tolerance, or a timeout (run.sh
// gives each input 60 seconds in this slow instrumented build: bezcam must
// finish or refuse quickly whatever it is fed).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace bezcam;
  static const MachineProfile generic = load_machine_profile("generic");
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Job job;
  try {
    job = parse_job(text, "fuzz.json");
  } catch (const Error&) {
    return 0;
  }
  static const MachineProfile fanuc = load_machine_profile("fanuc");
  // Curves are cut in every output mode (lines, arcs, exact NURBS blocks).
  // Surfaces are cut with G01 lines in every mode, so once; at no finer than
  // 0.05 mm, because a sample patch at its own 0.01 mm takes 5 to 10 s in
  // this instrumented build (0.3 s in a release build) and the fuzzer would
  // spend its time there instead of exploring.
  bool surfaces = false;
  for (const auto& e : job.entities) surfaces = surfaces || e.surface != nullptr;
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    if (mode != OutputMode::lines && surfaces) break;
    ConvertOptions opt;
    opt.output = mode;
    if (surfaces) opt.tolerance = std::max(job.tolerance, 0.05);
    try {
      const ConvertResult r = convert(job, mode == OutputMode::nurbs ? fanuc : generic, opt);
      // The program states the tolerance it was proven to: the proof and the
      // independent measurement must agree with it.
      if (r.program.max_measured > r.program.tolerance || r.program.max_bound > r.program.tolerance) __builtin_trap();
    } catch (const Error&) {
      return 0;  // refused, with a message naming the place
    }
  }
  return 0;
}
