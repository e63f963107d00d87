// The paths a part's cut is measured by (part_cut.hpp): the printed moves
// as the controller draws them, the tool centre's path under the
// controller's compensation on bezcam's model of it, and a polyline of even
// chords for a controller that compensates lines.
#include <algorithm>
#include <cmath>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/machine/cutter_comp.hpp"
#include "part_cut.hpp"

namespace bezcam::detail {

// The printed path of moves [from, to) from `cur`, in XY, as the controller
// draws it: lines, arcs from their printed numbers, curve blocks as their
// Bézier pieces (Z-only moves leave nothing).
std::vector<PathPiece> printed_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur) {
  std::vector<PathPiece> out;
  auto xy = [](const Vec3& p) { return Vec3{p.x, p.y, 0}; };
  for (size_t i = from; i < to; ++i) {
    const Move& mv = moves[i];
    if (const auto* l = std::get_if<LineMove>(&mv.what)) {
      if (l->to.x != cur.x || l->to.y != cur.y) out.push_back(PathPiece::line(xy(cur), xy(l->to)));
      cur = l->to;
    } else if (const auto* a = std::get_if<ArcMove>(&mv.what)) {
      out.push_back(PathPiece::of(PrintedArc{xy(cur), xy(a->to), xy(a->center), a->ccw}));
      cur = a->to;
    } else if (const auto* c = std::get_if<CurveMove>(&mv.what)) {
      std::vector<Vec3> ctrl;
      for (const auto& p : c->shape->ctrl) ctrl.push_back(xy(p));
      std::vector<Bezier> pieces;
      if (c->shape->form == CurveMove::Form::bezier)
        pieces.push_back(Bezier::make(ctrl, {}, 2));
      else
        pieces = to_bezier(NurbsCurve::make(c->shape->order - 1, ctrl, c->shape->knots, c->shape->weights, 2));
      for (const Bezier& b : pieces) out.push_back(PathPiece::of(b));
      cur = c->to;
    } else if (const auto* m = motion_of(mv)) {
      cur = m->to;
    }
  }
  return out;
}

// The tool centre's path under controller compensation (cutter_comp.hpp)
// for the moves [from, to) of a stretch from `cur`, entered and left by the
// leads, whose ends run along `ts` and `te`, in XY: the corners the
// controller turns between the leads and the stretch included, the leads
// themselves not.
std::vector<PathPiece> compensated_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur,
                                        const Vec3& ts, const Vec3& te, int side, double r) {
  Program run;
  LineMove start;
  start.to = cur;
  run.moves.push_back({start});
  for (size_t i = from; i < to; ++i) run.moves.push_back(moves[i]);
  auto blocks = program_motion(run);
  blocks.erase(blocks.begin());  // the move to the start
  if (blocks.empty()) return {};
  CutterComp comp;
  comp.on(side, r);
  MotionBlock entry, exit;
  entry.from = cur - ts * (2 * r + 1);
  entry.to = cur;
  exit.from = blocks.back().to;
  exit.to = exit.from + te * (2 * r + 1);
  std::vector<MotionBlock> tool;
  auto add = [&](std::vector<MotionBlock> bs) { tool.insert(tool.end(), bs.begin(), bs.end()); };
  add(comp.push(entry));
  for (const auto& b : blocks) add(comp.push(b));
  add(comp.push(exit));  // completes the last move and its corner, holds the exit
  std::vector<PathPiece> out;
  auto xy = [](const Vec3& p) { return Vec3{p.x, p.y, 0}; };
  for (size_t i = 1; i < tool.size(); ++i) {  // not the entry
    const MotionBlock& b = tool[i];
    if (b.kind == BlockKind::linear || b.kind == BlockKind::rapid) {
      if (b.from.x != b.to.x || b.from.y != b.to.y) out.push_back(PathPiece::line(xy(b.from), xy(b.to)));
    } else if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
      out.push_back(PathPiece::of(PrintedArc{xy(b.from), xy(b.to), xy(b.center), b.kind == BlockKind::arc_ccw}));
    } else {
      for (Bezier piece : block_to_bezier(b)) {
        for (Vec3& q : piece.points) q = xy(q);
        piece.dim = 2;
        out.push_back(PathPiece::of(piece));
      }
    }
  }
  return out;
}

// Chords of even size along each piece, for a controller that compensates
// the polyline: a short chord left at a joint by the greedy flattening is
// one the controller's offset would swallow on the inside of a bend
// (LinuxCNC stops: "Straight feed in concave corner cannot be reached by the
// tool without gouging"). The greedy chords of a piece, t_0 < ... < t_n,
// with the last one a fraction f of a full one, are spread over the piece
// as n chords of (n - 1 + f) / n greedy chords each (or n + 1); each is
// proven as the flattener proves its own (chord_deviation() plus the
// rounding of its ends), and a piece where that fails keeps its greedy
// chords. Returns the polyline; `bound` gets its proven deviation.
std::vector<Vec3> even_chords(std::span<const Bezier> pieces, double tol, int dec, double& bound) {
  std::vector<Vec3> out;
  bound = 0;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const Bezier& b = pieces[k];
    std::vector<double> ts;
    std::vector<Vec3> greedy;
    const double gb =
        flatten_pieces(std::span<const Bezier>(&b, 1),
                       FlattenOptions{.tolerance = tol, .decimals = dec, .on_curve = true}, [&](const FlatVertex& v) {
                         ts.push_back(v.t);
                         greedy.push_back(v.point);
                       });
    ts.front() = 0;
    ts.back() = 1;
    const size_t n = ts.size() - 1;
    std::vector<Vec3> chosen = greedy;
    double chosen_bound = gb;
    if (n >= 2) {
      const double f = std::clamp(std::sqrt(chord_deviation(b, ts[n - 1], 1) / tol), 0.05, 1.0);
      const double total = static_cast<double>(n - 1) + f;
      auto at = [&](double x) {  // the parameter at x greedy chords from the start
        const size_t j = static_cast<size_t>(std::floor(x));
        if (j >= n - 1) return ts[n - 1] + std::min(1.0, (x - static_cast<double>(n - 1)) / f) * (1 - ts[n - 1]);
        return ts[j] + (x - static_cast<double>(j)) * (ts[j + 1] - ts[j]);
      };
      for (size_t m = n; m <= n + 1; ++m) {
        std::vector<double> s(m + 1);
        for (size_t i = 0; i <= m; ++i)
          s[i] = i == m ? 1.0 : at(total * static_cast<double>(i) / static_cast<double>(m));
        std::vector<Vec3> exact(m + 1), printed(m + 1);
        for (size_t i = 0; i <= m; ++i) {
          exact[i] = i == 0 ? b.front() : i == m ? b.back() : evaluate(b, s[i]);
          printed[i] = dec < 0 ? exact[i] : quantize(exact[i], dec);
        }
        double worst = 0;
        bool ok = true;
        for (size_t i = 0; i < m && ok; ++i) {
          const double moved = std::max(dist(printed[i], exact[i]), dist(printed[i + 1], exact[i + 1]));
          const double dev = chord_deviation(b, s[i], s[i + 1], tol - moved) + moved;
          ok = s[i + 1] > s[i] && dev <= tol;
          worst = std::max(worst, dev);
        }
        if (ok) {
          chosen = printed;
          chosen.front() = greedy.front();  // the piece's ends as the flattener prints them
          chosen.back() = greedy.back();
          chosen_bound = worst;
          break;
        }
      }
    }
    out.insert(out.end(), chosen.begin() + (out.empty() ? 0 : 1), chosen.end());
    bound = std::max(bound, chosen_bound);
  }
  return out;
}

}  // namespace bezcam::detail
