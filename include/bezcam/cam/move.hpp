#pragma once
/// The canonical move: one instruction of a program, before any text.
/// Program building (program.hpp) makes them, validation (validate.hpp)
/// checks them as a whole, the G-code writer (gcode/writer.hpp) prints them
/// in a profile's dialect. One type, a variant: each alternative holds what
/// that instruction needs and nothing else.
///
/// Coordinates are program coordinates in the job's units, already rounded
/// to the decimals they will be printed with (so what is validated and
/// measured is what the controller will read). Axis words are modal: a
/// motion sets only the axes named in `axes`.
#include <memory>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "bezcam/job/job.hpp"     // Coolant
#include "bezcam/kernel/arc.hpp"  // Plane
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// Which axes a motion's end point sets: X 1, Y 2, Z 4.
inline constexpr unsigned kAxisX = 1, kAxisY = 2, kAxisZ = 4, kAxesXYZ = 7;

/// What every motion has: where it ends and the feed it runs at.
struct Motion {
  Vec3 to;                   ///< end point (printed values)
  unsigned axes = kAxesXYZ;  ///< which of X, Y, Z `to` sets
  double feed = 0;           ///< units/min; 0 for rapids
  bool operator==(const Motion&) const = default;
};

/// G00: straight, at the machine's rapid rate (only at or above safe Z, or
/// straight up to it).
struct RapidMove : Motion {
  bool operator==(const RapidMove&) const = default;
};
/// G01: straight, at `feed`.
struct LineMove : Motion {
  bool operator==(const LineMove&) const = default;
};
/// G02 (clockwise) / G03 in `plane` (G17, G18, G19), around `center`
/// (absolute; printed as the plane's centre words I J, K I or J K relative to
/// the start). The plane's axis moves linearly with the angle (a helix) when
/// the ends differ along it.
struct ArcMove : Motion {
  Vec3 center;
  bool ccw = false;
  Plane plane = Plane::xy;
  bool operator==(const ArcMove&) const = default;
};
/// The curve of a CurveMove: its control points, weights and knots.
struct CurveShape {
  enum class Form { nurbs, bezier };
  Form form = Form::nurbs;
  std::vector<Vec3> ctrl;
  std::vector<double> weights;  ///< nurbs: one per point (empty: all 1)
  std::vector<double> knots;    ///< nurbs: ctrl.size() + order values
  int order = 0;                ///< degree + 1
  bool operator==(const CurveShape&) const = default;
};
/// An exact curve block: a NURBS block (Fanuc G06.2 / LinuxCNC G5.2) or a
/// LinuxCNC G5 / G5.1 Bézier move. `ctrl` starts at the current position.
/// The curve is held apart (shared by copies of the move), so that every
/// move of a long program stays as small as a line's or an arc's.
struct CurveMove : Motion {
  using Form = CurveShape::Form;
  std::shared_ptr<CurveShape> shape = std::make_shared<CurveShape>();
  /// The same block: the same end, feed and curve (not the same copy of it).
  friend bool operator==(const CurveMove& a, const CurveMove& b) {
    return static_cast<const Motion&>(a) == b && (a.shape == b.shape || *a.shape == *b.shape);
  }
};
/// The profile's move to the tool-change position (`tool_change_position`
/// lines), before a tool change.
struct ToolChangePosition {
  bool operator==(const ToolChangePosition&) const = default;
};
/// M06 with a T word.
struct ToolChange {
  int tool = 0;
  bool operator==(const ToolChange&) const = default;
};
/// Spindle on at `rpm` (> 0), or off (0).
struct SpindleMove {
  double rpm = 0;
  bool operator==(const SpindleMove&) const = default;
};
/// A comment line.
struct Comment {
  std::string text;
  bool operator==(const Comment&) const = default;
};
/// G04: wait (the spindle reaching its speed).
struct Dwell {
  double seconds = 0;
  bool operator==(const Dwell&) const = default;
};
/// M07 mist, M08 flood, M09 off.
struct CoolantMove {
  Coolant mode = Coolant::off;
  bool operator==(const CoolantMove&) const = default;
};
/// M00: the program stops until the operator resumes it (a manual tool
/// change on a machine without a changer), saying why.
struct ProgramStop {
  std::string message;
  bool operator==(const ProgramStop&) const = default;
};

/// A line printed as the job gives it: an entity's `before` / `after`
/// sequence, placeholders already replaced. Not motion bezcam plans: the
/// job's author answers for it (`bezcam lint` reads it like any line).
struct Verbatim {
  std::string text;
  bool operator==(const Verbatim&) const = default;
};

/// Cutter radius compensation (cutter_comp.hpp): `G41 D-` (side +1: the
/// tool on the left of the path), `G42 D-` (-1), or `G40` (0: off). `d` is
/// the offset register (the tool's number); `radius` what bezcam expects
/// it to hold, so that a built program is measured where the tool goes.
struct CompensationMove {
  int side = 0;
  int d = 0;
  double radius = 0;
  bool operator==(const CompensationMove&) const = default;
};

/// A canned drilling cycle for one hole at `at` (x, y; z unused): G81
/// (drill), G82 (dwell `p` seconds at the bottom), G83 (pecks of `q`, out
/// to the R plane after each) or G73 (pecks, backing off a little), from
/// the R plane `r` down to `z` at `feed`, back to the R plane (G99) or to
/// the level where the cycle began (G98). Not motion itself: the motion it
/// stands for follows as ordinary moves marked Move::in_cycle, as the
/// profile's `canned_cycles` dialect runs the cycle (gcode/reader.hpp).
/// The writer prints the cycle line and skips them on a profile with
/// canned cycles, and prints them (without the cycle) on one without.
struct CannedCycle {
  Vec3 at;
  double r = 0, z = 0, q = 0, p = 0, feed = 0;
  int code = 81;      ///< 81, 82, 83 or 73
  bool to_r = false;  ///< G99 (true) or G98
  bool operator==(const CannedCycle&) const = default;
};

struct Move {
  std::variant<RapidMove, LineMove, ArcMove, CurveMove, ToolChangePosition, ToolChange, SpindleMove, Comment, Dwell,
               CoolantMove, ProgramStop, Verbatim, CompensationMove, CannedCycle>
      what;
  int entity = -1;  ///< index of the job entity it cuts, -1 for none
  /// Part of the motion of the CannedCycle before it.
  bool in_cycle = false;
  bool operator==(const Move&) const = default;
};

/// The motion part of a move; null for tool changes, spindle, coolant,
/// dwells, stops and comments.
inline const Motion* motion_of(const Move& m) {
  return std::visit(
      [](const auto& x) -> const Motion* {
        if constexpr (std::is_base_of_v<Motion, std::decay_t<decltype(x)>>)
          return &x;
        else
          return nullptr;
      },
      m.what);
}
/// Whether the move is a rapid (G00).
inline bool is_rapid(const Move& m) { return std::holds_alternative<RapidMove>(m.what); }

}  // namespace bezcam
