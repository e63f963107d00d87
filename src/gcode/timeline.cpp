#include "bezcam/gcode/timeline.hpp"

#include <string>

#include "bezcam/error.hpp"
#include "interpreter_impl.hpp"

namespace bezcam {

void add_to_timeline(Timeline& tl, const std::vector<MotionBlock>& blocks, const MachineState& before,
                     const MachineState& after, int line_no) {
  tl.units = after.units;
  // Execution order within a line (RS274/NGC): tool change, spindle,
  // dwell, then the motion; a program stop after it.
  auto pause = [&](PlanPause::Kind k, double s) { tl.pauses.push_back({k, s, line_no, tl.blocks.size()}); };
  if (after.tool != before.tool) pause(PlanPause::Kind::tool_change, 0);
  if (after.spindle_on && !before.spindle_on) pause(PlanPause::Kind::spindle_start, 0);
  if (after.dwell_seconds > before.dwell_seconds) pause(PlanPause::Kind::dwell, after.dwell_seconds - before.dwell_seconds);
  for (const MotionBlock& b : blocks) {
    tl.blocks.push_back(b);
    tl.path_tolerance.push_back(after.path_tolerance);
  }
  if (after.program_stops > before.program_stops) pause(PlanPause::Kind::program_stop, 0);
}

Timeline read_timeline(std::string_view text, const MachineProfile* profile) {
  if (const auto f = gcode::too_large(text)) throw InputError(f->id, "line 1", f->message);
  GcodeInterpreter in(profile);
  Timeline tl;
  int no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const MachineState before = in.state();
    const auto blocks = in.feed_line(text.substr(pos, end - pos), ++no);
    add_to_timeline(tl, blocks, before, in.state(), no);
    pos = end + 1;
  }
  const MachineState before = in.state();
  const auto rest = in.finish();
  add_to_timeline(tl, rest, before, in.state(), no);
  return tl;
}

}  // namespace bezcam
