// Surface passes: the tip-curve bound checked by independent brute-force
// measurement (the tip recomputed from the surface's own derivatives, not
// from the exact normal pieces), closed-form offsets, pass spacing measured
// on the polylines, adaptivity against the uniform baseline, gouges.
#include <gtest/gtest.h>
#include <random>

#include "bezcam/cam/gouge.hpp"
#include "bezcam/cam/pass_plan.hpp"
#include "bezcam/error.hpp"
#include "support/surface_fixtures.hpp"

namespace bezcam {
namespace {

constexpr double kTol = 0.01;

// Independent tip: S + r (N - z) with N from evaluate_derivs().
Vec3 direct_tip(const SurfaceGeometry& s, double r, double u, double v) {
  return evaluate(s, u, v) + (unit_normal(s, u, v) - Vec3{0, 0, 1}) * r;
}

double dist_to_poly(const Vec3& x, const std::vector<Vec3>& p) {
  if (p.size() == 1) return dist(x, p[0]);
  double m = 1e300;
  for (size_t i = 0; i + 1 < p.size(); ++i) m = std::min(m, dist_to_segment(x, p[i], p[i + 1]));
  return m;
}

// Two-sided distance between the tip iso-curve and the polyline by brute
// force: 3000 curve samples against every segment; the polyline sampled
// every tol/10 against the dense curve polyline near the same parameters
// (a window: the distance found is never below the true one).
double brute_deviation(const SurfaceGeometry& s, double r, char dir, double at, const TipPolyline& p) {
  constexpr int kN = 3000;
  std::vector<Vec3> dense;
  for (int k = 0; k <= kN; ++k) {
    const double t = double(k) / kN;
    dense.push_back(dir == 'u' ? direct_tip(s, r, t, at) : direct_tip(s, r, at, t));
  }
  double d = 0;
  for (const auto& x : dense) d = std::max(d, dist_to_poly(x, p.points));
  const auto& poly = p.points;
  for (size_t i = 0; i + 1 < poly.size(); ++i) {
    const int n = 1 + static_cast<int>(dist(poly[i], poly[i + 1]) / (kTol / 10));
    const double span = (p.params[i + 1] - p.params[i]) * kN;
    for (int k = 0; k <= n; ++k) {
      const double f = double(k) / n;
      const int mid = static_cast<int>((p.params[i] + f * (p.params[i + 1] - p.params[i])) * kN);
      const int w = 25 + static_cast<int>(0.05 * span);
      const std::vector<Vec3> win(dense.begin() + std::max(0, mid - w), dense.begin() + std::min(kN, mid + w) + 1);
      d = std::max(d, dist_to_poly(lerp(poly[i], poly[i + 1], f), win));
    }
  }
  return d;
}

struct Case {
  const char* name;
  std::shared_ptr<const SurfaceGeometry> s;
  double r;
};

std::vector<Case> cases() {
  std::mt19937 rng(31);
  BezierPatch wavy = fixtures::random_patch(rng, 3, 3, false);
  // Flatten the random net into a gentle height field over [0,100]^2.
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      Vec3& p = wavy.points[size_t(i) * 4 + j];
      p = {100.0 * i / 3, 100.0 * j / 3, p.z * 0.2};
    }
  return {{"paraboloid-r0", SurfaceGeometry::make(fixtures::paraboloid(30, 40)), 0},
          {"paraboloid-r6", SurfaceGeometry::make(fixtures::paraboloid(30, 40)), 6},
          {"saddle-r5", SurfaceGeometry::make(fixtures::saddle(60, 0.01)), 5},
          {"wavy-r3", SurfaceGeometry::make(wavy), 3},
          {"cylinder-r5", SurfaceGeometry::make(fixtures::quarter_cylinder(25, 40, false)), 5},
          {"coons-r4", SurfaceGeometry::make(fixtures::curved_coons(CoonsBlend::cubic)), 4}};
}

TEST(FlattenSurface, TipCurveBoundHoldsByIndependentMeasurement) {
  for (const auto& c : cases()) {
    for (char dir : {'u', 'v'})
      for (double at : {0.0, 0.35, 1.0}) {
        const SurfaceCurve iso = iso_curve(*c.s, dir, at, c.r > 0);
        const TipPolyline p = flatten_tip(iso, c.r, {kTol, 3});
        ASSERT_GE(p.points.size(), 2u);
        EXPECT_LE(p.bound, kTol) << c.name;
        const double brute = brute_deviation(*c.s, c.r, dir, at, p);
        EXPECT_LE(brute, p.bound + 1e-5) << c.name << " " << dir << at;
        const Deviation m = measure_tip(iso, c.r, p);
        EXPECT_LE(m.max(), p.bound + 1e-7) << c.name;
        EXPECT_NEAR(m.max(), brute, 2e-4) << c.name << " " << dir << at;
        // Parameters increase from 0 to 1 and each vertex is the rounded tip there.
        EXPECT_EQ(p.params.front(), 0);
        EXPECT_EQ(p.params.back(), 1);
        for (size_t i = 0; i < p.points.size(); ++i) {
          const double t = p.params[i];
          const Vec3 x = dir == 'u' ? direct_tip(*c.s, c.r, t, at) : direct_tip(*c.s, c.r, at, t);
          EXPECT_LE(dist(x, p.points[i]), 0.0009) << c.name;
        }
      }
  }
}

// approximate_tip(): the rational pieces follow the tip at the same
// parameter within their proven bound (checked against the tip recomputed
// from the surface), and measure_tip() catches a copy moved by more than
// the tolerance.
TEST(FlattenSurface, TipApproximationHoldsItsBoundAndAWrongOneIsMeasured) {
  for (const auto& c : cases()) {
    for (char dir : {'u', 'v'}) {
      const double at = 0.35;
      const SurfaceCurve iso = iso_curve(*c.s, dir, at, c.r > 0);
      const auto ap = approximate_tip(iso, c.r, 0.25 * kTol);
      ASSERT_TRUE(ap.has_value()) << c.name;
      ASSERT_EQ(ap->breaks.size(), ap->pieces.size() + 1);
      EXPECT_EQ(ap->breaks.front(), 0);
      EXPECT_EQ(ap->breaks.back(), 1);
      EXPECT_LE(ap->bound, 0.25 * kTol) << c.name;
      if (c.r == 0) EXPECT_EQ(ap->bound, 0);
      double worst = 0;
      TipPolyline dense, moved;
      for (size_t k = 0; k < ap->pieces.size(); ++k)
        for (int i = k ? 1 : 0; i <= 200; ++i) {
          const double x = i / 200.0, t = ap->breaks[k] + x * (ap->breaks[k + 1] - ap->breaks[k]);
          const Vec3 want = dir == 'u' ? direct_tip(*c.s, c.r, t, at) : direct_tip(*c.s, c.r, at, t);
          const Vec3 got = evaluate(ap->pieces[k], x);
          worst = std::max(worst, dist(want, got));
          dense.points.push_back(got);
          dense.params.push_back(t);
          moved.points.push_back(k == 0 && i == 100 ? got + Vec3{0, 0, 3 * kTol} : got);
          moved.params.push_back(t);
        }
      EXPECT_LE(worst, ap->bound + 1e-9) << c.name;
      EXPECT_LE(measure_tip(iso, c.r, dense).max(), ap->bound + 0.05 * kTol) << c.name;
      EXPECT_GT(measure_tip(iso, c.r, moved).max(), 2 * kTol) << c.name;
      // The measurement of printed pieces (surface blocks): the pieces
      // themselves read within their bound; one piece moved
      // (all its points) by 5 tolerances reads well above the tolerance.
      const double exact = measure_tip_pieces(iso, c.r, ap->pieces, ap->breaks).max();
      EXPECT_LE(exact, ap->bound + 1e-9) << c.name;
      EXPECT_GE(exact, 0.5 * worst - 1e-9) << c.name;
      std::vector<Bezier> wrong = ap->pieces;
      for (auto& p : wrong[wrong.size() / 2].points) p += Vec3{0, 0, 5 * kTol};
      EXPECT_GT(measure_tip_pieces(iso, c.r, wrong, ap->breaks).max(), 1.5 * kTol) << c.name;
    }
  }
}

TEST(FlattenSurface, CurveOnASurfaceWithABallEndToolHoldsItsBound) {
  // An S-shaped (u, v) path on the rational cylinder and on a Coons grid,
  // ridden by a ball of radius 4: the bound checked against the tip
  // recomputed from the surface at c(w), sampled densely.
  const Bezier c1 = Bezier::make({{0.05, 0.1}, {0.9, 0.2}, {0.1, 0.95}, {0.85, 0.9}}, {}, 2);
  CurveSegment seg{"bezier", 3, false, 0, 1, nullptr};
  const CurveGeometry uv = make_single(seg, {c1}, 2);
  for (auto s : {SurfaceGeometry::make(fixtures::quarter_cylinder(25, 40, false)),
                 SurfaceGeometry::make(fixtures::curved_coons(CoonsBlend::quintic))}) {
    const double r = 4;
    const SurfaceCurve m = map_curve(*s, uv, true);
    const TipPolyline p = flatten_tip(m, r, {kTol, 3});
    EXPECT_LE(p.bound, kTol);
    std::vector<Vec3> dense;
    for (int k = 0; k <= 6000; ++k) {
      const Vec3 q = evaluate(c1, k / 6000.0);
      dense.push_back(direct_tip(*s, r, q.x, q.y));
    }
    double d = 0;
    for (const auto& x : dense) d = std::max(d, dist_to_poly(x, p.points));
    for (size_t i = 0; i + 1 < p.points.size(); ++i)
      for (double f : {0.25, 0.5, 0.75}) d = std::max(d, dist_to_poly(lerp(p.points[i], p.points[i + 1], f), dense));
    EXPECT_LE(d, p.bound + 1e-5);
    EXPECT_GT(d, 0.3 * kTol);  // and the bound is not vacuous
  }
}

TEST(FlattenSurface, BallOnACylinderHasItsCentreOnTheOffsetCircle) {
  // Crest cylinder of radius 25 around the y axis: the ball centre (tip +
  // r z) lies at distance 25 + r from the axis, exactly.
  auto s = SurfaceGeometry::make(fixtures::quarter_cylinder(25, 40, false));
  for (double r : {2.0, 6.0}) {
    const TipPolyline p = flatten_tip(iso_curve(*s, 'u', 0.5, true), r, {kTol, 4});
    for (const auto& x : p.points) EXPECT_NEAR(std::hypot(x.x, x.z + r), 25 + r, 1e-4);
    // Chord midpoints stay within the tolerance of the circle too.
    for (size_t i = 0; i + 1 < p.points.size(); ++i) {
      const Vec3 m = lerp(p.points[i], p.points[i + 1], 0.5);
      EXPECT_LE(25 + r - std::hypot(m.x, m.z + r), kTol);
    }
  }
}

TEST(FlattenSurface, PolylineGapBoundIsRigorousAndTight) {
  TipPolyline a, b;
  for (int i = 0; i <= 10; ++i) {
    a.points.push_back({i * 10.0, 0, 0});
    a.params.push_back(i / 10.0);
    b.points.push_back({i * 10.0, 3, 4.0 * (i % 2)});
    b.params.push_back(i / 10.0);
  }
  // Farthest: b's odd vertices are 5 from a.
  const double g = polyline_gap_bound(a, b, 0.05, 10);
  EXPECT_GE(g, 5);
  EXPECT_LE(g, 5 + 0.025 + 1e-12);
  // A polyline shifted along itself: the windowed search must not be fooled.
  TipPolyline c = a;
  for (auto& p : c.points) p.x += 50;
  EXPECT_NEAR(polyline_gap_bound(a, c, 0.05, 1), 50 + 0.025, 1e-9);
}

// Brute-force two-sided distance between polylines.
double brute_gap(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double step) {
  double g = 0;
  for (int side = 0; side < 2; ++side) {
    const auto& x = side ? b : a;
    const auto& y = side ? a : b;
    for (size_t i = 0; i + 1 < x.size(); ++i) {
      const int n = 1 + static_cast<int>(dist(x[i], x[i + 1]) / step);
      for (int k = 0; k <= n; ++k) g = std::max(g, dist_to_poly(lerp(x[i], x[i + 1], double(k) / n), y));
    }
  }
  return g;
}

TEST(FlattenSurface, NeighbouringPassesAreNeverFartherApartThanTheStepover) {
  for (const auto& c : cases()) {
    for (char dir : {'u', 'v'}) {
      PassOptions o;
      o.direction = dir;
      o.stepover = 3;
      o.tolerance = kTol;
      o.decimals = 3;
      o.tool_radius = c.r;
      const PassPlan plan = plan_passes(*c.s, o);
      ASSERT_GE(plan.passes.size(), 2u);
      EXPECT_EQ(plan.passes.front().at, 0);
      EXPECT_EQ(plan.passes.back().at, 1);
      EXPECT_LE(plan.gap_bound, o.stepover);
      EXPECT_LE(plan.bound, kTol);
      double worst = 0;
      for (size_t i = 0; i + 1 < plan.passes.size(); ++i) {
        EXPECT_LT(plan.passes[i].at, plan.passes[i + 1].at);
        worst = std::max(worst, brute_gap(plan.passes[i].poly.points, plan.passes[i + 1].poly.points, 0.1));
      }
      EXPECT_LE(worst, o.stepover) << c.name << " " << dir;
      EXPECT_LE(worst, plan.gap_bound + 1e-9) << c.name;
      // Not wasteful: the widest pair uses most of the stepover.
      EXPECT_GE(worst, 0.8 * o.stepover) << c.name << " " << dir;
    }
  }
}

TEST(FlattenSurface, StretchedRegionsGetMorePassesThanUniformSpacingWouldNeedEverywhere) {
  // y(v) = 10 v + 90 v^3: the patch is stretched 28 times near v = 1; a
  // ridge in u makes the passes curved.
  const double y[4] = {0, 10.0 / 3, 20.0 / 3, 100};
  const double x[3] = {0, 25, 50}, z[3] = {0, 10, 0};
  std::vector<std::vector<Vec3>> rows(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) rows[i].push_back({x[i], y[j], z[i]});
  auto s = SurfaceGeometry::make(BezierPatch::make(rows));
  PassOptions o;
  o.direction = 'u';
  o.stepover = 2;
  o.tolerance = kTol;
  o.decimals = 3;
  const PassPlan a = plan_passes(*s, o), u = plan_uniform_passes(*s, o);
  // Parameter steps shrink where the patch stretches.
  const auto& P = a.passes;
  EXPECT_GT(P[1].at - P[0].at, 5 * (P.back().at - P[P.size() - 2].at));
  // The distance is 100 in y: about 50 gaps of 2; uniform spacing must use
  // the smallest step everywhere.
  EXPECT_LE(a.passes.size(), 60u);
  EXPECT_GT(u.passes.size(), 2 * a.passes.size());
  EXPECT_LE(u.gap_bound, o.stepover);
  EXPECT_LE(a.gap_bound, o.stepover);
}

TEST(FlattenSurface, StepoverBelowFourTolerancesIsRefused) {
  auto s = SurfaceGeometry::make(fixtures::saddle(10, 0.01));
  PassOptions o;
  o.stepover = 0.03;
  o.tolerance = kTol;
  try {
    plan_passes(*s, o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "toolpath.stepover");
    EXPECT_NE(e.message().find("at least 4 times the tolerance"), std::string::npos) << e.message();
  }
}

TEST(FlattenSurface, GougesAreFoundWhereTheValleyIsTighterThanTheTool) {
  // Paraboloid z = (x^2 + y^2) / 40 over [-30, 30]^2: along y = 0 the larger
  // principal curvature is 1 / (20 sqrt(1 + x^2/400)); a ball of radius 30
  // gouges where that radius is below 30: |x| < sqrt(30^2 - 20^2).
  auto s = SurfaceGeometry::make(fixtures::paraboloid(30, 20));
  const SurfaceCurve pass = iso_curve(*s, 'u', 0.5, true);
  const auto spans = find_gouges(*s, pass, 30, 256);
  ASSERT_EQ(spans.size(), 1u);
  const double half = std::sqrt(900.0 - 400.0) / 60;
  EXPECT_NEAR(spans[0].t0, 0.5 - half, 1e-8);
  EXPECT_NEAR(spans[0].t1, 0.5 + half, 1e-8);
  EXPECT_NEAR(spans[0].worst_u, 0.5, 1e-12);
  EXPECT_NEAR(spans[0].worst_v, 0.5, 1e-12);
  EXPECT_NEAR(spans[0].curvature_radius, 20, 1e-9);
  EXPECT_FALSE(spans[0].undercut);
  // A tool smaller than the tightest valley, or a convex crest: none.
  EXPECT_TRUE(find_gouges(*s, pass, 19.9, 256).empty());
  auto crest = SurfaceGeometry::make(fixtures::quarter_cylinder(5, 40, false));
  EXPECT_TRUE(find_gouges(*crest, iso_curve(*crest, 'u', 0.5, true), 50, 256).empty());
  auto valley = SurfaceGeometry::make(fixtures::quarter_cylinder(5, 40, true));
  const auto v = find_gouges(*valley, iso_curve(*valley, 'u', 0.5, true), 6, 256);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].t0, 0);
  EXPECT_EQ(v[0].t1, 1);
  EXPECT_NEAR(v[0].curvature_radius, 5, 1e-9);
}

}  // namespace
}  // namespace bezcam
