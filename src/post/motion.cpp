#include "bezcam/post/motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// A G17 arc as start angle, signed sweep and radii at both ends (printed
// ends may sit at slightly different radii; the tool follows a spiral
// between them, as LinuxCNC does).
struct ArcParams {
  double a0, sweep, r0, r1;
};

ArcParams arc_params(const MotionBlock& b) {
  const double r0 = std::hypot(b.from.x - b.center.x, b.from.y - b.center.y);
  const double r1 = std::hypot(b.to.x - b.center.x, b.to.y - b.center.y);
  const double a0 = std::atan2(b.from.y - b.center.y, b.from.x - b.center.x);
  const double a1 = std::atan2(b.to.y - b.center.y, b.to.x - b.center.x);
  const bool ccw = b.kind == BlockKind::arc_ccw;
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 0) sweep += kTwoPi;  // equal ends: a full circle
  while (sweep > kTwoPi) sweep -= kTwoPi;
  return {a0, ccw ? sweep : -sweep, r0, r1};
}

Vec3 arc_point(const MotionBlock& b, const ArcParams& a, double t) {
  if (t <= 0) return b.from;
  if (t >= 1) return b.to;
  const double ang = a.a0 + t * a.sweep, r = a.r0 + t * (a.r1 - a.r0);
  return {b.center.x + r * std::cos(ang), b.center.y + r * std::sin(ang), b.from.z + t * (b.to.z - b.from.z)};
}

bool is_arc(const MotionBlock& b) { return b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw; }

// A block prepared for evaluation at t in [0, 1]: lines by interpolation,
// arcs by angle, Bézier blocks by de Casteljau and NURBS blocks by A4.1
// over their knot domain (the kernel's curves, so the preview and the report
// evaluate exactly what the kernel and the reader define).
class BlockCurve {
 public:
  explicit BlockCurve(const MotionBlock& b) : b_(b) {
    if (is_arc(b)) {
      arc_ = arc_params(b);
    } else if (b.kind == BlockKind::bezier) {
      bez_ = Bezier::make(b.ctrl, {}, 3);
    } else if (b.kind == BlockKind::nurbs) {
      nurbs_ = NurbsCurve::make(b.order - 1, b.ctrl, b.knots, b.weights, 3);
    }
  }
  Vec3 at(double t) const {
    if (t <= 0) return b_.from;
    if (t >= 1) return b_.to;
    if (is_arc(b_)) return arc_point(b_, arc_, t);
    if (bez_) return evaluate(*bez_, t);
    if (nurbs_) return evaluate(*nurbs_, nurbs_->domain_start() + t * (nurbs_->domain_end() - nurbs_->domain_start()));
    return lerp(b_.from, b_.to, t);
  }

 private:
  const MotionBlock& b_;
  ArcParams arc_{};
  std::optional<Bezier> bez_;
  std::optional<NurbsCurve> nurbs_;
};

// Adaptive sampling of a curved block on [t0, t1]: split while the curve's
// points at the quarter parameters stray more than `chord` from the chord.
// The uniform start (16 intervals) keeps a loop from hiding between samples.
void refine(const BlockCurve& c, double t0, const Vec3& p0, double t1, const Vec3& p1, double chord, int depth,
            std::vector<Vec3>& out) {
  const double tm = 0.5 * (t0 + t1);
  const Vec3 pm = c.at(tm);
  const Vec3 pq = c.at(0.5 * (t0 + tm)), pr = c.at(0.5 * (tm + t1));
  const double err =
      std::max({dist_to_segment(pm, p0, p1), dist_to_segment(pq, p0, p1), dist_to_segment(pr, p0, p1)});
  if (err <= chord || depth >= 24) {
    out.push_back(p1);
    return;
  }
  refine(c, t0, p0, tm, pm, chord, depth + 1, out);
  refine(c, tm, pm, t1, p1, chord, depth + 1, out);
}

double box_size(const MotionBlock& b) {
  Box3 box;
  box.add(b.from);
  box.add(b.to);
  for (const auto& c : b.ctrl) box.add(c);
  return std::max(norm(box.hi - box.lo), 1e-12);
}

}  // namespace

std::vector<ToolMotion> program_motion(const Program& p) {
  std::vector<ToolMotion> out;
  Vec3 pos;
  unsigned known = 0;
  for (const Move& mv : p.moves) {
    ToolMotion tm;
    tm.entity = mv.entity;
    MotionBlock& b = tm.block;
    switch (mv.kind) {
      case MoveKind::rapid: b.kind = BlockKind::rapid; break;
      case MoveKind::linear: b.kind = BlockKind::linear; break;
      case MoveKind::arc_cw: b.kind = BlockKind::arc_cw; break;
      case MoveKind::arc_ccw: b.kind = BlockKind::arc_ccw; break;
      case MoveKind::nurbs: b.kind = BlockKind::nurbs; break;
      case MoveKind::bezier: b.kind = BlockKind::bezier; break;
      default: continue;  // no motion
    }
    Vec3 to = pos;
    for (int a = 0; a < 3; ++a)
      if (mv.axes & (1u << a)) to[a] = mv.to[a];
    Vec3 from = pos;
    for (int a = 0; a < 3; ++a)
      if (!(known & (1u << a))) from[a] = to[a];
    b.from = from;
    b.to = to;
    b.feed = b.kind == BlockKind::rapid ? 0 : mv.feed;
    b.center = mv.center;
    b.ctrl = mv.ctrl;
    b.weights = mv.weights;
    b.knots = mv.knots;
    b.order = mv.order;
    if (b.kind == BlockKind::bezier) b.order = static_cast<int>(mv.ctrl.size());
    out.push_back(std::move(tm));
    pos = to;
    known |= mv.axes;
  }
  return out;
}

double block_length(const MotionBlock& b) {
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return dist(b.from, b.to);
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: {
      const ArcParams a = arc_params(b);
      if (a.r0 == a.r1) return std::hypot(a.r0 * a.sweep, b.to.z - b.from.z);  // helix: exact
      break;  // a spiral: by chords below
    }
    default: break;
  }
  const auto pts = sample_block(b, 1e-7 * box_size(b));
  double len = 0;
  for (size_t i = 1; i < pts.size(); ++i) len += dist(pts[i - 1], pts[i]);
  return len;
}

std::vector<Vec3> sample_block(const MotionBlock& b, double chord) {
  if (b.kind == BlockKind::rapid || b.kind == BlockKind::linear) return {b.from, b.to};
  chord = std::max(chord, 1e-12 * box_size(b));
  std::vector<Vec3> out{b.from};
  if (is_arc(b)) {
    // Chord error of an arc step dθ at radius r is r (1 - cos(dθ/2)).
    const ArcParams a = arc_params(b);
    const double r = std::max({a.r0, a.r1, 1e-300});
    const double dtheta = 2 * std::acos(std::clamp(1 - chord / r, -1.0, 1.0));
    const int n = std::clamp(static_cast<int>(std::ceil(std::abs(a.sweep) / std::max(dtheta, 1e-9))), 1, 1 << 20);
    for (int i = 1; i <= n; ++i) out.push_back(arc_point(b, a, double(i) / n));
    return out;
  }
  constexpr int kStart = 16;
  const BlockCurve c(b);
  Vec3 prev = b.from;
  for (int i = 1; i <= kStart; ++i) {
    const double t0 = double(i - 1) / kStart, t1 = double(i) / kStart;
    const Vec3 p1 = c.at(t1);
    refine(c, t0, prev, t1, p1, chord, 0, out);
    prev = p1;
  }
  out.back() = b.to;
  return out;
}

}  // namespace bezcam
