#pragma once
// Patches with known closed-form geometry, shared by the surface tests of
// every layer (kernel, flatten, post).
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "bezcam/kernel/bezier_patch.hpp"
#include "bezcam/kernel/coons_patch.hpp"
#include "bezcam/kernel/surface.hpp"

namespace bezcam::fixtures {

/// Random polynomial or rational patch of degrees (nu, nv), coordinates in
/// [-50, 50], weights in [0.5, 2].
inline BezierPatch random_patch(std::mt19937& rng, int nu, int nv, bool rational) {
  std::uniform_real_distribution<double> c(-50, 50), w(0.5, 2);
  std::vector<std::vector<Vec3>> rows(nu + 1);
  std::vector<std::vector<double>> ws;
  for (auto& r : rows)
    for (int j = 0; j <= nv; ++j) r.push_back({c(rng), c(rng), c(rng)});
  if (rational) {
    ws.resize(nu + 1);
    for (auto& r : ws)
      for (int j = 0; j <= nv; ++j) r.push_back(w(rng));
  }
  return BezierPatch::make(rows, ws);
}

/// Paraboloid z = (x^2 + y^2) / (2 R) over [-a, a]^2 (a valley of
/// curvature 1/R at its bottom), exactly, as a biquadratic patch: x and y
/// are linear, z separable, so A(i,j) = (x_i, y_j, zx_i + zy_j).
inline BezierPatch paraboloid(double a, double R, double z0 = 0) {
  const double c = a * a / (2 * R);
  const double x[3] = {-a, 0, a}, z[3] = {c, -c, c};
  std::vector<std::vector<Vec3>> rows(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rows[i].push_back({x[i], x[j], z0 + z[i] + z[j]});
  return BezierPatch::make(rows);
}

/// Hyperbolic paraboloid (saddle) z = k x y over [0, a]^2: bilinear, so
/// exactly the patch of its four corners (degree 1 x 1).
inline BezierPatch saddle(double a, double k) {
  return BezierPatch::make({{{0, 0, 0}, {0, a, 0}}, {{a, 0, 0}, {a, a, k * a * a}}});
}

/// Quarter cylinder of radius R around the y axis, y in [0, len]: the
/// rational quadratic quarter circle x = R sin, z = R cos (a crest) or its
/// mirror z = -R cos + R (a valley), times a line in y.
inline BezierPatch quarter_cylinder(double R, double len, bool valley) {
  const double s = valley ? -1 : 1, z0 = valley ? R : 0;
  const Vec3 arc[3] = {{0, 0, z0 + s * R}, {R, 0, z0 + s * R}, {R, 0, z0}};
  std::vector<std::vector<Vec3>> rows(3);
  std::vector<std::vector<double>> w(3);
  const double ww[3] = {1, std::sqrt(0.5), 1};
  for (int i = 0; i < 3; ++i) {
    rows[i] = {arc[i], arc[i] + Vec3{0, len, 0}};
    w[i] = {ww[i], ww[i]};
  }
  return BezierPatch::make(rows, w);
}

inline Bezier cubic3(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return Bezier::make({a, b, c, d}, {}, 3); }
inline Bezier line3(Vec3 a, Vec3 b) { return Bezier::make({a, b}, {}, 3); }

/// A Coons patch from four curved cubic edges over roughly [0,100]x[0,80].
inline CoonsPatch curved_coons(CoonsBlend blend) {
  const Vec3 p00{0, 0, 0}, p10{100, 0, 5}, p01{0, 80, 8}, p11{100, 80, 0};
  auto v0 = cubic3(p00, {30, -10, 12}, {70, 10, 14}, p10);
  auto v1 = cubic3(p01, {35, 90, 20}, {65, 70, 16}, p11);
  auto u0 = cubic3(p00, {-8, 25, 10}, {8, 55, 15}, p01);
  auto u1 = cubic3(p10, {110, 30, 12}, {95, 50, 9}, p11);
  return CoonsPatch::make(BoundaryCurve::make({v0}), BoundaryCurve::make({v1}), BoundaryCurve::make({u0}),
                          BoundaryCurve::make({u1}), blend);
}

}  // namespace bezcam::fixtures
