// Resume from a line (bezcam/gcode/resume.hpp): the one G-code reader runs
// the lines before the asked one, its state there (and the multi-line
// block it may be inside) decides where a cut may begin, and the preamble
// is written from that state and checked by running it through a fresh
// reader, which must arrive at the same state.
#include "bezcam/gcode/resume.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/kernel/units.hpp"
#include "diagnostics.hpp"
#include "lexer.hpp"
#include "modal_state.hpp"

namespace bezcam {

namespace {

using gcode::GGroup;

// The program's lines as a controller numbers them: split at '\n', a last
// line without '\n' counts, an empty text has none.
std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t nl = text.find('\n', i);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view l = text.substr(i, nl - i);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.push_back(l);
    i = nl + 1;
  }
  return out;
}

std::string motion_word(ModalMotion m) {
  switch (m) {
    case ModalMotion::none: return "G80";
    case ModalMotion::rapid: return "G00";
    case ModalMotion::feed: return "G01";
    case ModalMotion::arc_cw: return "G02";
    case ModalMotion::arc_ccw: return "G03";
    case ModalMotion::cubic: return "G5";
    case ModalMotion::quadratic: return "G5.1";
    case ModalMotion::nurbs_g5_2: return "G5.2";
    case ModalMotion::nurbs_g06_2: return "G06.2";
    case ModalMotion::nurbs_g06_3: return "G06.3";
    case ModalMotion::chip_break: return "G73";
    case ModalMotion::drill: return "G81";
    case ModalMotion::drill_dwell: return "G82";
    case ModalMotion::peck: return "G83";
  }
  return "G80";
}

// The motions a preamble restores with a word alone, without moving.
bool restorable(ModalMotion m) { return m == ModalMotion::none || m == ModalMotion::rapid || m == ModalMotion::feed; }

// Why a cut may not begin at a line (lexed as `ln`) with the reader in
// `st` / `c` before it; "" when it may.
std::string barrier(const MachineState& st, const GcodeInterpreter::Continuation& c, const gcode::Line& ln) {
  if (c.open_block != ModalMotion::none)
    return "it is inside the " + motion_word(c.open_block) + " NURBS block that starts at line " +
           std::to_string(c.open_line) + ", which cannot be entered in the middle";
  if (st.cutter_comp != CutterCompMode::off)
    return "cutter radius compensation (G" + std::to_string(static_cast<int>(st.cutter_comp)) + " D" +
           std::to_string(st.cutter_comp_d) +
           ") is on there: the tool's offset depends on the moves before it; resume at the lead before the G" +
           std::to_string(static_cast<int>(st.cutter_comp)) + " line";
  bool names_motion = false, g5 = false, cycle = is_canned_cycle(st.motion);
  for (const auto& [code, text] : ln.g) {
    if (gcode::g_group(code) == GGroup::motion) {
      names_motion = true;
      cycle = is_canned_cycle(static_cast<ModalMotion>(code));
    }
    if (code == 50) g5 = true;
  }
  if (cycle)
    return "it drills in a canned cycle, whose initial level and words come from the lines before; resume before "
           "the cycle begins";
  if (g5 && c.g5_chain && !ln.has('I') && !ln.has('J'))
    return "it is a G5 that takes its start tangent from the G5 before it (no I and J)";
  if (!names_motion && !restorable(st.motion))
    return "the modal motion there is " + motion_word(st.motion) +
           ", which cannot be restored without moving, and the line gives no motion word of its own";
  return {};
}

// The text of a line's comment in parentheses ("" without one); a line
// number `N10` before it is allowed.
std::string_view comment_text(std::string_view l) {
  const std::size_t open = l.find('('), close = l.rfind(')');
  if (open == std::string_view::npos || close == std::string_view::npos || close < open) return {};
  return l.substr(open + 1, close - open - 1);
}

// The job's plunge feed at the resume line, from the program's header (the
// writer's lines `T2 plunge feed 200 mm/min`, and `T1 plunge feed 150
// mm/min: outline` where a tool's entities differ): the tool in the spindle
// there and, when its entities differ, the entity that the last `entity
// LABEL:` comment before the line names (the lowest of the tool's feeds
// when none is named). Unset when the header records none.
struct HeaderPlunge {
  double mm_min = 0;
  std::string what;  ///< where it comes from, for the messages
};
std::optional<HeaderPlunge> header_plunge(const std::vector<std::string_view>& lines, int start, int tool) {
  struct Record {
    double mm_min;
    std::string labels;  // "" when the tool's entities share it
  };
  std::vector<Record> records;
  std::string entity;  // the last entity comment before `start`
  const std::string tool_word = "T" + std::to_string(tool) + " ";
  for (int l = 1; l < start; ++l) {
    const std::string_view c = comment_text(lines[static_cast<size_t>(l - 1)]);
    if (c.rfind("entity ", 0) == 0) entity = std::string(c.substr(7));
    std::size_t at = c.find("plunge feed ");
    if (at == std::string_view::npos || !(at == 0 || c.substr(0, at) == tool_word)) continue;
    at += 12;
    double v = 0;
    const auto [end, ec] = std::from_chars(c.data() + at, c.data() + c.size(), v);
    if (ec != std::errc() || !(v > 0) || !std::isfinite(v)) continue;
    std::string_view rest = c.substr(static_cast<std::size_t>(end - c.data()));
    double unit = 0;
    if (rest.rfind(" mm/min", 0) == 0)
      unit = 1;
    else if (rest.rfind(" in/min", 0) == 0)
      unit = 25.4;
    else
      continue;
    rest.remove_prefix(7);
    records.push_back({v * unit, rest.rfind(": ", 0) == 0 ? std::string(rest.substr(2)) : std::string()});
  }
  if (records.empty()) return std::nullopt;
  const std::string who =
      tool > 0 ? "the program's plunge feed for T" + std::to_string(tool) : "the program's plunge feed";
  if (records.size() == 1) return HeaderPlunge{records.front().mm_min, who};
  // Per entity: the record that lists the entity the resume line cuts.
  for (const Record& r : records) {
    std::size_t i = 0;
    while (i < r.labels.size()) {
      std::size_t j = r.labels.find(", ", i);
      if (j == std::string::npos) j = r.labels.size();
      const std::string label = r.labels.substr(i, j - i);
      if (!label.empty() && entity.rfind(label + ":", 0) == 0) return HeaderPlunge{r.mm_min, who + ", entity " + label};
      i = j + 2;
    }
  }
  const auto low = std::min_element(records.begin(), records.end(),
                                    [](const Record& a, const Record& b) { return a.mm_min < b.mm_min; });
  return HeaderPlunge{low->mm_min, who + ", the lowest of its entities'"};
}

struct Snapshot {
  int line = 0;
  MachineState state;
  GcodeInterpreter::Continuation cont;
};

// The preamble, one block per line (the comment that opens it excluded).
std::vector<std::string> preamble_blocks(const Snapshot& s, double safe_z, double plunge) {
  const MachineState& st = s.state;
  std::vector<std::string> out;
  // The arc plane in force there (G18/G19 inside a run of surface arcs).
  std::string modes = "G" + std::to_string(g_number(st.plane)) + " G90 G94 G40";
  if (st.units_set) modes += st.units == Units::inch ? " G20" : " G21";
  modes += " G" + std::to_string(static_cast<int>(st.coord_system));
  if (st.path_mode == PathMode::exact_path)
    modes += " G61.1";
  else if (st.path_mode == PathMode::blend && std::isfinite(st.path_tolerance) && st.path_tolerance > 0)
    modes += " G64 P" + format_exact_fixed(st.path_tolerance);  // the tolerance in force, not only the mode
  else if (st.path_mode != PathMode::unset)
    modes += " G" + std::to_string(static_cast<int>(st.path_mode));
  if (st.arc_centers == ArcCenterMode::absolute)
    modes += " G90.1";  // only a program that used it: not every controller knows it
  if (st.cycle_return_set) modes += st.cycle_return == CycleReturn::r_plane ? " G99" : " G98";
  out.push_back(modes);
  if (st.tool > 0) out.push_back("T" + std::to_string(st.tool) + " M06");
  const int sel = s.cont.selected_tool;
  if (sel >= 0 && !(st.tool > 0 && sel == st.tool)) out.push_back("T" + std::to_string(sel));
  if (st.tool_length_comp) out.push_back("G43 H" + std::to_string(st.tool_length_h));
  if (st.spindle_on)
    out.push_back("S" + format_exact_fixed(st.spindle_rpm) + (st.spindle_ccw ? " M04" : " M03"));
  else if (st.spindle_rpm != 0)
    out.push_back("S" + format_exact_fixed(st.spindle_rpm));
  if (st.coolant_mist) out.push_back("M07");
  if (st.coolant_flood) out.push_back("M08");

  // Retract, move over the resume point, plunge: only along the axes the
  // program had set (an axis it never programmed is not moved).
  const bool zk = st.known_axes & 4, xk = st.known_axes & 1, yk = st.known_axes & 2;
  double feed_now = 0;
  ModalMotion motion_now = ModalMotion::none;
  const double top = zk ? std::max(safe_z, st.pos.z) : safe_z;
  if (zk) {
    out.push_back("G00 Z" + format_exact_fixed(top));
    motion_now = ModalMotion::rapid;
  }
  if (xk || yk) {
    std::string over = "G00";
    if (xk) over += " X" + format_exact_fixed(st.pos.x);
    if (yk) over += " Y" + format_exact_fixed(st.pos.y);
    out.push_back(over);
    motion_now = ModalMotion::rapid;
  }
  if (zk && st.pos.z < top) {
    out.push_back("G01 Z" + format_exact_fixed(st.pos.z) + " F" + format_exact_fixed(plunge));
    feed_now = plunge;
    motion_now = ModalMotion::feed;
  }
  if (st.feed != feed_now) out.push_back("F" + format_exact_fixed(st.feed));
  if (restorable(st.motion) && st.motion != motion_now) out.push_back(motion_word(st.motion));
  // The moves above are absolute; the program goes on in its own mode.
  if (st.distance == DistanceMode::incremental) out.push_back("G91");
  return out;
}

// The differences between the state a preamble reached and the state it
// had to restore ("" when none): a failure here is a bug of this file.
std::string differences(const Snapshot& want, const MachineState& got, const GcodeInterpreter::Continuation& gc) {
  const MachineState& w = want.state;
  std::string d;
  auto diff = [&d](bool differ, const char* what) {
    if (differ) d += std::string(d.empty() ? "" : ", ") + what;
  };
  diff(got.known_axes != w.known_axes, "known axes");
  for (int a = 0; a < 3; ++a)
    if (w.known_axes & (1u << a)) diff(got.pos[a] != w.pos[a], "position");
  diff(got.units != w.units || got.units_set != w.units_set, "units");
  diff(got.distance != w.distance, "distance mode");
  diff(got.arc_centers != w.arc_centers, "arc centre mode");
  diff(got.plane != w.plane, "plane");
  diff(got.coord_system != w.coord_system, "work offset");
  diff(got.path_mode != w.path_mode, "path mode");
  diff(got.path_tolerance != w.path_tolerance, "path tolerance");
  diff(got.tool != w.tool || gc.selected_tool != want.cont.selected_tool, "tool");
  diff(got.tool_length_comp != w.tool_length_comp || got.tool_length_h != w.tool_length_h, "tool length offset");
  diff(got.spindle_on != w.spindle_on || got.spindle_rpm != w.spindle_rpm ||
           (w.spindle_on && got.spindle_ccw != w.spindle_ccw),
       "spindle");
  diff(got.coolant_mist != w.coolant_mist || got.coolant_flood != w.coolant_flood, "coolant");
  diff(got.feed != w.feed, "feed");
  diff(restorable(w.motion) && got.motion != w.motion, "motion mode");
  diff(gc.open_block != ModalMotion::none || got.program_end, "block or program end");
  return d;
}

}  // namespace

ResumePlan plan_resume(std::string_view program, const MachineProfile* profile, int line,
                       const ResumeSettings& settings) {
  const auto lines = split_lines(program);
  const int total = static_cast<int>(lines.size());
  if (line < 1 || line > total)
    throw InputError(errc::resume_no_line, Place::at_line(line),
                     "cannot resume there: the program has " + std::to_string(total) + " line" +
                         (total == 1 ? "" : "s") + (line < 1 ? " and lines count from 1" : ""));

  // Safe height, in mm until the program's units are known; the plunge
  // feed once the tool at the resume line is known (plunge_feed_mm()).
  std::optional<double> safe_mm = settings.safe_z_mm;
  if (!safe_mm && profile) safe_mm = profile->defaults.safe_z;
  const std::string from_where = profile ? ", and machine \"" + profile->name + "\" has no default" : "";
  if (!safe_mm)
    throw InputError(errc::resume_setting, Place::at_setting("safe_z"),
                     "the safe height to retract to is not given" + from_where);
  if (!std::isfinite(*safe_mm))
    throw InputError(errc::resume_setting, Place::at_setting("safe_z"),
                     "expected a finite safe height, found " + fmt_num(*safe_mm));
  if (settings.plunge_feed_mm_min && !(*settings.plunge_feed_mm_min > 0 && std::isfinite(*settings.plunge_feed_mm_min)))
    throw InputError(errc::resume_setting, Place::at_setting("plunge_feed"),
                     "expected a plunge feed > 0 mm/min, found " + fmt_num(*settings.plunge_feed_mm_min));

  // Run the lines before `line` through the reader, remembering the last
  // line where a cut may begin and the state before it.
  GcodeInterpreter in(profile);
  Snapshot snap;
  std::string why_not;  // why `line` itself is no place to begin
  for (int l = 1; l <= line; ++l) {
    const std::string_view text = lines[static_cast<size_t>(l - 1)];
    gcode::Line ln;
    try {
      ln = gcode::lex_line(text, gcode::Diagnostics{l, nullptr});
    } catch (const InputError& e) {
      if (l == line) throw;  // the asked line itself cannot be read
      throw InputError(errc::resume_state_unknown, Place::at_line(l),
                       "cannot resume at line " + std::to_string(line) +
                           ": the modal state before it cannot be known: " + e.message() + " [" + e.id() + "]");
    }
    const bool code = !(ln.percent || ln.program_number || ln.empty());
    if (l == line && !code)
      throw InputError(errc::resume_no_code, Place::at_line(line),
                       "cannot resume at a line that holds no block (a blank, comment, % or program-number line): "
                       "give the line of a block");
    // Past M02/M30 nothing runs: not line N, nor a block between the end and N.
    if (const int end = in.continuation().end_line; end && code)
      throw InputError(errc::resume_after_end, Place::at_line(line),
                       "cannot resume there: the program ended at line " + std::to_string(end) + " (M02/M30)");
    if (code) {
      std::string b = barrier(in.state(), in.continuation(), ln);
      if (b.empty()) snap = {l, in.state(), in.continuation()};
      if (l == line) why_not = std::move(b);
    }
    if (l == line) break;
    try {
      in.feed_line(text, l);
    } catch (const InputError& e) {
      throw InputError(errc::resume_state_unknown, Place::at_line(l),
                       "cannot resume at line " + std::to_string(line) +
                           ": the modal state before it cannot be known, as the reader refuses this line: " +
                           e.message() + " [" + e.id() + "]");
    }
  }
  if (snap.line == 0) throw std::logic_error("plan_resume: no line where a cut may begin");

  ResumePlan plan;
  plan.asked_line = line;
  plan.start_line = snap.line;
  plan.total_lines = total;
  plan.state = snap.state;
  if (snap.line != line) plan.reason = "line " + std::to_string(line) + " is no place to begin a cut: " + why_not;
  const double unit = mm_per_unit(snap.state.units);
  plan.safe_z = *safe_mm / unit;
  // The plunge feed: as given, else the job's from the program's header,
  // else the profile's.
  std::optional<double> plunge_mm = settings.plunge_feed_mm_min;
  plan.plunge_from = "the plunge feed asked for";
  if (!plunge_mm) {
    if (const auto h = header_plunge(lines, snap.line, snap.state.tool)) {
      plunge_mm = h->mm_min;
      plan.plunge_from = h->what;
    } else if (profile && profile->defaults.plunge_feed) {
      plunge_mm = profile->defaults.plunge_feed;
      plan.plunge_from = "machine " + profile->name + "'s plunge_feed";
    }
  }
  if (!plunge_mm)
    throw InputError(errc::resume_setting, Place::at_setting("plunge_feed"),
                     "the plunge feed is not given, the program's header records none" + from_where);
  if (!(*plunge_mm > 0) || !std::isfinite(*plunge_mm))
    throw InputError(errc::resume_setting, Place::at_setting("plunge_feed"),
                     "expected a plunge feed > 0 mm/min, found " + fmt_num(*plunge_mm));
  plan.plunge_feed = *plunge_mm / unit;

  std::vector<std::string> blocks = preamble_blocks(snap, plan.safe_z, plan.plunge_feed);
  plan.preamble_lines = static_cast<int>(blocks.size()) + 1;
  plan.preamble = "(bezcam resume: lines 1-" + std::to_string(plan.preamble_lines) + " restore the state of line " +
                  std::to_string(snap.line) + ", line " + std::to_string(plan.preamble_lines + 1) + " is line " +
                  std::to_string(snap.line) + " of the program" +
                  (snap.line != line ? ", asked " + std::to_string(line) : std::string()) + ")\n";
  for (const auto& b : blocks) plan.preamble += b + "\n";

  // The preamble through a fresh reader: the profile's limits apply to its
  // moves, and it must arrive at the state it restores.
  GcodeInterpreter check(profile);
  for (int i = 0; i < static_cast<int>(blocks.size()); ++i) {
    try {
      check.feed_line(blocks[static_cast<size_t>(i)], i + 2);
    } catch (const InputError& e) {
      const bool feed = e.id() == errc::gcode_feed_limit;
      throw InputError(errc::resume_setting, Place::at_setting(feed ? "plunge_feed" : "safe_z"),
                       "the preamble's block \"" + blocks[static_cast<size_t>(i)] + "\" is refused: " + e.message() +
                           " [" + e.id() + "]");
    }
  }
  if (const std::string d = differences(snap, check.state(), check.continuation()); !d.empty())
    throw std::logic_error("plan_resume: the preamble does not restore the state of line " + std::to_string(snap.line) +
                           ": " + d);

  // The tail: the original text from the start line on, byte for byte.
  const std::size_t offset =
      static_cast<std::size_t>(lines[static_cast<size_t>(snap.line - 1)].data() - program.data());
  plan.program = plan.preamble;
  plan.program.append(program.substr(offset));
  return plan;
}

}  // namespace bezcam
