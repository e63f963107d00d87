// Surface entities as exact grids: orientation, curvature with closed-form
// answers, exact curves on the surface (iso-curves across cells, mapped
// (u, v) curves crossing cell borders), restriction and reversal.
#include "bezcam/kernel/surface.hpp"

#include <gtest/gtest.h>
#include <random>

#include "support/surface_fixtures.hpp"

namespace bezcam {
namespace {

double sin_angle(const Vec3& a, const Vec3& b) { return norm(cross(a, b)) / (norm(a) * norm(b)); }

// A Coons patch with a two-piece boundary on each side: a 2 x 2 grid.
std::shared_ptr<const SurfaceGeometry> two_by_two() {
  const CoonsPatch c = fixtures::curved_coons(CoonsBlend::quintic);
  auto [a, b] = split(c.v0.pieces[0], 0.4);
  auto [d, e] = split(c.u1.pieces[0], 0.7);
  return SurfaceGeometry::make(CoonsPatch::make(BoundaryCurve::make({a, b}, {0, 0.4, 1}), c.v1, c.u0,
                                                BoundaryCurve::make({d, e}, {0, 0.7, 1}), CoonsBlend::quintic));
}

TEST(Surface, NormalPointsUpWhateverTheNetOrder) {
  BezierPatch p = fixtures::paraboloid(10, 20);
  auto s = SurfaceGeometry::make(p);
  EXPECT_EQ(s->orientation, 1);
  // Swapping u and v flips Su x Sv; the orientation compensates.
  std::vector<std::vector<Vec3>> rows(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rows[i].push_back(p.at(j, i));
  auto t = SurfaceGeometry::make(BezierPatch::make(rows));
  EXPECT_EQ(t->orientation, -1);
  for (double u : {0.1, 0.5, 0.8}) EXPECT_GT(unit_normal(*t, u, 0.3).z, 0.5);
}

TEST(Surface, PrincipalCurvaturesHaveClosedForms) {
  // Paraboloid z = (x^2 + y^2) / 2R: at the bottom both curvatures are 1/R
  // and the surface bends toward the (upward) normal: a valley, positive.
  auto par = SurfaceGeometry::make(fixtures::paraboloid(10, 20));
  const Curvatures c = principal_curvatures(*par, 0.5, 0.5);
  ASSERT_TRUE(c.defined);
  EXPECT_NEAR(c.k_max, 1 / 20.0, 1e-14);
  EXPECT_NEAR(c.k_min, 1 / 20.0, 1e-14);
  // Cylinders: crest (convex, -1/R and 0) and valley (concave, 1/R and 0).
  for (bool valley : {false, true}) {
    auto cyl = SurfaceGeometry::make(fixtures::quarter_cylinder(25, 40, valley));
    for (double u : {0.0, 0.3, 0.77, 1.0}) {
      const Curvatures k = principal_curvatures(*cyl, u, 0.5);
      EXPECT_NEAR(valley ? k.k_max : k.k_min, valley ? 1 / 25.0 : -1 / 25.0, 1e-12);
      EXPECT_NEAR(valley ? k.k_min : k.k_max, 0, 1e-12);
    }
  }
  // Saddle z = k x y at the origin: curvatures +-k.
  auto sad = SurfaceGeometry::make(fixtures::saddle(10, 0.02));
  const Curvatures k = principal_curvatures(*sad, 0, 0);
  EXPECT_NEAR(k.k_max, 0.02, 1e-14);
  EXPECT_NEAR(k.k_min, -0.02, 1e-14);
}

TEST(Surface, IsoCurvesAcrossCellsAreExactAndCarryTheirNormals) {
  auto s = two_by_two();
  ASSERT_EQ(s->grid.cells.size(), 4u);
  for (char dir : {'u', 'v'})
    for (double at : {0.0, 0.25, 0.7, 1.0}) {
      const SurfaceCurve c = iso_curve(*s, dir, at, true);
      ASSERT_EQ(c.points.size(), 2u);
      ASSERT_EQ(c.normals.size(), 2u);
      for (int k = 0; k <= 40; ++k) {
        const double t = k / 40.0;
        const auto [i, x] = locate(c, t);
        const double u = dir == 'u' ? t : at, v = dir == 'u' ? at : t;
        EXPECT_LE(dist(evaluate(c.points[i], x), evaluate(*s, u, v)), 1e-11);
        EXPECT_LE(sin_angle(evaluate(c.normals[i], x), unit_normal(*s, u, v)), 1e-9);
        EXPECT_GT(dot(evaluate(c.normals[i], x), unit_normal(*s, u, v)), 0);
        const auto [uu, vv] = uv_at(c, t);
        EXPECT_NEAR(uu, u, 1e-15);
        EXPECT_NEAR(vv, v, 1e-15);
      }
    }
}

TEST(Surface, MappedCurvesAreExactAcrossCellBorders) {
  auto s = two_by_two();
  // A uv path that crosses both the u = 0.4 and the v = 0.7 borders.
  const Bezier c1 = Bezier::make({{0.05, 0.1}, {0.9, 0.2}, {0.1, 0.95}, {0.85, 0.9}}, {}, 2);
  const Bezier c2 = Bezier::make({{0.85, 0.9}, {0.95, 0.5}, {0.6, 0.05}}, {1, 2, 1}, 2);
  CurveSegment seg1{"bezier", 3, false, 0, 1, nullptr}, seg2{"bezier", 2, true, 1, 1, nullptr};
  const CurveGeometry uv = make_path({seg1, seg2}, {c1, c2}, false, 2);
  const SurfaceCurve m = map_curve(*s, uv, true);
  EXPECT_GT(m.points.size(), 4u);  // split at the borders
  for (int k = 0; k <= 200; ++k) {
    const double t = k / 200.0;
    const double w = t * 2;
    const Vec3 p = w <= 1 ? evaluate(c1, w) : evaluate(c2, w - 1);
    const auto [i, x] = locate(m, t);
    EXPECT_LE(dist(evaluate(m.points[i], x), evaluate(*s, p.x, p.y)), 1e-10) << t;
    EXPECT_LE(sin_angle(evaluate(m.normals[i], x), unit_normal(*s, p.x, p.y)), 1e-8) << t;
    EXPECT_GT(dot(evaluate(m.normals[i], x), unit_normal(*s, p.x, p.y)), 0);
    const auto [uu, vv] = uv_at(m, t);
    EXPECT_NEAR(uu, p.x, 1e-12);
    EXPECT_NEAR(vv, p.y, 1e-12);
  }
  // Consecutive pieces meet.
  for (size_t i = 1; i < m.points.size(); ++i) EXPECT_LE(dist(m.points[i - 1].back(), m.points[i].front()), 1e-10);
}

TEST(Surface, RestrictAndReverseKeepTheGeometry) {
  auto s = two_by_two();
  const SurfaceCurve c = iso_curve(*s, 'u', 0.3, true);
  const SurfaceCurve r = restrict(c, 0.2, 0.9);
  const SurfaceCurve b = reversed(c);
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    const auto [i, x] = locate(r, t);
    EXPECT_LE(dist(evaluate(r.points[i], x), evaluate(*s, 0.2 + 0.7 * t, 0.3)), 1e-11);
    const auto [j, y] = locate(b, t);
    EXPECT_LE(dist(evaluate(b.points[j], y), evaluate(*s, 1 - t, 0.3)), 1e-11);
    EXPECT_NEAR(uv_at(b, t).first, 1 - t, 1e-14);
  }
}

}  // namespace
}  // namespace bezcam
