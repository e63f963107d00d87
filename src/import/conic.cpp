#include "bezcam/import/conic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bezcam::import {

Affine Affine::after(const Affine& o) const {
  // this * o, as 3x3 matrices [a c e; b d f; 0 0 1].
  return {a * o.a + c * o.b, b * o.a + d * o.b,     a * o.c + c * o.d,
          b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
}

Piece line_piece(const Vec3& a, const Vec3& b) {
  Piece p;
  p.points = {a, b};
  return p;
}

std::vector<Piece> ellipse_arc(const Vec3& center, const Vec3& u, const Vec3& v, double t0, double sweep) {
  const double quarter = std::numbers::pi / 2;
  // Never more pieces than needed, never one above 90 degrees: a tiny
  // excess from rounding (sweep = pi/2 (1 + 1e-16)) must not add a piece.
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / quarter - 1e-12)));
  const double step = sweep / n;
  const double h = step / 2, w = std::cos(h);
  // cos and sin, exact at multiples of 90 degrees (a DXF arc from 270 to 0
  // degrees ends at (r, 0), not at (r, -2e-16)).
  const auto cs = [quarter](double t) {
    const double k = std::round(t / quarter);
    if (std::abs(t - k * quarter) <= 1e-13 * std::max(1.0, std::abs(t))) {
      const long q = ((static_cast<long>(k) % 4) + 4) % 4;
      static const double c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
      return std::pair{c[q], sn[q]};
    }
    return std::pair{std::cos(t), std::sin(t)};
  };
  const auto at = [&](double t) {
    const auto [c, s] = cs(t);
    return center + u * c + v * s;
  };
  std::vector<Piece> out;
  out.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double a = t0 + step * i;
    Piece p;
    // The middle control point is the tangents' intersection: p(m) pushed
    // out by 1 / cos(h); its weight cos(h) makes the piece the exact conic.
    // The tangents meet at the chord's midpoint pushed out by 1 / cos^2(h):
    // from the ends' own cos and sin, so a quarter arc's corner is exact.
    const double b = t0 + step * (i + 1);
    const auto [ca, sa] = cs(a);
    const auto [cb, sb] = cs(b);
    const double cstep = cs(step).first;
    p.points = {at(a), center + (u * (ca + cb) + v * (sa + sb)) / (1 + cstep), at(b)};
    p.weights = {1, w, 1};
    out.push_back(std::move(p));
  }
  // Shared ends are the same double, so consecutive pieces meet exactly.
  for (int i = 1; i < n; ++i)
    out[static_cast<size_t>(i)].points.front() = out[static_cast<size_t>(i) - 1].points.back();
  return out;
}

std::vector<Piece> svg_arc(const Vec3& from, double rx, double ry, double x_axis_rotation_deg, bool large_arc,
                           bool sweep, const Vec3& to) {
  if (from.x == to.x && from.y == to.y) return {};  // F.6.2: omitted
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0 || ry == 0) return {line_piece(from, to)};
  const double phi = x_axis_rotation_deg * std::numbers::pi / 180;
  const double cp = std::cos(phi), sp = std::sin(phi);
  // F.6.5 step 1: (x1', y1').
  const double dx = (from.x - to.x) / 2, dy = (from.y - to.y) / 2;
  const double x1 = cp * dx + sp * dy, y1 = -sp * dx + cp * dy;
  // F.6.6: radii too small are scaled up uniformly.
  const double lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
  if (lambda > 1) {
    const double s = std::sqrt(lambda);
    rx *= s;
    ry *= s;
  }
  // Step 2: (cx', cy').
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  double k = den > 0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
  if (large_arc == sweep) k = -k;
  const double cxp = k * rx * y1 / ry, cyp = -k * ry * x1 / rx;
  // Step 3: centre.
  const Vec3 c{cp * cxp - sp * cyp + (from.x + to.x) / 2, sp * cxp + cp * cyp + (from.y + to.y) / 2, from.z};
  // Step 4: angles, in the ellipse's own parameter.
  const double t1 = std::atan2((y1 - cyp) / ry, (x1 - cxp) / rx);
  const double t2 = std::atan2((-y1 - cyp) / ry, (-x1 - cxp) / rx);
  double dt = t2 - t1;
  const double two_pi = 2 * std::numbers::pi;
  if (sweep && dt < 0) dt += two_pi;
  if (!sweep && dt > 0) dt -= two_pi;
  const Vec3 u{rx * cp, rx * sp, 0}, v{-ry * sp, ry * cp, 0};
  std::vector<Piece> out = ellipse_arc(c, u, v, t1, dt);
  // The ends are the command's own points, exactly (the joints of a path).
  out.front().points.front() = from;
  out.back().points.back() = to;
  return out;
}

}  // namespace bezcam::import
