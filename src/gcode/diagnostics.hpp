#pragma once
// How the G-code reader reports a problem on a line: refuse it (an
// InputError "gcode.<id>" at "line N"), or, under lint_gcode(), record a
// recoverable problem and go on. Private to src/gcode.
#include <string>
#include <vector>

#include "bezcam/error_ids.hpp"
#include "bezcam/gcode/reader.hpp"

namespace bezcam::gcode {

struct Diagnostics {
  int line = 0;                                   // 1-based line being read
  std::vector<GcodeFinding>* findings = nullptr;  // set under lint_gcode()

  /// Refuses the line: throws InputError(id, Place::at_line(line), msg).
  [[noreturn]] void fail(ErrorId id, const std::string& msg) const;
  /// A problem the line can go on from: thrown by the reader, recorded by
  /// lint (at line `at` when nonzero).
  void soft(ErrorId id, const std::string& msg, int at = 0) const;
  /// Lint only: what a demanding machinist flags but a controller would run.
  void note(ErrorId id, const std::string& msg, int at = 0) const;
  /// Whether lint_gcode() is reading (findings are recorded, not thrown).
  bool lint() const { return findings != nullptr; }
};

}  // namespace bezcam::gcode
