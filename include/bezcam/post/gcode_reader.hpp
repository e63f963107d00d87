#pragma once
/// One G-code reader for every dialect bezcam emits: G00/G01, G02/G03 (G17
/// with I/J), the Fanuc-style NURBS block (G06.2 or G06.3 start word, P rank,
/// K knots, R weights), LinuxCNC G5 / G5.1 Bézier moves and G5.2 ... G5.3
/// NURBS. Used by `bezcam lint`, by the round-trip tests, by the simulated
/// controller and by the preview. Parse, validate, then execute (Grbl's
/// structure): a line is checked completely before it changes the state.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/kernel/job.hpp"
#include "bezcam/post/machine_profile.hpp"

namespace bezcam {

enum class BlockKind { rapid, linear, arc_cw, arc_ccw, nurbs, bezier };

/// One executed motion in absolute program coordinates.
struct MotionBlock {
  BlockKind kind = BlockKind::linear;
  int line = 0;            ///< 1-based line of the program where the block ends
  int first_line = 0;      ///< where it starts (NURBS blocks span lines)
  Vec3 from, to;
  double feed = 0;         ///< units/min (0 for rapids)
  Vec3 center;             ///< arcs
  int order = 0;           ///< nurbs: degree + 1; bezier: degree + 1
  std::vector<Vec3> ctrl;  ///< nurbs / bezier control points, ctrl[0] == from
  std::vector<double> weights, knots;  ///< nurbs (LinuxCNC G5.2: the interpreter's clamped uniform knots)
};

/// Modal state of the interpreter.
struct MachineState {
  Vec3 pos;
  unsigned known_axes = 0;   ///< X 1, Y 2, Z 4: set once a word gave the axis
  Units units = Units::mm;
  bool units_set = false;
  bool absolute = true;
  int plane = 17;
  int motion = -1;           ///< 0,1,2,3 (G00..G03), -1 none
  double feed = 0;
  double spindle_rpm = 0;
  bool spindle_on = false;
  int tool = 0;
  bool program_end = false;  ///< M02 / M30 seen
};

/// A problem in a program, naming its line.
struct GcodeFinding {
  int line = 0;
  std::string id;       ///< stable id, e.g. gcode.knot-order
  std::string message;  ///< what is wrong and what was expected
};

/// Streaming interpreter: feed it lines in order.
class GcodeInterpreter {
 public:
  /// With a profile, travel limits and maximum feed are enforced too.
  explicit GcodeInterpreter(const MachineProfile* profile = nullptr);

  /// Interprets one line (`line_no` is 1-based). Returns the motion blocks
  /// the line completes (a NURBS block completes on the line that ends it).
  /// Throws InputError("gcode.*", "line N", ...) on any error; the state is
  /// unchanged by a refused line.
  std::vector<MotionBlock> feed_line(std::string_view text, int line_no);
  /// End of input: throws if a multi-line block is still open.
  std::vector<MotionBlock> finish();

  const MachineState& state() const { return state_; }

 private:
  struct Impl;
  const MachineProfile* profile_;
  MachineState state_;
  std::vector<std::string> pending_;  // implementation state of open blocks
  std::vector<int> pending_lines_;
};

/// Reads a whole program; throws at the first error (InputError, "line N").
std::vector<MotionBlock> read_gcode(std::string_view text, const MachineProfile* profile = nullptr);

/// Point of a block at t in [0,1] (arcs by angle, NURBS over the knot domain).
Vec3 evaluate_block(const MotionBlock& b, double t);

/// Checks a program against a profile; every finding names its line.
/// Syntax, knot order and counts and the other NURBS block rules, arcs valid
/// after rounding, travel limits and feeds.
std::vector<GcodeFinding> lint_gcode(std::string_view text, const MachineProfile& profile);

}  // namespace bezcam
