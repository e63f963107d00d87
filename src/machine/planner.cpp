// The trajectory planner (machine/planner.hpp, docs/motion.md).
//
// 1. Segments. Every block becomes one or more segments with a length, a
//    top speed and a tangential acceleration: lines with the axes' limits
//    projected on their direction; arcs with the centripetal acceleration
//    v^2/R taking part of the acceleration (at most sqrt(3)/2 of it, the
//    rest tangential); curve blocks cut into pieces along the true curve,
//    each with the speed its tightest curvature allows.
// 2. Corners. Between two lines that meet at an angle, a circular blend arc
//    that stays within the path tolerance of the corner, trims at most
//    half of each line and runs at the speed its radius allows; what is
//    left of a line between two blends, if shorter than a few periods at
//    the blend's speed, is absorbed into the blend. Corners that touch an
//    arc or a curve keep their shape and are taken at the speed of an
//    equivalent blend. Exact stop where the tolerance is 0, at pauses,
//    and where rapid and feed meet.
// 3. Caps. A segment of length L runs at most at L / (min_segment_periods x
//    period) and a block at most at L_block x block_rate: the controller
//    needs that long to take each one (data starvation).
// 4. Speeds. A windowed backward pass (the controller sees only
//    lookahead_blocks ahead and must be able to stop at the window's end),
//    a backward pass and a forward pass give every junction's speed; each
//    segment is then a trapezoid (an S-curve's durations when a jerk is
//    given), which gives its time.
#include "bezcam/machine/planner.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace bezcam {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// Share of the acceleration a curved move gives to its normal part (the
// tangential part keeps 1/2 of it): sqrt(1 - 0.5^2).
constexpr double kNormalShare = 0.8660254037844386;
constexpr double kTangentialShare = 0.5;
// A blend may take at most this fraction of each neighbouring line.
constexpr double kBlendFraction = 0.5;
// The path tolerance of a blend is at most this fraction of a line.
constexpr double kToleranceFraction = 0.25;
// A remnant of a line between two blends shorter than this many periods at
// the blend's speed is absorbed into the blend.
constexpr double kGapPeriods = 4;
// Directions closer than this (radians) meet tangentially: no corner.
constexpr double kTangentAngle = 1e-3;
// Share of the acceleration a near-tangent kink may use within one period.
constexpr double kKinkShare = 0.25;
// LinuxCNC: a kink whose acceleration spike is below this share of the
// limits is taken as tangent (at the cost of as much acceleration).
constexpr double kKinkRatio = 0.1;
// Blends at arcs are refused below this half-angle between the secants.
constexpr double kMinBlendTheta = kPi / 12;

struct Limits {
  Vec3 vmax;   // units/s per axis
  Vec3 amax;   // units/s^2
  Vec3 jmax;   // units/s^3 (0: none)
  bool jerk = false;
};

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
      const Vec3 p = to_plane(end ? b.to : b.from, b.plane);
      Vec3 r = p - to_plane(b.center, b.plane);
      r.z = 0;
      Vec3 t = b.kind == BlockKind::arc_ccw ? Vec3{-r.y, r.x, 0} : Vec3{r.y, -r.x, 0};
      t = unit(t);
      const double L = block_length(b);
      const double sweep = arc_sweep(b);
      const double rr = norm(r);
      const int h = world_axis(b.plane, 2);
      if (L > 0 && rr > 0) t = unit(t * (rr * sweep) + Vec3{0, 0, b.to[h] - b.from[h]});
      return from_plane(t, b.plane);
    }
    default: {
      const double h = 1e-6;
      return end ? unit(evaluate_block(b, 1) - evaluate_block(b, 1 - h)) : unit(evaluate_block(b, h) - evaluate_block(b, 0));
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

// A speed change from v0 to v1 (either way) at acceleration a, jerk j
// (0: none): its duration (a symmetric S-curve with jerk; its distance is
// then the mean speed times the duration, as for a linear ramp).
double ramp_time(double v0, double v1, double a, double j) {
  const double dv = std::abs(v1 - v0);
  if (dv <= 0) return 0;
  if (j <= 0) return dv / a;
  if (dv >= a * a / j) return dv / a + a / j;
  return 2 * std::sqrt(dv / j);
}
double ramp_distance(double v0, double v1, double a, double j) { return 0.5 * (v0 + v1) * ramp_time(v0, v1, a, j); }

// The same with the jerk's build-up at the ramp's start (`in`) and its
// wind-down at the end (`out`) each counted only where the acceleration
// really starts or ends: a ramp that continues over several segments
// builds up its acceleration once.
double ramp_time(double v0, double v1, double a, double j, bool in, bool out) {
  if (j <= 0 || (in && out)) return ramp_time(v0, v1, a, j);
  const double dv = std::abs(v1 - v0);
  if (dv <= 0) return 0;
  if (!in && !out) return dv / a;
  // One end only: half of the jerk phases, limited as for a short ramp.
  return std::max(dv / a + 0.5 * a / j * std::min(1.0, dv * j / (a * a)), 0.5 * ramp_time(v0, v1, a, j));
}

// The highest speed reachable from v0 within distance L (the inverse of
// ramp_distance in v1, by bisection with jerk, closed form without).
double reachable(double v0, double L, double a, double j, double cap) {
  if (j <= 0) return std::min(cap, std::sqrt(v0 * v0 + 2 * a * L));
  if (ramp_distance(v0, cap, a, j) <= L) return cap;
  double lo = v0, hi = cap;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ramp_distance(v0, mid, a, j) <= L ? lo : hi) = mid;
  }
  return lo;
}

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
    const size_t j = static_cast<size_t>(std::clamp<long>(it - breaks_.begin() - 1, 0, static_cast<long>(pieces_.size()) - 1));
    const double w = breaks_[j + 1] - breaks_[j];
    return evaluate(pieces_[j], w > 0 ? (u - breaks_[j]) / w : 0);
  }

 private:
  const MotionBlock& b_;
  std::vector<Bezier> pieces_;
  std::vector<double> breaks_;
};

// How many pieces the planner cuts a curve block into (Builder::add_block).
int curve_pieces(const MotionBlock& b) {
  return std::clamp(static_cast<int>(4 * std::max<size_t>(b.ctrl.size(), 2)), 8, 256);
}

// What the speed passes and the totals read and write of a segment, packed:
// they run over every segment of a long program, and a summary keeps only
// this of a segment once no blend can reach it (PlanSegment holds its
// geometry too, several times the size).
struct Lean {
  double length = 0, vmax = 0, accel = 0;  // accel: tangential, the kinks' share taken off
  int block = -1;
  SpeedLimit limit = SpeedLimit::programmed;
  bool rapid = false;
  double vpeak = 0, t_acc = 0, t_cruise = 0, t_dec = 0;  // entry and exit speeds: speeds()'s v
  double time() const { return t_acc + t_cruise + t_dec; }
};

struct Builder {
  Builder(const Timeline& t, const MotionModel& m, bool summary_only)
      : tl(t), model(m), summary(summary_only), period(m.period_s), scale(mm_per_unit(t.units)) {}
  const Timeline& tl;
  const MotionModel& model;
  bool summary;  // PlanDetail::summary: no curve tables (only sampling reads them)
  Limits lim{};
  double period;
  double scale;  // mm per program unit
  std::vector<PlanSegment> segs;
  std::vector<double> junction;   // junction[i]: largest speed entering segs[i] (0: stop)
  std::vector<PlanSegment> mine_;  // build(): the block's segments before they join segs
  // Every segment's speed figures, in order (speeds(), totals()). A summary
  // moves a segment here once no blend can reach it and drops it from
  // `segs`, which then holds only the last few; a full plan keeps `segs`
  // whole and fills this from it.
  std::vector<Lean> lean;
  size_t most_segments = 0;  // at most this many segments (plan_timed())

  // The segment's figures for the passes, the share its kinks take off its
  // acceleration applied (to the segment too: a full plan keeps it).
  void add_lean(PlanSegment& sg) {
    sg.accel *= 1 - sg.kink_reduce;
    Lean l;
    l.length = sg.length;
    l.vmax = sg.vmax;
    l.accel = sg.accel;
    l.block = sg.block;
    l.limit = sg.limit;
    l.rapid = sg.rapid;
    lean.push_back(l);
  }
  MotionPlan plan;

  double path_tolerance(size_t block) const {
    double t = tl.path_tolerance.size() > block ? tl.path_tolerance[block] : -1;
    if (t < 0) t = model.blend_tolerance_mm / scale;
    return t;
  }

  // The feed a block asks, units/s, and whether the axes cap it.
  void block_speed(const MotionBlock& b, const Vec3& dir, double& v, SpeedLimit& why, bool& clamped) const {
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

  PlanSegment line_segment(int bi, const Vec3& a, const Vec3& b, bool rapid) {
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

  bool linuxcnc() const { return model.planner == MotionModel::Planner::linuxcnc; }

  // The acceleration a curved move may use in all: the plane's.
  double arc_accel(double a_plane) const { return a_plane; }

  // Speed and tangential acceleration of a curved move of radius R asking
  // speed v with acceleration a in all: the centripetal part v^2/R takes at
  // most sqrt(3)/2 of a (the speed drops until it fits), the tangential
  // part what is left of a, at least half of it.
  void curved_limits(PlanSegment& s, double v, SpeedLimit why, double R, double a) const {
    const double an_max = kNormalShare * a;
    double tan_share = 1;
    if (linuxcnc()) {
      // LinuxCNC keeps half of the acceleration for the tangent on every
      // arc (and on the arcs its interpreter makes of curves).
      tan_share = kTangentialShare;
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

  // Segments of one block, appended to `out`.
  void add_block(int bi, std::vector<PlanSegment>& out) {
    const MotionBlock& b = tl.blocks[static_cast<size_t>(bi)];
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
      curved_limits(s, v, why, R, aplane);
      s.curved = true;
      Vec3 c = to_plane(b.center, b.plane);
      c.z = to_plane(b.to, b.plane).z;
      s.center = from_plane(c, b.plane);
      s.radius = R;
      s.angle = arc_sweep(b);
      out.push_back(std::move(s));
      pb.programmed_feed = b.feed;
    } else {
      // A curve block on the true curve: pieces of the parameter range,
      // each with the speed its tightest curvature allows.
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
      for (int i = 0; i <= pieces * kSub; ++i) pts[static_cast<size_t>(i)] = curve.at(static_cast<double>(i) / (pieces * kSub));
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
        curved_limits(s, v, s.limit, rmin, aax);
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

  // Blends the corner between the last segment of segs (a line) and `next`
  // (a line), both in the same mode. Returns the speed limit at the join
  // when the corner is not blended by an arc (then the lines keep their
  // shape), or -1 when a blend arc was inserted.
  double blend_lines(PlanSegment& next, double tol, double nominal_prev, double nominal_next, int line) {
    PlanSegment& prev = segs.back();
    const Vec3 a = prev.pieces.back().a, c = prev.pieces.back().b, e = next.pieces.front().b;
    const Vec3 u1 = unit(c - a), u2 = unit(e - c);
    const double cosang = std::clamp(dot(u1, u2), -1.0, 1.0);
    const double phi = std::acos(cosang);  // turning angle
    if (phi > kPi - 1e-6) return 0;  // reversal: stop
    const double theta = 0.5 * (kPi - phi);
    const Vec3 normal = unit(cross(u1, u2));
    const double aplane = in_plane(normal, lim.amax), vplane = in_plane(normal, lim.vmax);
    const double an = kNormalShare * aplane;
    const double T = std::min({tol, kToleranceFraction * nominal_prev, kToleranceFraction * nominal_next});
    if (!(T > 0)) return 0;
    const double d_tol = std::cos(theta) * T / (1 - std::sin(theta));
    const double L1 = std::min(prev.pieces.back().length, kBlendFraction * nominal_prev);
    const double L2 = kBlendFraction * next.length;
    const double d_geom = std::min({L1, L2, d_tol});
    const double R_geom = std::tan(theta) * d_geom;
    const double v_goal = std::min(std::max(prev.vmax, next.vmax), vplane);
    const double v_plan = std::min(std::sqrt(an * R_geom), v_goal);
    // How much of the lines the blend takes: no more than a parabolic
    // blend at half the acceleration would need to reach v_plan.
    const double a_par = 0.5 * aplane;
    const double v_tri = std::sqrt(2 * a_par * d_geom);
    const double s_blend = std::min(v_tri, v_plan) / a_par * v_plan;
    const double R_blend = std::min(s_blend / phi, R_geom);
    const double R = std::max(v_plan * v_plan / an, R_blend);
    const double d = std::min(R / std::tan(theta), d_geom);
    if (R <= 1e-12 || R * phi < 1e-9) return 0;
    // Trim the lines.
    PlanSegment::Piece& pl = prev.pieces.back();
    pl.b = c - u1 * d;
    pl.length = std::max(0.0, pl.length - d);
    prev.length = 0;
    for (const auto& q : prev.pieces) prev.length += q.length;
    cap_segment_time(prev);
    PlanSegment::Piece& nl = next.pieces.front();
    nl.a = c + u2 * d;
    nl.length = std::max(0.0, nl.length - d);
    next.length = nl.length;
    // The blend arc.
    PlanSegment blend;
    blend.block = prev.block;
    blend.rapid = prev.rapid;
    PlanSegment::Piece arc;
    arc.shape = PlanSegment::Shape::arc;
    const Vec3 inward = unit(u2 - u1);
    arc.center = pl.b + unit(inward - u1 * dot(inward, u1)) * R;
    arc.u = unit(pl.b - arc.center);
    arc.w = u1;
    arc.radius = R;
    arc.angle = phi;
    arc.length = R * phi;
    blend.pieces.push_back(arc);
    blend.length = arc.length;
    blend.vmax = v_plan;
    blend.limit = v_plan < v_goal ? SpeedLimit::corner : (prev.vmax >= next.vmax ? prev.limit : next.limit);
    blend.accel = kTangentialShare * aplane;
    if (model.min_segment_periods > 0) {
      const double cap = blend.length / (model.min_segment_periods * period);
      if (cap < blend.vmax) {
        blend.vmax = cap;
        blend.limit = SpeedLimit::segment_time;
      }
    }
    const double dev = R / std::sin(theta) - R;
    if (dev > plan.max_path_deviation) {
      plan.max_path_deviation = dev;
      plan.max_deviation_line = line;
    }
    // A remnant of the previous line too short to run on its own is
    // absorbed into the blend (the blend then starts where the remnant did).
    if (prev.pieces.size() == 1 && prev.length < kGapPeriods * period * blend.vmax && segs.size() >= 1) {
      PlanSegment::Piece remnant = prev.pieces.back();
      blend.pieces.insert(blend.pieces.begin(), remnant);
      blend.length += remnant.length;
      blend.block = prev.block;
      segs.pop_back();
      junction.pop_back();  // the blend takes the remnant's entry
      segs.push_back(std::move(blend));
      junction.push_back(junction_pending_);
    } else {
      segs.push_back(std::move(blend));
      junction.push_back(std::min(segs[segs.size() - 2].vmax, segs.back().vmax));
    }
    return -1;
  }
  double junction_pending_ = 0;

  // Whether the two moves meet tangentially enough to pass without a
  // blend, and at what speed. Generic: directions within kTangentAngle, at
  // the speed a one-period kink allows. LinuxCNC: the acceleration spike
  // of turning by the kink within one period, as a share of the axes'
  // limits (twice as much at an arc), below kKinkRatio; the moves then
  // lose that share of their acceleration. `kink_scale` receives the share.
  bool tangent(PlanSegment& prev, PlanSegment& next, const Vec3& u1, const Vec3& u2, double phi, double& vj,
               double& kink_scale) const {
    const double vmax = std::min(prev.vmax, next.vmax);
    if (!linuxcnc()) {
      if (phi >= kTangentAngle) return false;
      const double aa = std::min(prev.accel, next.accel);
      const double kink = phi > 0 ? kNormalShare * kKinkShare * aa * period / phi : kInf;
      vj = std::min(vmax, kink);
      return true;
    }
    const double a_inst = vmax / period + next.overall_accel;
    const Vec3 diff = (u2 - u1) * a_inst;
    double spike = 0;
    for (int i = 0; i < 3; ++i) spike = std::max(spike, std::abs(diff[i]) / lim.amax[i]);
    if (prev.curved || next.curved) spike /= kTangentialShare;
    kink_scale = spike;
    if (spike >= kKinkRatio) return false;
    vj = vmax;
    prev.kink_reduce = std::max(prev.kink_reduce, spike);
    next.kink_reduce = std::max(next.kink_reduce, spike);
    return true;
  }

  // A corner where an arc or a curve meets another move: the speed of a
  // blend arc within the tolerance between the secants of the arcs' ends
  // (each arc lends at most a part of its sweep: 2/3 of the one before,
  // 1/3 of the one after, and half of it for a line), the shape kept.
  // -1 when no blend fits.
  double curved_corner(const PlanSegment& prev, const PlanSegment& next, const MotionBlock& pbk, const MotionBlock&,
                       const Vec3& u1, const Vec3& u2, double phi, double tol) {
    const Vec3 P = pbk.to;
    const double theta_tan = 0.5 * (kPi - phi);
    double theta = theta_tan, L1, L2;
    if (prev.curved && std::isfinite(prev.radius)) {
      const bool convex = dot(P - prev.center, u2) < 0;
      const double phi_max = std::min(prev.angle * 2 / 3, convex ? theta_tan : kPi / 2);
      if (convex) theta = std::min(theta, theta_tan - phi_max / 4);
      L1 = convex ? std::sin(phi_max / 4) * prev.radius : phi_max * prev.radius;
    } else {
      L1 = std::min(prev.length, kBlendFraction * plan.blocks[static_cast<size_t>(prev.block)].length);
    }
    if (next.curved && std::isfinite(next.radius)) {
      const bool convex = dot(P - next.center, u1) >= 0;
      const double phi_max = std::min(next.angle / 3, convex ? theta_tan : kPi / 2);
      if (convex) theta = std::min(theta, theta_tan - phi_max / 4);
      L2 = convex ? std::sin(phi_max / 4) * next.radius : phi_max * next.radius;
    } else {
      L2 = kBlendFraction * next.length;
    }
    if (theta < kMinBlendTheta) return -1;
    const double turn = kPi - 2 * theta;
    if (turn <= 0) return std::min(prev.vmax, next.vmax);
    Vec3 normal = cross(u1, u2);
    normal = norm(normal) > 1e-9 ? unit(normal) : Vec3{0, 0, 1};
    const double aplane = in_plane(normal, lim.amax), vplane = in_plane(normal, lim.vmax);
    const double an = kNormalShare * aplane;
    const double T = std::min({tol, kToleranceFraction * plan.blocks[static_cast<size_t>(prev.block)].length,
                               kToleranceFraction * plan.blocks[static_cast<size_t>(next.block)].length});
    if (!(T > 0)) return -1;
    const double d_tol = std::cos(theta) * T / (1 - std::sin(theta));
    const double d_geom = std::min({L1, L2, d_tol});
    const double R_geom = std::tan(theta) * d_geom;
    const double v_goal = std::min(std::max(prev.vmax, next.vmax), vplane);
    const double v_plan = std::min(std::sqrt(an * R_geom), v_goal);
    // The blend's own length caps it like any segment.
    const double a_par = 0.5 * aplane;
    const double s_blend = std::min(std::sqrt(2 * a_par * d_geom), v_plan) / a_par * v_plan;
    const double R = std::max(v_plan * v_plan / an, std::min(s_blend / turn, R_geom));
    double v = v_plan;
    if (model.min_segment_periods > 0) v = std::min(v, R * turn / (model.min_segment_periods * period));
    const double dev = R / std::sin(theta) - R;
    if (dev > plan.max_path_deviation) {
      plan.max_path_deviation = dev;
      plan.max_deviation_line = pbk.line;
    }
    return std::min({v, prev.vmax, next.vmax});
  }

  void cap_segment_time(PlanSegment& s) const {
    if (model.min_segment_periods <= 0 || s.length <= 0) return;
    const double cap = s.length / (model.min_segment_periods * period);
    if (cap < s.vmax) {
      s.vmax = cap;
      s.limit = SpeedLimit::segment_time;
    }
  }

  void build() {
    size_t pause = 0;
    bool stop_before = true;  // the machine is at rest
    // Reserved once (address space only until used): no reallocation
    // holding the segments twice while a long program grows.
    const size_t most = most_segments + 16;
    if (summary) lean.reserve(most);
    else segs.reserve(most);
    junction.reserve(most + 1);
    plan.blocks.reserve(tl.blocks.size());
    for (size_t bi = 0; bi < tl.blocks.size(); ++bi) {
      bool pause_here = false;
      while (pause < tl.pauses.size() && tl.pauses[pause].before_block <= bi) {
        pause_here = true;
        ++pause;
      }
      // Build this block's segments aside (one vector for every block),
      // then join them.
      std::vector<PlanSegment>& mine = mine_;
      mine.clear();
      add_block(static_cast<int>(bi), mine);
      const MotionBlock& b = tl.blocks[bi];
      // A block that does not move (its end is where it starts) takes no
      // time and makes no corner: controllers drop it.
      if (plan.blocks.back().length <= 1e-9) mine.clear();
      for (size_t k = 0; k < mine.size(); ++k) {
        PlanSegment s = std::move(mine[k]);
        if (segs.empty() || (k == 0 && (stop_before || pause_here))) {
          // The first move may start moving (a window of a longer program
          // planned at machine pace: Timeline::start_speed); after a pause
          // the machine is at rest.
          const bool first = segs.empty() && !pause_here;
          if (!segs.empty()) exact_stop_end(Stop::pause);
          cap_segment_time(s);
          junction.push_back(first ? tl.start_speed : 0);
          segs.push_back(std::move(s));
          continue;
        }
        if (k > 0) {  // inside a block: tangent pieces
          cap_segment_time(s);
          junction.push_back(std::min(segs.back().vmax, s.vmax));
          segs.push_back(std::move(s));
          continue;
        }
        // A corner between blocks.
        PlanSegment& prev = segs.back();
        const MotionBlock& pbk = tl.blocks[static_cast<size_t>(prev.block)];
        const double tol = std::min(path_tolerance(bi), path_tolerance(static_cast<size_t>(prev.block)));
        double vj = 0;
        const Vec3 u1 = block_tangent(pbk, true), u2 = block_tangent(b, false);
        const double phi = std::acos(std::clamp(dot(u1, u2), -1.0, 1.0));
        const bool lines = prev.pieces.back().shape == PlanSegment::Shape::line &&
                           s.pieces.front().shape == PlanSegment::Shape::line && prev.pieces.size() == 1 &&
                           s.pieces.size() == 1;
        double kink_scale = -1;  // LinuxCNC: the kink's share of the acceleration
        if (tol <= 0 || phi > kPi - 2 * kPi / 180 || (prev.rapid != s.rapid && !linuxcnc())) {
          vj = 0;  // exact stop: asked, a reversal, or a generic controller between rapid and feed
        } else if (tangent(prev, s, u1, u2, phi, vj, kink_scale)) {
          // vj set
        } else if (lines) {
          junction_pending_ = junction.back();
          const double nominal_prev = dist(pbk.from, pbk.to), nominal_next = dist(b.from, b.to);
          const double r = blend_lines(s, tol, nominal_prev, nominal_next, pbk.line);
          if (r < 0) {
            cap_segment_time(s);
            junction.push_back(std::min(segs.back().vmax, s.vmax));
            segs.push_back(std::move(s));
            continue;
          }
          vj = r;
        } else {
          vj = curved_corner(prev, s, pbk, b, u1, u2, phi, tol);
          if (vj < 0) {
            // No blend fits (too sharp for the arcs' share): LinuxCNC takes
            // the corner as a kink at a reduced speed; others stop.
            vj = 0;
            if (linuxcnc() && kink_scale > 0) {
              vj = std::min(prev.vmax, s.vmax) * kKinkRatio / kink_scale;
              prev.kink_reduce = std::max(prev.kink_reduce, kKinkRatio);
              s.kink_reduce = std::max(s.kink_reduce, kKinkRatio);
            }
          }
        }
        if (vj <= 0) exact_stop_end(tol <= 0 ? Stop::exact_mode : Stop::corner);
        cap_segment_time(s);
        junction.push_back(vj);
        segs.push_back(std::move(s));
      }
      stop_before = false;
      if (mine.empty() && pause_here) stop_before = true;
      // A summary needs no segment once no blend can reach it (corners
      // change the last two): only its figures are kept, as the program goes.
      if (summary && segs.size() > 2) {
        for (size_t k = 0; k + 2 < segs.size(); ++k) add_lean(segs[k]);
        segs.erase(segs.begin(), segs.end() - 2);
      }
    }
    if (!segs.empty()) exact_stop_end(Stop::end);
    junction.push_back(0);  // the end
    for (PlanSegment& sg : segs) add_lean(sg);
    if (summary) segs.clear();
  }

  // Why the machine stops between two moves.
  enum class Stop { end, pause, exact_mode, corner };

  // A segment that ends in a stop. LinuxCNC plans a move whose end it could
  // not blend (the program's end, a pause) with half its acceleration (and
  // an arc that no next move finalized with half of that tangentially),
  // and a move that stops in exact-stop mode (G61) with 0.9 of it (both
  // measured on LinuxCNC 2.9; docs/motion.md). A sharp corner's stop keeps
  // the whole acceleration.
  void exact_stop_end(Stop why) {
    if (!linuxcnc() || segs.empty()) return;
    PlanSegment& s = segs.back();
    const bool exact = path_tolerance(static_cast<size_t>(s.block)) <= 0;
    double f = 1;
    if (why == Stop::exact_mode || (exact && why != Stop::corner)) f = 0.9;
    else if (why == Stop::end || why == Stop::pause) f = 0.5;
    if (f == 1) return;
    s.overall_accel *= f;
    s.accel = s.curved ? kTangentialShare * s.overall_accel : std::min(s.accel * f, s.overall_accel);
  }

  void speeds() {
    const size_t n = lean.size();
    const double j = lim.jerk ? std::min({lim.jmax.x, lim.jmax.y, lim.jmax.z}) : 0;
    // junction has n + 1 entries: entering each segment, then the end.
    std::vector<double> v(junction);
    for (size_t i = 0; i < n; ++i) {
      v[i] = std::min(v[i], lean[i].vmax);
      if (i > 0) v[i] = std::min(v[i], lean[i - 1].vmax);
    }
    // Look-ahead: at each segment the controller must be able to stop
    // within the segments it sees (counted in blocks).
    const int window = std::max(1, model.lookahead_blocks);
    std::vector<double> look(n + 1, kInf);
    {
      // Only where the window is short compared with a stop.
      std::vector<double> prefix(n + 1, 0);
      for (size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + lean[i].length;
      std::vector<size_t> end_of(n);
      // Window end: the segment after `window` distinct blocks.
      size_t e = 0;
      int last_block = -2;
      std::vector<int> bcount(n + 1, 0);
      for (size_t i = 0; i < n; ++i) {
        bcount[i + 1] = bcount[i] + (lean[i].block != last_block ? 1 : 0);
        last_block = lean[i].block;
      }
      for (size_t i = 0; i < n; ++i) {
        if (e < i) e = i;
        while (e < n && bcount[e + 1] - bcount[i] <= window) ++e;
        end_of[i] = e;  // segments [i, e) are seen
      }
      // The least acceleration over each window, by a sliding minimum (both
      // ends only move forward).
      std::deque<size_t> mins;
      size_t pushed = 0;
      for (size_t i = 0; i < n; ++i) {
        // Entering segment i, the controller is still executing segment
        // i - 1: it sees the window that began there.
        const size_t stop = end_of[i > 0 ? i - 1 : 0];
        if (stop >= n) continue;  // sees the program's end: the normal passes cover it
        for (; pushed < stop; ++pushed) {
          while (!mins.empty() && lean[mins.back()].accel >= lean[pushed].accel) mins.pop_back();
          mins.push_back(pushed);
        }
        while (!mins.empty() && mins.front() < i) mins.pop_front();
        const double a_min = mins.empty() ? lean[i].accel : lean[mins.front()].accel;
        // A window long enough to stop from the top speed does not limit.
        const double dist_needed = ramp_distance(0, lean[i].vmax, a_min, 0);
        if (prefix[stop] - prefix[i] >= dist_needed * 1.0001) continue;
        double w = 0;
        for (size_t k = stop; k-- > i;) w = std::min(reachable(w, lean[k].length, lean[k].accel, 0, lean[k].vmax), v[k]);
        look[i] = w;
      }
    }
    for (size_t i = 0; i < n; ++i) {
      if (look[i] < v[i]) {
        v[i] = look[i];
        lookahead_limited_.resize(n, false);
        lookahead_limited_[i] = true;
      }
    }
    // Backward then forward (speeds by the acceleration; the jerk's share
    // of a ramp is counted below, once per ramp).
    for (size_t i = n; i-- > 0;) v[i] = std::min(v[i], reachable(v[i + 1], lean[i].length, lean[i].accel, 0, lean[i].vmax));
    for (size_t i = 0; i < n; ++i)
      v[i + 1] = std::min(v[i + 1], reachable(v[i], lean[i].length, lean[i].accel, 0, lean[i].vmax));
    // Trapezoids, then (with a jerk limit) S-curves: a ramp's build-up and
    // wind-down where the acceleration starts and ends, not at every joint.
    for (size_t i = 0; i < n; ++i) profile_one(lean[i], v[i], v[i + 1], 0, {1, 1, 1, 1});
    if (j > 0) {
      std::vector<char> acc_in(n, 1), acc_out(n, 1), dec_in(n, 1), dec_out(n, 1);
      // A phase counts when it covers more than rounding would leave of the
      // segment (1e-9 of its length, at most its peak speed times its
      // duration): a cruise or a ramp of a few ulps, left where the speeds
      // meet exactly on paper, must not decide whether a ramp continues into
      // the next segment (that would move the time by a jerk's share of a
      // ramp for a change of 1e-12 in a length).
      auto has = [](const Lean& q, double t) { return t * q.vpeak > 1e-9 * q.length; };
      auto ends_acc = [&](const Lean& q) { return has(q, q.t_acc) && !has(q, q.t_cruise) && !has(q, q.t_dec); };
      auto starts_acc = [&](const Lean& q) { return has(q, q.t_acc); };
      auto ends_dec = [&](const Lean& q) { return has(q, q.t_dec); };
      auto starts_dec = [&](const Lean& q) { return has(q, q.t_dec) && !has(q, q.t_acc) && !has(q, q.t_cruise); };
      for (size_t i = 0; i + 1 < n; ++i) {
        if (ends_acc(lean[i]) && starts_acc(lean[i + 1])) acc_out[i] = acc_in[i + 1] = 0;
        if (ends_dec(lean[i]) && starts_dec(lean[i + 1])) dec_out[i] = dec_in[i + 1] = 0;
      }
      for (size_t i = 0; i < n; ++i) {
        std::array<char, 4> f{acc_in[i], acc_out[i], dec_in[i], dec_out[i]};
        profile_one(lean[i], v[i], v[i + 1], j, f);
      }
    }
    if (!summary)
      for (size_t i = 0; i < n; ++i) {
        PlanSegment& sg = segs[i];
        sg.v0 = v[i];
        sg.v1 = v[i + 1];
        sg.vpeak = lean[i].vpeak;
        sg.t_acc = lean[i].t_acc;
        sg.t_cruise = lean[i].t_cruise;
        sg.t_dec = lean[i].t_dec;
      }
  }

  // One segment from v0 to v1: the highest peak that fits its length.
  static void profile_one(Lean& s, double v0, double v1, double j, std::array<char, 4> f) {
    const double a = s.accel;
    auto up = [&](double vp) { return ramp_time(v0, vp, a, j, f[0], f[1]); };
    auto down = [&](double vp) { return ramp_time(vp, v1, a, j, f[2], f[3]); };
    auto used = [&](double vp) { return 0.5 * (v0 + vp) * up(vp) + 0.5 * (vp + v1) * down(vp); };
    double lo = std::max(v0, v1), hi = s.vmax;
    double vp = hi;
    if (used(hi) > s.length * (1 + 1e-12)) {
      if (j <= 0) {
        vp = std::clamp(std::sqrt(std::max(0.0, (2 * a * s.length + v0 * v0 + v1 * v1) / 2)), lo, hi);
      } else {
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (used(mid) <= s.length ? lo : hi) = mid;
        }
        vp = lo;
      }
    }
    s.vpeak = vp;
    s.t_acc = up(vp);
    s.t_dec = down(vp);
    const double rest = s.length - used(vp);
    s.t_cruise = vp > 0 ? std::max(0.0, rest) / vp : 0;
  }
  std::vector<bool> lookahead_limited_;

  void totals() {
    double t = 0;
    size_t pause = 0;
    // Pauses sit before the first segment of their block.
    std::vector<size_t> first_seg(tl.blocks.size() + 1, lean.size());
    for (size_t i = lean.size(); i-- > 0;) first_seg[static_cast<size_t>(lean[i].block)] = i;
    for (size_t b = tl.blocks.size(); b-- > 0;) first_seg[b] = std::min(first_seg[b], first_seg[b + 1]);
    plan.pause_start_s.assign(tl.pauses.size(), 0);
    // One pass over the segments, in order: the times, per block what held
    // it below its programmed feed (the limit of its fastest segment), and
    // the mean feed ratio over the cutting moves: the length cut over the
    // length the programmed feeds would have cut in the same time (so each
    // stretch of path counts by its length, blends with their block). A
    // cutting segment's block is a cutting block, whose programmed feed
    // add_block() took from the block as it is.
    std::vector<SpeedLimit> why(plan.blocks.size(), SpeedLimit::programmed);
    std::vector<double> top(plan.blocks.size(), 0);
    double cut = 0, at_feed = 0;
    for (size_t i = 0; i <= lean.size(); ++i) {
      while (pause < tl.pauses.size() && first_seg[std::min(tl.pauses[pause].before_block, tl.blocks.size())] <= i) {
        plan.pause_start_s[pause] = t;
        t += tl.pauses[pause].seconds;
        plan.pause_time_s += tl.pauses[pause].seconds;
        ++pause;
      }
      if (i == lean.size()) break;
      const Lean& s = lean[i];
      if (!summary) segs[i].t_start = t;
      t += s.time();
      (s.rapid ? plan.rapid_time_s : plan.cutting_time_s) += s.time();
      const size_t b = static_cast<size_t>(s.block);
      PlannedBlock& pb = plan.blocks[b];
      pb.time_s += s.time();
      pb.peak_feed = std::max(pb.peak_feed, s.vpeak * 60);
      SpeedLimit l = s.limit;
      if (i < lookahead_limited_.size() && lookahead_limited_[i]) l = SpeedLimit::lookahead;
      if (s.vmax >= top[b]) {
        top[b] = s.vmax;
        why[b] = l;
      }
      if (s.rapid) continue;
      const double want = pb.programmed_feed / 60;
      if (!(want > 0)) continue;
      cut += s.length;
      at_feed += s.time() * want;
    }
    while (pause < tl.pauses.size()) {
      plan.pause_start_s[pause] = t;
      t += tl.pauses[pause].seconds;
      plan.pause_time_s += tl.pauses[pause].seconds;
      ++pause;
    }
    plan.cycle_time_s = t;
    plan.mean_feed_ratio = at_feed > 0 ? cut / at_feed : 1;
    // Per block (add_block() gave a cutting block its programmed feed, a
    // rapid the axes' rate along it).
    for (size_t b = 0; b < plan.blocks.size(); ++b) {
      PlannedBlock& pb = plan.blocks[b];
      const bool rapid = pb.kind == BlockKind::rapid;
      if (pb.length <= 1e-9) {
        if (rapid) pb.programmed_feed = 0;
        continue;  // no move: no time, no limit
      }
      const double want = pb.programmed_feed;
      if (want > 0) plan.programmed_feed_time_s += pb.length / want * 60;
      if (pb.clamped) ++plan.clamped_blocks;
      if (pb.peak_feed < want * (1 - 1e-6)) {
        pb.limit = why[b];
        if (pb.limit == SpeedLimit::programmed) pb.limit = SpeedLimit::acceleration;
      }
      pb.starved = pb.peak_feed < want * 0.99 && is_starvation(pb.limit);
      if (pb.starved) ++plan.starved_blocks;
    }
  }
};

}  // namespace

const char* to_string(SpeedLimit l) {
  switch (l) {
    case SpeedLimit::programmed: return "programmed";
    case SpeedLimit::axes: return "axes";
    case SpeedLimit::curvature: return "curvature";
    case SpeedLimit::corner: return "corner";
    case SpeedLimit::segment_time: return "segment-time";
    case SpeedLimit::block_rate: return "block-rate";
    case SpeedLimit::lookahead: return "lookahead";
    case SpeedLimit::acceleration: return "acceleration";
  }
  return "?";
}

double PlanSegment::distance_at(double tau) const {
  if (tau <= 0) return 0;
  if (tau < t_acc) {
    const double a = t_acc > 0 ? (vpeak - v0) / t_acc : 0;
    return v0 * tau + 0.5 * a * tau * tau;
  }
  const double d_acc = 0.5 * (v0 + vpeak) * t_acc;
  tau -= t_acc;
  if (tau < t_cruise) return d_acc + vpeak * tau;
  const double d_cr = vpeak * t_cruise;
  tau -= t_cruise;
  if (tau < t_dec) {
    const double a = t_dec > 0 ? (v1 - vpeak) / t_dec : 0;
    return d_acc + d_cr + vpeak * tau + 0.5 * a * tau * tau;
  }
  return length;
}

Vec3 PlanSegment::point_at(double s, const std::vector<MotionBlock>& blocks) const {
  for (size_t k = 0; k < pieces.size(); ++k) {
    const Piece& p = pieces[k];
    if (s > p.length && k + 1 < pieces.size()) {
      s -= p.length;
      continue;
    }
    s = std::clamp(s, 0.0, p.length);
    switch (p.shape) {
      case Shape::line: return p.length > 0 ? p.a + (p.b - p.a) * (s / p.length) : p.a;
      case Shape::arc: {
        const double ang = p.radius > 0 ? s / p.radius : 0;
        return p.center + p.u * (p.radius * std::cos(ang)) + p.w * (p.radius * std::sin(ang));
      }
      case Shape::block: {
        const MotionBlock& b = blocks[static_cast<size_t>(p.block)];
        const auto it = std::upper_bound(p.s.begin(), p.s.end(), s);
        size_t i = static_cast<size_t>(std::clamp<long>(it - p.s.begin(), 1, static_cast<long>(p.s.size()) - 1));
        const double ds = p.s[i] - p.s[i - 1];
        const double f = ds > 0 ? (s - p.s[i - 1]) / ds : 0;
        // Curves: between the points the planner sampled (a few hundred
        // per block); arcs exactly.
        if (p.pts.size() == p.s.size()) return p.pts[i - 1] + (p.pts[i] - p.pts[i - 1]) * f;
        return evaluate_block(b, p.t[i - 1] + f * (p.t[i] - p.t[i - 1]));
      }
    }
  }
  return {};
}

namespace {

// Plans `timed`, a copy of the timeline to plan that it changes (starts of
// unknown axes, pause times). `original`: the timeline's own blocks, kept
// by a full plan (PlanDetail::full; null for a summary).
MotionPlan plan_timed(Timeline& timed, const std::vector<MotionBlock>* original, const MotionModel& model,
                      PlanDetail detail) {
  if (!(model.period_s > 0)) throw std::invalid_argument("motion model: period_s must be > 0");
  const Timeline& tl = timed;
  // Axes the program had not set yet start where the machine stands. And
  // in the same pass: at most a segment per line, rapid or arc and one per
  // curve piece, and a blend after each.
  Vec3 pos = tl.start;
  size_t most = 0;
  for (MotionBlock& mb : timed.blocks) {
    if (mb.from_known != 7u) {
      for (int k = 0; k < 3; ++k)
        if (!(mb.from_known & (1u << k))) mb.from[k] = pos[k];
      if (!mb.ctrl.empty()) mb.ctrl.front() = mb.from;
    }
    pos = mb.to;
    most += 1 + (mb.kind == BlockKind::nurbs || mb.kind == BlockKind::bezier ? static_cast<size_t>(curve_pieces(mb)) : 1);
  }
  // Tool changes and spindle starts take the machine's time.
  for (PlanPause& p : timed.pauses) {
    if (p.kind == PlanPause::Kind::tool_change) p.seconds = model.tool_change_s;
    if (p.kind == PlanPause::Kind::spindle_start) p.seconds = model.spindle_start_s;
  }
  const bool summary = detail == PlanDetail::summary;
  Builder b(timed, model, summary);
  b.most_segments = most;
  for (int i = 0; i < 3; ++i) {
    b.lim.vmax[i] = model.max_velocity_mm_min[static_cast<size_t>(i)] / 60 / b.scale;
    b.lim.amax[i] = model.max_acceleration_mm_s2[static_cast<size_t>(i)] / b.scale;
    if (model.max_jerk_mm_s3) b.lim.jmax[i] = (*model.max_jerk_mm_s3)[static_cast<size_t>(i)] / b.scale;
  }
  b.lim.jerk = model.max_jerk_mm_s3.has_value();
  b.plan.units = tl.units;
  b.plan.period_s = model.period_s;
  b.build();
  b.speeds();
  b.totals();
  if (summary) {
    b.plan.blocks.clear();
    b.plan.blocks.shrink_to_fit();
    b.plan.pause_start_s.clear();
    return std::move(b.plan);
  }
  b.plan.segments = std::move(b.segs);
  b.plan.pauses = timed.pauses;
  b.plan.motion = *original;
  return std::move(b.plan);
}

}  // namespace

MotionPlan plan_motion(const Timeline& tl, const MotionModel& model, PlanDetail detail) {
  Timeline timed = tl;
  return plan_timed(timed, &tl.blocks, model, detail);
}

MotionPlan plan_motion(Timeline&& tl, const MotionModel& model, PlanDetail detail) {
  if (detail == PlanDetail::full) return plan_motion(std::as_const(tl), model, detail);
  return plan_timed(tl, nullptr, model, detail);  // a summary keeps no blocks: no copy of them
}

void sample_plan(const MotionPlan& plan, const std::function<void(double, const Vec3&, double)>& out) {
  const double T = plan.period_s;
  const auto steps = static_cast<long long>(std::ceil(plan.cycle_time_s / T - 1e-9));
  size_t seg = 0;
  Vec3 last = plan.segments.empty() ? Vec3{} : plan.segments.front().point_at(0, plan.motion);
  for (long long k = 0; k <= steps; ++k) {
    const double t = std::min(static_cast<double>(k) * T, plan.cycle_time_s);
    while (seg < plan.segments.size() && plan.segments[seg].t_start + plan.segments[seg].time() < t) ++seg;
    double feed = 0;
    if (seg < plan.segments.size() && t >= plan.segments[seg].t_start) {
      const PlanSegment& s = plan.segments[seg];
      const double tau = t - s.t_start;
      last = s.point_at(s.distance_at(tau), plan.motion);
      // Speed at tau.
      if (tau < s.t_acc) feed = s.v0 + (s.vpeak - s.v0) * (s.t_acc > 0 ? tau / s.t_acc : 1);
      else if (tau < s.t_acc + s.t_cruise) feed = s.vpeak;
      else feed = s.vpeak + (s.v1 - s.vpeak) * (s.t_dec > 0 ? (tau - s.t_acc - s.t_cruise) / s.t_dec : 1);
      feed *= 60;
    } else if (seg > 0 && seg <= plan.segments.size()) {
      const PlanSegment& s = plan.segments[seg - 1];
      last = s.point_at(s.length, plan.motion);
    }
    out(t, last, feed);
  }
}

}  // namespace bezcam
