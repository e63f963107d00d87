#pragma once
/// Checking a G-code program against a machine profile (`bezcam lint`): the
/// G-code reader (reader.hpp) run with its findings collected instead of
/// thrown, plus the checks a demanding machinist adds.
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {

/// A problem in a program, naming its line.
struct GcodeFinding {
  int line = 0;
  std::string id;       ///< stable id, e.g. gcode.knot-order
  std::string message;  ///< what is wrong and what was expected
};

/// Checks a program against a profile; every finding names its line.
/// Syntax, knot order and counts and the other NURBS block rules, arcs valid
/// after rounding, travel limits and feeds: everything read_gcode() refuses,
/// but all of it (a line with an error is skipped, recoverable problems such
/// as a decreasing knot are reported and the values kept, so that every
/// decreasing knot is listed). Beyond the reader, it flags: a first move
/// before G20/G21, G90 and G17 are all set; cutting from an unknown
/// position; cutting with the spindle stopped; a rapid that lowers Z while
/// moving in X or Y; M06 without a T word; N numbers that do not increase;
/// a NURBS block whose interior knot of multiplicity P lets the curve jump;
/// no M02/M30. Sorted by line.
std::vector<GcodeFinding> lint_gcode(std::string_view text, const MachineProfile& profile);

}  // namespace bezcam
