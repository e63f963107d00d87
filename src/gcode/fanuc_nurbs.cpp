// The Fanuc-style NURBS block (G06.2 or G06.3 start word): a first block
// "G06.2 P- K- X- Y- Z- [R-]", one "K X Y Z R" block per further control
// point, then exactly P knot-only K blocks, with the knot rules checked as
// each knot arrives.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "interpreter_impl.hpp"

namespace bezcam {

using namespace gcode;

bool GcodeInterpreter::LineRun::continue_block() {
  if (mo.open == ModalMotion::nurbs_g5_2) return continue_g52();
  // Fanuc: "K- [X- Y- Z- R-]" until the P-th knot-only block.
  const bool only_block_words =
      ln.g.empty() && ln.m.empty() && std::all_of(ln.words.begin(), ln.words.end(), [](const Word& w) {
        return std::string_view("KXYZR").find(w.letter) != std::string_view::npos;
      });
  if (!ln.has('K') || !only_block_words) {
    if (ln.has('K') && ln.g.empty() && ln.m.empty()) {
      if (ln.has('P'))
        fail(errc::gcode_nurbs_word,
             "P (the rank) is only given on the first block of a NURBS block, found " + txt('P'));
      if (ln.has('F'))
        fail(errc::gcode_nurbs_word, "F is only given on the first block of a NURBS block, found " + txt('F'));
    }
    const std::string msg = "the NURBS block opened at line " + std::to_string(mo.open_line) +
                            " is incomplete: it has " + std::to_string(mo.ctrl.size()) + " control points and " +
                            std::to_string(mo.knot_only) + " of its " + std::to_string(mo.order) +
                            " knot-only blocks; until the last knot every line must be 'K- [X- Y- Z- R-]'";
    if (!lint()) fail(errc::gcode_nurbs_open, msg);
    soft(errc::gcode_nurbs_open, msg);
    abandon_block();
    return false;  // lint reads the line on its own
  }
  const Word& k = *ln.get('K');
  const bool knot_only = ln.words.size() == 1;
  if (!knot_only) {
    if (mo.knot_only > 0)
      fail(errc::gcode_knot_count, "a control point after the knot-only blocks that began at line " +
                                       std::to_string(mo.knot_only_line) +
                                       ": a NURBS block lists every control point first, "
                                       "then exactly P (" +
                                       std::to_string(mo.order) + ") knot-only K blocks");
    // In G91 each point is the travel from the one before (Fanuc).
    Vec3 p = mo.ctrl.back();
    for (int a = 0; a < 3; ++a)
      if (const Word* w = ln.get("XYZ"[a])) p[a] = coordinate(*w, p[a]);
    double w = 1;
    if (ln.has('R')) w = weight(*ln.get('R'));
    mo.ctrl.push_back(p);
    mo.weights.push_back(w);
  } else {
    if (mo.knot_only == 0) mo.knot_only_line = line;
    ++mo.knot_only;
  }
  add_knot(k, knot_only);
  if (mo.knot_only == mo.order) complete_fanuc();
  return true;
}

void GcodeInterpreter::LineRun::add_knot(const Word& k, bool knot_only) {
  const double v = k.value;
  const int rank = mo.order;
  size_t prev = mo.knots.size();
  while (prev > 0 && std::isnan(mo.knots[prev - 1])) --prev;
  bool reported = false;
  if (prev > 0 && v < mo.knots[prev - 1]) {
    soft(errc::gcode_knot_order, k.text + ": expected a knot >= " + fmt_num(mo.knots[prev - 1]) +
                                     " (knots must not decrease; the previous knot is on line " +
                                     std::to_string(mo.knot_lines[prev - 1]) + "), found " + fmt_num(v));
    reported = true;
  }
  const size_t idx = mo.knots.size();  // this knot's index
  // Clamped start: the first `rank` knots are equal.
  if (!reported && idx < static_cast<size_t>(rank)) {
    for (size_t j = 0; j < idx; ++j)
      if (!std::isnan(mo.knots[j]) && mo.knots[j] != v) {
        soft(errc::gcode_knot_clamped, k.text + " is knot " + std::to_string(idx + 1) + " of the block: the first P (" +
                                           std::to_string(rank) +
                                           ") knots must be equal (a clamped start: the curve starts "
                                           "at the current position), but the first is " +
                                           fmt_num(mo.knots[j]) + " (line " + std::to_string(mo.knot_lines[j]) + ")");
        reported = true;
        break;
      }
  }
  // Clamped end: the knot-only blocks (the last `rank` knots) are equal.
  if (!reported && knot_only && mo.knot_only > 1) {
    const size_t first_end = mo.knots.size() - static_cast<size_t>(mo.knot_only - 1);
    if (mo.knots[first_end] != v) {
      soft(errc::gcode_knot_clamped,
           k.text + ": the last P (" + std::to_string(rank) +
               ") knots, the knot-only blocks, must "
               "be equal (a clamped end: the curve ends at its last control point), but the first "
               "of them is " +
               fmt_num(mo.knots[first_end]) + " (line " + std::to_string(mo.knot_lines[first_end]) + ")");
      reported = true;
    }
  }
  // Multiplicity: no knot repeated more than `rank` times.
  if (!reported) {
    size_t run = 1;
    for (size_t j = idx; j > 0 && mo.knots[j - 1] == v; --j) ++run;
    if (run == static_cast<size_t>(rank) + 1)
      soft(errc::gcode_knot_multiplicity, k.text + ": knot " + fmt_num(v) + " now appears " + std::to_string(run) +
                                              " times (from line " + std::to_string(mo.knot_lines[idx + 1 - run]) +
                                              "); no knot may repeat more than the rank P (" + std::to_string(rank) +
                                              ") times");
  }
  mo.knots.push_back(v);
  mo.knot_lines.push_back(line);
}

void GcodeInterpreter::LineRun::complete_fanuc() {
  if (mo.ctrl.size() < static_cast<size_t>(mo.order)) {
    const std::string msg = "the NURBS block opened at line " + std::to_string(mo.open_line) + " has " +
                            std::to_string(mo.ctrl.size()) + " control points; a block of rank P" +
                            std::to_string(mo.order) + " needs at least " + std::to_string(mo.order);
    if (!lint()) fail(errc::gcode_knot_count, msg);
    soft(errc::gcode_knot_count, msg);  // lint: the block is dropped and reading goes on
    abandon_block();
    return;
  }
  finish_nurbs_block(mo.knots);
  st.motion = mo.open;  // NURBS mode goes on until G00..G03
  clear_block();
}

void GcodeInterpreter::LineRun::fanuc_start(int code) {
  st.motion = static_cast<ModalMotion>(code);  // 62 or 63
  mo.g5_chain = false;
  mo.nurbs_mode_line = line;
  const int max = self.profile ? self.profile->nurbs_max_rank : 4;
  int rank = 4;
  if (ln.has('P')) {
    const double P = val('P');
    if (P != std::floor(P) || P < 2 || P > max) {
      soft(errc::gcode_rank,
           "rank " + txt('P') + ": expected P from 2 to " + std::to_string(max) + " (order = degree + 1)" + machine());
      rank = static_cast<int>(std::clamp(std::floor(P), 2.0, static_cast<double>(max)));
    } else {
      rank = static_cast<int>(P);
    }
  }
  require_feed(wt(code));
  // The first control point is the current position.
  Vec3 p0 = st.pos;
  // (In G91 its words are the travel from there: 0, as Fanuc asks.)
  for (int a = 0; a < 3; ++a) {
    const Word* w = ln.get("XYZ"[a]);
    if (!w || !gives_coordinate(a, *w)) continue;
    const double v = coordinate(*w, st.pos[a]);
    if (st.known_axes & (1u << a)) {
      const double slack = 1e-12 * std::max(1.0, std::abs(st.pos[a]));
      if (std::abs(v - st.pos[a]) > slack)
        soft(errc::gcode_nurbs_start,
             w->text + ": the first control point of a NURBS block must be the current position (" +
                 (st.distance == DistanceMode::absolute ? axis_name(a) + " = " + fmt_num(st.pos[a])
                                                        : "in G91 (incremental distances): " + axis_name(a) + "0") +
                 ")");
    }
    p0[a] = v;
  }
  if ((st.known_axes & 7) != 7 && lint() && !mo.noted_position) {
    // Axes neither known nor given: lint goes on with 0.
    note(errc::gcode_position_unknown,
         "the NURBS block starts from a position this program has not set (its first "
         "control point must be the current position): position the tool with G00 first");
    mo.noted_position = true;
  }
  double w = 1;
  if (ln.has('R')) w = weight(*ln.get('R'));
  mo.open = static_cast<ModalMotion>(code);
  mo.open_line = line;
  mo.order = rank;
  mo.open_feed = st.feed;
  save_lists();
  mo.ctrl = {p0};
  mo.weights = {w};
  mo.knots.clear();
  mo.knot_lines.clear();
  mo.knot_only = 0;
  if (!ln.has('K')) {
    soft(errc::gcode_knot_missing, "the first block of a NURBS block needs its knot K (K- X- Y- Z- R-)");
    mo.knots.push_back(kNaN);
    mo.knot_lines.push_back(line);
  } else {
    add_knot(*ln.get('K'), false);
  }
  lint_motion(BlockKind::nurbs, p0, p0, 0);
  // The position is defined from here on (the block starts there).
  st.pos = p0;
  st.known_axes = 7;
}

}  // namespace bezcam
