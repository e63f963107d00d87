#include "bezcam/kernel/arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bezcam {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
}  // namespace

double Arc::start_angle() const { return std::atan2(from.y - center.y, from.x - center.x); }

double Arc::r_start() const { return std::hypot(from.x - center.x, from.y - center.y); }

double Arc::r_end() const { return std::hypot(to.x - center.x, to.y - center.y); }

double Arc::sweep() const {
  // The difference of the ends' atan2 angles: the programs' outputs were
  // made with this rounding, so it stays the one formula.
  const double a0 = start_angle();
  const double a1 = std::atan2(to.y - center.y, to.x - center.x);
  double s = ccw ? a1 - a0 : a0 - a1;
  while (s <= 0) s += kTwoPi;  // equal ends: a full circle
  while (s > kTwoPi) s -= kTwoPi;
  if (from.x == to.x && from.y == to.y) s = kTwoPi;
  return s;
}

Vec3 Arc::point(double s) const {
  if (s <= 0) return from;
  if (s >= 1) return to;
  const double w = sweep(), a0 = start_angle();
  const double a = ccw ? a0 + s * w : a0 - s * w;
  const double r0 = r_start(), r1 = r_end();
  const double r = r0 + (r1 - r0) * s;
  return {center.x + r * std::cos(a), center.y + r * std::sin(a), from.z + (to.z - from.z) * s};
}

Box3 xy_box(const Arc& a) {
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
  const Vec3 c{a.center.x, a.center.y, a.from.z};
  auto on = [&](double ang, double rr) { return c + Vec3{rr * std::cos(ang), rr * std::sin(ang), 0}; };
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
