// Tensor-product Bézier patches: the digest's facts (§5) exactly, then the
// exact constructions (iso-curves, normals, composition) against direct
// evaluation on seeded random patches.
#include "bezcam/kernel/bezier_patch.hpp"

#include <gtest/gtest.h>
#include <random>

#include "bezcam/error.hpp"
#include "support/surface_fixtures.hpp"

namespace bezcam {
namespace {

double rel_err(const Vec3& a, const Vec3& b, double scale) { return dist(a, b) / scale; }

TEST(BezierPatch, BorderCurvesAreTheBezierCurvesOfTheBorderRowsAndColumns) {
  std::mt19937 rng(11);
  for (bool rational : {false, true}) {
    const BezierPatch s = fixtures::random_patch(rng, 3, 4, rational);
    // S(0,v) is row 0, S(1,v) row n; S(u,0) column 0, S(u,1) column m.
    for (int side = 0; side < 2; ++side) {
      const Bezier row = iso_curve(s, 'v', side);
      const int i = side ? s.nu : 0;
      ASSERT_EQ(row.degree(), s.nv);
      for (int j = 0; j <= s.nv; ++j) {
        EXPECT_LE(dist(row.points[j], s.at(i, j)), 1e-13 * 50);
        if (rational) EXPECT_NEAR(row.weights[j] / row.weights[0], s.weight(i, j) / s.weight(i, 0), 1e-14);
      }
      const Bezier col = iso_curve(s, 'u', side);
      const int j = side ? s.nv : 0;
      ASSERT_EQ(col.degree(), s.nu);
      for (int k = 0; k <= s.nu; ++k) EXPECT_LE(dist(col.points[k], s.at(k, j)), 1e-13 * 50);
    }
  }
}

TEST(BezierPatch, CornersAreNetCornersAndInnerNetPointsAreNotInterpolated) {
  const BezierPatch s = fixtures::paraboloid(10, 20);
  EXPECT_EQ(evaluate(s, 0, 0), s.at(0, 0));
  EXPECT_EQ(evaluate(s, 1, 1), s.at(2, 2));
  // The centre net point A(1,1) = (0, 0, -2c) is below the surface's lowest point (0,0,0).
  EXPECT_NEAR(evaluate(s, 0.5, 0.5).z, 0, 1e-15);
  EXPECT_LT(s.at(1, 1).z, -1);
}

TEST(BezierPatch, DeCasteljauAndBernsteinFormsAgree) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> t(0, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const BezierPatch s = fixtures::random_patch(rng, 1 + trial % 5, 1 + (trial / 5) % 4, trial % 2);
    for (int k = 0; k < 10; ++k) {
      const double u = t(rng), v = t(rng);
      EXPECT_LE(rel_err(evaluate(s, u, v), evaluate_bernstein(s, u, v), 50), 1e-12);
    }
  }
}

TEST(BezierPatch, IsoCurvesAreBezierCurvesOfTheSameDegreeOnTheSurface) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> t(0, 1);
  for (int trial = 0; trial < 30; ++trial) {
    const BezierPatch s = fixtures::random_patch(rng, 1 + trial % 4, 2 + trial % 3, trial % 3 == 0);
    const double at = t(rng);
    const Bezier cu = iso_curve(s, 'u', at), cv = iso_curve(s, 'v', at);
    EXPECT_EQ(cu.degree(), s.nu);
    EXPECT_EQ(cv.degree(), s.nv);
    EXPECT_EQ(cu.rational(), s.rational());
    for (int k = 0; k < 8; ++k) {
      const double x = t(rng);
      EXPECT_LE(rel_err(evaluate(cu, x), evaluate(s, x, at), 50), 1e-12);
      EXPECT_LE(rel_err(evaluate(cv, x), evaluate(s, at, x), 50), 1e-12);
    }
  }
}

TEST(BezierPatch, PartialDerivativesMatchCentralDifferences) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> t(0.1, 0.9);
  for (bool rational : {false, true}) {
    const BezierPatch s = fixtures::random_patch(rng, 3, 3, rational);
    for (int k = 0; k < 10; ++k) {
      const double u = t(rng), v = t(rng), h = 1e-4;
      const PatchDerivs d = evaluate_derivs(s, u, v);
      EXPECT_LE(dist(d.p, evaluate(s, u, v)), 1e-12);
      const PatchDerivs du0 = evaluate_derivs(s, u - h, v), du1 = evaluate_derivs(s, u + h, v);
      const PatchDerivs dv0 = evaluate_derivs(s, u, v - h), dv1 = evaluate_derivs(s, u, v + h);
      const double sc = 1e-6 * (norm(d.su) + norm(d.sv) + norm(d.suu) + norm(d.svv) + norm(d.suv));
      EXPECT_LE(dist(d.su, (du1.p - du0.p) / (2 * h)), sc);
      EXPECT_LE(dist(d.sv, (dv1.p - dv0.p) / (2 * h)), sc);
      EXPECT_LE(dist(d.suu, (du1.su - du0.su) / (2 * h)), sc);
      EXPECT_LE(dist(d.suv, (dv1.su - dv0.su) / (2 * h)), sc);
      EXPECT_LE(dist(d.svv, (dv1.sv - dv0.sv) / (2 * h)), sc);
    }
  }
}

// |a x b| / (|a| |b|): zero when parallel.
double sin_angle(const Vec3& a, const Vec3& b) { return norm(cross(a, b)) / (norm(a) * norm(b)); }

TEST(BezierPatch, ExactNormalFieldsAreParallelToSuCrossSv) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> t(0, 1);
  for (bool rational : {false, true}) {
    const BezierPatch s = fixtures::random_patch(rng, 3, 2, rational);
    const BezierPatch np = normal_patch(s);
    EXPECT_EQ(np.nu, rational ? 11 : 5);
    EXPECT_EQ(np.nv, rational ? 7 : 3);
    for (int k = 0; k < 10; ++k) {
      const double u = t(rng), v = t(rng);
      const PatchDerivs d = evaluate_derivs(s, u, v);
      const Vec3 n = cross(d.su, d.sv);
      const Vec3 a = evaluate(np, u, v);
      EXPECT_LE(sin_angle(a, n), 1e-9);
      EXPECT_GT(dot(a, n), 0);
      const Vec3 iu = evaluate(iso_normal(s, 'u', v), u), iv = evaluate(iso_normal(s, 'v', u), v);
      EXPECT_LE(sin_angle(iu, n), 1e-9);
      EXPECT_GT(dot(iu, n), 0);
      EXPECT_LE(sin_angle(iv, n), 1e-9);
      EXPECT_GT(dot(iv, n), 0);
    }
  }
}

TEST(BezierPatch, CompositionIsTheSurfaceAlongTheCurveExactly) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> t(0, 1), w(0.5, 2);
  for (int trial = 0; trial < 12; ++trial) {
    const bool rat_patch = trial % 2, rat_curve = (trial / 2) % 2;
    const BezierPatch s = fixtures::random_patch(rng, 2 + trial % 2, 3, rat_patch);
    const int d = 1 + trial % 3;
    std::vector<Vec3> pts;
    std::vector<double> ws;
    for (int k = 0; k <= d; ++k) pts.push_back({t(rng), t(rng)}), ws.push_back(w(rng));
    const Bezier c = Bezier::make(pts, rat_curve ? ws : std::vector<double>{}, 2);
    const Bezier m = compose(s, c);
    EXPECT_EQ(m.degree(), (s.nu + s.nv) * d);
    EXPECT_EQ(m.rational(), rat_patch || rat_curve);
    for (double x : m.weights) EXPECT_GT(x, 0);
    const Bezier nd = compose_direction(normal_patch(s), c);
    for (int k = 0; k < 10; ++k) {
      const double x = t(rng);
      const Vec3 uv = evaluate(c, x);
      EXPECT_LE(rel_err(evaluate(m, x), evaluate(s, uv.x, uv.y), 50), 1e-11) << trial;
      const PatchDerivs dd = evaluate_derivs(s, uv.x, uv.y);
      EXPECT_LE(sin_angle(evaluate(nd, x), cross(dd.su, dd.sv)), 1e-8);
    }
  }
}

TEST(BezierPatch, SubpatchIsTheRestriction) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> t(0, 1);
  const BezierPatch s = fixtures::random_patch(rng, 3, 3, true);
  const BezierPatch p = subpatch(s, 0.2, 0.7, 0.1, 0.4);
  for (int k = 0; k < 10; ++k) {
    const double x = t(rng), y = t(rng);
    EXPECT_LE(rel_err(evaluate(p, x, y), evaluate(s, 0.2 + 0.5 * x, 0.1 + 0.3 * y), 50), 1e-12);
  }
}

TEST(BezierPatch, BoundsAreTightAndContainTheSurface) {
  // The paraboloid's lowest point (0,0,0) is inside; its net goes to -2c.
  const BezierPatch s = fixtures::paraboloid(10, 20);
  const Box3 b = bounds(s);
  EXPECT_NEAR(b.lo.z, 0, 1e-7);
  EXPECT_NEAR(b.hi.z, 2 * 100 / 40.0, 1e-7);
  EXPECT_LT(control_bounds(s).lo.z, -2);
  std::mt19937 rng(18);
  const BezierPatch r = fixtures::random_patch(rng, 3, 3, true);
  const Box3 rb = bounds(r);
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const Vec3 p = evaluate(r, i / 20.0, j / 20.0);
      for (int a = 0; a < 3; ++a) {
        EXPECT_GE(p[a], rb.lo[a] - 1e-9);
        EXPECT_LE(p[a], rb.hi[a] + 1e-9);
      }
    }
}

TEST(BezierPatch, RationalCylinderIsExact) {
  const BezierPatch s = fixtures::quarter_cylinder(25, 40, false);
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) {
      const Vec3 p = evaluate(s, i / 10.0, j / 10.0);
      EXPECT_NEAR(std::hypot(p.x, p.z), 25, 1e-12);
      EXPECT_NEAR(p.y, 40 * j / 10.0, 1e-12);
    }
}

TEST(BezierPatch, ValidationNamesThePlace) {
  auto where = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.where() + " | " + e.message();
    }
    return std::string("no error");
  };
  const std::string w1 = where([] { BezierPatch::make({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}}}); });
  EXPECT_EQ(w1.substr(0, 9), "points[1]");
  EXPECT_NE(w1.find("expected a row of 2 points"), std::string::npos);
  const std::string w2 = where([] {
    BezierPatch::make({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}}, {{1, 1}, {0, 1}});
  });
  EXPECT_EQ(w2.substr(0, 13), "weights[1][0]");
  const std::string w3 = where([] { BezierPatch::make({{{0, 0, 0}, {1, 0, 0}}}); });
  EXPECT_NE(w3.find("at least 2 rows"), std::string::npos);
  const std::string w4 = where([] { BezierPatch::make({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, NAN, 0}}}); });
  EXPECT_EQ(w4.substr(0, 12), "points[1][1]");
  // Equal weights: a polynomial patch.
  EXPECT_FALSE(BezierPatch::make({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}}, {{2, 2}, {2, 2}}).rational());
}

}  // namespace
}  // namespace bezcam
