// NURBS curves: the exact circle first, then seeded property tests
// (decomposition = de Boor evaluation, knot insertion and clamping keep the
// curve, derivatives match differences), then validation messages.
#include "bezcam/kernel/nurbs_curve.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

#include "bezcam/error.hpp"
#include "bezcam/kernel/knot_vector.hpp"
#include "support/refusal.hpp"

using namespace bezcam;

namespace {

// The degree-2 NURBS full circle of radius r around c (The NURBS Book ex.
// 7.2: nine points on the square, corner weights sqrt(2)/2).
NurbsCurve circle(Vec3 c, double r) {
  const double s = std::sqrt(2.0) / 2;
  std::vector<Vec3> pts{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  for (auto& p : pts) p = c + p * r;
  return NurbsCurve::make(2, pts, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, {1, s, 1, s, 1, s, 1, s, 1});
}

// A random B-spline or NURBS: degree 1..5, clamped or not, 2D or 3D, with
// repeated interior knots now and then.
NurbsCurve random_curve(std::mt19937& rng) {
  std::uniform_real_distribution<double> uni(-50, 50), w(0.2, 5);
  const int p = 1 + static_cast<int>(rng() % 5);
  const size_t n = static_cast<size_t>(p) + 1 + rng() % 8;
  const int dim = rng() % 2 ? 3 : 2;
  std::vector<Vec3> pts;
  for (size_t i = 0; i < n; ++i) pts.push_back({uni(rng), uni(rng), dim == 3 ? uni(rng) : 0});
  std::vector<double> U;
  for (size_t i = 0; i < n + p + 1; ++i) U.push_back(std::round(uni(rng) + 50) / 4);  // coarse: repeats happen
  std::sort(U.begin(), U.end());
  if (rng() % 2) {
    for (int k = 0; k <= p; ++k) U[k] = U.front(), U[U.size() - 1 - k] = U.back();
  }
  std::vector<double> ws;
  if (rng() % 2)
    for (size_t i = 0; i < n; ++i) ws.push_back(w(rng));
  try {
    return NurbsCurve::make(p, pts, U, ws, dim);
  } catch (const InputError&) {
    return random_curve(rng);  // too many repeats or an empty domain: draw again
  }
}

// Evaluates Bézier pieces as one curve: the piece for span k covers
// [breaks[k], breaks[k+1]].
std::vector<double> breaks(const NurbsCurve& c) {
  std::vector<double> b;
  const double a = c.domain_start(), e = c.domain_end();
  for (double u : c.knots)
    if (u >= a && u <= e && (b.empty() || u != b.back())) b.push_back(u);
  return b;
}

}  // namespace

TEST(NurbsCurve, FullCircleLiesOnItsCircle) {
  for (const auto& [c, r] : {std::pair{Vec3{0, 0}, 1.0}, std::pair{Vec3{120.5, -33.25}, 25.0}}) {
    const NurbsCurve k = circle(c, r);
    double worst = 0;
    for (int i = 0; i <= 4000; ++i) worst = std::max(worst, std::abs(dist(evaluate(k, i / 4000.0), c) - r));
    EXPECT_LE(worst, 1e-12 * std::max(1.0, max_abs(c) + r)) << "radius " << r;
    // Quarter points land on the axes.
    EXPECT_LE(dist(evaluate(k, 0.25), c + Vec3{0, r}), 1e-12 * (max_abs(c) + r));
    EXPECT_LE(dist(evaluate(k, 0.5), c + Vec3{-r, 0}), 1e-12 * (max_abs(c) + r));
    // Its four rational Bézier pieces are quarter circles, on the circle too.
    const auto pieces = to_bezier(k);
    ASSERT_EQ(pieces.size(), 4u);
    double worst_piece = 0;
    for (const auto& b : pieces) {
      ASSERT_EQ(b.degree(), 2);
      ASSERT_TRUE(b.rational());
      for (int i = 0; i <= 1000; ++i)
        worst_piece = std::max(worst_piece, std::abs(dist(evaluate(b, i / 1000.0), c) - r));
    }
    EXPECT_LE(worst_piece, 1e-12 * std::max(1.0, max_abs(c) + r));
    // End to end.
    for (size_t i = 1; i < pieces.size(); ++i) EXPECT_EQ(pieces[i - 1].back(), pieces[i].front());
    EXPECT_EQ(pieces.front().front(), (c + Vec3{r, 0}));
  }
}

TEST(NurbsCurve, CircleDerivativeIsTangent) {
  const NurbsCurve k = circle({0, 0}, 2);
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const auto d = derivatives(k, u, 2);
    EXPECT_NEAR(dot(d[1], d[0]), 0.0, 1e-12 * norm(d[1]));
    // The second derivative of |C|^2 = r^2 vanishes: |C'|^2 + C.C'' = 0.
    EXPECT_NEAR(dot(d[1], d[1]) + dot(d[0], d[2]), 0.0, 1e-10 * dot(d[1], d[1]));
  }
}

TEST(NurbsCurve, DecompositionAgreesWithDeBoor) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const NurbsCurve c = random_curve(rng);
    const auto pieces = to_bezier(c);
    const auto br = breaks(c);
    ASSERT_EQ(pieces.size() + 1, br.size()) << "trial " << trial;
    double scale = 1;
    for (const auto& p : c.points) scale = std::max(scale, max_abs(p));
    for (size_t k = 0; k < pieces.size(); ++k) {
      EXPECT_EQ(pieces[k].degree(), c.degree);
      EXPECT_EQ(pieces[k].rational(), c.rational());
      if (k > 0) EXPECT_LE(dist(pieces[k - 1].back(), pieces[k].front()), 1e-11 * scale);
      for (int s = 0; s <= 16; ++s) {
        const double t = s / 16.0;
        const double u = br[k] + (br[k + 1] - br[k]) * t;
        EXPECT_LE(dist(evaluate(pieces[k], t), evaluate(c, u)), 1e-10 * scale) << "trial " << trial << " piece " << k;
      }
    }
  }
}

TEST(NurbsCurve, KnotInsertionKeepsTheCurve) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const NurbsCurve c = random_curve(rng);
    const double a = c.domain_start(), b = c.domain_end();
    // Insert an existing knot or a new value, once or up to the degree.
    double u = a + (b - a) * uni(rng);
    if (trial % 3 == 0) u = c.knots[static_cast<size_t>(c.degree) + rng() % (c.knots.size() - 2 * c.degree - 1)];
    const int room = c.degree - multiplicity(c.knots, u);
    if (room < 1) continue;
    const int times = 1 + static_cast<int>(rng() % static_cast<unsigned>(room));
    const NurbsCurve d = insert_knot(c, u, times);
    ASSERT_EQ(d.points.size(), c.points.size() + static_cast<size_t>(times));
    ASSERT_EQ(multiplicity(d.knots, u), multiplicity(c.knots, u) + times);
    EXPECT_NO_THROW(validate_knots(d.knots, d.degree, d.points.size()));
    double scale = 1;
    for (const auto& p : c.points) scale = std::max(scale, max_abs(p));
    for (int s = 0; s <= 40; ++s) {
      const double v = a + (b - a) * s / 40.0;
      EXPECT_LE(dist(evaluate(c, v), evaluate(d, v)), 1e-10 * scale) << "trial " << trial;
    }
  }
}

TEST(NurbsCurve, ClampingAnUnclampedCurveKeepsItOnItsDomain) {
  // A uniform (unclamped) cubic: the domain is [u_3, u_{m-3}] = [3, 6].
  const std::vector<Vec3> pts{{0, 0}, {10, 20}, {30, 25}, {40, 0}, {60, -10}, {70, 10}};
  const NurbsCurve c = NurbsCurve::make(3, pts, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  EXPECT_FALSE(c.clamped());
  EXPECT_EQ(c.domain_start(), 3);
  EXPECT_EQ(c.domain_end(), 6);
  const NurbsCurve k = clamp(c);
  EXPECT_TRUE(k.clamped());
  EXPECT_EQ(k.domain_start(), 3);
  EXPECT_EQ(k.domain_end(), 6);
  EXPECT_NO_THROW(validate_knots(k.knots, 3, k.points.size()));
  for (int s = 0; s <= 60; ++s) {
    const double u = 3 + s / 20.0;
    EXPECT_LE(dist(evaluate(c, u), evaluate(k, u)), 1e-12 * 70);
  }
  // A uniform cubic B-spline starts at (P0 + 4 P1 + P2) / 6.
  EXPECT_LE(dist(k.points.front(), (pts[0] + pts[1] * 4 + pts[2]) / 6), 1e-12 * 70);
  EXPECT_LE(dist(to_bezier(c).front().front(), (pts[0] + pts[1] * 4 + pts[2]) / 6), 1e-12 * 70);
  EXPECT_EQ(to_bezier(c).size(), 3u);
}

TEST(NurbsCurve, ClampRandomUnclampedCurves) {
  std::mt19937 rng(5);
  int tested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const NurbsCurve c = random_curve(rng);
    if (c.clamped()) continue;
    ++tested;
    const NurbsCurve k = clamp(c);
    EXPECT_TRUE(k.clamped());
    EXPECT_NO_THROW(validate_knots(k.knots, k.degree, k.points.size()));
    double scale = 1;
    for (const auto& p : c.points) scale = std::max(scale, max_abs(p));
    for (int s = 0; s <= 30; ++s) {
      const double u = c.domain_start() + (c.domain_end() - c.domain_start()) * s / 30.0;
      EXPECT_LE(dist(evaluate(c, u), evaluate(k, u)), 1e-10 * scale) << "trial " << trial;
    }
  }
  EXPECT_GT(tested, 50);
}

TEST(NurbsCurve, DerivativesMatchCentralDifferences) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 200; ++trial) {
    const NurbsCurve c = random_curve(rng);
    const auto br = breaks(c);
    for (size_t k = 0; k + 1 < br.size(); ++k) {
      const double u = br[k] + (br[k + 1] - br[k]) * 0.37, h = 1e-5 * (br[k + 1] - br[k]);
      const auto d = derivatives(c, u, 2);
      const Vec3 fd = (evaluate(c, u + h) - evaluate(c, u - h)) / (2 * h);
      EXPECT_LE(dist(d[1], fd), 1e-5 * (1 + norm(d[1]))) << "trial " << trial;
      const Vec3 fd2 = (derivative(c, u + h) - derivative(c, u - h)) / (2 * h);
      EXPECT_LE(dist(d[2], fd2), 1e-4 * (1 + norm(d[2]))) << "trial " << trial;
      EXPECT_LE(dist(d[0], evaluate(c, u)), 1e-12 * (1 + norm(d[0])));
    }
  }
}

TEST(NurbsCurve, BezierRoundTrip) {
  const Bezier b = Bezier::make({{0, 0}, {1, 0}, {2, 1}, {0, 1}});
  const NurbsCurve c = from_bezier(b);
  EXPECT_EQ(c.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  const auto pieces = to_bezier(c);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].points, b.points);
  // Seeds digest exercise 4 at t = 1/2 through the B-spline path.
  EXPECT_LE(dist(evaluate(c, 0.5), evaluate(b, 0.5)), 1e-15);
}

TEST(NurbsCurve, ValidationNamesTheOffendingItem) {
  const std::vector<Vec3> pts{{0, 0}, {1, 1}, {2, 0}};
  const auto refusal = [](auto f) { return test::refusal_of(f); };
  auto e = refusal([&] { NurbsCurve::make(2, pts, {0, 0, 0, 1, 1, 1}, {1, 0.5, -1}); });
  EXPECT_EQ(e.where(), "weights[2]");
  EXPECT_EQ(e.message(), "expected a finite weight > 0, found -1");
  e = refusal([&] { NurbsCurve::make(2, pts, {0, 0, 0, 1, 1, 1}, {1, 1}); });
  EXPECT_EQ(e.where(), "weights");
  e = refusal([&] { NurbsCurve::make(2, {{0, 0}, {1, NAN}, {2, 0}}, {0, 0, 0, 1, 1, 1}); });
  EXPECT_EQ(e.where(), "points[1]");
  e = refusal([&] { NurbsCurve::make(3, pts, {0, 0, 0, 0, 1, 1, 1}); });
  EXPECT_EQ(e.where(), "degree");
  e = refusal([&] { NurbsCurve::make(2, pts, {0, 0, 0.5, 0.25, 1, 1}); });
  EXPECT_EQ(e.where(), "knots[3]");
  EXPECT_NO_THROW(NurbsCurve::make(2, pts, {0, 0, 0, 1, 1, 1}));
}
