// Modal groups and the non-motion words of a line: one code per group,
// every word meaning something, then RS274/NGC's execution order (F, S, T,
// M06, spindle, coolant, dwell, plane, units, distance, motion, end).
#include "modal_state.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "interpreter_impl.hpp"

namespace bezcam {

namespace gcode {

GGroup g_group(int c) {
  switch (c) {
    case 0:
    case 10:
    case 20:
    case 30:
    case 50:
    case 51:
    case 52:
    case 53:
    case 62:
    case 63:
    case 730:
    case 800:
    case 810:
    case 820:
    case 830: return GGroup::motion;
    case 40:
    case 280:
    case 300:
    case 530: return GGroup::non_modal;
    case 170:
    case 180:
    case 190: return GGroup::plane;
    case 900:
    case 910: return GGroup::distance;
    case 901:
    case 911: return GGroup::arc_distance;
    case 930:
    case 940:
    case 950: return GGroup::feed_mode;
    case 200:
    case 210: return GGroup::units;
    case 400:
    case 410:
    case 420: return GGroup::cutter_comp;
    case 430:
    case 490: return GGroup::tool_length;
    case 980:
    case 990: return GGroup::cycle_return;
    case 540:
    case 550:
    case 560:
    case 570:
    case 580:
    case 590: return GGroup::coord_system;
    case 610:
    case 611:
    case 640: return GGroup::path_mode;
    default: return GGroup::unsupported;
  }
}

MGroup m_group(int c) {
  switch (c) {
    case 0:
    case 1:
    case 2:
    case 30: return MGroup::stopping;
    case 3:
    case 4:
    case 5: return MGroup::spindle;
    case 6: return MGroup::tool_change;
    case 7:
    case 8:
    case 9: return MGroup::coolant;
    default: return MGroup::unsupported;
  }
}

}  // namespace gcode

using namespace gcode;

void GcodeInterpreter::LineRun::run_modal() {
  const Codes codes = gather_codes();
  if (mo.open == ModalMotion::nurbs_g5_2 && codes.motion != 53)
    fail(errc::gcode_nurbs_open,
         "the G5.2 block opened at line " + std::to_string(mo.open_line) + " is still open: close it with G5.3");
  const int active = active_motion(codes);
  check_combinations(codes, active);

  // Execution order (RS274/NGC): F, S, T, M06, spindle, coolant, dwell,
  // plane, units, distance modes, motion, program end.
  set_feed_speed_tool();
  run_m_codes();
  if (codes.dwell) dwell();
  for (const auto& [c, t] : ln.g) set_mode(c, t);
  // Cutter compensation before motion (RS274/NGC's order).
  if (codes.comp) cutter_comp(codes.comp);
  if ((codes.home || codes.machine_coords) && mo.comp.active())
    fail(errc::gcode_cutter_comp, (codes.home ? g_text(codes.home) : std::string("G53")) +
                                      " cannot be used with cutter radius compensation on: cancel it with G40 first");
  // LinuxCNC refuses G53 in G91 ("cannot use G53 incremental"); Fanuc
  // ignores it there. Either way the line would not move as written.
  if (codes.machine_coords && st.distance != DistanceMode::absolute)
    fail(errc::gcode_incremental,
         "G53 (machine coordinates) takes absolute coordinates: it cannot be used in G91 "
         "(incremental distances); give G90 first");
  if (codes.home) go_home(codes.home);
  if (active != -999) motion_line(active, codes.motion != -999);
  for (const auto& [c, t] : ln.m)
    if (c == 2 || c == 30) {
      // The end of the program turns compensation off (LinuxCNC, Fanuc).
      comp_off();
      st.cutter_comp = CutterCompMode::off;
      st.program_end = true;
      mo.end_line = line;
    }
}

// One code per modal group, every code one this reader takes; what the
// line's codes ask, for the steps after.
GcodeInterpreter::LineRun::Codes GcodeInterpreter::LineRun::gather_codes() {
  Codes k;
  std::array<std::string, kModalGroups> seen_g{};
  std::string non_modal;  // RS274/NGC: one code of group 0 per line
  for (const auto& [c, t] : ln.g) {
    const GGroup grp = g_group(c);
    if (grp == GGroup::unsupported) fail(errc::gcode_unsupported, "G-code " + t + " is not supported by this reader");
    if (grp != GGroup::non_modal) {
      std::string& seen = seen_g[static_cast<size_t>(grp)];
      if (!seen.empty()) fail(errc::gcode_modal_group, seen + " and " + t + " are in the same modal group: give one");
      seen = t;
    } else {
      if (!non_modal.empty())
        fail(errc::gcode_modal_group,
             non_modal + " and " + t + " are both non-modal codes (group 0): give one per line");
      non_modal = t;
    }
    switch (c) {
      case 170:
      case 180:
      case 190:
        k.plane = plane_of(c);
        if (c != 170 && st.cutter_comp != CutterCompMode::off)
          fail(errc::gcode_plane, t + " selects the " + std::string(c == 180 ? "ZX" : "YZ") +
                                      " plane while cutter radius compensation is on: it compensates in G17 (XY) only; "
                                      "cancel it with G40 first");
        break;
      case 930:
      case 950:
        fail(errc::gcode_unsupported, t + std::string(c == 930 ? " (inverse-time feed)" : " (feed per revolution)") +
                                          " is not supported by this reader: use G94 (units per minute)");
      case 410:
      case 420: k.comp_d = true; break;
      case 430: k.length_comp = true; break;
      case 40: k.dwell = true; break;
      case 640: k.blend = true; break;
      case 280:
      case 300: k.home = c; break;
      case 530: k.machine_coords = true; break;
      default: break;
    }
    if (grp == GGroup::cutter_comp) k.comp = c;
    if (grp == GGroup::motion) {
      k.motion = c;
      word = t;
    }
  }
  std::array<std::string, kModalGroups> seen_m{};
  for (const auto& [c, t] : ln.m) {
    const MGroup grp = m_group(c);
    if (grp == MGroup::unsupported) fail(errc::gcode_unsupported, "M-code " + t + " is not supported by this reader");
    std::string& seen = seen_m[static_cast<size_t>(grp)];
    if (!seen.empty()) fail(errc::gcode_modal_group, seen + " and " + t + " are in the same modal group: give one");
    seen = t;
  }
  return k;
}

// Which motion the line's words belong to (-999: none; -1: G80). G28
// and G30 take the line's axis words (their intermediate point).
int GcodeInterpreter::LineRun::active_motion(const Codes& k) const {
  const bool has_axes = ln.has('X') || ln.has('Y') || ln.has('Z');
  bool motion_words = has_axes && !k.home;
  // G04's P is its duration, G64's P and Q its tolerances: not motion words.
  for (char c : std::string_view(k.dwell ? "IJKRQL" : k.blend ? "IJKRL" : "IJKRQLP"))
    motion_words = motion_words || ln.has(c);
  if (k.motion == 800) return -1;
  if (k.motion != -999) return k.motion;
  if (motion_words) return static_cast<int>(st.motion);
  return -999;
}

// Codes that cannot share a line, then every word must mean something.
void GcodeInterpreter::LineRun::check_combinations(const Codes& k, int active) {
  const bool has_axes = ln.has('X') || ln.has('Y') || ln.has('Z');
  if (k.dwell && (has_axes || k.motion != -999))
    fail(errc::gcode_modal_group, "G04 (dwell) cannot share a line with a motion: put it on its own line");
  if (k.home && k.motion != -999)
    fail(errc::gcode_modal_group,
         g_text(k.home) + " uses the line's axis words for its intermediate point: put " + word + " on another line");
  if (k.machine_coords && !(active == 0 || active == 10))
    fail(errc::gcode_unsupported, "G53 (machine coordinates) applies to a G00 or G01 move on the same line; found " +
                                      (active >= 0 ? wt(active) : std::string("no motion")));
  std::string extra = k.dwell ? "P" : k.blend ? "PQ" : "";
  if (k.home) extra += "XYZ";
  if (k.length_comp) extra += "H";
  if (k.comp_d) extra += "D";
  check_letters(active, extra, k.motion != -999, k.plane ? *k.plane : st.plane);
}

// F, S and T, in that order.
void GcodeInterpreter::LineRun::set_feed_speed_tool() {
  if (ln.has('F')) {
    if (val('F') < 0) fail(errc::gcode_feed, "expected a feed rate F >= 0, found " + txt('F'));
    st.feed = val('F');
  }
  if (ln.has('S')) {
    if (val('S') < 0) fail(errc::gcode_spindle, "expected a spindle speed S >= 0, found " + txt('S'));
    st.spindle_rpm = val('S');
  }
  if (ln.has('T')) {
    // (Bounded before the conversion: T1e20 as an int is undefined; found by fuzzing.)
    if (val('T') < 0 || val('T') != std::floor(val('T')) || val('T') > 1e9)
      fail(errc::gcode_tool, "expected a whole tool number T from 0 to 1000000000, found " + txt('T'));
    mo.selected_tool = static_cast<int>(val('T'));
  }
}

// M06, the spindle, the coolant and the program stops (the end comes
// after the motion, run_modal()).
void GcodeInterpreter::LineRun::run_m_codes() {
  for (const auto& [c, t] : ln.m) {
    if (c == 6) {
      if (mo.selected_tool < 0) note(errc::gcode_tool_unset, "M06 changes the tool, but no T word has selected one");
      st.tool = std::max(mo.selected_tool, 0);
    }
    if (c == 3 || c == 4) {
      st.spindle_on = true;
      st.spindle_ccw = c == 4;
      mo.noted_spindle = false;
    }
    if (c == 5) st.spindle_on = false;
    if (c == 7) st.coolant_mist = true;
    if (c == 8) st.coolant_flood = true;
    if (c == 9) st.coolant_mist = st.coolant_flood = false;
    if (c == 0 || c == 1) ++st.program_stops;
  }
}

void GcodeInterpreter::LineRun::dwell() {
  if (!ln.has('P') || val('P') < 0) fail(errc::gcode_dwell, "G04 needs its duration P (seconds) >= 0");
  st.dwell_seconds += val('P');
}

// One modal G code other than motion and cutter compensation: path mode,
// plane, units, distance modes, work offset, tool length compensation.
void GcodeInterpreter::LineRun::set_mode(int c, const std::string& t) {
  if (c == 610 || c == 611) {
    st.path_tolerance = 0;
    st.path_mode = c == 611 ? PathMode::exact_path : PathMode::exact_stop;
  } else if (c == 640) {
    blend();
  } else if (c == 170 || c == 180 || c == 190) {
    st.plane = plane_of(c);
    mo.plane_set = true;
  } else if (c == 200 || c == 210) {
    const Units u = c == 200 ? Units::inch : Units::mm;
    if (mo.moved && u != st.units)
      fail(errc::gcode_units_change, t + " changes the units after the first move: positions would change meaning; set "
                                         "the units once, before any move");
    st.units = u;
    st.units_set = true;
  } else if (c == 900 || c == 910) {
    st.distance = c == 900 ? DistanceMode::absolute : DistanceMode::incremental;
    mo.distance_set = true;
  } else if (c == 901 || c == 911) {
    st.arc_centers = c == 901 ? ArcCenterMode::absolute : ArcCenterMode::incremental;
  } else if (c >= 540 && c <= 590 && c % 10 == 0) {
    st.coord_system = static_cast<WorkOffset>(c / 10);
  } else if (c == 980 || c == 990) {
    // LinuxCNC: "Cannot change retract mode with cutter radius compensation on".
    if (st.cutter_comp != CutterCompMode::off)
      fail(errc::gcode_cutter_comp, t + " (canned cycle return) cannot be given with cutter radius compensation on");
    st.cycle_return = c == 980 ? CycleReturn::initial_level : CycleReturn::r_plane;
    st.cycle_return_set = true;
  } else if (c == 430) {
    tool_length_on();
  } else if (c == 490) {
    st.tool_length_comp = false;
    st.tool_length_h = 0;
  }
}

// G64 P- (LinuxCNC): corners blended within P; without P, as fast as the
// planner can (no tolerance). Q (naive-CAM merging) is accepted and not
// modelled.
void GcodeInterpreter::LineRun::blend() {
  st.path_mode = PathMode::blend;
  if (ln.has('P') && !(val('P') >= 0)) fail(errc::gcode_number, "G64 needs a path tolerance P >= 0, found " + txt('P'));
  if (ln.has('Q') && !(val('Q') >= 0))
    fail(errc::gcode_number, "G64's Q (merge tolerance) must be >= 0, found " + txt('Q'));
  st.path_tolerance = ln.has('P') && val('P') > 0 ? val('P') : std::numeric_limits<double>::infinity();
}

// G43 H-: H defaults to the tool in the spindle, as LinuxCNC does.
void GcodeInterpreter::LineRun::tool_length_on() {
  int h = st.tool;
  if (ln.has('H')) {
    if (val('H') < 0 || val('H') != std::floor(val('H')) || val('H') > 1e9)
      fail(errc::gcode_tool, "expected a whole tool length offset number H from 0 to 1000000000, found " + txt('H'));
    h = static_cast<int>(val('H'));
  }
  st.tool_length_comp = true;
  st.tool_length_h = h;
}

// Every word must mean something on this line.
void GcodeInterpreter::LineRun::check_letters(int active, const std::string& extra, bool explicit_motion, Plane plane) {
  std::string allowed = "FST";
  switch (active) {
    case 0:
    case 10: allowed += "XYZ"; break;
    case 20:
    case 30: allowed += plane == Plane::xy ? "XYZIJR" : plane == Plane::zx ? "XYZIKR" : "XYZJKR"; break;
    case 50: allowed += "XYIJPQ"; break;
    case 51: allowed += "XYIJ"; break;
    case 52: allowed += "XYPL"; break;
    case 62:
    case 63: allowed += explicit_motion ? "XYZKRP" : ""; break;
    case 810: allowed += "XYZRL"; break;
    case 820: allowed += "XYZRLP"; break;
    case 730:
    case 830: allowed += "XYZRLQ"; break;
    default: break;
  }
  allowed += extra;
  for (const Word& w : ln.words) {
    if (allowed.find(w.letter) != std::string::npos) continue;
    if (std::string_view("ABCUVW").find(w.letter) != std::string_view::npos)
      fail(errc::gcode_unsupported,
           "axis " + std::string(1, w.letter) + " (" + w.text + ") is not supported by this reader: X, Y and Z only");
    if ((active == 20 || active == 30) && std::string_view("IJK").find(w.letter) != std::string_view::npos) {
      const char* words = plane == Plane::xy ? "I and J" : plane == Plane::zx ? "I and K" : "J and K";
      fail(errc::gcode_arc, w.text + ": " + std::string(1, w.letter) + " is not a centre word in the G" +
                                std::to_string(g_number(plane)) + " plane (some controllers refuse even " +
                                std::string(1, w.letter) + "0): give " + words + " only");
    }
    if (w.letter == 'Z' && (active == 50 || active == 51 || active == 52))
      fail(errc::gcode_bezier, wt(active) + " moves in X and Y only: a Z word (" + w.text + ") is not allowed");
    if ((active == 62 || active == 63) && !explicit_motion) {
      if (w.letter == 'K')
        fail(errc::gcode_nurbs_start, "K word outside a NURBS block (the last one ended at line " +
                                          std::to_string(mo.nurbs_mode_line) + "): a block starts with " +
                                          g_text(active) + " P- K- X- Y- Z-");
      fail(errc::gcode_nurbs_mode,
           w.text + " in NURBS mode (" + g_text(active) + " since line " + std::to_string(mo.nurbs_mode_line) +
               ") outside a block: start a new block with " + g_text(active) + ", or leave the mode with G00 or G01");
    }
    if (std::string_view("XYZ").find(w.letter) != std::string_view::npos)
      fail(errc::gcode_no_motion, w.text + ": axis words without a motion mode (none is active): give G00 or G01");
    if (w.letter == 'K')
      fail(errc::gcode_nurbs_start, "K word outside a NURBS block: a block starts with G06.2 P- K- X- Y- Z-");
    fail(errc::gcode_unexpected_word, "word " + w.text + " has no meaning on this line" +
                                          (active >= 0 ? " (" + wt(active) + ")" : std::string()) + ": remove it");
  }
}

}  // namespace bezcam
