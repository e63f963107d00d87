#include "bezcam/kernel/arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bezcam {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
}  // namespace

int g_number(Plane p) { return 17 + static_cast<int>(p); }

int world_axis(Plane pl, int k) {
  // G17 (x, y, z), G18 (z, x, y), G19 (y, z, x).
  return (k + 3 - static_cast<int>(pl)) % 3;
}

Vec3 to_plane(const Vec3& p, Plane pl) { return {p[world_axis(pl, 0)], p[world_axis(pl, 1)], p[world_axis(pl, 2)]}; }

Vec3 from_plane(const Vec3& q, Plane pl) {
  Vec3 p;
  for (int k = 0; k < 3; ++k) p[world_axis(pl, k)] = q[k];
  return p;
}

namespace {
// The ends and the centre in plane coordinates.
struct Local {
  Vec3 f, t, c;
  explicit Local(const Arc& a)
      : f(to_plane(a.from, a.plane)), t(to_plane(a.to, a.plane)), c(to_plane(a.center, a.plane)) {}
};
}  // namespace

double Arc::start_angle() const {
  const Local l(*this);
  return std::atan2(l.f.y - l.c.y, l.f.x - l.c.x);
}

double Arc::r_start() const {
  const Local l(*this);
  return std::hypot(l.f.x - l.c.x, l.f.y - l.c.y);
}

double Arc::r_end() const {
  const Local l(*this);
  return std::hypot(l.t.x - l.c.x, l.t.y - l.c.y);
}

double Arc::sweep() const {
  // The difference of the ends' atan2 angles: the programs' outputs were
  // made with this rounding, so it stays the one formula.
  const Local l(*this);
  const double a0 = std::atan2(l.f.y - l.c.y, l.f.x - l.c.x);
  const double a1 = std::atan2(l.t.y - l.c.y, l.t.x - l.c.x);
  double s = ccw ? a1 - a0 : a0 - a1;
  while (s <= 0) s += kTwoPi;  // equal ends: a full circle
  while (s > kTwoPi) s -= kTwoPi;
  if (l.f.x == l.t.x && l.f.y == l.t.y) s = kTwoPi;
  return s;
}

Vec3 Arc::point(double s) const {
  if (s <= 0) return from;
  if (s >= 1) return to;
  return ArcPoints(*this).at(s);
}

ArcPoints::ArcPoints(const Arc& a)
    : from_(a.from),
      to_(a.to),
      a0_(a.start_angle()),
      w_(a.sweep()),
      r0_(a.r_start()),
      r1_(a.r_end()),
      ccw_(a.ccw),
      plane_(a.plane) {
  const Local l(a);
  c_ = l.c;
  z0_ = l.f.z;
  z1_ = l.t.z;
}

Vec3 ArcPoints::at(double s) const {
  if (s <= 0) return from_;
  if (s >= 1) return to_;
  const double a = ccw_ ? a0_ + s * w_ : a0_ - s * w_;
  const double r = r0_ + (r1_ - r0_) * s;
  return from_plane({c_.x + r * std::cos(a), c_.y + r * std::sin(a), z0_ + (z1_ - z0_) * s}, plane_);
}

Box3 arc_extent(const Arc& a) {
  Box3 box;
  box.add(a.from);
  box.add(a.to);
  const double w = a.sweep(), a0 = a.start_angle();
  // Axis directions within two turns either side cover every start angle.
  for (int q = -8; q <= 8; ++q) {
    const double ang = q * std::numbers::pi / 2;
    const double d = a.ccw ? ang - a0 : a0 - ang;  // angle travelled to reach ang
    if (d > 0 && d < w) box.add(a.point(d / w));
  }
  return box;
}

std::vector<Bezier> bezier_pieces(const Arc& a) {
  const double w = a.sweep();
  const int n = std::max(1, static_cast<int>(std::ceil(w / (std::numbers::pi / 2) - 1e-12)));
  const double th = w / n, dir = a.ccw ? 1 : -1;
  const double r = a.r_start(), a0 = a.start_angle();
  const Local l(a);
  const Vec3 c{l.c.x, l.c.y, l.f.z};
  auto on = [&](double ang, double rr) {
    return from_plane(c + Vec3{rr * std::cos(ang), rr * std::sin(ang), 0}, a.plane);
  };
  std::vector<Bezier> out;
  // Rational quadratic arc: middle point at r / cos(th/2) on the bisector,
  // weight cos(th/2) (The NURBS Book, section 7.3).
  for (int k = 0; k < n; ++k) {
    const double s = a0 + dir * th * k, e = s + dir * th, mid = s + dir * th / 2;
    Bezier z;
    z.dim = 3;
    z.points = {k == 0 ? a.from : on(s, r), on(mid, r / std::cos(th / 2)), k == n - 1 ? a.to : on(e, r)};
    z.weights = {1, std::cos(th / 2), 1};
    out.push_back(std::move(z));
  }
  return out;
}

}  // namespace bezcam
