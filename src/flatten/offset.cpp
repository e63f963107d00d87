// The offset of a planar curve with a proven bound: see offset.hpp and
// docs/offset.md for the method and the argument.
#include "bezcam/flatten/offset.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "offset_chain.hpp"
#include "offset_smooth.hpp"

namespace bezcam {

namespace {
Vec3 polar(const Vec3& c, double r, double ang) { return {c.x + r * std::cos(ang), c.y + r * std::sin(ang), 0}; }
// Angle in (-pi, pi].
double wrap(double a) {
  while (a <= -std::numbers::pi) a += 2 * std::numbers::pi;
  while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
  return a;
}
Vec3 flat(const Vec3& p) { return {p.x, p.y, 0}; }
}  // namespace

ArcSeg ArcSeg::line(const Vec3& a, const Vec3& b) {
  ArcSeg s;
  s.a = flat(a);
  s.b = flat(b);
  return s;
}

ArcSeg ArcSeg::make_arc(const Vec3& a, const Vec3& b, const Vec3& c, double sweep) {
  ArcSeg s;
  s.arc = true;
  s.a = flat(a);
  s.b = flat(b);
  s.c = flat(c);
  s.radius = dist(s.a, s.c);
  s.a0 = std::atan2(s.a.y - s.c.y, s.a.x - s.c.x);
  s.sweep = sweep;
  return s;
}

Vec3 ArcSeg::point(double s) const {
  if (s <= 0) return a;
  if (s >= 1) return b;
  if (!arc) return lerp(a, b, s);
  return polar(c, radius, a0 + sweep * s);
}

Vec3 ArcSeg::tangent(double s) const {
  if (!arc) {
    const Vec3 d = b - a;
    const double n = norm(d);
    return n > 0 ? d / n : Vec3{1, 0, 0};
  }
  const double ang = a0 + sweep * std::clamp(s, 0.0, 1.0), dir = sweep >= 0 ? 1 : -1;
  return {-std::sin(ang) * dir, std::cos(ang) * dir, 0};
}

double ArcSeg::length() const { return arc ? radius * std::abs(sweep) : dist(a, b); }

ArcSeg ArcSeg::reversed() const {
  ArcSeg r = *this;
  std::swap(r.a, r.b);
  if (arc) {
    r.a0 = a0 + sweep;
    r.sweep = -sweep;
  }
  return r;
}

ArcSeg ArcSeg::sub(double s0, double s1) const {
  ArcSeg r = *this;
  r.a = point(s0);
  r.b = point(s1);
  if (arc) {
    r.a0 = a0 + sweep * s0;
    r.sweep = sweep * (s1 - s0);
  }
  return r;
}

double distance(const ArcSeg& s, const Vec3& p) {
  const Vec3 q = flat(p);
  if (!s.arc) {
    const Vec3 d = s.b - s.a;
    const double l2 = dot(d, d);
    const double t = l2 > 0 ? std::clamp(dot(q - s.a, d) / l2, 0.0, 1.0) : 0.0;
    return dist(q, lerp(s.a, s.b, t));
  }
  // Inside the sector: radial distance; outside it: the nearer end.
  const double ang = std::atan2(q.y - s.c.y, q.x - s.c.x);
  double u = wrap(ang - s.a0);
  if (s.sweep < 0) u = -u;
  if (u < 0) u += 2 * std::numbers::pi;
  if (u <= std::abs(s.sweep)) return std::abs(dist(q, s.c) - s.radius);
  return std::min(dist(q, s.a), dist(q, s.b));
}

namespace {

// Parameter of a point known to lie on the arc's circle; nothing when it is
// outside the sweep (with a little slack at the ends).
std::optional<double> arc_param(const ArcSeg& s, const Vec3& p) {
  const double ang = std::atan2(p.y - s.c.y, p.x - s.c.x);
  double u = wrap(ang - s.a0);
  if (s.sweep < 0) u = -u;
  const double w = std::abs(s.sweep), slack = 1e-12;
  if (u < -slack) u += 2 * std::numbers::pi;
  if (u > w + slack) {
    if (u - 2 * std::numbers::pi >= -slack)
      u -= 2 * std::numbers::pi;
    else
      return std::nullopt;
  }
  return std::clamp(u / w, 0.0, 1.0);
}

std::optional<double> line_param(const ArcSeg& s, const Vec3& p) {
  const Vec3 d = s.b - s.a;
  const double l2 = dot(d, d);
  if (l2 == 0) return std::nullopt;
  const double t = dot(p - s.a, d) / l2;
  if (t < -1e-12 || t > 1 + 1e-12) return std::nullopt;
  return std::clamp(t, 0.0, 1.0);
}

std::optional<double> param_on(const ArcSeg& s, const Vec3& p) { return s.arc ? arc_param(s, p) : line_param(s, p); }

// Points where the line through (a, d) meets the circle (c, r).
std::vector<Vec3> line_circle(const Vec3& a, const Vec3& d, const Vec3& c, double r) {
  const double l2 = dot(d, d);
  if (l2 == 0) return {};
  const double t0 = dot(c - a, d) / l2;  // foot of the perpendicular
  const Vec3 foot = a + d * t0;
  const double h2 = r * r - dot(foot - c, foot - c);
  if (h2 < -1e-12 * r * r) return {};
  const double h = std::sqrt(std::max(h2, 0.0)) / std::sqrt(l2);
  if (h == 0) return {foot};
  return {a + d * (t0 - h), a + d * (t0 + h)};
}

std::vector<Vec3> circle_circle(const Vec3& c1, double r1, const Vec3& c2, double r2) {
  const Vec3 d = c2 - c1;
  const double l = norm(d);
  if (l == 0 || l > r1 + r2 + 1e-12 * (r1 + r2) || l < std::abs(r1 - r2) - 1e-12 * (r1 + r2)) return {};
  const double x = (l * l + r1 * r1 - r2 * r2) / (2 * l);
  const double h = std::sqrt(std::max(r1 * r1 - x * x, 0.0));
  const Vec3 u = d / l, n{-u.y, u.x, 0};
  const Vec3 m = c1 + u * x;
  if (h == 0) return {m};
  return {m + n * h, m - n * h};
}

}  // namespace

std::vector<std::pair<double, double>> intersections(const ArcSeg& p, const ArcSeg& q) {
  std::vector<Vec3> cand;
  if (!p.arc && !q.arc) {
    const Vec3 d1 = p.b - p.a, d2 = q.b - q.a;
    const double den = d1.x * d2.y - d1.y * d2.x;
    if (den == 0) return {};
    const Vec3 w = q.a - p.a;
    const double t = (w.x * d2.y - w.y * d2.x) / den, u = (w.x * d1.y - w.y * d1.x) / den;
    if (t < 0 || t > 1 || u < 0 || u > 1) return {};
    return {{t, u}};
  }
  if (p.arc && q.arc)
    cand = circle_circle(p.c, p.radius, q.c, q.radius);
  else if (p.arc)
    cand = line_circle(q.a, q.b - q.a, p.c, p.radius);
  else
    cand = line_circle(p.a, p.b - p.a, q.c, q.radius);
  std::vector<std::pair<double, double>> out;
  for (const Vec3& x : cand) {
    const auto s = param_on(p, x), t = param_on(q, x);
    if (s && t) out.push_back({*s, *t});
  }
  return out;
}

std::vector<Bezier> bezier_pieces(std::span<const ArcSeg> chain) {
  std::vector<Bezier> out;
  for (const ArcSeg& s : chain) {
    if (!s.arc) {
      out.push_back(Bezier::make({s.a, s.b}, {}, 2));
      continue;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / (std::numbers::pi / 2) - 1e-12)));
    const double th = s.sweep / n;
    for (int k = 0; k < n; ++k) {
      const double s0 = s.a0 + th * k, mid = s0 + th / 2;
      const double w = std::cos(th / 2);
      const Vec3 p0 = k == 0 ? s.a : polar(s.c, s.radius, s0);
      const Vec3 p2 = k == n - 1 ? s.b : polar(s.c, s.radius, s0 + th);
      const Vec3 p1 = polar(s.c, s.radius / w, mid);
      out.push_back(Bezier::make({p0, p1, p2}, {1.0, w, 1.0}, 2));
    }
  }
  return out;
}

double signed_area(std::span<const Bezier> pieces) {
  Box3 box;
  for (const auto& b : pieces)
    for (const auto& p : b.points) box.add(p);
  const double size = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  const auto poly =
      flatten(pieces, {.tolerance = std::max(size * 1e-5, 1e-9), .decimals = -1, .on_curve = true}).points;
  double a = 0;
  for (size_t i = 0; i + 1 < poly.size(); ++i) a += poly[i].x * poly[i + 1].y - poly[i + 1].x * poly[i].y;
  if (!poly.empty()) a += poly.back().x * poly.front().y - poly.front().x * poly.back().y;
  return a / 2;
}

namespace {

// The raw offset's pieces: each knows the primitive of A it offsets (-1 for
// a join arc) so that what is clipped away maps back onto the curve.
struct Raw {
  ArcSeg seg;
  int source = -1;
  /// On the other side of the curve: the offset of a primitive at -r, the
  /// arc about a joint on that side, an open curve's end caps. Travelled so
  /// that the curve is on the same hand as from the path's own pieces.
  bool other = false;
};

Box3 box_of(const ArcSeg& s) {
  Box3 b;
  b.add(s.a);
  b.add(s.b);
  if (s.arc) {
    // Conservative: the whole circle's box when the sweep is not small.
    if (std::abs(s.sweep) > 0.5) {
      b.add(s.c + Vec3{s.radius, s.radius, 0});
      b.add(s.c - Vec3{s.radius, s.radius, 0});
    } else {
      b.add(s.point(0.5));
      const double sag = s.radius * (1 - std::cos(s.sweep / 2));
      b.lo = b.lo - Vec3{sag, sag, 0};
      b.hi = b.hi + Vec3{sag, sag, 0};
    }
  }
  return b;
}

bool overlap(const Box3& p, const Box3& q, double eps) {
  return p.lo.x <= q.hi.x + eps && q.lo.x <= p.hi.x + eps && p.lo.y <= q.hi.y + eps && q.lo.y <= p.hi.y + eps;
}

// Indices 0..n-1 sorted by their boxes' low x (ties by index).
std::vector<size_t> sorted_by_x(const std::vector<Box3>& boxes) {
  std::vector<size_t> by_x(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](size_t p, size_t q) {
    return boxes[p].lo.x < boxes[q].lo.x || (boxes[p].lo.x == boxes[q].lo.x && p < q);
  });
  return by_x;
}

// The exact offset of a primitive of A at distance r on the hand `hand` of
// its direction of travel (+1 left, -1 right): a parallel line, or the
// concentric arc (turned inside out where the arc is tighter than r).
ArcSeg offset_of(const ArcSeg& s, int hand, double r) {
  if (!s.arc) {
    const Vec3 t = s.tangent(0), n{-t.y * hand * r, t.x * hand * r, 0};
    return ArcSeg::line(s.a + n, s.b + n);
  }
  // Left of a counter-clockwise arc is towards its centre.
  const double k = s.sweep > 0 ? s.radius - hand * r : s.radius + hand * r;
  ArcSeg o = s;
  o.radius = std::abs(k);
  if (k < 0) o.a0 += std::numbers::pi;
  o.a = polar(o.c, o.radius, o.a0);
  o.b = polar(o.c, o.radius, o.a0 + o.sweep);
  return o;
}

// Whether a point is valid: at least r (less the margin) from every
// primitive of A, the primitives sorted by their boxes' low x.
class SplineIndex {
 public:
  SplineIndex(const std::vector<ArcSeg>& A, double r, double keep_at)
      : A_(A), r_(r), keep_at_(keep_at), boxes_(A.size()) {
    for (size_t i = 0; i < A.size(); ++i) boxes_[i] = box_of(A[i]);
    by_x_ = sorted_by_x(boxes_);
    for (const auto& b : boxes_) widest_ = std::max(widest_, b.hi.x - b.lo.x);
  }
  bool valid(const Vec3& p) const {
    const double lo = p.x - r_ - widest_;
    auto it = std::lower_bound(by_x_.begin(), by_x_.end(), lo, [&](size_t k, double v) { return boxes_[k].lo.x < v; });
    for (; it != by_x_.end() && boxes_[*it].lo.x <= p.x + r_; ++it) {
      const Box3& b = boxes_[*it];
      if (p.x < b.lo.x - r_ || p.x > b.hi.x + r_ || p.y < b.lo.y - r_ || p.y > b.hi.y + r_) continue;
      if (distance(A_[*it], p) < keep_at_) return false;
    }
    return true;
  }

 private:
  const std::vector<ArcSeg>& A_;
  double r_, keep_at_;
  std::vector<Box3> boxes_;
  std::vector<size_t> by_x_;
  double widest_ = 0;
};

// The side's region of a closed curve: a valid point is at least r from A,
// so A's arcs may be replaced by chords with a sagitta under r / 2 without
// moving it across; inside is a non-zero winding number (by the crossings
// of a ray). The region asked is the inside when the side is the left of a
// counter-clockwise curve or the right of a clockwise one. A curve that
// bounds no area has no region (empty()).
class Region {
 public:
  Region() = default;
  Region(const std::vector<ArcSeg>& A, double r, int side, double scale) {
    for (const ArcSeg& a : A) {
      ring_.push_back(a.a);
      if (!a.arc) continue;
      const double most = a.radius <= r / 4 ? std::numbers::pi / 2
                                            : std::min(std::numbers::pi / 2, 2 * std::acos(1 - r / (2 * a.radius)));
      const int parts = std::max(1, static_cast<int>(std::ceil(std::abs(a.sweep) / most)));
      for (int q = 1; q < parts; ++q) ring_.push_back(a.point(static_cast<double>(q) / parts));
    }
    double area = 0;
    for (size_t i = 0; i < ring_.size(); ++i) {
      const Vec3& p = ring_[i];
      const Vec3& q = ring_[(i + 1) % ring_.size()];
      area += p.x * q.y - q.x * p.y;
    }
    if (std::abs(area) <= 1e-9 * scale * scale) ring_.clear();
    want_inside_ = (side > 0) == (area > 0);
  }
  bool empty() const { return ring_.empty(); }
  bool contains(const Vec3& p) const {
    int w = 0;
    for (size_t i = 0; i < ring_.size(); ++i) {
      const Vec3& a = ring_[i];
      const Vec3& b = ring_[(i + 1) % ring_.size()];
      if ((a.y > p.y) == (b.y > p.y)) continue;
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (x > p.x) w += b.y > a.y ? 1 : -1;
    }
    return (w != 0) == want_inside_;
  }

 private:
  std::vector<Vec3> ring_;
  bool want_inside_ = false;
};

// A stretch of A's primitive `source` whose offset was cut away, on [s0, s1].
struct Clipped {
  int source;
  double s0, s1;
};

// offset_curve() stage by stage (the steps of offset.hpp).
struct OffsetBuilder {
  OffsetBuilder(const OffsetOptions& o, bool c) : opt(o), closed(c), r(o.distance), side(o.side >= 0 ? 1 : -1) {}

  const OffsetOptions& opt;
  bool closed;
  double r;
  int side;
  OffsetResult res;
  std::vector<ArcSeg> A;  ///< the arc spline
  double scale = 0, eps = 0;
  std::vector<Raw> raw;
  /// The sweep of the arc about each joint (after A[i]; 0 where the
  /// offsets meet).
  std::vector<double> joint_turn;

  void fit_spline(std::span<const Bezier> pieces);
  void smooth_joints(std::span<const Bezier> pieces, const std::vector<std::pair<size_t, double>>& ends);
  ArcSeg join(const Vec3& v, const Vec3& from, const Vec3& to) const;
  void offset_side();
  void round_open_ends(std::span<const Bezier> pieces);
  void close_round();
  void add_other_side();
  std::vector<std::vector<double>> crossings() const;
  std::vector<ArcSeg> keep_valid(std::vector<std::vector<double>>& cuts, std::vector<Clipped>& clipped) const;
  std::vector<std::vector<Vec3>> mark_left(const std::vector<Clipped>& clipped);
  void read_depths(const std::vector<std::vector<Vec3>>& probes);
};

// 1. The arc spline A, without rounding.
void OffsetBuilder::fit_spline(std::span<const Bezier> pieces) {
  ArcFitOptions ao;
  ao.tolerance = opt.fit;
  ao.decimals = -1;
  ao.radius_tolerance = HUGE_VAL;
  ao.tangent = opt.tangent;
  Vec3 from = flat(pieces.front().front());
  // Where each move of A ends on the curve (piece, parameter).
  std::vector<std::pair<size_t, double>> ends;
  const double bound = fit_arcs(pieces, ao, [&](const FitMove& f) {
    const Vec3 to = flat(f.to);
    if (to == from) return;
    ends.emplace_back(f.piece, f.t);
    if (f.kind == FitKind::line) {
      A.push_back(ArcSeg::line(from, to));
    } else {
      const Arc arc{from, to, f.center, f.kind == FitKind::arc_ccw};
      A.push_back(ArcSeg::make_arc(from, to, f.center, arc.ccw ? arc.sweep() : -arc.sweep()));
    }
    from = to;
  });
  res.bound = bound;
  res.fitted = A.size();
  if (A.empty()) return;
  if (closed) A.back().b = A.front().a;
  if (opt.tangent) smooth_joints(pieces, ends);
  scale = r;
  for (const auto& s : A) scale = std::max({scale, max_abs(s.a), max_abs(s.b)});
  eps = 1e-9 * scale;  // floating-point margin of the tests below
  joint_turn.assign(A.size(), 0.0);
}

// Where a tangent chain of A starts again at a small angle, and where a
// closed curve's chain closes, on a stretch where the curve is smooth: the
// move before the joint becomes a biarc into the next move's direction
// (offset_smooth.hpp). From the last joint to the first, so that the moves
// before a joint keep their places.
void OffsetBuilder::smooth_joints(std::span<const Bezier> pieces, const std::vector<std::pair<size_t, double>>& ends) {
  if (A.size() < 2 || ends.size() != A.size()) return;
  const double budget = check_tolerance(opt.fit, -1, 2, control_magnitude(pieces)).budget;
  // The curve is smooth at the end of move k: inside a piece, or where
  // it goes on into the next piece (the first, where a closed one closes)
  // without a corner.
  auto smooth_at = [&](size_t k) {
    const auto [pi, t] = ends[k];
    if (t < 1) return true;
    if (pi + 1 < pieces.size()) return tangent_joint(pieces[pi], pieces[pi + 1]);
    return closed && tangent_joint(pieces[pi], pieces.front());
  };
  for (size_t k = A.size(); k-- > 0;) {
    if (k + 1 == A.size() && !closed) continue;
    const size_t next = k + 1 < A.size() ? k + 1 : 0;
    if (!smooth_at(k)) continue;
    const size_t pi = ends[k].first;
    // The move's span of its piece: from where the move before ended on
    // it, else from the piece's start (not where a piece before got no
    // move).
    double t_from = 0;
    if (k > 0 && ends[k - 1].first == pi)
      t_from = ends[k - 1].second;
    else if (k > 0 ? !(ends[k - 1].first + 1 == pi && ends[k - 1].second >= 1) : pi != 0)
      continue;
    const double biarc =
        flatten_detail::smooth_joint(A, k, A[next].tangent(0), pieces[pi], t_from, ends[k].second, budget);
    if (biarc >= 0) res.bound = std::max(res.bound, biarc), res.fitted = A.size();
  }
}

// The arc of radius r about v from `from` to `to` (both r from v).
ArcSeg OffsetBuilder::join(const Vec3& v, const Vec3& from, const Vec3& to) const {
  const double a0 = std::atan2(from.y - v.y, from.x - v.x), a1 = std::atan2(to.y - v.y, to.x - v.x);
  ArcSeg j = ArcSeg::make_arc(from, to, v, wrap(a1 - a0));
  j.radius = r;
  return j;
}

// 2. and 3. Exact offsets, joined by arcs of radius r about the joints.
void OffsetBuilder::offset_side() {
  for (size_t i = 0; i < A.size(); ++i) {
    ArcSeg o = offset_of(A[i], side, r);
    if (!raw.empty()) {
      const Vec3 v = A[i].a, e = raw.back().seg.b;
      if (dist(e, o.a) <= eps) {
        o.a = e;
        if (o.arc) o.a0 = std::atan2(o.a.y - o.c.y, o.a.x - o.c.x);
      } else {
        const ArcSeg j = join(v, e, o.a);
        raw.push_back({j, -1});
        joint_turn[i - 1] = j.sweep;
      }
    }
    raw.push_back({o, static_cast<int>(i)});
  }
}

// The ends of an open curve: A's end tangents may differ a little from the
// curve's, so the path starts and ends where the true offset does, rolling
// about the (exact) end points to there.
void OffsetBuilder::round_open_ends(std::span<const Bezier> pieces) {
  auto true_normal = [&](const Bezier& b, double t, const ArcSeg& fallback, double s) {
    Vec3 d = derivative(b, t);
    if (std::hypot(d.x, d.y) == 0) d = fallback.tangent(s);
    const double l = std::hypot(d.x, d.y);
    return Vec3{-d.y / l * side * r, d.x / l * side * r, 0};
  };
  auto roll = [&](const Vec3& v, const Vec3& from, const Vec3& to) {
    const ArcSeg j = join(v, from, to);
    // Its points are r from the end point; from A's first or last
    // primitive at least r cos(sweep).
    res.bound += r * (1 - std::cos(j.sweep));
    return Raw{j, -1};
  };
  const Vec3 v0 = A.front().a, s0 = v0 + true_normal(pieces.front(), 0, A.front(), 0);
  if (dist(s0, raw.front().seg.a) > eps) raw.insert(raw.begin(), roll(v0, s0, raw.front().seg.a));
  const Vec3 v1 = A.back().b, e1 = v1 + true_normal(pieces.back(), 1, A.back(), 1);
  if (dist(e1, raw.back().seg.b) > eps) raw.push_back(roll(v1, raw.back().seg.b, e1));
}

// A closed curve's path ends where it starts, joined about A's start.
void OffsetBuilder::close_round() {
  const Vec3 v = A.front().a, e = raw.back().seg.b, s0 = raw.front().seg.a;
  if (dist(e, s0) <= eps) {
    raw.back().seg.b = s0;
  } else {
    const ArcSeg j = join(v, e, s0);
    raw.push_back({j, -1});
    joint_turn[A.size() - 1] = j.sweep;
  }
}

// The other side: where the curve doubles back on itself (a cusp, a spur of
// zero width, a curl) the points at r from A on the side asked include
// points of the other side's offsets and joints, and a piece of the path
// crosses from valid to invalid where it meets them. They are cut against
// like the rest, so that every piece is valid or invalid as a whole, and
// for a closed curve they are kept where they are valid and on the side's
// region (step 4). The other side's arc about a joint turns the same way as
// the side's, so that at a joint where the curve turns back exactly (half a
// turn either way) the two make the whole circle.
void OffsetBuilder::add_other_side() {
  auto about = [&](const Vec3& v, const Vec3& from, double sweep) {
    const Vec3 to = polar(v, r, std::atan2(from.y - v.y, from.x - v.x) + sweep);
    ArcSeg j = ArcSeg::make_arc(from, to, v, sweep);
    j.radius = r;
    return j;
  };
  const size_t n = A.size();
  std::vector<Raw> others;
  for (size_t i = 0; i < n; ++i) {
    const ArcSeg o = offset_of(A[i], -side, r);
    if (o.length() > eps) others.push_back({o.reversed(), -1, true});
    if (i + 1 < n || closed) {
      const Vec3 v = A[i].b, t0 = A[i].tangent(1);
      const double turn = joint_turn[i];
      if (std::abs(turn) * r > eps) {
        const Vec3 m{t0.y * side * r, -t0.x * side * r, 0};  // the other side's normal at the joint's start
        others.push_back({about(v, v + m, turn).reversed(), -1, true});
      }
    }
  }
  if (!closed) {
    // The caps round the two ends, from the other side to the side asked.
    const Vec3 t0 = A.front().tangent(0), t1 = A.back().tangent(1);
    others.push_back(
        {about(A.front().a, A.front().a + Vec3{t0.y * side * r, -t0.x * side * r, 0}, -side * std::numbers::pi), -1,
         true});
    others.push_back(
        {about(A.back().b, A.back().b + Vec3{-t1.y * side * r, t1.x * side * r, 0}, -side * std::numbers::pi), -1,
         true});
  }
  raw.insert(raw.end(), others.begin(), others.end());
}

// 4. Where the raw path crosses itself: per raw piece, the parameters of
// its crossings (boxes sorted by x to skip far pairs).
std::vector<std::vector<double>> OffsetBuilder::crossings() const {
  const size_t m = raw.size();
  std::vector<Box3> boxes(m);
  for (size_t i = 0; i < m; ++i) boxes[i] = box_of(raw[i].seg);
  const std::vector<size_t> by_x = sorted_by_x(boxes);
  std::vector<std::vector<double>> cuts(m);
  for (size_t ii = 0; ii < m; ++ii) {
    const size_t i = by_x[ii];
    for (size_t jj = ii + 1; jj < m; ++jj) {
      const size_t j = by_x[jj];
      if (boxes[j].lo.x > boxes[i].hi.x + eps) break;
      if (!overlap(boxes[i], boxes[j], eps)) continue;
      for (const auto& [s, t] : intersections(raw[i].seg, raw[j].seg)) {
        cuts[i].push_back(s);
        cuts[j].push_back(t);
      }
    }
  }
  return cuts;
}

// The raw pieces cut at their crossings; a piece is kept when it is valid
// (and, for a closed curve that bounds an area, in the side's region; else
// when it is on the side asked); what is cut away from a primitive's
// offset goes to `clipped`.
std::vector<ArcSeg> OffsetBuilder::keep_valid(std::vector<std::vector<double>>& cuts,
                                              std::vector<Clipped>& clipped) const {
  const SplineIndex index(A, r, r - eps);
  const Region region = closed ? Region(A, r, side, scale) : Region();
  std::vector<ArcSeg> kept;
  for (size_t i = 0; i < raw.size(); ++i) {
    auto& c = cuts[i];
    c.push_back(0);
    c.push_back(1);
    std::sort(c.begin(), c.end());
    const ArcSeg& s = raw[i].seg;
    const double len = s.length();
    for (size_t k = 0; k + 1 < c.size(); ++k) {
      const double s0 = c[k], s1 = c[k + 1];
      if ((s1 - s0) * len <= eps) continue;
      const ArcSeg part = s.sub(s0, s1);
      bool ok = index.valid(part.point(0.5)) &&
                (part.length() < 1e3 * eps || (index.valid(part.point(0.25)) && index.valid(part.point(0.75))));
      if (ok) ok = region.empty() ? !raw[i].other : region.contains(part.point(0.5));
      if (ok)
        kept.push_back(part);
      else if (raw[i].source >= 0)
        clipped.push_back({raw[i].source, s0, s1});
    }
  }
  return kept;
}

// Material left: the clipped stretches, merged where they meet along A.
// Returns, per stretch, the points of the curve its depth is read at.
std::vector<std::vector<Vec3>> OffsetBuilder::mark_left(const std::vector<Clipped>& clipped) {
  std::vector<std::vector<Vec3>> probes;
  for (const auto& [src, s0, s1] : clipped) {
    const ArcSeg& a = A[static_cast<size_t>(src)];
    const Vec3 f = a.point(s0), t = a.point(s1);
    const double l = a.length() * (s1 - s0);
    // How deep the material stands: the curve's distance from the path,
    // less r (measured at the stretch's middle, once the path is known).
    const Vec3 mid = a.point(0.5 * (s0 + s1));
    if (!res.left.empty() && dist(res.left.back().to, f) <= 1e3 * eps) {
      res.left.back().to = t;
      res.left.back().length += l;
      res.left.back().points.push_back(mid);
      res.left.back().points.push_back(t);
      probes.back().push_back(mid);
    } else {
      res.left.push_back({f, t, l, 0, {f, mid, t}});
      probes.push_back({f, mid, t});
    }
  }
  if (closed && res.left.size() > 1 && dist(res.left.back().to, res.left.front().from) <= 1e3 * eps) {
    res.left.front().from = res.left.back().from;
    res.left.front().length += res.left.back().length;
    auto pts = res.left.back().points;
    pts.insert(pts.end(), res.left.front().points.begin() + 1, res.left.front().points.end());
    res.left.front().points = std::move(pts);
    res.left.pop_back();
    probes.front().insert(probes.front().end(), probes.back().begin(), probes.back().end());
    probes.pop_back();
  }
  return probes;
}

// Each stretch's depth: the largest distance of its probes from the path,
// less r.
void OffsetBuilder::read_depths(const std::vector<std::vector<Vec3>>& probes) {
  for (size_t i = 0; i < res.left.size(); ++i) {
    double depth = 0;
    for (const Vec3& q : probes[i]) {
      double near = HUGE_VAL;
      for (const auto& chain : res.chains)
        for (const auto& s : chain) near = std::min(near, distance(s, q));
      depth = std::max(depth, near - r);
    }
    res.left[i].depth = depth;
  }
}

}  // namespace

OffsetResult offset_curve(std::span<const Bezier> pieces, bool closed, const OffsetOptions& opt) {
  OffsetBuilder b(opt, closed);
  b.fit_spline(pieces);
  if (b.A.empty()) return b.res;
  b.offset_side();
  if (closed)
    b.close_round();
  else
    b.round_open_ends(pieces);
  b.add_other_side();
  auto cuts = b.crossings();
  std::vector<Clipped> clipped;
  const std::vector<ArcSeg> kept = b.keep_valid(cuts, clipped);
  const auto probes = b.mark_left(clipped);
  flatten_detail::chain_pieces(kept, closed, {.eps = b.eps, .link = 1e-7 * b.scale, .fit = opt.fit}, b.res);
  b.read_depths(probes);
  b.res.bound += 2 * b.eps;
  return b.res;
}

}  // namespace bezcam
