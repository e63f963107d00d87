#include "bezcam/gcode/timeline.hpp"

#include <algorithm>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/limits.hpp"
#include "interpreter_impl.hpp"

namespace bezcam {

void add_to_timeline(Timeline& tl, const std::vector<MotionBlock>& blocks, const MachineState& before,
                     const MachineState& after, int line_no) {
  tl.units = after.units;
  // Execution order within a line (RS274/NGC): tool change, spindle,
  // dwell, then the motion; a program stop after it. A canned cycle's
  // dwells come after the blocks they follow (G04 cannot share their line).
  auto pause = [&](PlanPause::Kind k, double s) { tl.pauses.push_back({k, s, line_no, tl.blocks.size()}); };
  if (after.tool != before.tool) pause(PlanPause::Kind::tool_change, 0);
  if (after.spindle_on && !before.spindle_on) pause(PlanPause::Kind::spindle_start, 0);
  const bool block_dwells = std::any_of(blocks.begin(), blocks.end(), [](const auto& b) { return b.dwell_s > 0; });
  if (!block_dwells && after.dwell_seconds > before.dwell_seconds)
    pause(PlanPause::Kind::dwell, after.dwell_seconds - before.dwell_seconds);
  for (const MotionBlock& b : blocks) {
    tl.blocks.push_back(b);
    tl.path_tolerance.push_back(after.path_tolerance);
    tl.tools.push_back(after.tool);
    if (b.dwell_s > 0) pause(PlanPause::Kind::dwell, b.dwell_s);
  }
  if (after.program_stops > before.program_stops) pause(PlanPause::Kind::program_stop, 0);
}

void TimelineReader::line(std::string_view text) {
  const MachineState before = in_.state();
  const auto blocks = in_.feed_line(text, ++no_);
  add_to_timeline(tl_, blocks, before, in_.state(), no_);
}

void TimelineReader::feed(std::string_view text) {
  bytes_ += text.size();
  if (bytes_ > kMaxProgramBytes) return;  // refused at finish(), with its size
  while (!text.empty()) {
    const size_t end = text.find('\n');
    if (end == std::string_view::npos) {
      partial_ += text;
      return;
    }
    if (partial_.empty()) {
      line(text.substr(0, end));
    } else {
      partial_ += text.substr(0, end);
      line(partial_);
      partial_.clear();
    }
    text.remove_prefix(end + 1);
  }
}

Timeline TimelineReader::finish() {
  if (const auto f = gcode::too_large(bytes_)) throw InputError(f->id, Place::at_line(1), f->message);
  if (!partial_.empty()) line(partial_);  // the last line, without its newline
  partial_.clear();
  const MachineState before = in_.state();
  const auto rest = in_.finish();
  add_to_timeline(tl_, rest, before, in_.state(), no_);
  return std::move(tl_);
}

Timeline read_timeline(std::string_view text, const MachineProfile* profile) {
  if (const auto f = gcode::too_large(text)) throw InputError(f->id, Place::at_line(1), f->message);
  TimelineReader r(profile);
  r.feed(text);
  return r.finish();
}

}  // namespace bezcam
