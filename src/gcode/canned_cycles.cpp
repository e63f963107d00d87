// Canned drilling cycles: G81 (drill), G82 (drill, dwell at the bottom),
// G83 (peck, out to the R plane after each peck), G73 (peck, backing off a
// little), with G98 / G99 and G80, as the profile's `canned_cycles` dialect
// runs them (docs/gcode-dialects.md#canned-drilling-cycles). Each hole
// becomes ordinary rapid and feed blocks of its line.
//
// LinuxCNC: its interpreter (rs274ngc, version 2.9: interp_cycles.cc,
// convert_cycle_xy() and its CYCLE_MACRO). Fanuc: the operator's manuals'
// sequence (position in the plane, rapid to R, drill, return to the
// initial level or R), with the drilling data kept for every cycle until
// the mode ends.
#include <cmath>
#include <string>

#include "bezcam/limits.hpp"
#include "interpreter_impl.hpp"

namespace bezcam {

using namespace gcode;

namespace {

using Dialect = CannedCycles::Dialect;

Dialect dialect_of(const MachineProfile* p) { return p ? p->cycles.dialect : Dialect::linuxcnc; }

}  // namespace

void GcodeInterpreter::LineRun::end_cycles() { mo.cycle = {}; }

void GcodeInterpreter::LineRun::cycle_move(bool rapid, const Vec3& plane_to, double dwell) {
  const Vec3 to = from_plane(plane_to, st.plane);
  if (rapid && (st.known_axes & 7) == 7 && to == st.pos) return;
  MotionBlock b = block(rapid ? BlockKind::rapid : BlockKind::linear, to);
  b.dwell_s = dwell;
  lint_motion(b.kind, b.from, to, 7);
  Box3 box;
  box.add(to);
  check_travel(box, 7);
  st.dwell_seconds += dwell;
  commit_move(b, 7);
}

void GcodeInterpreter::LineRun::canned_cycle(int code, bool explicit_motion) {
  const Dialect dialect = dialect_of(self.profile);
  const bool fanuc = dialect == Dialect::fanuc;
  const std::string g = wt(code);
  if (dialect == Dialect::none)
    fail(errc::gcode_dialect, g + " is a canned drilling cycle, and machine \"" + self.profile->name +
                                  "\" has none: write each hole as G0 and G1 moves");
  const Plane pl = st.plane;
  const int ia = world_axis(pl, 0), ib = world_axis(pl, 1), ih = world_axis(pl, 2);
  const char la = "XYZ"[ia], lb = "XYZ"[ib], lh = "XYZ"[ih];
  const std::string h_name(1, lh);
  // In cycle mode a line drills a hole when it has an axis word (Fanuc:
  // or R); P, Q or L alone mean nothing.
  if (!explicit_motion && !(ln.has('X') || ln.has('Y') || ln.has('Z') || (fanuc && ln.has('R')))) {
    for (const Word& w : ln.words)
      if (std::string_view("RQLP").find(w.letter) != std::string_view::npos)
        fail(errc::gcode_unexpected_word, "word " + w.text + " alone in canned cycle mode (" + g + " since line " +
                                              std::to_string(mo.cycle.line) +
                                              ") drills nothing: a hole needs its position (" + std::string(1, la) +
                                              ", " + std::string(1, lb) + " or " + h_name + ")");
  }
  if (st.cutter_comp != CutterCompMode::off)
    fail(errc::gcode_cutter_comp,
         g + " (a canned cycle) cannot be used with cutter radius compensation on: cancel it with G40 first");
  require_feed(g);

  // The words a hole takes over from the line before: LinuxCNC only from
  // the same cycle, Fanuc from any while the cycle mode lasts.
  const bool reuse = mo.cycle.in && (fanuc || st.motion == static_cast<ModalMotion>(code));
  const auto taken = [&](char c, std::optional<double>& kept, const std::string& what) {
    if (ln.has(c)) return val(c);
    if (reuse && kept) return *kept;
    fail(errc::gcode_cycle,
         g + " needs " + what +
             (mo.cycle.in && !fanuc ? " (LinuxCNC takes it over only from a line of the same cycle)" : ""));
  };
  const bool incremental = st.distance == DistanceMode::incremental;
  const double rw = taken(
      'R', mo.cycle.r,
      std::string("the R plane R- (where the feed starts") + (incremental ? ", from the initial level in G91)" : ")"));
  const double zw = taken(lh, mo.cycle.z,
                          "the bottom of the hole " + h_name + "-" + (incremental ? " (from the R plane in G91)" : ""));
  double q = 0, p = 0;
  if (code == 730 || code == 830) {
    q = taken('Q', mo.cycle.q, "the peck depth Q-");
    if (!(q > 0))
      fail(errc::gcode_cycle, g + ": expected a peck depth Q > 0, found " + (ln.has('Q') ? txt('Q') : fmt_num(q)));
  }
  if (code == 820) {
    p = taken('P', mo.cycle.p, "the dwell P- (seconds at the bottom of the hole)");
    if (!(p >= 0)) fail(errc::gcode_dwell, g + ": expected a dwell P >= 0 (seconds), found " + txt('P'));
  }
  double repeats = 1;
  if (ln.has('L')) {
    repeats = val('L');
    if (!(repeats >= 1 && repeats <= 10000 && repeats == std::floor(repeats)))
      fail(errc::gcode_cycle, "expected a whole number of repeats L from 1 to 10000, found " + txt('L'));
  }

  // The plane's coordinates (a, b, h), h along the drilling axis.
  unsigned need = 1u << ih;
  if (incremental || !ln.has(la)) need |= 1u << ia;
  if (incremental || !ln.has(lb)) need |= 1u << ib;
  require_known(g, need);
  const Vec3 cur = to_plane(st.pos, pl);
  const double initial = mo.cycle.in ? mo.cycle.initial : cur.z;
  double a = cur.x, b = cur.y, da = 0, db = 0, r = rw, bottom = zw;
  if (incremental) {
    da = ln.has(la) ? val(la) : 0;
    db = ln.has(lb) ? val(lb) : 0;
    r = rw + initial;
    bottom = r + zw;
  } else {
    if (ln.has(la)) a = val(la);
    if (ln.has(lb)) b = val(lb);
  }
  if (!std::isfinite(r) || !std::isfinite(bottom) || !std::isfinite(a + da * repeats) ||
      !std::isfinite(b + db * repeats))
    fail(errc::gcode_number, g + " in G91 (incremental distances) goes beyond the largest number bezcam reads");
  if (r < bottom)
    fail(errc::gcode_cycle, g + ": the R plane (" + h_name + " = " + fmt_num(r) +
                                ") is below the bottom of the hole (" + h_name + " = " + fmt_num(bottom) +
                                "): R must be at or above it");
  // Every hole is a few moves, and a peck three (G73: two) more.
  double per_hole = 4;
  if (code == 730 || code == 830) per_hole += (code == 830 ? 3 : 2) * std::ceil((r - bottom) / q);
  if (per_hole * repeats > static_cast<double>(kMaxCycleMoves))
    fail(errc::gcode_cycle, g + " would make about " + fmt_num(per_hole * repeats) + " moves, more than the " +
                                std::to_string(kMaxCycleMoves) +
                                " bezcam expands from one line (docs/limits.md): use a larger Q or fewer repeats");

  double h = cur.z;        // where the drill stands along its axis
  double level = initial;  // where G98 returns to
  if (initial < r) {
    if (fanuc)
      fail(errc::gcode_cycle, g + ": the cycle mode began at " + h_name + " = " + fmt_num(initial) +
                                  ", below the R plane (" + h_name + " = " + fmt_num(r) +
                                  "): a Fanuc control would move in " + std::string(1, la) + std::string(1, lb) +
                                  " at that height; move above R before the cycle");
    // LinuxCNC: straight up to the R plane first.
    cycle_move(true, {cur.x, cur.y, r});
    h = level = r;
  }
  const double clear = st.cycle_return == CycleReturn::r_plane ? r : level;
  const double delta =
      from_mm(self.profile ? (code == 730 ? self.profile->cycles.g73_retract_mm : self.profile->cycles.g83_clearance_mm)
                           : kLinuxcncPeckClearanceMm);
  check_feed_limit(st.feed);
  for (int k = 0; k < static_cast<int>(repeats); ++k) {
    a += da;
    b += db;
    // To the hole, then down to R.
    if (fanuc || (k == 0 && h > r)) {
      cycle_move(true, {a, b, h});
      cycle_move(true, {a, b, r});
    } else {
      cycle_move(true, {a, b, clear});  // LinuxCNC: straight to the return level
      if (clear > r) cycle_move(true, {a, b, r});
    }
    if (code == 730 || code == 830)
      for (double depth = r - q; depth > bottom; depth -= q) {
        cycle_move(false, {a, b, depth});
        if (code == 830) cycle_move(true, {a, b, r});
        cycle_move(true, {a, b, depth + delta});
      }
    cycle_move(false, {a, b, bottom}, p);
    cycle_move(true, {a, b, clear});
    h = clear;
  }

  if (!mo.cycle.in) {
    mo.cycle.in = true;
    mo.cycle.line = line;
    mo.cycle.initial = initial;
  }
  mo.cycle.r = rw;
  mo.cycle.z = zw;
  if (code == 730 || code == 830) mo.cycle.q = q;
  if (code == 820) mo.cycle.p = p;
  st.motion = static_cast<ModalMotion>(code);
  mo.g5_chain = false;
}

}  // namespace bezcam
