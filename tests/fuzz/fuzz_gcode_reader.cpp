// libFuzzer target: G-code program text -> read_gcode (without a profile and
// with each dialect's profile) and lint_gcode, then every block read is
// evaluated and turned into its exact Bézier pieces, as the preview and the
// round-trip tests do.
//
// A refusal (bezcam::Error naming the line) is a correct answer, and so is
// std::invalid_argument from block_to_bezier() for a helical arc (its
// documented contract). Anything else is a finding.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"

namespace {

// The reader validated these blocks: every point of them is finite, and
// each starts where it says and ends where it says (evaluate_block's
// contract, up to rounding of the evaluation).
void use_blocks(const std::vector<bezcam::MotionBlock>& blocks) {
  using bezcam::Vec3;
  auto near = [](const Vec3& a, const Vec3& b) {
    const double scale = 1 + std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z)});
    return std::abs(a.x - b.x) <= 1e-6 * scale && std::abs(a.y - b.y) <= 1e-6 * scale &&
           std::abs(a.z - b.z) <= 1e-6 * scale;
  };
  for (const auto& b : blocks) {
    const Vec3 p0 = bezcam::evaluate_block(b, 0), pm = bezcam::evaluate_block(b, 0.37),
               p1 = bezcam::evaluate_block(b, 1);
    for (const Vec3& p : {p0, pm, p1})
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
    if (!near(p0, b.from) || !near(p1, b.to)) __builtin_trap();
    try {
      (void)bezcam::block_to_bezier(b);
    } catch (const std::invalid_argument&) {  // a helical arc: documented
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace bezcam;
  static const MachineProfile profiles[] = {load_machine_profile("generic"), load_machine_profile("fanuc"),
                                            load_machine_profile("fanuc-g063"), load_machine_profile("linuxcnc")};
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    use_blocks(read_gcode(text, nullptr));
  } catch (const Error&) {
  }
  for (const auto& p : profiles) {
    try {
      use_blocks(read_gcode(text, &p));
    } catch (const Error&) {
    }
    (void)lint_gcode(text, p);  // never throws: every problem is a finding
  }
  return 0;
}
