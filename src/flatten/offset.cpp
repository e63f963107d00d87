// The offset of a planar curve with a proven bound: see offset.hpp and
// docs/offset.md for the method and the argument.
#include "bezcam/flatten/offset.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/flatten_curve.hpp"

namespace bezcam {

namespace {
constexpr double kPi = std::numbers::pi;
Vec3 polar(const Vec3& c, double r, double ang) { return {c.x + r * std::cos(ang), c.y + r * std::sin(ang), 0}; }
// Angle in (-pi, pi].
double wrap(double a) {
  while (a <= -kPi) a += 2 * kPi;
  while (a > kPi) a -= 2 * kPi;
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
  if (u < 0) u += 2 * kPi;
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
  if (u < -slack) u += 2 * kPi;
  if (u > w + slack) {
    if (u - 2 * kPi >= -slack) u -= 2 * kPi;
    else return std::nullopt;
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
  if (p.arc && q.arc) cand = circle_circle(p.c, p.radius, q.c, q.radius);
  else if (p.arc) cand = line_circle(q.a, q.b - q.a, p.c, p.radius);
  else cand = line_circle(p.a, p.b - p.a, q.c, q.radius);
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
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / (kPi / 2) - 1e-12)));
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
  const auto poly = flatten(pieces, {.tolerance = std::max(size * 1e-5, 1e-9), .decimals = -1, .on_curve = true}).points;
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

}  // namespace

OffsetResult offset_curve(std::span<const Bezier> pieces, bool closed, const OffsetOptions& opt) {
  OffsetResult res;
  const double r = opt.distance;
  const int side = opt.side >= 0 ? 1 : -1;
  // 1. The arc spline A, without rounding.
  std::vector<ArcSeg> A;
  {
    ArcFitOptions ao;
    ao.tolerance = opt.fit;
    ao.decimals = -1;
    ao.radius_tolerance = HUGE_VAL;
    Vec3 from = flat(pieces.front().front());
    const double bound = fit_arcs(pieces, ao, [&](const FitMove& f) {
      const Vec3 to = flat(f.to);
      if (to == from) return;
      if (f.kind == FitKind::line) {
        A.push_back(ArcSeg::line(from, to));
      } else {
        const Arc arc{from, to, f.center, f.kind == FitKind::arc_ccw};
        A.push_back(ArcSeg::make_arc(from, to, f.center, arc.ccw ? arc.sweep() : -arc.sweep()));
      }
      from = to;
    });
    res.bound = bound;
  }
  res.fitted = A.size();
  if (A.empty()) return res;
  if (closed) A.back().b = A.front().a;
  double scale = r;
  for (const auto& s : A) scale = std::max({scale, max_abs(s.a), max_abs(s.b)});
  const double eps = 1e-9 * scale;  // floating-point margin of the tests below

  // 2. and 3. Exact offsets, joined by arcs of radius r about the joints.
  std::vector<Raw> raw;
  auto off = [&](const ArcSeg& s) {
    if (!s.arc) {
      const Vec3 t = s.tangent(0), n{-t.y * side * r, t.x * side * r, 0};
      return ArcSeg::line(s.a + n, s.b + n);
    }
    // Left of a counter-clockwise arc is towards its centre.
    const double k = s.sweep > 0 ? s.radius - side * r : s.radius + side * r;
    ArcSeg o = s;
    o.radius = std::abs(k);
    if (k < 0) o.a0 += kPi;
    o.a = polar(o.c, o.radius, o.a0);
    o.b = polar(o.c, o.radius, o.a0 + o.sweep);
    return o;
  };
  const size_t n = A.size();
  // The sweep of the arc about each joint (after A[i]; 0 where the offsets
  // meet): the other side's arc turns the same way, so that at a joint
  // where the curve turns back exactly (half a turn either way) the two
  // make the whole circle.
  std::vector<double> joint_turn(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    ArcSeg o = off(A[i]);
    if (!raw.empty()) {
      const Vec3 v = A[i].a, e = raw.back().seg.b;
      if (dist(e, o.a) <= eps) {
        o.a = e;
        if (o.arc) o.a0 = std::atan2(o.a.y - o.c.y, o.a.x - o.c.x);
      } else {
        const double a0 = std::atan2(e.y - v.y, e.x - v.x), a1 = std::atan2(o.a.y - v.y, o.a.x - v.x);
        ArcSeg j = ArcSeg::make_arc(e, o.a, v, wrap(a1 - a0));
        j.radius = r;
        raw.push_back({j, -1});
        joint_turn[i - 1] = j.sweep;
      }
    }
    raw.push_back({o, static_cast<int>(i)});
  }
  if (!closed) {
    // The ends of an open curve: A's end tangents may differ a little from
    // the curve's, so the path starts and ends where the true offset does,
    // rolling about the (exact) end points to there.
    auto true_normal = [&](const Bezier& b, double t, const ArcSeg& fallback, double s) {
      Vec3 d = derivative(b, t);
      if (std::hypot(d.x, d.y) == 0) d = fallback.tangent(s);
      const double l = std::hypot(d.x, d.y);
      return Vec3{-d.y / l * side * r, d.x / l * side * r, 0};
    };
    auto roll = [&](const Vec3& v, const Vec3& from, const Vec3& to) {
      const double a0 = std::atan2(from.y - v.y, from.x - v.x), a1 = std::atan2(to.y - v.y, to.x - v.x);
      ArcSeg j = ArcSeg::make_arc(from, to, v, wrap(a1 - a0));
      j.radius = r;
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
  if (closed) {
    const Vec3 v = A.front().a, e = raw.back().seg.b, s0 = raw.front().seg.a;
    if (dist(e, s0) <= eps) {
      raw.back().seg.b = s0;
    } else {
      const double a0 = std::atan2(e.y - v.y, e.x - v.x), a1 = std::atan2(s0.y - v.y, s0.x - v.x);
      ArcSeg j = ArcSeg::make_arc(e, s0, v, wrap(a1 - a0));
      j.radius = r;
      raw.push_back({j, -1});
      joint_turn[n - 1] = j.sweep;
    }
  }

  // The other side: where the curve doubles back on itself (a cusp, a spur
  // of zero width, a curl) the points at r from A on the side asked include
  // points of the other side's offsets and joints, and a piece of the path
  // crosses from valid to invalid where it meets them. They are cut
  // against like the rest, so that every piece is valid or invalid as a
  // whole, and for a closed curve they are kept where they are valid and on
  // the side's region (step 4).
  {
    auto other_off = [&](const ArcSeg& s) {
      if (!s.arc) {
        const Vec3 t = s.tangent(0), nn{t.y * side * r, -t.x * side * r, 0};
        return ArcSeg::line(s.a + nn, s.b + nn);
      }
      const double k = s.sweep > 0 ? s.radius + side * r : s.radius - side * r;
      ArcSeg o = s;
      o.radius = std::abs(k);
      if (k < 0) o.a0 += kPi;
      o.a = polar(o.c, o.radius, o.a0);
      o.b = polar(o.c, o.radius, o.a0 + o.sweep);
      return o;
    };
    auto about = [&](const Vec3& v, const Vec3& from, double sweep) {
      const Vec3 to = polar(v, r, std::atan2(from.y - v.y, from.x - v.x) + sweep);
      ArcSeg j = ArcSeg::make_arc(from, to, v, sweep);
      j.radius = r;
      return j;
    };
    std::vector<Raw> others;
    for (size_t i = 0; i < n; ++i) {
      const ArcSeg o = other_off(A[i]);
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
      others.push_back({about(A.front().a, A.front().a + Vec3{t0.y * side * r, -t0.x * side * r, 0}, -side * kPi), -1, true});
      others.push_back({about(A.back().b, A.back().b + Vec3{-t1.y * side * r, t1.x * side * r, 0}, -side * kPi), -1, true});
    }
    raw.insert(raw.end(), others.begin(), others.end());
  }

  // 4. Cut at every crossing (boxes sorted by x to skip far pairs).
  const size_t m = raw.size();
  std::vector<Box3> boxes(m);
  for (size_t i = 0; i < m; ++i) boxes[i] = box_of(raw[i].seg);
  std::vector<size_t> by_x(m);
  for (size_t i = 0; i < m; ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](size_t p, size_t q) { return boxes[p].lo.x < boxes[q].lo.x || (boxes[p].lo.x == boxes[q].lo.x && p < q); });
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
  // Sorted index of A for the distance test.
  std::vector<Box3> aboxes(n);
  for (size_t i = 0; i < n; ++i) aboxes[i] = box_of(A[i]);
  std::vector<size_t> a_by_x(n);
  for (size_t i = 0; i < n; ++i) a_by_x[i] = i;
  std::sort(a_by_x.begin(), a_by_x.end(), [&](size_t p, size_t q) { return aboxes[p].lo.x < aboxes[q].lo.x || (aboxes[p].lo.x == aboxes[q].lo.x && p < q); });
  double widest = 0;
  for (const auto& b : aboxes) widest = std::max(widest, b.hi.x - b.lo.x);
  const double keep_at = r - eps;
  auto valid = [&](const Vec3& p) {
    // dist(p, A) >= r - eps: no primitive of A nearer.
    const double lo = p.x - r - widest;
    auto it = std::lower_bound(a_by_x.begin(), a_by_x.end(), lo, [&](size_t k, double v) { return aboxes[k].lo.x < v; });
    for (; it != a_by_x.end() && aboxes[*it].lo.x <= p.x + r; ++it) {
      const Box3& b = aboxes[*it];
      if (p.x < b.lo.x - r || p.x > b.hi.x + r || p.y < b.lo.y - r || p.y > b.hi.y + r) continue;
      if (distance(A[*it], p) < keep_at) return false;
    }
    return true;
  };

  // The side's region of a closed curve: a valid point is at least r from
  // A, so A's arcs may be replaced by chords with a sagitta under r / 2
  // without moving it across; inside is a non-zero winding number (by the
  // crossings of a ray). The region asked is the inside when the side is
  // the left of a counter-clockwise curve or the right of a clockwise one.
  // A curve that bounds no area has no region: the other side's pieces
  // then cut the path and are not kept, as for an open curve.
  std::vector<Vec3> region;
  bool want_inside = false;
  if (closed) {
    for (const ArcSeg& a : A) {
      region.push_back(a.a);
      if (!a.arc) continue;
      const double most = a.radius <= r / 4 ? kPi / 2 : std::min(kPi / 2, 2 * std::acos(1 - r / (2 * a.radius)));
      const int parts = std::max(1, static_cast<int>(std::ceil(std::abs(a.sweep) / most)));
      for (int q = 1; q < parts; ++q) region.push_back(a.point(static_cast<double>(q) / parts));
    }
    double area = 0;
    for (size_t i = 0; i < region.size(); ++i) {
      const Vec3& p = region[i];
      const Vec3& q = region[(i + 1) % region.size()];
      area += p.x * q.y - q.x * p.y;
    }
    if (std::abs(area) <= 1e-9 * scale * scale) region.clear();
    want_inside = (side > 0) == (area > 0);
  }
  auto in_region = [&](const Vec3& p) {
    int w = 0;
    for (size_t i = 0; i < region.size(); ++i) {
      const Vec3& a = region[i];
      const Vec3& b = region[(i + 1) % region.size()];
      if ((a.y > p.y) == (b.y > p.y)) continue;
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (x > p.x) w += b.y > a.y ? 1 : -1;
    }
    return (w != 0) == want_inside;
  };

  struct Piece {
    ArcSeg seg;
    int source;
    double s0, s1;
  };
  std::vector<Piece> kept;
  // Clipped stretches of the curve, in order along it.
  std::vector<std::pair<int, std::pair<double, double>>> clipped;
  for (size_t i = 0; i < m; ++i) {
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
      bool ok = valid(part.point(0.5)) && (part.length() < 1e3 * eps || (valid(part.point(0.25)) && valid(part.point(0.75))));
      if (ok) ok = region.empty() ? !raw[i].other : in_region(part.point(0.5));
      if (ok) kept.push_back({part, raw[i].source, s0, s1});
      else if (raw[i].source >= 0) clipped.push_back({raw[i].source, {s0, s1}});
    }
  }
  // Material left: merge clipped stretches that meet along A.
  std::vector<std::vector<Vec3>> left_probes;
  for (const auto& [src, range] : clipped) {
    const ArcSeg& a = A[static_cast<size_t>(src)];
    const Vec3 f = a.point(range.first), t = a.point(range.second);
    const double l = a.length() * (range.second - range.first);
    // How deep the material stands: the curve's distance from the path,
    // less r (measured at the stretch's middle, once the path is known).
    const Vec3 mid = a.point(0.5 * (range.first + range.second));
    if (!res.left.empty() && dist(res.left.back().to, f) <= 1e3 * eps) {
      res.left.back().to = t;
      res.left.back().length += l;
      res.left.back().points.push_back(mid);
      res.left.back().points.push_back(t);
      left_probes.back().push_back(mid);
    } else {
      res.left.push_back({f, t, l, 0, {f, mid, t}});
      left_probes.push_back({f, mid, t});
    }
  }
  if (closed && res.left.size() > 1 && dist(res.left.back().to, res.left.front().from) <= 1e3 * eps) {
    res.left.front().from = res.left.back().from;
    res.left.front().length += res.left.back().length;
    auto pts = res.left.back().points;
    pts.insert(pts.end(), res.left.front().points.begin() + 1, res.left.front().points.end());
    res.left.front().points = std::move(pts);
    res.left.pop_back();
    left_probes.front().insert(left_probes.front().end(), left_probes.back().begin(), left_probes.back().end());
    left_probes.pop_back();
  }

  // Chain the kept pieces: each continues with the kept piece that starts
  // where it ends, the next one along the raw path first.
  const double link = 1e-7 * scale;
  const size_t k = kept.size();
  std::vector<int> next(k, -1), prev(k, -1);
  for (size_t i = 0; i < k; ++i) {
    int best = -1;
    double best_d = link;
    for (size_t step = 1; step <= k; ++step) {
      const size_t j = (i + step) % k;
      if (!closed && j <= i) break;
      if (prev[j] >= 0) continue;
      const double d = dist(kept[i].seg.b, kept[j].seg.a);
      if (d <= best_d) {
        best = static_cast<int>(j);
        best_d = d;
        if (d <= eps) break;
      }
    }
    if (best >= 0 && best != static_cast<int>(i)) {
      next[i] = best;
      prev[static_cast<size_t>(best)] = static_cast<int>(i);
    } else if (best == static_cast<int>(i)) {
      next[i] = best;
      prev[i] = best;
    }
  }
  std::vector<bool> used(k, false);
  auto walk = [&](size_t from) {
    std::vector<ArcSeg> chain;
    size_t i = from;
    bool loop = false;
    while (!used[i]) {
      used[i] = true;
      ArcSeg s = kept[i].seg;
      if (!chain.empty()) s.a = chain.back().b;  // the shared crossing, exactly
      // A crumb (a kink's sliver, a touch) is absorbed by its neighbour.
      if (!chain.empty() && s.length() <= 1e3 * eps) {
        ArcSeg& last = chain.back();
        if (last.arc) {
          last = ArcSeg::make_arc(last.a, s.b, last.c, last.sweep);
        } else {
          last.b = s.b;
        }
      } else if (!chain.empty() && chain.back().arc == s.arc && !s.arc &&
                 std::abs(cross(chain.back().tangent(0), s.tangent(0)).z) < 1e-12 &&
                 dot(chain.back().tangent(0), s.tangent(0)) > 0) {
        // one line on (a line that turns back is a spur the tool goes into)
        chain.back().b = s.b;
      } else {
        chain.push_back(s);
      }
      if (next[i] < 0) break;
      i = static_cast<size_t>(next[i]);
      if (i == from) {
        loop = true;
        break;
      }
    }
    if (chain.size() > 1 && chain.front().length() <= 1e3 * eps) {
      chain[1].a = chain.front().a;
      if (chain[1].arc) chain[1] = ArcSeg::make_arc(chain[1].a, chain[1].b, chain[1].c, chain[1].sweep);
      chain.erase(chain.begin());
    }
    if (loop && !chain.empty()) chain.back().b = chain.front().a;
    // A loop of the chain that closes on itself within the fit is cut
    // out: at a small kink of A the two offsets overshoot their crossing,
    // and the overshoots with the join between them are valid within the
    // floating-point margin, so the chain ran past the crossing, back and
    // on again. Every point taken out is a valid one, and the chain
    // stays continuous (the loop starts and ends at one point). A closed
    // chain is read twice, from its start and from its middle, for a loop
    // over its start.
    auto excise = [&](std::vector<ArcSeg>& ch) {
      std::vector<ArcSeg> out;
      for (ArcSeg s : ch) {
        if (!out.empty()) s.a = out.back().b;
        out.push_back(s);
        double around = 0;
        for (size_t q = out.size(); q-- > 0;) {
          around += out[q].length();
          if (around > opt.fit) break;
          if (dist(out[q].a, out.back().b) <= link) {
            out.erase(out.begin() + static_cast<std::ptrdiff_t>(q), out.end());
            break;
          }
        }
      }
      ch = std::move(out);
    };
    excise(chain);
    // A chain that comes back to its start and runs on into such crumbs
    // (or starts in them) is closed where it comes back.
    if (!loop && chain.size() > 2) {
      double around = 0;
      for (size_t q = chain.size() - 1; q > 1 && (around += chain[q].length()) <= opt.fit; --q)
        if (dist(chain[q - 1].b, chain.front().a) <= link) {
          chain.erase(chain.begin() + static_cast<std::ptrdiff_t>(q), chain.end());
          loop = true;
          break;
        }
      around = 0;
      for (size_t q = 0; !loop && q + 2 < chain.size() && (around += chain[q].length()) <= opt.fit; ++q)
        if (dist(chain[q + 1].a, chain.back().b) <= link) {
          chain.erase(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(q + 1));
          loop = true;
        }
      if (loop) chain.back().b = chain.front().a;
    }
    if (loop && chain.size() > 2) {
      std::rotate(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(chain.size() / 2), chain.end());
      excise(chain);
      if (!chain.empty()) chain.back().b = chain.front().a;
    }
    double len = 0;
    for (const auto& s : chain) len += s.length();
    // A sliver shorter than the fit is a crumb of a crossing (at a small
    // kink of A): every point of it is valid, but it cuts nothing.
    if (len > std::max(1e3 * eps, opt.fit)) {
      res.chains.push_back(std::move(chain));
      res.closed.push_back(loop);
    }
  };
  for (size_t i = 0; i < k; ++i)
    if (prev[i] < 0 && !used[i]) walk(i);
  for (size_t i = 0; i < k; ++i)
    if (!used[i]) walk(i);
  for (size_t i = 0; i < res.left.size(); ++i) {
    double depth = 0;
    for (const Vec3& q : left_probes[i]) {
      double near = HUGE_VAL;
      for (const auto& chain : res.chains)
        for (const auto& s : chain) near = std::min(near, distance(s, q));
      depth = std::max(depth, near - r);
    }
    res.left[i].depth = depth;
  }
  res.bound += 2 * eps;
  return res;
}

}  // namespace bezcam
