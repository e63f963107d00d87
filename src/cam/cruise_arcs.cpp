// Arcs output on a controller whose arcs accelerate more slowly than its
// lines (LinuxCNC): arcs where the tool cruises at the feed, the lines
// program's own chords where it speeds up or slows down, joined by lines
// tangent to the arcs (docs/motion.md, "Arcs where the tool cruises").
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "cut_emitters.hpp"
#include "speed_stretches.hpp"

namespace bezcam::detail {

namespace {

// A tangent line stays within this share of the budget, so that the chord
// joining it to the curve has room.
constexpr double kTangentShare = 0.5;
// Shortest tangent line, in rounding steps: its printed direction is good
// to about one step over its length.
constexpr double kTangentSteps = 100;
// Margin over the shortest line the controller runs at the feed.
constexpr double kTangentMargin = 1.25;

double norm_xy(const Vec3& v) { return std::hypot(v.x, v.y); }

// The parameter farthest from the fixed end where `ok` holds: in (lo, hi]
// towards `hi` when `up`, else in [lo, hi) towards `lo`; `ok` is taken to
// hold near the fixed end and fail beyond some point. nullopt: nowhere.
template <class F>
std::optional<double> farthest(double lo, double hi, bool up, F ok) {
  double fail = up ? hi : lo;
  if (ok(fail)) return fail;
  double good = up ? lo : hi;
  std::optional<double> found;
  for (int i = 0; i < 48 && std::abs(fail - good) > 1e-10; ++i) {
    const double m = 0.5 * (good + fail);
    if (ok(m)) {
      good = m;
      found = m;
    } else {
      fail = m;
    }
  }
  return found;
}

// A printed line of a joint: a line along a tangent (`t`: the parameter
// where it meets the rest of the stretch) or a chord from or to one of the
// lines program's vertices (`vertex`: its index).
struct Joint {
  double t = 0;
  size_t vertex = 0;
  Vec3 a, b;  // printed ends
  double dev = 0;
};

// The printed point on the line through `at` along `dir` nearest M(t), and
// how far along `dir` it is.
Vec3 foot(const Bezier& b, double t, const Vec3& at, const Vec3& dir, int decimals, double& along) {
  const Vec3 m = evaluate(b, t);
  along = (m.x - at.x) * dir.x + (m.y - at.y) * dir.y;
  return quantize(Vec3{at.x + dir.x * along, at.y + dir.y * along, at.z}, decimals);
}

struct Budget {
  double tol = 0;  // what a line may deviate by
  int decimals = 0;
  double shortest = 0;  // the shortest line a joint may use
};

// The parameter on piece `p` of a flattener's vertex, or -1 when it is
// not on that piece (a vertex at a joint belongs to both pieces).
double on_piece(const FlatVertex& v, size_t p) {
  if (v.piece == p) return v.t;
  if (v.piece + 1 == p && v.t >= 1) return 0;
  if (v.piece == p + 1 && v.t <= 0) return 1;
  return -1;
}

// Leaving a chain at vx[0] in direction `dir`: the longest line along
// `dir` over the first piece on [0, t], then the longest chord from its
// end to a vertex of the chords (`.second.vertex`), over the
// first piece only and before vertex `last`. Both proven by
// band_deviation() between their printed ends.
std::optional<std::pair<Joint, Joint>> leave_chain(const Bezier& b, const std::vector<FlatVertex>& vx, size_t last,
                                                   const Vec3& dir, const Budget& bd) {
  // The line takes at most the first half of the first piece's chords.
  double t_max = 0;
  for (size_t j = 1; j < last; ++j)
    if (const double t = on_piece(vx[j], 0); t >= 0) t_max = t;
  if (!(t_max > 0)) return std::nullopt;
  const double share = kTangentShare * bd.tol;
  const Vec3 from = vx[0].point;
  Joint line;
  double along = 0;
  const auto line_ok = [&](double t) {
    line.b = foot(b, t, from, dir, bd.decimals, along);
    line.dev = along > 0 ? band_deviation(b, 0, t, from, line.b, share) : share * 2;
    line.t = t;
    return line.dev <= share;
  };
  const auto t = farthest(0, 0.5 * t_max, true, line_ok);
  if (!t || !line_ok(*t) || along < bd.shortest) return std::nullopt;
  line.a = from;
  // The farthest vertex the chord back reaches.
  Joint back;
  for (size_t j = 1; j < last; ++j) {
    const double tj = on_piece(vx[j], 0);
    if (!(tj > line.t)) continue;
    const double dev = band_deviation(b, line.t, tj, line.b, vx[j].point, bd.tol);
    if (!(dev <= bd.tol)) break;
    back = {tj, j, line.b, vx[j].point, dev};
  }
  if (back.vertex == 0 || dist(back.a, back.b) < bd.shortest) return std::nullopt;
  return std::make_pair(line, back);
}

// Entering a chain at the last vertex along the curve's tangent there: the
// longest line ending there along that tangent, over the last piece `p` on
// [t, 1], and the longest chord to its start from a vertex of the chords
// after vertex `first` (`.first.vertex`).
std::optional<std::pair<Joint, Joint>> enter_chain(const Bezier& b, size_t p, const std::vector<FlatVertex>& vx,
                                                   size_t first, const Budget& bd) {
  Vec3 dir = derivative(b, 1.0);
  dir.z = 0;
  if (!(norm_xy(dir) > 0)) return std::nullopt;
  dir = dir / norm_xy(dir);
  const size_t n = vx.size() - 1;
  double t_min = 1;
  for (size_t k = n; k-- > first + 1;)
    if (const double t = on_piece(vx[k], p); t >= 0) t_min = t;
  if (!(t_min < 1)) return std::nullopt;
  const Vec3 to = vx[n].point;
  const double share = kTangentShare * bd.tol;
  Joint line;
  double along = 0;
  const auto line_ok = [&](double t) {
    line.a = foot(b, t, to, dir, bd.decimals, along);
    line.dev = along < 0 ? band_deviation(b, t, 1, line.a, to, share) : share * 2;
    line.t = t;
    return line.dev <= share;
  };
  const auto t = farthest(0.5 * (t_min + 1), 1, false, line_ok);
  if (!t || !line_ok(*t) || -along < bd.shortest) return std::nullopt;
  line.b = to;
  Joint in;
  for (size_t k = n; k-- > first + 1;) {
    const double tk = on_piece(vx[k], p);
    if (tk < 0 || !(tk < line.t)) continue;
    const double dev = band_deviation(b, tk, line.t, vx[k].point, line.a, bd.tol);
    if (!(dev <= bd.tol)) break;
    in = {tk, k, vx[k].point, line.a, dev};
  }
  if (in.vertex == 0 || dist(in.a, in.b) < bd.shortest) return std::nullopt;
  return std::make_pair(in, line);
}

// The lines program's chords of a stretch.
std::vector<FlatVertex> chords(const SpeedStretch& st, const FlattenOptions& fo, double& bound) {
  std::vector<FlatVertex> vx;
  bound = std::max(bound, flatten_pieces(st.pieces, fo, [&](const FlatVertex& v) { vx.push_back(v); }));
  return vx;
}

// The stretches with the steady ones that cannot be entered or left along
// tangent lines of at least bd.shortest joined to the lines around them.
std::vector<SpeedStretch> joinable(std::vector<SpeedStretch> st, const FlattenOptions& fo, const Budget& bd) {
  double unused = 0;
  std::vector<char> keep(st.size());
  for (size_t i = 1; i + 1 < st.size(); ++i) {
    if (!st[i].steady) continue;
    const SpeedStretch &before = st[i - 1], &after = st[i + 1];
    bool ok =
        enter_chain(before.pieces.back(), before.pieces.size() - 1, chords(before, fo, unused), 0, bd).has_value();
    if (ok) {
      Vec3 dir = derivative(st[i].pieces.back(), 1.0);
      dir.z = 0;
      const std::vector<FlatVertex> vx = chords(after, fo, unused);
      ok = norm_xy(dir) > 0 && leave_chain(after.pieces.front(), vx, vx.size() - 1, dir / norm_xy(dir), bd);
    }
    keep[i] = ok;
  }
  std::vector<SpeedStretch> out;
  for (size_t i = 0; i < st.size(); ++i) {
    st[i].steady = keep[i];
    if (!out.empty() && out.back().steady == st[i].steady) {
      auto& p = out.back().pieces;
      p.insert(p.end(), st[i].pieces.begin(), st[i].pieces.end());
    } else {
      out.push_back(std::move(st[i]));
    }
  }
  return out;
}

}  // namespace

double append_cruise(CutContext& c, std::span<const Bezier> pieces, std::vector<Vec3>& path, size_t& blocks,
                     const SteadyEmitter& steady) {
  const MotionModel& mm = *c.machine.motion;
  const ToleranceBudget tb = check_tolerance(c.tolerance, c.decimals, pieces.front().dim, control_magnitude(pieces));
  // A line shorter than the feed runs in two of the controller's shortest
  // segment times (a blend takes up to half of it) makes the tool slow.
  const double v = c.params.feed / 60;
  const double shortest = std::max(kTangentSteps * (c.decimals >= 0 ? std::pow(10.0, -c.decimals) : 0.0),
                                   2 * v * mm.period_s * std::max(1.0, mm.min_segment_periods) * kTangentMargin);
  const Budget bd{tb.budget, c.decimals, shortest};
  const FlattenOptions fo{c.tolerance, c.decimals};
  const std::vector<SpeedStretch> stretches =
      joinable(speed_stretches(pieces, c.params.feed, mm, c.job.units, c.tolerance, c.decimals, c.ends), fo, bd);
  if (path.empty()) path.push_back(quantize(pieces.front().front(), c.decimals));
  double bound = 0;
  auto push_line = [&](const Vec3& to, double dev) {
    bound = std::max(bound, dev);
    append_line(c, to, path, blocks);
  };
  // The direction the last chain ends in (zero: none); where the cut goes
  // on from a tangent move, the one that move ends in.
  Vec3 chain_end = incoming_direction(c, pieces);
  for (size_t i = 0; i < stretches.size(); ++i) {
    const SpeedStretch& st = stretches[i];
    if (st.steady) {
      // The chain goes on from the line before when that line is tangent.
      bound = std::max(bound, steady(st.pieces, chain_end));
      continue;
    }
    const std::vector<FlatVertex> vx = chords(st, fo, bound);
    // Out of the chain before: a line along the direction it ends in, then
    // a chord back to the chords.
    std::optional<std::pair<Joint, Joint>> leave;
    if (norm_xy(chain_end) > 0) leave = leave_chain(st.pieces.front(), vx, vx.size() - 1, chain_end, bd);
    chain_end = {};
    const size_t from = leave ? leave->second.vertex : 0;
    // Into the next chain, or the tangent move the cut goes on into: a
    // chord to a line along the curve's tangent there.
    std::optional<std::pair<Joint, Joint>> enter;
    if (i + 1 < stretches.size() || !c.ends.to_rest)
      enter = enter_chain(st.pieces.back(), st.pieces.size() - 1, vx, from, bd);
    const size_t to = enter ? enter->first.vertex : vx.size() - 1;
    if (leave) push_line(leave->first.b, leave->first.dev);
    for (size_t k = from; k <= to; ++k)
      if (k > 0) push_line(vx[k].point, k == from && leave ? leave->second.dev : 0);
    if (enter) {
      push_line(enter->first.b, enter->first.dev);
      push_line(enter->second.b, enter->second.dev);
      const Vec3 d = enter->second.b - enter->second.a;
      chain_end = Vec3{d.x, d.y, 0} / norm_xy(d);
    }
  }
  return bound;
}

namespace {

// The planned time (machine.motion) of `moves` cut along `pieces` as the
// program cuts them: after a plunge at the start, or a straight run at the
// feed along the curve's tangent where the cut goes on from a tangent move
// (c.ends), and before a retract, or such a run; the cut's own blocks, its
// ends blended as the controller blends them.
double planned_cut_time(const CutContext& c, std::span<const Bezier> pieces, std::span<const Move> moves) {
  Program p;
  p.units = c.program.units;
  const int entity = static_cast<int>(c.entity.index);
  const Vec3 at = cut_point(c, pieces.front().front());
  const double run = run_length(c.params.feed, *c.machine.motion, c.program.units);
  const Vec3 t0 = end_direction(pieces, false), t1 = end_direction(pieces, true);
  const bool run_in = !c.ends.from_rest && norm(t0) > 0, run_out = !c.ends.to_rest && norm(t1) > 0;
  const Vec3 before = run_in ? at - t0 * run : at;
  const Vec3 above{before.x, before.y, at.z + kPlungeDepth / mm_per_unit(c.program.units)};
  RapidMove over;
  over.to = above;
  p.moves.push_back({over, entity});
  LineMove down;
  down.to = before;
  down.feed = c.params.plunge_feed > 0 ? c.params.plunge_feed : c.params.feed;
  p.moves.push_back({down, entity});
  LineMove in;
  in.to = at;
  in.feed = c.params.feed;
  if (run_in) p.moves.push_back({in, entity});
  const size_t own = p.moves.size();
  p.moves.insert(p.moves.end(), moves.begin(), moves.end());
  const Vec3* end = nullptr;
  for (const Move& mv : moves)
    if (const Motion* m = motion_of(mv)) end = &m->to;
  LineMove out;
  out.to = (end ? *end : at) + t1 * run;
  out.feed = c.params.feed;
  if (run_out) p.moves.push_back({out, entity});
  RapidMove up;
  up.to = run_out ? out.to : end ? *end : at;
  up.to.z = above.z;
  p.moves.push_back({up, entity});
  // The cut's own blocks: after the rapid, the plunge and the run in,
  // before the run out and the retract.
  const MotionPlan plan = plan_motion(program_timeline(p), *c.machine.motion);
  double t = 0;
  for (size_t i = own; i + (run_out ? 2 : 1) < plan.blocks.size(); ++i) t += plan.blocks[i].time_s;
  return t;
}

}  // namespace

std::optional<size_t> keep_faster_cut(CutContext& c, std::span<const Bezier> pieces, size_t first, size_t plain_blocks,
                                      const std::function<std::optional<size_t>()>& make) {
  auto& moves = c.program.moves;
  std::vector<Move> plain = split_off(moves, first);
  const std::optional<size_t> blocks = make();
  if (blocks &&
      take_cruise(planned_cut_time(c, pieces, plain), plain_blocks,
                  planned_cut_time(c, pieces, {moves.begin() + static_cast<std::ptrdiff_t>(first), moves.end()}),
                  *blocks)) {
    note_once(c.program, "G01 where the tool speeds up or slows down, where that is faster: machine " + c.machine.name +
                             " gives arcs less acceleration than lines");
    return blocks;
  }
  moves.resize(first);
  moves.insert(moves.end(), std::make_move_iterator(plain.begin()), std::make_move_iterator(plain.end()));
  return std::nullopt;
}

}  // namespace bezcam::detail
