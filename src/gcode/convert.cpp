#include "bezcam/gcode/convert.hpp"

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/gcode/writer.hpp"
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

namespace {

// The text of the program read back and planned (its header written from
// `moves`: comments only, the motion is the same whatever they say).
MotionPlan text_plan(const Program& p, const MachineProfile& m, const MotionPlan& moves) {
  const MachineProfile set_up = with_compensation_registers(m, p);
  return plan_motion(read_timeline(write_gcode(p, m, &moves), &set_up), *m.motion, PlanDetail::summary);
}

}  // namespace

}  // namespace detail

MotionPlan program_plan(const Program& p, const MachineProfile& m, MotionPlan moves) {
  if (detail::plans_from_moves(p, m)) return moves;
  const MotionPlan text = detail::text_plan(p, m, moves);
  // The times are the text's; the time along the curves is the moves'
  // (the text read back does not say which blocks cut a curve), and the
  // tool change position lines run between entities, never along one.
  moves.cycle_time_s = text.cycle_time_s;
  moves.cutting_time_s = text.cutting_time_s;
  moves.rapid_time_s = text.rapid_time_s;
  moves.pause_time_s = text.pause_time_s;
  moves.programmed_feed_time_s = text.programmed_feed_time_s;
  return moves;
}

double program_cycle_time_s(const Program& p, const MachineProfile& m, const MotionPlan& moves) {
  return detail::plans_from_moves(p, m) ? moves.cycle_time_s : detail::text_plan(p, m, moves).cycle_time_s;
}

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
    // sample's plan against its text read back and planned). Where the
    // profile's tool change position lines move the machine between tools
    // (moves in the text only), its times are the text's read back.
    if (m.motion) r.plan = program_plan(p, m, plan_program_summary(p, *m.motion));
  });
  return r;
}

}  // namespace bezcam
