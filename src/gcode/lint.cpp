// lint_gcode(): the reader run with findings recorded instead of thrown,
// and the checks only lint makes (modes unset, unknown position, spindle
// stopped, rapid plunges, N order, jumps inside a NURBS block).
#include "bezcam/gcode/lint.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "interpreter_impl.hpp"

namespace bezcam {

using namespace gcode;

void GcodeInterpreter::LineRun::lint_motion(BlockKind kind, const Vec3& from, const Vec3& to, unsigned axes) {
  if (!lint()) return;
  if (!mo.noted_modes && (!st.units_set || !mo.distance_set || !mo.plane_set)) {
    std::vector<std::string> missing;
    if (!st.units_set) missing.push_back("G21/G20 (units)");
    if (!mo.distance_set) missing.push_back("G90 (absolute)");
    if (!mo.plane_set) missing.push_back("G17 (XY plane)");
    std::string list = missing[0];
    for (size_t k = 1; k < missing.size(); ++k) list += (k + 1 == missing.size() ? " and " : ", ") + missing[k];
    note(errc::gcode_modes_unset, "the first move comes before " + list + (missing.size() == 1 ? " is" : " are") +
                                      " set: the machine would use whatever the last program left; start with a safety "
                                      "line such as G21 G90 G17");
    mo.noted_modes = true;
  }
  if (is_cutting(kind)) {
    if (!mo.noted_position && (st.known_axes & 7) != 7) {
      note(errc::gcode_position_unknown, "this cutting move starts from an unknown position (no earlier move set " +
                                             std::string((st.known_axes & 1) ? "" : "X ") +
                                             ((st.known_axes & 2) ? "" : "Y ") + ((st.known_axes & 4) ? "" : "Z ") +
                                             "): position the tool with G00 first");
      mo.noted_position = true;
    }
    if (!st.spindle_on && !mo.noted_spindle) {
      note(errc::gcode_spindle_off, "cutting move with the spindle stopped: no M03/M04 is in effect");
      mo.noted_spindle = true;
    }
  } else if ((axes & 3) && (axes & 4) && to.z < from.z && (to.x != from.x || to.y != from.y)) {
    note(errc::gcode_rapid_plunge,
         "a rapid move lowers Z while moving in X/Y: plunge separately (G00 over the point, then "
         "G01 down)");
  }
}

void GcodeInterpreter::LineRun::lint_jumps(const MotionBlock& b) {
  const auto& U = b.knots;
  const size_t k = static_cast<size_t>(b.order);
  for (size_t i = k; i + k < U.size();) {
    size_t j = i;
    while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
    if (j - i + 1 >= k && i < b.ctrl.size() && b.ctrl[i - 1] != b.ctrl[i])
      note(errc::gcode_nurbs_jump,
           "knot " + fmt_num(U[i]) + " repeats " + std::to_string(j - i + 1) +
               " times inside the NURBS block of line " + std::to_string(b.first_line) + ": the curve jumps from " +
               pt(b.ctrl[i - 1]) + " to " + pt(b.ctrl[i]),
           b.line);
    i = j + 1;
  }
}

void GcodeInterpreter::LineRun::check_n() {
  if (mo.last_n >= 0 && *ln.n <= mo.last_n)
    note(errc::gcode_line_number_order, "line number N" + std::to_string(*ln.n) +
                                            " does not increase (the previous was N" + std::to_string(mo.last_n) + ")");
  mo.last_n = *ln.n;
}

std::vector<GcodeFinding> lint_gcode(std::string_view text, const MachineProfile& profile) {
  if (const auto f = too_large(text)) return {*f};
  std::vector<GcodeFinding> findings;
  GcodeInterpreter in(&profile);
  in.impl_->findings = &findings;
  int no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    ++no;
    try {
      in.feed_line(text.substr(pos, end - pos), no);
    } catch (const InputError& e) {
      findings.push_back({no, e.id(), e.message()});  // the line is skipped
      if (e.id() == errc::gcode_program_too_long) {   // and so is the rest: one finding, not millions
        std::stable_sort(findings.begin(), findings.end(),
                         [](const auto& a, const auto& b) { return a.line < b.line; });
        return findings;
      }
    }
    pos = end + 1;
  }
  try {
    in.finish();
  } catch (const InputError& e) {
    findings.push_back({std::max(no, 1), e.id(), e.message()});
  }
  if (!in.state().program_end)
    findings.push_back({std::max(no, 1), errc::gcode_no_program_end,
                        "the program has no end (M02 or M30): the controller may wait or run on"});
  std::stable_sort(findings.begin(), findings.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
  return findings;
}

}  // namespace bezcam
