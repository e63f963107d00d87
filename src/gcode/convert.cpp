#include "bezcam/gcode/convert.hpp"

#include "bezcam/cam/program_motion.hpp"

namespace bezcam {

namespace {

// Whether the profile's tool change position lines (e.g. G53 G00 Z0.) run
// after the program has moved: a motion the program's moves do not hold.
bool retracts_between_tools(const Program& p, const MachineProfile& m) {
  if (m.tool_change_position.empty()) return false;
  bool moved = false;
  for (const Move& mv : p.moves) {
    if (moved && std::holds_alternative<ToolChangePosition>(mv.what)) return true;
    moved = moved || motion_of(mv) != nullptr;
  }
  return false;
}

}  // namespace

ConvertResult convert(const Job& job, const MachineProfile& m, const ConvertOptions& opt) {
  ConvertResult r = convert_program(job, m, opt);
  r.gcode = write_gcode(r.program, m, r.plan ? &*r.plan : nullptr);
  return r;
}

ConvertResult convert_program(const Job& job, const MachineProfile& m, const ConvertOptions& opt) {
  ConvertResult r;
  // Validation and the plan read the moves only, never the measured
  // readings: they run while the measurements finish on the other cores.
  // A failed measurement is still the error thrown when both fail (as when
  // they ran after it), and either leaves no program to write.
  r.program = build_program(job, m, opt, [&](const Program& p) {
    validate_program(p, m);  // before one character is written
    // One plan for the header and the report, from the program's moves:
    // the printed program's motion (coordinates are rounded to the printed
    // decimals when the program is built; MotionGolden checks every
    // sample's plan against its text read back and planned). Not where the
    // profile's tool change position lines move the machine between tools:
    // those moves are in the text only, and the report plans the text read
    // back.
    if (m.motion && !retracts_between_tools(p, m)) r.plan = plan_program_summary(p, *m.motion);
  });
  return r;
}

}  // namespace bezcam
