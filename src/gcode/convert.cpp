#include "bezcam/gcode/convert.hpp"

#include "bezcam/cam/program_motion.hpp"
#include "convert_plan.hpp"

namespace bezcam {

namespace detail {

bool plans_from_moves(const Program& p, const MachineProfile& m) {
  if (m.tool_change_position.empty()) return true;
  bool moved = false;
  for (const Move& mv : p.moves) {
    if (moved && std::holds_alternative<ToolChangePosition>(mv.what)) return false;
    moved = moved || motion_of(mv) != nullptr;
  }
  return true;
}

}  // namespace detail

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
    if (m.motion && detail::plans_from_moves(p, m)) r.plan = plan_program_summary(p, *m.motion);
  });
  return r;
}

}  // namespace bezcam
