#pragma once
/// A point or vector in model units. 2D geometry keeps z = 0 and records its
/// dimension on the curve, so one type serves 2D and 3D.
#include <algorithm>
#include <cmath>
#include <string>

#include "bezcam/format.hpp"

namespace bezcam {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_ = 0) : x(x_), y(y_), z(z_) {}

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  constexpr Vec3& operator*=(double s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline double dist(const Vec3& a, const Vec3& b) { return norm(a - b); }
/// Distance in the xy plane (z is ignored).
inline double dist_xy(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y); }
/// True when no coordinate is infinite or NaN.
inline bool all_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
/// Largest absolute coordinate: the magnitude that sets floating-point error.
inline double max_abs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }
/// a + t (b - a).
constexpr Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

/// Distance from p to the segment [a, b] (a point when a == b).
inline double dist_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  if (len2 == 0) return dist(p, a);
  const double s = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  return dist(p, a + ab * s);
}

/// Squared distance from p to the segment [a, b] in the xy plane (z is
/// ignored; a point when a == b).
inline double dist2_to_segment_xy(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double abx = b.x - a.x, aby = b.y - a.y;
  const double len2 = abx * abx + aby * aby;
  double s = 0;
  if (len2 > 0) s = std::clamp(((p.x - a.x) * abx + (p.y - a.y) * aby) / len2, 0.0, 1.0);
  const double dx = a.x + abx * s - p.x, dy = a.y + aby * s - p.y;
  return dx * dx + dy * dy;
}

/// Axis-aligned box.
struct Box3 {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  void add(const Box3& b) {
    if (!b.empty()) {
      add(b.lo);
      add(b.hi);
    }
  }
  bool empty() const { return lo.x > hi.x; }
  /// Whether `inner` lies within this box grown by `eps` on every side.
  bool contains(const Box3& inner, double eps = 0) const {
    for (int k = 0; k < 3; ++k)
      if (inner.lo[k] < lo[k] - eps || inner.hi[k] > hi[k] + eps) return false;
    return true;
  }
};

/// A point for messages: "(x, y, z)", or "(x, y)" when `dim` is 2, each
/// coordinate as fmt_num() writes it with `digits` significant digits.
inline std::string fmt_point(const Vec3& p, int dim = 3, int digits = 10) {
  return "(" + fmt_num(p.x, digits) + ", " + fmt_num(p.y, digits) +
         (dim == 3 ? ", " + fmt_num(p.z, digits) : std::string()) + ")";
}

}  // namespace bezcam
