#pragma once
/// A G-code program as the trajectory planner sees it (machine/planner.hpp):
/// its motion blocks, the path mode in force at each (G61, G64 P-) and the
/// pauses between them (tool changes, spindle starts, dwells, program
/// stops), read with the one G-code reader.
#include <string>
#include <string_view>

#include "bezcam/gcode/reader.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam {

/// Reads the whole program (throws InputError "gcode.*" at "line N" as
/// read_gcode() does).
Timeline read_timeline(std::string_view text, const MachineProfile* profile = nullptr);

/// The same, from the text in pieces as it is written (a streamed program
/// read back without holding it): feed() any pieces in order, lines are
/// split here; finish() ends the input and returns the timeline. The same
/// refusals as read_timeline() (a program over the size bezcam reads is
/// refused at finish(), when its size is known).
class TimelineReader {
 public:
  /// The profile must outlive the reader.
  explicit TimelineReader(const MachineProfile* profile = nullptr) : in_(profile) {}
  void feed(std::string_view text);
  Timeline finish();

 private:
  void line(std::string_view text);
  GcodeInterpreter in_;
  Timeline tl_;
  std::string partial_;  // the start of a line a piece ended in
  int no_ = 0;
  size_t bytes_ = 0;
};

/// The same, one line at a time: what the simulated controller feeds as it
/// executes. `after` is the state once `line_no` was interpreted, `before`
/// the state before it.
void add_to_timeline(Timeline& tl, const std::vector<MotionBlock>& blocks, const MachineState& before,
                     const MachineState& after, int line_no);

}  // namespace bezcam
