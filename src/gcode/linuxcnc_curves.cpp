// LinuxCNC's curve words: G5 (cubic Bézier, I J P Q), G5.1 (quadratic,
// I J) and the G5.2 ... G5.3 NURBS block (order L, points "X- Y- P-",
// the interpreter's clamped uniform knots).
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "interpreter_impl.hpp"

namespace bezcam {

using namespace gcode;

std::vector<double> linuxcnc_knots(size_t n_points, int order) {
  // knot_vector_creator(n, k) with n = n_points - 1: i < k -> 0,
  // k <= i <= n -> i - k + 1, else n - k + 2.
  const long n = static_cast<long>(n_points) - 1, k = order;
  std::vector<double> U;
  for (long i = 0; i <= n + k; ++i) U.push_back(static_cast<double>(i < k ? 0 : (i <= n ? i - k + 1 : n - k + 2)));
  return U;
}

bool GcodeInterpreter::LineRun::continue_g52() {
  const bool closes = ln.g.size() == 1 && ln.g[0].first == 53;
  if (closes) return false;  // run_modal() handles G5.3
  const bool only_points =
      ln.g.empty() && ln.m.empty() && std::all_of(ln.words.begin(), ln.words.end(), [](const Word& w) {
        return std::string_view("XYP").find(w.letter) != std::string_view::npos;
      });
  if (!only_points) {
    std::string msg = "the G5.2 block opened at line " + std::to_string(mo.open_line) +
                      " is still open: only control points 'X- Y- P-' may follow until G5.3";
    if (ln.has('Z')) msg = "G5.2 blocks move in X and Y only: a Z word is not allowed (" + txt('Z') + ")";
    if (!lint()) fail(errc::gcode_nurbs_open, msg);
    soft(errc::gcode_nurbs_open, msg);
    abandon_block();
    return false;
  }
  g52_point();
  return true;
}

void GcodeInterpreter::LineRun::g52_point() {
  if (ln.has('X') != ln.has('Y'))
    fail(errc::gcode_nurbs_point,
         std::string("a G5.2 control point needs both X and Y, found only ") + (ln.has('X') ? txt('X') : txt('Y')));
  if (!ln.has('X')) fail(errc::gcode_nurbs_point, "a G5.2 control point line needs X, Y and P (its weight)");
  double w = 1;
  if (!ln.has('P'))
    soft(errc::gcode_weight, "a G5.2 control point needs its weight P (LinuxCNC refuses a point without it)");
  else
    w = weight(*ln.get('P'));
  // In G91 LinuxCNC's interpreter measures every point of the block from
  // where the block began (the current position until G5.3).
  mo.ctrl.push_back({coordinate(*ln.get('X'), st.pos.x), coordinate(*ln.get('Y'), st.pos.y), st.pos.z});
  mo.weights.push_back(w);
}

void GcodeInterpreter::LineRun::g5() {
  st.motion = ModalMotion::cubic;
  require_xy_known("G5");
  require_feed("G5");
  if (ln.has('I') != ln.has('J')) fail(errc::gcode_bezier, "G5 needs both I and J, or neither");
  if (!ln.has('P') || !ln.has('Q'))
    fail(errc::gcode_bezier, "G5 needs both P and Q (the second control point's offset from the end point)");
  Vec3 ij;
  if (ln.has('I'))
    ij = {val('I'), val('J'), 0};
  else if (mo.g5_chain)
    ij = mo.g5_next_ij;
  else
    fail(errc::gcode_bezier,
         "G5 without I and J continues the tangent of a G5 just before it, and there is none: give I and J");
  const auto [to, axes] = target();
  const Vec3 from = st.pos;
  MotionBlock b = block(BlockKind::bezier, to);
  b.order = 4;
  b.ctrl = {from, from + ij, to + Vec3{val('P'), val('Q'), 0}, to};
  curve_move(b, axes);
  mo.g5_chain = true;
  mo.g5_next_ij = {-val('P'), -val('Q'), 0};
}

void GcodeInterpreter::LineRun::g51() {
  st.motion = ModalMotion::quadratic;
  mo.g5_chain = false;
  require_xy_known("G5.1");
  require_feed("G5.1");
  if (!ln.has('I') || !ln.has('J'))
    fail(errc::gcode_bezier, "G5.1 needs both I and J (the middle control point's offset from the start)");
  const auto [to, axes] = target();
  MotionBlock b = block(BlockKind::bezier, to);
  b.order = 3;
  b.ctrl = {st.pos, st.pos + Vec3{val('I'), val('J'), 0}, to};
  curve_move(b, axes);
}

void GcodeInterpreter::LineRun::curve_move(MotionBlock& b, unsigned axes) {
  lint_motion(b.kind, b.from, b.to, axes);
  Box3 box;
  for (const auto& z : block_to_bezier(b)) box.add(bounds(z));
  check_travel(box, 7);
  check_feed_limit(st.feed);
  commit_move(b, axes);
}

void GcodeInterpreter::LineRun::g52() {
  if (mo.open == ModalMotion::nurbs_g5_2)
    fail(errc::gcode_nurbs_open,
         "a G5.2 block is already open since line " + std::to_string(mo.open_line) + ": close it with G5.3 first");
  require_xy_known("G5.2");
  require_feed("G5.2");
  mo.g5_chain = false;
  int order = 3;
  if (ln.has('L')) {
    const double L = val('L');
    if (L != std::floor(L) || L < 3)
      soft(errc::gcode_rank,
           "G5.2 order " + txt('L') + ": LinuxCNC ignores an order below 3 (it then uses 3); give L3 or more");
    // Any order above the largest is refused below; one past it keeps a
    // huge L from overflowing the int (found by fuzzing).
    else
      order = static_cast<int>(std::min(L, static_cast<double>(kMaxBezierDegree) + 2));
  }
  const int max = self.profile ? self.profile->nurbs_max_rank : kMaxBezierDegree + 1;
  if (order > max) {
    soft(errc::gcode_rank,
         "G5.2 order " + txt('L') + " exceeds the largest order" + machine() + ", " + std::to_string(max));
  }
  mo.open = ModalMotion::nurbs_g5_2;
  mo.open_line = line;
  mo.order = order;
  mo.open_feed = st.feed;
  save_lists();
  mo.ctrl = {st.pos};
  mo.weights = {1};
  if (ln.has('X') || ln.has('Y')) {
    // LinuxCNC: the current position gets weight 1, the point its P.
    g52_point();
  } else if (!ln.has('P')) {
    soft(errc::gcode_weight,
         "the G5.2 line needs P, the weight of its first control point (the current position): "
         "without it the weight differs between LinuxCNC versions");
  } else {
    mo.weights[0] = weight(*ln.get('P'));
  }
  st.motion = ModalMotion::nurbs_g5_2;
  lint_motion(BlockKind::nurbs, st.pos, st.pos, 0);
}

void GcodeInterpreter::LineRun::g53() {
  if (mo.open != ModalMotion::nurbs_g5_2) fail(errc::gcode_nurbs_start, "G5.3 ends a G5.2 block, and none is open");
  if (!ln.words.empty()) fail(errc::gcode_unexpected_word, "G5.3 takes no words, found " + ln.words.front().text);
  if (mo.ctrl.size() < static_cast<size_t>(mo.order)) {
    const std::string msg = "the G5.2 block opened at line " + std::to_string(mo.open_line) + " has " +
                            std::to_string(mo.ctrl.size()) + " control points; order L" + std::to_string(mo.order) +
                            " needs at least " + std::to_string(mo.order);
    if (!lint()) fail(errc::gcode_knot_count, msg);
    soft(errc::gcode_knot_count, msg);
    abandon_block();
    return;
  }
  finish_nurbs_block(linuxcnc_knots(mo.ctrl.size(), mo.order));
  clear_block();
  st.motion = ModalMotion::none;  // as LinuxCNC does after G5.3
}

}  // namespace bezcam
