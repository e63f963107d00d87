// libFuzzer target: drawing text (SVG or DXF) -> read_svg / read_dxf ->
// join_contours -> to_job -> convert (generic, lines and arcs), as `bezcam
// convert DRAWING` runs them. The first byte chooses the reader (even: SVG,
// odd: DXF); the replay of samples and tests/bad feeds each file to both.
//
// A refusal (bezcam::Error) is a correct answer. Anything else is a
// finding: another exception, a crash, a sanitizer report, a program whose
// measured deviation exceeds its tolerance, a timeout.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/import/dxf_reader.hpp"
#include "bezcam/import/svg_reader.hpp"

namespace {
void run(std::string_view text, bool dxf) {
  using namespace bezcam;
  static const MachineProfile generic = load_machine_profile("generic");
  try {
    import::Drawing d = dxf ? import::read_dxf(text, "fuzz.dxf") : import::read_svg(text, "fuzz.svg");
    if (dxf) import::join_contours(d);
    const Job job = import::to_job(d);
    for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
      ConvertOptions opt;
      opt.output = mode;
      const ConvertResult r = convert(job, generic, opt);
      if (r.program.max_measured > r.program.tolerance) std::abort();
    }
  } catch (const Error&) {
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  run(text, (data[0] & 1) != 0);
  // The whole input as a file of either kind (the replay's samples).
  const std::string_view whole(reinterpret_cast<const char*>(data), size);
  run(whole, false);
  run(whole, true);
  return 0;
}
