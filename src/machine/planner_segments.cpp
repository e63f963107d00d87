// The planner's segments (planner_builder.hpp): every block becomes one or
// more segments with a length, a top speed and a tangential acceleration:
// lines with the axes' limits projected on their direction, arcs with the
// centripetal acceleration taking part of it, curve blocks cut into pieces
// along the true curve (with the table of points that sampling reads), each
// with the speed its tightest curvature allows; then the block rate's cap.
#include <algorithm>
#include <cmath>

#include "planner_builder.hpp"

namespace bezcam::planner_detail {

namespace {

// Points of a curve block at block parameters t in [0, 1], fast: NURBS
// blocks are cut into their Bézier pieces once (one per knot span), so that
// each point costs a Bézier evaluation.
class CurvePoints {
 public:
  explicit CurvePoints(const MotionBlock& b) : b_(b) {
    if (b.kind != BlockKind::nurbs) return;
    try {
      pieces_ = block_to_bezier(b);
    } catch (const std::exception&) {
      pieces_.clear();
    }
    const int p = b.order - 1;
    if (p < 1 || b.knots.size() < b.ctrl.size() + static_cast<size_t>(b.order)) return;
    const double d0 = b.knots[static_cast<size_t>(p)], d1 = b.knots[b.knots.size() - 1 - static_cast<size_t>(p)];
    breaks_.push_back(d0);
    for (size_t i = static_cast<size_t>(p) + 1; i + static_cast<size_t>(p) < b.knots.size(); ++i)
      if (b.knots[i] > breaks_.back() && b.knots[i] < d1) breaks_.push_back(b.knots[i]);
    breaks_.push_back(d1);
    if (breaks_.size() != pieces_.size() + 1) pieces_.clear();  // not one piece per span: evaluate directly
  }
  Vec3 at(double t) const {
    if (pieces_.empty()) return evaluate_block(b_, t);
    if (t <= 0) return b_.from;
    if (t >= 1) return b_.to;
    const double u = breaks_.front() + t * (breaks_.back() - breaks_.front());
    const auto it = std::upper_bound(breaks_.begin(), breaks_.end(), u);
    const size_t j =
        static_cast<size_t>(std::clamp<long>(it - breaks_.begin() - 1, 0, static_cast<long>(pieces_.size()) - 1));
    const double w = breaks_[j + 1] - breaks_[j];
    return evaluate(pieces_[j], w > 0 ? (u - breaks_[j]) / w : 0);
  }

 private:
  const MotionBlock& b_;
  std::vector<Bezier> pieces_;
  std::vector<double> breaks_;
};

}  // namespace

// The most a move along unit `u` may reach when each axis is bounded by `b`.
double along(const Vec3& u, const Vec3& b) {
  double m = kInf;
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) > 1e-12) m = std::min(m, b[i] / std::abs(u[i]));
  return m;
}
// The most any direction of the plane with unit normal `n` may reach: the
// radius of the circle inscribed in the box's section by the plane.
double in_plane(const Vec3& n, const Vec3& b) {
  double m = kInf;
  for (int i = 0; i < 3; ++i) {
    const double proj = std::sqrt(std::max(0.0, 1 - n[i] * n[i]));
    if (proj > 1e-9) m = std::min(m, b[i] / proj);
  }
  return m;
}

Vec3 unit(const Vec3& v) {
  const double n = norm(v);
  return n > 0 ? v * (1 / n) : Vec3{};
}

// Tangent of a block at its start (end = false) or end, by a short chord
// for curves (their derivative is not at hand for every form).
Vec3 block_tangent(const MotionBlock& b, bool end) {
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return unit(b.to - b.from);
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: {
      // In the plane's coordinates (a, b, axis), every plane is G17's.
      // The radius runs linearly from the start's to the end's: a
      // spiral leans the tangent outwards by (end - start radius) / sweep.
      Vec3 r = to_plane(end ? b.to : b.from, b.plane) - to_plane(b.center, b.plane);
      r.z = 0;
      const Arc a = block_arc(b);
      Vec3 t = b.kind == BlockKind::arc_ccw ? Vec3{-r.y, r.x, 0} : Vec3{r.y, -r.x, 0};
      t = unit(t);
      const double L = block_length(b);
      const double sweep = arc_sweep(b);
      const double rr = norm(r);
      const int h = world_axis(b.plane, 2);
      if (L > 0 && rr > 0 && sweep > 0)
        t = unit(t * (rr * sweep) + r * ((a.r_end() - a.r_start()) / rr) + Vec3{0, 0, b.to[h] - b.from[h]});
      return from_plane(t, b.plane);
    }
    default: {
      const double h = 1e-6;
      return end ? unit(evaluate_block(b, 1) - evaluate_block(b, 1 - h))
                 : unit(evaluate_block(b, h) - evaluate_block(b, 0));
    }
  }
}

// Radius of the circle through three points (infinity when collinear).
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double A = dist(b, c), B = dist(a, c), C = dist(a, b);
  const double area2 = norm(cross(b - a, c - a));  // twice the area
  if (area2 <= 1e-15 * std::max({A * B, B * C, A * C, 1e-300})) return kInf;
  return A * B * C / (2 * area2);
}

// How many pieces the planner cuts a curve block into (Builder::add_block).
int curve_pieces(const MotionBlock& b) {
  return std::clamp(static_cast<int>(4 * std::max<size_t>(b.ctrl.size(), 2)), 8, 256);
}

// The segment's figures for the passes, the share its kinks take off its
// acceleration applied (to the segment too: a full plan keeps it).
void Builder::add_lean(PlanSegment& sg) {
  sg.accel *= 1 - sg.kink_reduce;
  Lean l;
  l.length = sg.length;
  l.vmax = sg.vmax;
  l.accel = sg.accel;
  l.block = sg.block;
  l.limit = static_cast<std::uint8_t>(sg.limit);
  l.rapid = sg.rapid;
  l.blend = sg.blend;
  lean.push_back(l);
}

double Builder::path_tolerance(size_t block) const {
  double t = tl.path_tolerance.size() > block ? tl.path_tolerance[block] : -1;
  if (t < 0) t = model.blend_tolerance_mm / scale;
  return t;
}

// The feed a block asks, units/s, and whether the axes cap it.
void Builder::block_speed(const MotionBlock& b, const Vec3& dir, double& v, SpeedLimit& why, bool& clamped) const {
  const double axes = along(dir, lim.vmax);
  if (b.kind == BlockKind::rapid) {
    v = axes;
    why = SpeedLimit::programmed;
    return;
  }
  v = b.feed / 60;
  why = SpeedLimit::programmed;
  if (v > axes * (1 + 1e-9)) {
    v = axes;
    why = SpeedLimit::axes;
    clamped = true;
  }
}

PlanSegment Builder::line_segment(int bi, const Vec3& a, const Vec3& b, bool rapid) {
  PlanSegment s;
  s.block = bi;
  s.rapid = rapid;
  PlanSegment::Piece p;
  p.shape = PlanSegment::Shape::line;
  p.a = a;
  p.b = b;
  p.length = dist(a, b);
  s.pieces.push_back(p);
  s.length = p.length;
  return s;
}

// Speed and tangential acceleration of a curved move of radius R asking
// speed v with acceleration a in all: the centripetal part v^2/R takes at
// most sqrt(3)/2 of a (the speed drops until it fits), the tangential
// part what is left of a, at least half of it. LinuxCNC sizes the
// tangential part for the machine's top speed in the plane `vm`, not for
// the feed asked (its arc's own speed limit): half of a where that speed
// would need more than sqrt(3)/2 of a across, else what it leaves.
void Builder::curved_limits(PlanSegment& s, double v, SpeedLimit why, double R, double a, double vm) const {
  const double an_max = kNormalShare * a;
  double tan_share = 1;
  if (linuxcnc()) {
    tan_share = linuxcnc_tangential_share(R, a, vm);
    if (std::isfinite(R) && R > 0 && v * v / R > an_max) {
      v = std::sqrt(an_max * R);
      why = SpeedLimit::curvature;
    }
  } else if (std::isfinite(R) && R > 0) {
    if (v * v / R > an_max) {
      v = std::sqrt(an_max * R);
      why = SpeedLimit::curvature;
      tan_share = kTangentialShare;
    } else {
      const double q = v * v / (R * a);
      tan_share = std::sqrt(std::max(0.0, 1 - q * q));
    }
  }
  s.vmax = v;
  s.limit = why;
  s.accel = tan_share * a;
  s.overall_accel = a;
}

double Builder::linuxcnc_tangential_share(double R, double a, double vm) {
  if (!(std::isfinite(R) && R > 0) || !(a > 0)) return 1;
  const double an = vm * vm / R;
  if (an > kNormalShare * a) return kTangentialShare;
  return std::sqrt(std::max(0.0, 1 - (an / a) * (an / a)));
}

// Segments of one block, appended to `out`.
void Builder::add_block(int bi, std::vector<PlanSegment>& out) {
  const MotionBlock& b = block(static_cast<size_t>(bi));
  PlannedBlock pb;
  pb.line = b.line;
  pb.first_line = b.first_line ? b.first_line : b.line;
  pb.kind = b.kind;
  // Lines and arcs exactly; curves by the planner's own samples below.
  const bool curved_block = b.kind == BlockKind::nurbs || b.kind == BlockKind::bezier;
  pb.length = curved_block ? 0 : block_length(b);
  const bool rapid = b.kind == BlockKind::rapid;
  const size_t first = out.size();
  if (b.kind == BlockKind::rapid || b.kind == BlockKind::linear) {
    const Vec3 u = unit(b.to - b.from);
    double v;
    SpeedLimit why;
    block_speed(b, u, v, why, pb.clamped);
    PlanSegment s = line_segment(bi, b.from, b.to, rapid);
    s.vmax = v;
    s.limit = why;
    s.accel = along(u, lim.amax);
    if (!std::isfinite(s.accel)) s.accel = lim.amax.x;
    s.overall_accel = s.accel;
    out.push_back(std::move(s));
    pb.programmed_feed = rapid ? v * 60 : b.feed;
  } else if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
    add_arc_segment(bi, pb, out);
  } else {
    add_curve_segments(bi, pb, out);
  }
  // The block rate: the block takes at least 1 / block_rate.
  if (model.block_rate_hz > 0 && pb.length > 0) {
    const double cap = pb.length * model.block_rate_hz;
    for (size_t i = first; i < out.size(); ++i)
      if (cap < out[i].vmax) {
        out[i].vmax = cap;
        out[i].limit = SpeedLimit::block_rate;
      }
  }
  plan.blocks.push_back(pb);
}

// An arc block: one segment, its speed and acceleration shared with the
// centripetal part.
void Builder::add_arc_segment(int bi, PlannedBlock& pb, std::vector<PlanSegment>& out) {
  const MotionBlock& b = block(static_cast<size_t>(bi));
  const Vec3 n = from_plane({0, 0, 1}, b.plane);  // the plane's axis
  const double vplane = in_plane(n, lim.vmax), aplane = arc_accel(in_plane(n, lim.amax));
  double v = b.feed / 60;
  SpeedLimit why = SpeedLimit::programmed;
  if (v > vplane) {
    v = vplane;
    why = SpeedLimit::axes;
    pb.clamped = true;
  }
  Vec3 r0 = to_plane(b.from - b.center, b.plane);
  r0.z = 0;
  const double R = norm(r0);
  PlanSegment s;
  s.block = bi;
  PlanSegment::Piece p;
  p.shape = PlanSegment::Shape::block;
  p.block = bi;
  p.length = pb.length;
  p.s = {0, pb.length};
  p.t = {0, 1};
  s.pieces.push_back(std::move(p));
  s.length = pb.length;
  curved_limits(s, v, why, R, aplane, vplane);
  s.curved = true;
  Vec3 c = to_plane(b.center, b.plane);
  c.z = to_plane(b.to, b.plane).z;
  s.center = from_plane(c, b.plane);
  s.radius = R;
  s.angle = arc_sweep(b);
  out.push_back(std::move(s));
  pb.programmed_feed = b.feed;
}

// A curve block on the true curve: pieces of the parameter range, each with
// the speed its tightest curvature allows (and, in a full plan, the table
// of points that sampling reads).
void Builder::add_curve_segments(int bi, PlannedBlock& pb, std::vector<PlanSegment>& out) {
  const MotionBlock& b = block(static_cast<size_t>(bi));
  const int pieces = curve_pieces(b);
  constexpr int kSub = 12;
  const Vec3 n{0, 0, 1};
  bool planar = true;
  for (const Vec3& c : b.ctrl) planar = planar && std::abs(c.z - b.from.z) < 1e-12;
  const double vax = planar ? in_plane(n, lim.vmax) : std::min({lim.vmax.x, lim.vmax.y, lim.vmax.z});
  const double aax = arc_accel(planar ? in_plane(n, lim.amax) : std::min({lim.amax.x, lim.amax.y, lim.amax.z}));
  double vfeed = b.feed / 60;
  SpeedLimit base = SpeedLimit::programmed;
  if (vfeed > vax) {
    vfeed = vax;
    base = SpeedLimit::axes;
    pb.clamped = true;
  }
  std::vector<Vec3> pts(static_cast<size_t>(pieces * kSub + 1));
  const CurvePoints curve(b);
  for (int i = 0; i <= pieces * kSub; ++i)
    pts[static_cast<size_t>(i)] = curve.at(static_cast<double>(i) / (pieces * kSub));
  for (int k = 0; k < pieces; ++k) {
    PlanSegment s;
    s.block = bi;
    PlanSegment::Piece p;
    p.shape = PlanSegment::Shape::block;
    p.block = bi;
    if (!summary) {
      p.s.push_back(0);
      p.t.push_back(static_cast<double>(k * kSub) / (pieces * kSub));
      p.pts.push_back(pts[static_cast<size_t>(k * kSub)]);
    }
    double len = 0, rmin = kInf;
    for (int i = 1; i <= kSub; ++i) {
      const size_t at = static_cast<size_t>(k * kSub + i);
      len += dist(pts[at - 1], pts[at]);
      if (!summary) {
        p.s.push_back(len);
        p.t.push_back(static_cast<double>(at) / (pieces * kSub));
        p.pts.push_back(pts[at]);
      }
      if (at + 1 < pts.size()) rmin = std::min(rmin, circumradius(pts[at - 1], pts[at], pts[at + 1]));
    }
    p.length = len;
    s.length = len;
    s.pieces.push_back(std::move(p));
    if (linuxcnc()) {
      // LinuxCNC's interpreter follows the curve by arcs: each takes the
      // mean curvature of its stretch (the turn over the length), not
      // the tightest point's.
      const size_t a0 = static_cast<size_t>(k * kSub), a1 = static_cast<size_t>((k + 1) * kSub);
      const Vec3 t0 = unit(pts[a0 + 1] - pts[a0]), t1 = unit(pts[a1] - pts[a1 - 1]);
      const double turn = std::acos(std::clamp(dot(t0, t1), -1.0, 1.0)) * kSub / (kSub - 1);
      rmin = turn > 1e-12 ? len / turn : kInf;
    }
    const double v = vfeed;
    s.limit = base;
    curved_limits(s, v, s.limit, rmin, aax, in_plane({0, 0, 1}, lim.vmax));
    s.curved = true;
    s.radius = rmin;
    s.angle = std::isfinite(rmin) && rmin > 0 ? len / rmin : 0;
    {
      // The centre of the circle through the piece's last three points.
      const size_t at = static_cast<size_t>((k + 1) * kSub);
      const Vec3 a = pts[at - 2], m = pts[at - 1], c = pts[at];
      const Vec3 ab = m - a, ac = c - a, nrm = cross(ab, ac);
      const double d = 2 * dot(nrm, nrm);
      if (d > 0) s.center = a + (cross(nrm, ab) * dot(ac, ac) + cross(ac, nrm) * dot(ab, ab)) * (1 / d);
    }
    pb.length += len;
    if (len > 0) out.push_back(std::move(s));
  }
  pb.programmed_feed = b.feed;
}

void Builder::cap_segment_time(PlanSegment& s) const {
  if (model.min_segment_periods <= 0 || s.length <= 0) return;
  const double cap = s.length / (model.min_segment_periods * period);
  if (cap < s.vmax) {
    s.vmax = cap;
    s.limit = SpeedLimit::segment_time;
  }
}

}  // namespace bezcam::planner_detail
