// libFuzzer target: job JSON text -> parse_job -> convert for the generic
// profile (lines, then arcs), as `bezcam convert` runs them.
//
// A refusal (bezcam::Error: InputError naming the place) is a correct
// answer. Anything else is a finding: another exception escaping (an
// internal error), a crash, a sanitizer report, a leak, or a timeout
// (run.sh gives each input 60 seconds in this slow instrumented build,
// where the sample patches take 5 to 10: bezcam must finish or refuse
// quickly whatever it is fed).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bezcam/error.hpp"
#include "bezcam/kernel/job.hpp"
#include "bezcam/post/convert.hpp"

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
  // Surfaces are cut with G01 lines in every mode: arcs only add work for curves.
  bool surfaces = false;
  for (const auto& e : job.entities) surfaces = surfaces || e.surface != nullptr;
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
    if (mode == OutputMode::arcs && surfaces) break;
    ConvertOptions opt;
    opt.output = mode;
    try {
      const ConvertResult r = convert(job, generic, opt);
      // The program states the tolerance it was proven to: the proof and the
      // independent measurement must agree with it.
      if (r.program.max_measured > r.program.tolerance || r.program.max_bound > r.program.tolerance) __builtin_trap();
    } catch (const Error&) {
      return 0;  // refused, with a message naming the place
    }
  }
  return 0;
}
