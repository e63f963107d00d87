// The G-code reader: one interpreter for every dialect bezcam emits, in
// Grbl's parse-validate-execute order. A line is parsed into words, checked
// completely on copies of the modal state, and only then committed. This
// file holds the line's order, the plain motions (G00-G03) and the
// multi-line block machinery; interpreter_impl.hpp lists the other parts.
#include "bezcam/gcode/reader.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "bezcam/error.hpp"
#include "bezcam/kernel/arc.hpp"
#include "bezcam/limits.hpp"
#include "interpreter_impl.hpp"

namespace bezcam {

using namespace gcode;

namespace {

// Box of an arc (in its plane): both ends and every axis extreme the sweep passes.
Box3 arc_box(const MotionBlock& b) { return arc_extent(block_arc(b)); }

}  // namespace

std::optional<GcodeFinding> gcode::too_large(std::string_view text) { return too_large(text.size()); }

std::optional<GcodeFinding> gcode::too_large(size_t bytes) {
  if (bytes <= kMaxProgramBytes) return std::nullopt;
  return GcodeFinding{1, errc::gcode_program_too_large,
                      "the program is " + std::to_string(bytes >> 20) + " MiB, more than the " +
                          std::to_string(kMaxProgramBytes >> 20) +
                          " MiB bezcam reads (docs/limits.md); split it into several programs"};
}

// ---------------------------------------------------------------------------
// GcodeInterpreter::LineRun: the line and the plain motions.

void GcodeInterpreter::LineRun::run(std::string_view text) {
  ln = lex_line(text, diag());
  if (ln.percent || ln.program_number) return;
  if (ln.empty()) {
    if (ln.n) check_n();
    return;
  }
  if (mo.end_line)
    fail(errc::gcode_after_end, "the program ended at line " + std::to_string(mo.end_line) +
                                    " (M02/M30): nothing after it runs; remove this line or move the end");
  if (ln.n) check_n();
  if (mo.open != ModalMotion::none) {
    if (continue_block()) return;
  }
  run_modal();
}

void GcodeInterpreter::LineRun::save_lists() {
  if (lists_saved) return;
  lists_saved = true;
  // Before this call the line only appended: the first sizes0 elements
  // are the lists as they were.
  saved.ctrl.assign(mo.ctrl.begin(), mo.ctrl.begin() + static_cast<std::ptrdiff_t>(sizes0[0]));
  saved.weights.assign(mo.weights.begin(), mo.weights.begin() + static_cast<std::ptrdiff_t>(sizes0[1]));
  saved.knots.assign(mo.knots.begin(), mo.knots.begin() + static_cast<std::ptrdiff_t>(sizes0[2]));
  saved.knot_lines.assign(mo.knot_lines.begin(), mo.knot_lines.begin() + static_cast<std::ptrdiff_t>(sizes0[3]));
}

double GcodeInterpreter::LineRun::coordinate(const Word& w, double from) const {
  if (st.distance == DistanceMode::absolute) return w.value;
  const double v = from + w.value;
  // Travels that add up beyond a double must not read as infinity.
  if (!std::isfinite(v))
    fail(errc::gcode_number, w.text + " in G91 (incremental distances) takes " + std::string(1, w.letter) +
                                 " beyond the largest number bezcam reads (about 1e308)");
  return v;
}

bool GcodeInterpreter::LineRun::gives_coordinate(int a, const Word& w) const {
  if (st.distance == DistanceMode::absolute || (st.known_axes & (1u << a))) return true;
  // The travel from a position this program never set: the controller
  // knows where it ends, a reader does not. No travel leaves it unknown.
  if (w.value == 0) return false;
  fail(errc::gcode_incremental, w.text + " in G91 (incremental distances) travels from the current " + axis_name(a) +
                                    ", which no earlier move has set: set it with an absolute (G90) move first");
}

std::pair<Vec3, unsigned> GcodeInterpreter::LineRun::target() const {
  Vec3 t = st.pos;
  unsigned axes = 0;
  for (int a = 0; a < 3; ++a) {
    const Word* w = ln.get("XYZ"[a]);
    if (!w || !gives_coordinate(a, *w)) continue;
    t[a] = coordinate(*w, st.pos[a]);
    axes |= 1u << a;
  }
  return {t, axes};
}

unsigned GcodeInterpreter::LineRun::named_axes() const {
  unsigned axes = 0;
  for (int a = 0; a < 3; ++a)
    if (ln.has("XYZ"[a])) axes |= 1u << a;
  return axes;
}

Vec3 GcodeInterpreter::LineRun::start_for(const Vec3& to) const {
  Vec3 f = st.pos;
  for (int a = 0; a < 3; ++a)
    if (!(st.known_axes & (1u << a))) f[a] = to[a];
  return f;
}

void GcodeInterpreter::LineRun::require_known(const std::string& what, unsigned mask) const {
  const unsigned missing = mask & ~st.known_axes;
  if (!missing) return;
  std::string names;
  for (int a = 0; a < 3; ++a)
    if (missing & (1u << a)) names += (names.empty() ? "" : " and ") + axis_name(a);
  fail(errc::gcode_position_unknown, what + " cannot start from an unknown position: no earlier move has set " + names);
}

void GcodeInterpreter::LineRun::require_feed(const std::string& what) const {
  if (!(st.feed > 0))
    soft(errc::gcode_no_feed, what + " needs a feed rate, and no F word has set one (F is in " + unit() + "/min)");
}

void GcodeInterpreter::LineRun::check_travel(const Box3& b, unsigned axes) const {
  if (!self.profile || b.empty()) return;
  const auto& m = *self.profile;
  for (int a = 0; a < 3; ++a) {
    if (!(axes & (1u << a))) continue;
    const double lo = from_mm(m.travel_mm[a][0]), hi = from_mm(m.travel_mm[a][1]);
    if (b.lo[a] < lo || b.hi[a] > hi) {
      const double v = b.lo[a] < lo ? b.lo[a] : b.hi[a];
      soft(errc::gcode_travel, "the move reaches " + axis_name(a) + " = " + fmt_num(v) + " " + unit() +
                                   ", outside the travel of machine \"" + m.name + "\" (" + axis_name(a) + " from " +
                                   fmt_num(lo) + " to " + fmt_num(hi) + " " + unit() + ")");
    }
  }
}

void GcodeInterpreter::LineRun::check_feed_limit(double feed) {
  if (!self.profile) return;
  const double max = from_mm(self.profile->max_feed_mm_min);
  if (feed > max && feed != mo.feed_reported) {
    mo.feed_reported = feed;  // lint: once per feed value, not on every move at it
    soft(errc::gcode_feed_limit, "feed F" + fmt_num(feed) + " (" + unit() + "/min) exceeds the maximum feed" +
                                     machine() + ", " + fmt_num(max) + " " + unit() + "/min");
  }
}

MotionBlock GcodeInterpreter::LineRun::block(BlockKind k, const Vec3& to) const {
  MotionBlock b;
  b.kind = k;
  b.line = b.first_line = line;
  b.to = to;
  b.from = start_for(to);
  b.from_known = st.known_axes & 7;
  b.feed = k == BlockKind::rapid ? 0 : st.feed;
  return b;
}

void GcodeInterpreter::LineRun::commit_move(const MotionBlock& b, unsigned axes) {
  st.pos = b.to;
  st.known_axes |= axes;
  mo.moved = true;
  emit(b);
}

void GcodeInterpreter::LineRun::emit_all(std::vector<MotionBlock> blocks) {
  for (auto& b : blocks) out.push_back(std::move(b));
}

void GcodeInterpreter::LineRun::comp_off() {
  try {
    emit_all(mo.comp.off());
  } catch (const CompensationError& e) {
    fail(errc::gcode_cutter_comp, e.what());
  }
}

void GcodeInterpreter::LineRun::emit(const MotionBlock& b) {
  if (mo.comp.idle()) {  // no compensation: the block as it is, no copy
    out.push_back(b);
    return;
  }
  try {
    emit_all(mo.comp.push(b));
  } catch (const CompensationError& e) {
    fail(errc::gcode_cutter_comp, e.what());
  }
}

// G40, G41 / G42 with D (default: the tool in the spindle, as LinuxCNC).
void GcodeInterpreter::LineRun::cutter_comp(int code) {
  if (code == 400) {
    comp_off();
    st.cutter_comp = CutterCompMode::off;
    st.cutter_comp_d = 0;
    st.cutter_comp_radius = 0;
    return;
  }
  const std::string g = code == 410 ? "G41" : "G42";
  if (self.profile && !self.profile->cutter_compensation)
    fail(errc::gcode_cutter_comp, g + " (cutter radius compensation): machine \"" + self.profile->name +
                                      "\" has none; the program must describe the tool centre");
  if (st.plane != Plane::xy) fail(errc::gcode_cutter_comp, g + " compensates in the XY plane (G17) only");
  int d = st.tool;
  if (ln.has('D')) {
    if (val('D') < 0 || val('D') != std::floor(val('D')) || val('D') > 99999)
      fail(errc::gcode_cutter_comp, "expected a whole offset register D from 0 to 99999, found " + txt('D'));
    d = static_cast<int>(val('D'));
  }
  double radius = 0;
  if (d != 0) {
    const auto& table = self.tool_diameters_mm;
    const auto it = table.find(d);
    if (it == table.end())
      fail(errc::gcode_cutter_comp, g + " D" + std::to_string(d) + ": the diameter register D" + std::to_string(d) +
                                        " is not set" + machine() +
                                        ": give its diameter in the machine profile's tool_diameters_mm, or on the "
                                        "command line");
    radius = from_mm(it->second / 2);
  }
  if (radius > 0) {
    try {
      mo.comp.on(code == 410 ? 1 : -1, radius);
    } catch (const CompensationError& e) {
      fail(errc::gcode_cutter_comp, e.what());
    }
  } else if (mo.comp.active()) {
    fail(errc::gcode_cutter_comp, g + " while cutter compensation is already on: cancel it with G40 first");
  }
  st.cutter_comp = code == 410 ? CutterCompMode::left : CutterCompMode::right;
  st.cutter_comp_d = d;
  st.cutter_comp_radius = radius;
}

double GcodeInterpreter::LineRun::weight(const Word& r) const {
  if (!(r.value > 0)) soft(errc::gcode_weight, "weight " + r.text + ": expected a weight R > 0");
  return r.value;
}

void GcodeInterpreter::LineRun::finish_nurbs_block(std::vector<double> knots) {
  MotionBlock b;
  b.kind = BlockKind::nurbs;
  b.first_line = mo.open_line;
  b.line = line;
  b.from = mo.ctrl.front();
  b.to = mo.ctrl.back();
  b.feed = mo.open_feed;
  b.order = mo.order;
  b.ctrl = mo.ctrl;
  b.weights = mo.weights;
  b.knots = std::move(knots);
  finish_curve_block(b);
}

void GcodeInterpreter::LineRun::finish_curve_block(MotionBlock& b) {
  const bool valid = std::none_of(b.knots.begin(), b.knots.end(), [](double k) { return std::isnan(k); });
  Box3 box;
  bool exact = false;
  if (valid) {
    try {
      for (const auto& z : block_to_bezier(b)) box.add(bounds(z));
      exact = true;
    } catch (const std::invalid_argument&) {
    }
  }
  if (!exact)
    for (const auto& p : b.ctrl) box.add(p);  // the hull contains the curve
  check_travel(box, 7);
  check_feed_limit(b.feed);
  if (lint() && valid) lint_jumps(b);
  st.pos = b.to;
  st.known_axes = 7;
  mo.moved = true;
  emit(b);
}

void GcodeInterpreter::LineRun::clear_block() {
  save_lists();
  mo.open = ModalMotion::none;
  mo.ctrl.clear();
  mo.weights.clear();
  mo.knots.clear();
  mo.knot_lines.clear();
  mo.knot_only = 0;
  mo.knot_only_line = 0;
}

void GcodeInterpreter::LineRun::abandon_block() {
  clear_block();
  st.motion = ModalMotion::none;
}

void GcodeInterpreter::LineRun::motion_line(int code, bool explicit_motion) {
  if (code == -1) {  // G80 or no motion words
    st.motion = ModalMotion::none;
    mo.g5_chain = false;
    end_cycles();
    return;
  }
  if (is_canned_cycle(static_cast<ModalMotion>(code))) {
    canned_cycle(code, explicit_motion);
    return;
  }
  end_cycles();
  if (self.profile && explicit_motion) check_dialect(code);
  if (code >= 50 && code <= 52 && st.plane != Plane::xy)
    fail(errc::gcode_plane, wt(code) + " moves in the XY plane: select it with G17 first (G" +
                                std::to_string(g_number(st.plane)) + " is in force)");
  switch (code) {
    case 0:
    case 10: linear(code == 0); break;
    case 20:
    case 30: arc(code == 20); break;
    case 50: g5(); break;
    case 51: g51(); break;
    case 52: g52(); break;
    case 53: g53(); break;
    case 62:
    case 63:
      if (!explicit_motion) break;  // K lines are handled by continue_block()
      fanuc_start(code);
      break;
    default: break;
  }
}

void GcodeInterpreter::LineRun::check_dialect(int code) const {
  const auto& m = *self.profile;
  if ((code == 20 || code == 30) && !m.arcs)
    fail(errc::gcode_dialect, "machine \"" + m.name + "\" does not take arcs (" + wt(code) + "): use G01");
  if (code >= 50 && code <= 53 && m.nurbs != NurbsDialect::linuxcnc)
    fail(errc::gcode_dialect, wt(code) + " is a LinuxCNC word; machine \"" + m.name + "\" does not take it");
  if (is_fanuc(code)) {
    if (m.nurbs != NurbsDialect::fanuc)
      fail(errc::gcode_dialect, "machine \"" + m.name + "\" does not take Fanuc-style NURBS blocks (" + wt(code) + ")");
    if (code != start_code(m.nurbs_start_word))
      fail(errc::gcode_dialect,
           "machine \"" + m.name + "\" starts a NURBS block with " + m.nurbs_start_word + ", not " + wt(code));
  }
}

int GcodeInterpreter::LineRun::start_code(const std::string& word) {
  double v = 0;
  if (word.size() > 1) std::from_chars(word.data() + 1, word.data() + word.size(), v);
  return static_cast<int>(std::nearbyint(v * 10));
}

void GcodeInterpreter::LineRun::linear(bool rapid) {
  st.motion = rapid ? ModalMotion::rapid : ModalMotion::feed;
  mo.g5_chain = false;
  const auto [to, axes] = target();
  if (!axes) return;
  if (!rapid) require_feed("G01");
  MotionBlock b = block(rapid ? BlockKind::rapid : BlockKind::linear, to);
  lint_motion(b.kind, b.from, to, axes);
  Box3 box;
  box.add(to);
  check_travel(box, axes | st.known_axes);
  if (!rapid) check_feed_limit(st.feed);
  commit_move(b, axes);
}

Vec3 GcodeInterpreter::LineRun::reference_point(int) const { return Vec3{0, 0, 0}; }

void GcodeInterpreter::LineRun::go_home(int code) {
  mo.g5_chain = false;
  const auto [via, axes] = target();
  // An intermediate point where the tool stands is no move.
  if (axes && (via != st.pos || (axes & ~st.known_axes))) {
    MotionBlock b = block(BlockKind::rapid, via);
    lint_motion(b.kind, b.from, via, axes);
    Box3 box;
    box.add(via);
    check_travel(box, axes | st.known_axes);
    commit_move(b, axes);
  }
  // With axis words only those axes go home (in G91, G28 Z0 sends Z there
  // straight from where it is); without, all of them.
  const unsigned named = named_axes();
  const unsigned home_axes = named ? named : 7u;
  const Vec3 ref = reference_point(code);
  Vec3 home = st.pos;
  for (int a = 0; a < 3; ++a)
    if (home_axes & (1u << a)) home[a] = ref[a];
  MotionBlock b = block(BlockKind::rapid, home);
  lint_motion(b.kind, b.from, home, home_axes);
  Box3 box;
  box.add(home);
  check_travel(box, home_axes | st.known_axes);
  commit_move(b, home_axes);
}

double GcodeInterpreter::LineRun::arc_tolerance() const {
  return from_mm(self.profile ? self.profile->arc_tolerance_mm : kDefaultArcToleranceMm);
}

void GcodeInterpreter::LineRun::arc(bool cw) {
  st.motion = cw ? ModalMotion::arc_cw : ModalMotion::arc_ccw;
  mo.g5_chain = false;
  // In the plane's coordinates (a, b, axis) every plane is G17's: the
  // centre words of a and b, the end words of a and b.
  const Plane pl = st.plane;
  const int ia = world_axis(pl, 0), ib = world_axis(pl, 1);
  const char la = "IJK"[ia], lb = "IJK"[ib];
  const std::string words = std::string(1, std::min(la, lb)) + " and " + std::string(1, std::max(la, lb));
  const std::string g =
      std::string(cw ? "G02" : "G03") + (pl == Plane::xy ? "" : " (G" + std::to_string(g_number(pl)) + ")");
  const bool ij = ln.has(la) || ln.has(lb), r = ln.has('R');
  if (ij && r) fail(errc::gcode_arc, g + ": give either " + words + " (the centre) or R (the radius), not both");
  if (!ij && !r) fail(errc::gcode_arc, g + " needs the centre offsets " + words + " (or a radius R)");
  // G90.1: the centre is a point, both its words needed (LinuxCNC: "I word
  // missing in absolute center arc").
  if (ij && st.arc_centers == ArcCenterMode::absolute && !(ln.has(la) && ln.has(lb)))
    fail(errc::gcode_arc, g + " in G90.1 (absolute arc centres) needs both " + words + ": the centre's coordinates");
  require_known(g, (1u << ia) | (1u << ib));
  require_feed(g);
  const auto [to, axes] = target();
  const Vec3 from = st.pos;
  const Vec3 lf = to_plane(from, pl), lt = to_plane(to, pl);
  Vec3 c = lf;  // the centre, in plane coordinates
  if (ij && st.arc_centers == ArcCenterMode::absolute) {
    c.x = val(la);
    c.y = val(lb);
  } else if (ij) {
    c.x += ln.has(la) ? val(la) : 0;
    c.y += ln.has(lb) ? val(lb) : 0;
  } else {
    if (!(axes & ((1u << ia) | (1u << ib))))
      fail(errc::gcode_arc, g + " with R needs an end point " + axis_name(ia) + " or " + axis_name(ib) +
                                " (a full circle needs " + words + ")");
    const double dx = lt.x - lf.x, dy = lt.y - lf.y, d = std::hypot(dx, dy);
    const double R = val('R');
    if (d == 0)
      fail(errc::gcode_arc, g + " with R: the end point equals the start point; give a full circle with I and J");
    const double tol = arc_tolerance();
    if (std::abs(R) < d / 2 - tol)
      fail(errc::gcode_arc, txt('R') + " is too small for the chord of " + fmt_num(d) + " " + unit() +
                                " between start and end (the radius must be at least half of it)");
    const double h = std::sqrt(std::max(0.0, R * R - d * d / 4));
    // Centre left of the chord for a minor CCW arc or a major CW one.
    const double side = ((!cw) == (R > 0)) ? 1.0 : -1.0;
    c.x = (lf.x + lt.x) / 2 - side * h * dy / d;
    c.y = (lf.y + lt.y) / 2 + side * h * dx / d;
  }
  const double r0 = std::hypot(lf.x - c.x, lf.y - c.y), r1 = std::hypot(lt.x - c.x, lt.y - c.y);
  if (r0 == 0)
    fail(errc::gcode_arc,
         g + ": the centre coincides with the start point (" + words +
             (st.arc_centers == ArcCenterMode::absolute ? " name the start point in G90.1)" : " are both 0)"));
  const double tol = arc_tolerance();
  const double slack = 1e-12 * std::max({1.0, max_abs(from), max_abs(to), max_abs(c)});
  if (std::abs(r0 - r1) > tol + slack)
    soft(errc::gcode_arc_radius, g + ": the centre (" + fmt_num(from_plane(c, pl)[std::min(ia, ib)]) + ", " +
                                     fmt_num(from_plane(c, pl)[std::max(ia, ib)]) + ") is " + fmt_num(r0) +
                                     " from the start and " + fmt_num(r1) + " from the end; they differ by " +
                                     fmt_num(std::abs(r0 - r1)) + " " + unit() + ", more than the arc tolerance" +
                                     machine() + " (" + fmt_num(tol) + " " + unit() +
                                     "): the end point or the centre is wrong");
  MotionBlock b = block(cw ? BlockKind::arc_cw : BlockKind::arc_ccw, to);
  b.center = from_plane(c, pl);  // along the plane's axis: the start's
  b.plane = pl;
  lint_motion(b.kind, b.from, to, axes);
  check_travel(arc_box(b), 7);
  check_feed_limit(st.feed);
  commit_move(b, axes);
}

// ---------------------------------------------------------------------------

GcodeInterpreter::GcodeInterpreter(const MachineProfile* profile) : impl_(std::make_unique<Impl>()) {
  impl_->profile = profile;
  if (profile) impl_->tool_diameters_mm = profile->tool_diameters_mm;
  // The return mode until a program sets it: LinuxCNC's interpreter starts
  // in G99, a Fanuc control (parameter) in G98.
  const bool fanuc = profile && profile->cycles.dialect == CannedCycles::Dialect::fanuc;
  impl_->state.cycle_return = fanuc ? CycleReturn::initial_level : CycleReturn::r_plane;
}

GcodeInterpreter::~GcodeInterpreter() = default;
GcodeInterpreter::GcodeInterpreter(GcodeInterpreter&&) noexcept = default;
GcodeInterpreter& GcodeInterpreter::operator=(GcodeInterpreter&&) noexcept = default;
GcodeInterpreter::GcodeInterpreter(const GcodeInterpreter& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
GcodeInterpreter& GcodeInterpreter::operator=(const GcodeInterpreter& o) {
  if (this != &o) impl_ = std::make_unique<Impl>(*o.impl_);
  return *this;
}

const MachineState& GcodeInterpreter::state() const { return impl_->state; }

void GcodeInterpreter::set_tool_diameters_mm(const std::map<int, double>& d) {
  for (const auto& [k, v] : d) impl_->tool_diameters_mm[k] = v;
}

GcodeInterpreter::Continuation GcodeInterpreter::continuation() const {
  const Impl::More& m = impl_->more;
  return {m.open, m.open_line, m.g5_chain, m.selected_tool, m.end_line};
}

std::vector<MotionBlock> GcodeInterpreter::feed_line(std::string_view text, int line_no) {
  Impl& d = *impl_;
  d.more.last_line = line_no;  // bookkeeping for finish(), even if the line is refused
  // Stated limits (limits.hpp), checked before the line is looked at.
  if (static_cast<size_t>(line_no) > kMaxReadLines)
    throw InputError(errc::gcode_program_too_long, Place::at_line(line_no),
                     "the program has more than " + std::to_string(kMaxReadLines) +
                         " lines, the most bezcam reads (docs/limits.md); split it into several programs");
  while (!text.empty() && (text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
  if (text.size() > kMaxLineBytes)
    throw InputError(errc::gcode_line_too_long, Place::at_line(line_no),
                     "the line has " + std::to_string(text.size()) + " characters, more than the " +
                         std::to_string(kMaxLineBytes) + " bezcam reads in one line (docs/limits.md)");
  // The line runs on copies of the state, committed only when it is
  // accepted. The open NURBS block's lists are moved in, not copied (a copy
  // per line would make a block of n control points cost n^2): until a line
  // clears or replaces them (LineRun::save_lists() keeps them then) it only
  // appends, so a refused line is undone by cutting them back.
  const std::array<size_t, 4> sizes{d.more.ctrl.size(), d.more.weights.size(), d.more.knots.size(),
                                    d.more.knot_lines.size()};
  LineRun im{d, d.state, std::move(d.more), line_no, {}, {}, {}};
  im.sizes0 = sizes;
  try {
    im.run(text);
  } catch (...) {
    // A line compensation cannot follow turns compensation off, so that
    // lint reports it once and reads on.
    bool comp_error = false;
    try {
      throw;
    } catch (const InputError& e) {
      comp_error = e.id() == errc::gcode_cutter_comp;
    } catch (...) {
    }
    if (comp_error) {
      d.more.comp = CutterComp{};
      d.state.cutter_comp = CutterCompMode::off;
      d.state.cutter_comp_d = 0;
      d.state.cutter_comp_radius = 0;
    }
    // d.more kept every scalar (moving copies them); give the lists back.
    LineRun::Lists& back = im.saved;
    if (!im.lists_saved) {
      back.ctrl = std::move(im.mo.ctrl);
      back.weights = std::move(im.mo.weights);
      back.knots = std::move(im.mo.knots);
      back.knot_lines = std::move(im.mo.knot_lines);
      back.ctrl.resize(sizes[0]);
      back.weights.resize(sizes[1]);
      back.knots.resize(sizes[2]);
      back.knot_lines.resize(sizes[3]);
    }
    d.more.ctrl = std::move(back.ctrl);
    d.more.weights = std::move(back.weights);
    d.more.knots = std::move(back.knots);
    d.more.knot_lines = std::move(back.knot_lines);
    throw;
  }
  d.state = im.st;
  d.more = std::move(im.mo);
  return std::move(im.out);
}

std::vector<MotionBlock> GcodeInterpreter::finish() {
  Impl::More& more = impl_->more;
  if (more.open != ModalMotion::none) {
    const bool fanuc = more.open != ModalMotion::nurbs_g5_2;
    const std::string msg =
        fanuc ? "the program ends inside the NURBS block opened at line " + std::to_string(more.open_line) +
                    ": it has " + std::to_string(more.ctrl.size()) + " control points and " +
                    std::to_string(more.knot_only) + " of its " + std::to_string(more.order) + " knot-only K blocks"
              : "the program ends inside the G5.2 block opened at line " + std::to_string(more.open_line) +
                    ": close it with G5.3";
    throw InputError(errc::gcode_nurbs_open, Place::at_line(std::max(more.last_line, 1)), msg);
  }
  try {
    return more.comp.finish();  // the move compensation still holds
  } catch (const CompensationError& e) {
    throw InputError(errc::gcode_cutter_comp, Place::at_line(std::max(more.last_line, 1)), e.what());
  }
}

std::vector<MotionBlock> read_gcode(std::string_view text, const MachineProfile* profile) {
  if (const auto f = too_large(text)) throw InputError(f->id, Place::at_line(1), f->message);
  GcodeInterpreter in(profile);
  std::vector<MotionBlock> out;
  int no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    auto blocks = in.feed_line(text.substr(pos, end - pos), ++no);
    out.insert(out.end(), std::make_move_iterator(blocks.begin()), std::make_move_iterator(blocks.end()));
    pos = end + 1;
  }
  auto held = in.finish();
  out.insert(out.end(), std::make_move_iterator(held.begin()), std::make_move_iterator(held.end()));
  return out;
}

}  // namespace bezcam
