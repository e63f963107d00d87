// Where along a cut the tool changes speed (speed_stretches.hpp).
#include "speed_stretches.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam::detail {

namespace {

// A block runs steadily when its speed stays within this share of the feed.
constexpr double kSteadyShare = 1e-3;
// Parameters this close to a piece's ends are its ends (no sliver pieces).
constexpr double kEndParameter = 1e-6;

// The curvature of a planar curve at t (1/length), from its derivatives.
double curvature(const Bezier& b, double t) {
  const Vec3 d1 = derivative(b, t), d2 = second_derivative(b, t);
  const double speed = norm(d1);
  if (!(speed > 0)) return 0;
  return norm(cross(d1, d2)) / (speed * speed * speed);
}

}  // namespace

Vec3 end_direction(std::span<const Bezier> pieces, bool at_end) {
  if (pieces.empty()) return {};
  const Bezier& b = at_end ? pieces.back() : pieces.front();
  Vec3 d = derivative(b, at_end ? 1.0 : 0.0);
  // (where the end control points coincide, the curve leaves along the
  // next distinct one)
  for (size_t i = 1; std::hypot(d.x, d.y) == 0 && i < b.points.size(); ++i)
    d = at_end ? b.back() - b.points[b.points.size() - 1 - i] : b.points[i] - b.front();
  const double l = std::hypot(d.x, d.y);
  return l > 0 ? Vec3{d.x / l, d.y / l, 0} : Vec3{};
}

double run_length(double feed, const MotionModel& model, Units units) {
  const double vf = feed / 60;
  const double accel = std::min(model.max_acceleration_mm_s2[0], model.max_acceleration_mm_s2[1]) / mm_per_unit(units);
  // Twice the distance to reach the feed at the plane's acceleration.
  return vf * vf / accel;
}

bool arcs_accelerate_slower(const MotionModel& model) { return model.planner == MotionModel::Planner::linuxcnc; }

std::vector<SpeedStretch> speed_stretches(std::span<const Bezier> pieces, double feed, const MotionModel& model,
                                          Units units, double tolerance, int decimals, CutEnds ends) {
  std::vector<SpeedStretch> out;
  if (pieces.empty()) return out;
  // The lines program of the curve, as lines output makes it, planned.
  std::vector<FlatVertex> vx;
  flatten_pieces(pieces, FlattenOptions{tolerance, decimals}, [&](const FlatVertex& v) { vx.push_back(v); });
  if (vx.size() < 2) {
    out.push_back({{pieces.begin(), pieces.end()}, false});
    return out;
  }
  // Where the cut goes on from, or into, a tangent move at the feed, the
  // plan has a straight run along the curve's tangent before or after it.
  const double run = run_length(feed, model, units);
  const Vec3 dir_in = end_direction(pieces, false), dir_out = end_direction(pieces, true);
  const bool run_in = !ends.from_rest && norm(dir_in) > 0, run_out = !ends.to_rest && norm(dir_out) > 0;
  Timeline tl;
  tl.units = units;
  auto line = [&](const Vec3& from, const Vec3& to) {
    MotionBlock mb;
    mb.kind = BlockKind::linear;
    mb.line = static_cast<int>(tl.blocks.size() + 1);
    mb.first_line = mb.line;
    mb.from = from;
    mb.to = to;
    mb.feed = feed;
    tl.blocks.push_back(std::move(mb));
  };
  tl.start = run_in ? vx.front().point - dir_in * run : vx.front().point;
  if (run_in) line(tl.start, vx.front().point);
  for (size_t i = 1; i < vx.size(); ++i) line(vx[i - 1].point, vx[i].point);
  if (run_out) line(vx.back().point, vx.back().point + dir_out * run);
  tl.path_tolerance.assign(tl.blocks.size(), -1);
  const MotionPlan plan = plan_motion(std::move(tl), model);
  const size_t nb = vx.size() - 1;
  const int first_block = run_in ? 1 : 0;
  // Steady blocks: every segment of the block (and the blend after it) at
  // the feed, and the curve no tighter than an arc at the feed allows.
  const double vf = feed / 60;  // units/s
  std::vector<char> steady(nb, 1);
  for (const PlanSegment& sg : plan.segments) {
    const int b = sg.block - first_block;
    if (b >= 0 && static_cast<size_t>(b) < nb && !(std::min(sg.v0, sg.v1) >= vf * (1 - kSteadyShare)))
      steady[static_cast<size_t>(b)] = 0;
  }
  const double k = mm_per_unit(units);
  const double accel = std::min(model.max_acceleration_mm_s2[0], model.max_acceleration_mm_s2[1]) / k;  // units/s^2
  const double kappa_max = std::sqrt(3.0) / 2.0 * accel / (vf * vf);
  auto tight = [&](size_t piece, double t) { return curvature(pieces[piece], t) > kappa_max; };
  for (size_t i = 0; i < nb; ++i) {
    const FlatVertex &a = vx[i], &b = vx[i + 1];
    const double tm = a.piece == b.piece ? 0.5 * (a.t + b.t) : a.t;
    if (steady[i] && (tight(a.piece, a.t) || tight(b.piece, b.t) || tight(a.piece, tm))) steady[i] = 0;
  }
  // A steady run ends where the lines start slowing down at full
  // acceleration; arcs, with less of it, must start earlier: the run
  // gives up the distance the lines need to stop from the feed.
  const double stop = vf * vf / (2 * accel);
  for (size_t i = 0; i < nb;) {
    size_t j = i;
    while (j < nb && steady[j]) ++j;
    if (j == nb && run_out) break;  // it goes on at the feed past the end
    double d = 0;
    for (size_t m = j; m-- > i && d < stop;) {
      d += dist(vx[m].point, vx[m + 1].point);
      steady[m] = 0;
    }
    i = j + 1;
  }
  // Cut the pieces at the vertices where `steady` changes.
  std::vector<std::pair<size_t, double>> cuts;  // (piece, t), in order
  std::vector<char> kinds{steady[0]};
  for (size_t i = 1; i < nb; ++i) {
    if (steady[i] == steady[i - 1]) continue;
    cuts.emplace_back(vx[i].piece, vx[i].t);
    kinds.push_back(steady[i]);
  }
  out.push_back({{}, kinds[0] != 0});
  size_t c = 0;
  for (size_t p = 0; p < pieces.size(); ++p) {
    double t0 = 0;
    Bezier rest = pieces[p];
    for (; c < cuts.size() && cuts[c].first == p; ++c) {
      const double t = cuts[c].second;
      if (t > kEndParameter && t < 1 - kEndParameter && t > t0) {
        // Both parts meet at the same point.
        out.back().pieces.push_back(subcurve(pieces[p], t0, t));
        rest = subcurve(pieces[p], t, 1);
        rest.points.front() = out.back().pieces.back().points.back();
        t0 = t;
      } else if (t >= 1 - kEndParameter) {
        break;  // at the piece's end: cut after it
      }
      out.push_back({{}, kinds[c + 1] != 0});
    }
    out.back().pieces.push_back(std::move(rest));
    if (c < cuts.size() && cuts[c].first == p) {
      out.push_back({{}, kinds[c + 1] != 0});
      ++c;
    }
  }
  // Drop empty stretches and join neighbours of one kind.
  std::vector<SpeedStretch> merged;
  for (auto& st : out) {
    if (st.pieces.empty()) continue;
    if (!merged.empty() && merged.back().steady == st.steady) {
      auto& p = merged.back().pieces;
      p.insert(p.end(), std::make_move_iterator(st.pieces.begin()), std::make_move_iterator(st.pieces.end()));
    } else {
      merged.push_back(std::move(st));
    }
  }
  return merged;
}

}  // namespace bezcam::detail
