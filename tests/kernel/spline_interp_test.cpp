// Interpolation: the natural spline against an independent textbook solver
// (second-derivative moments, per coordinate), C2 joints and natural ends,
// the periodic spline closed and C2 at its seam, Lagrange through its
// points and overshooting on a step (Runge's phenomenon), and the refusals.
#include "bezcam/kernel/spline_interp.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

#include "bezcam/error.hpp"
#include "support/refusal.hpp"

using namespace bezcam;

namespace {

// Textbook natural cubic spline of one coordinate over parameters t:
// solve the tridiagonal system for the second derivatives M_k (M_0 = M_n =
// 0) and evaluate the piecewise cubic in its classic form.
struct Moments {
  std::vector<double> t, y, M;
  Moments(std::vector<double> t_, std::vector<double> y_) : t(std::move(t_)), y(std::move(y_)), M(t.size(), 0.0) {
    const size_t n = t.size() - 1;
    if (n < 2) return;
    std::vector<double> a(n + 1), b(n + 1), c(n + 1), d(n + 1);
    for (size_t k = 1; k < n; ++k) {
      const double h0 = t[k] - t[k - 1], h1 = t[k + 1] - t[k];
      a[k] = h0 / 6;
      b[k] = (h0 + h1) / 3;
      c[k] = h1 / 6;
      d[k] = (y[k + 1] - y[k]) / h1 - (y[k] - y[k - 1]) / h0;
    }
    // Thomas algorithm on rows 1..n-1.
    for (size_t k = 2; k < n; ++k) {
      const double m = a[k] / b[k - 1];
      b[k] -= m * c[k - 1];
      d[k] -= m * d[k - 1];
    }
    for (size_t k = n - 1; k >= 1; --k) M[k] = (d[k] - (k + 1 < n ? c[k] * M[k + 1] : 0.0)) / b[k];
  }
  double operator()(double u) const {
    size_t k = 0;
    while (k + 2 < t.size() && u > t[k + 1]) ++k;
    const double h = t[k + 1] - t[k], A = (t[k + 1] - u) / h, B = (u - t[k]) / h;
    return A * y[k] + B * y[k + 1] + ((A * A * A - A) * M[k] + (B * B * B - B) * M[k + 1]) * h * h / 6;
  }
};

// The point of a spline at parameter u, from its Bézier pieces (piece k
// covers [breaks[k], breaks[k+1]]).
Vec3 at_param(const std::vector<Bezier>& pieces, const std::vector<double>& breaks, double u) {
  size_t k = 0;
  while (k + 1 < pieces.size() && u > breaks[k + 1]) ++k;
  return evaluate(pieces[k], (u - breaks[k]) / (breaks[k + 1] - breaks[k]));
}

// Checks C1 and C2 at every joint of pieces over `breaks` (derivatives in
// the spline's own parameter: piece derivatives divided by the span).
void expect_c2(const std::vector<Bezier>& pc, const std::vector<double>& br, bool closed, double scale) {
  const size_t n = pc.size();
  for (size_t k = 0; k + (closed ? 0 : 1) < n; ++k) {
    const size_t j = (k + 1) % n;
    const double h0 = br[k + 1] - br[k], h1 = br[j + 1] - br[j];
    EXPECT_LE(dist(pc[k].back(), pc[j].front()), 1e-12 * scale) << "joint " << k;
    EXPECT_LE(dist(derivative(pc[k], 1) / h0, derivative(pc[j], 0) / h1), 1e-9 * (1 + norm(derivative(pc[k], 1) / h0)))
        << "C1 at joint " << k;
    const Vec3 s0 = second_derivative(pc[k], 1) / (h0 * h0), s1 = second_derivative(pc[j], 0) / (h1 * h1);
    EXPECT_LE(dist(s0, s1), 1e-8 * (1 + norm(s0))) << "C2 at joint " << k;
  }
}

}  // namespace

TEST(SplineInterp, ChordLengthParameters) {
  const std::vector<Vec3> p{{0, 0}, {3, 4}, {3, 10}, {0, 10}};
  EXPECT_EQ(chord_length_parameters(p), (std::vector<double>{0, 5, 11, 14}));
}

TEST(SplineInterp, NaturalSplineMatchesTheTextbookSolver) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-100, 100);
  for (int trial = 0; trial < 50; ++trial) {
    const size_t m = 2 + rng() % 12;
    const int dim = trial % 2 ? 3 : 2;
    std::vector<Vec3> p;
    for (size_t i = 0; i < m; ++i) p.push_back({uni(rng), uni(rng), dim == 3 ? uni(rng) : 0});
    const NurbsCurve c = natural_cubic_spline(p, dim);
    const auto t = chord_length_parameters(p);
    EXPECT_EQ(c.knots.front(), 0);
    EXPECT_EQ(c.knots.back(), t.back());
    const auto pieces = to_bezier(c);
    ASSERT_EQ(pieces.size(), m - 1);
    std::vector<double> xs, ys, zs;
    for (const auto& q : p) xs.push_back(q.x), ys.push_back(q.y), zs.push_back(q.z);
    const Moments X(t, xs), Y(t, ys), Z(t, zs);
    for (int s = 0; s <= 200; ++s) {
      const double u = t.back() * s / 200;
      const Vec3 got = at_param(pieces, t, u);
      EXPECT_LE(dist(got, Vec3(X(u), Y(u), Z(u))), 1e-9 * 100) << "trial " << trial << " u " << u;
    }
    // Through every point, C2, natural ends.
    for (size_t k = 0; k < m; ++k) EXPECT_LE(dist(evaluate(c, t[k]), p[k]), 1e-10 * 100);
    expect_c2(pieces, t, false, 100);
    const double h0 = t[1], hn = t.back() - t[m - 2];
    EXPECT_LE(norm(second_derivative(pieces.front(), 0)) / (h0 * h0), 1e-9);
    EXPECT_LE(norm(second_derivative(pieces.back(), 1)) / (hn * hn), 1e-9);
    if (dim == 2)
      for (const auto& b : pieces)
        for (const auto& q : b.points) EXPECT_EQ(q.z, 0);
  }
}

TEST(SplineInterp, CollinearPointsGiveTheLineExactly) {
  // Natural spline of linear data is linear (its moments are all zero),
  // whatever the spacing.
  const std::vector<Vec3> p{{0, 0}, {1, 2}, {4, 8}, {4.5, 9}, {10, 20}};
  const NurbsCurve c = natural_cubic_spline(p, 2);
  for (int s = 0; s <= 100; ++s) {
    const Vec3 q = evaluate(c, c.domain_end() * s / 100);
    EXPECT_NEAR(q.y, 2 * q.x, 1e-12 * 20);
    EXPECT_NEAR(norm(q), c.domain_end() * s / 100, 1e-11 * 20);  // chord length = arc length here
  }
}

TEST(SplineInterp, PeriodicSplineIsClosedAndC2AtTheSeam) {
  // Sixteen points of a circle of radius 10: the spline closes, is C2
  // everywhere, symmetric (every span bulges alike) and within the
  // h^4 error of cubic interpolation, (5/384) h^4 / R^3 ~ 0.003.
  std::vector<Vec3> p;
  for (int k = 0; k < 16; ++k)
    p.push_back({10 * std::cos(k * std::numbers::pi / 8), 10 * std::sin(k * std::numbers::pi / 8)});
  const NurbsCurve c = periodic_cubic_spline(p, 2);
  EXPECT_FALSE(c.clamped());
  const auto pieces = to_bezier(c);
  ASSERT_EQ(pieces.size(), 16u);
  EXPECT_LE(dist(pieces.back().back(), pieces.front().front()), 1e-12 * 10);
  auto t = chord_length_parameters(p);
  t.push_back(t.back() + dist(p.back(), p.front()));
  expect_c2(pieces, t, true, 10);
  for (size_t k = 0; k < 16; ++k) EXPECT_LE(dist(pieces[k].front(), p[k]), 1e-12 * 10);
  const double mid0 = norm(evaluate(pieces[0], 0.5));
  for (const auto& b : pieces) {
    EXPECT_NEAR(norm(evaluate(b, 0.5)), mid0, 1e-10);
    for (int s = 0; s <= 10; ++s) EXPECT_NEAR(norm(evaluate(b, s / 10.0)), 10, 0.005);
  }
  EXPECT_GT(std::abs(mid0 - 10), 1e-6);  // it is an approximation, not the circle
  // The last point may repeat the first.
  auto q = p;
  q.push_back(p.front());
  const NurbsCurve c2 = periodic_cubic_spline(q, 2);
  EXPECT_EQ(c2.points, c.points);
  // Random closed polygons, 3D.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uni(-50, 50);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Vec3> r;
    for (size_t i = 0; i < 3 + rng() % 8; ++i) r.push_back({uni(rng), uni(rng), uni(rng)});
    const NurbsCurve k = periodic_cubic_spline(r, 3);
    const auto pc = to_bezier(k);
    ASSERT_EQ(pc.size(), r.size());
    auto tr = chord_length_parameters(r);
    tr.push_back(tr.back() + dist(r.back(), r.front()));
    expect_c2(pc, tr, true, 50);
    for (size_t i = 0; i < r.size(); ++i) EXPECT_LE(dist(pc[i].front(), r[i]), 1e-10 * 50) << "trial " << trial;
  }
}

TEST(SplineInterp, LagrangePassesThroughItsPointsAndOvershootsOnAStep) {
  const std::vector<Vec3> line{{0, 0}, {1, 1}, {3, 3}, {6, 6}};
  const Bezier l = lagrange_polynomial(line, 2);
  EXPECT_EQ(l.degree(), 3);
  for (int s = 0; s <= 20; ++s) {
    const Vec3 q = evaluate(l, s / 20.0);
    EXPECT_NEAR(q.x, q.y, 1e-12);
    EXPECT_NEAR(q.x, 6 * s / 20.0, 1e-12);  // chord-length parameters on a line: uniform speed
  }
  EXPECT_LE(bounding_box_overshoot(std::span<const Bezier>(&l, 1), line), 1e-12);
  // A step: five points on y = 0, then six on y = 20. One polynomial
  // through them swings far outside (Runge's phenomenon, seeds digest §4).
  std::vector<Vec3> step;
  for (int k = 0; k <= 10; ++k) step.push_back({10.0 * k, k < 5 ? 0.0 : 20.0});
  const Bezier r = lagrange_polynomial(step, 2);
  EXPECT_EQ(r.degree(), 10);
  const auto t = chord_length_parameters(step);
  for (size_t k = 0; k < step.size(); ++k) EXPECT_LE(dist(evaluate(r, t[k] / t.back()), step[k]), 1e-9 * 100);
  const double lag = bounding_box_overshoot(std::span<const Bezier>(&r, 1), step);
  EXPECT_GT(lag, 5.0);
  // The spline through the same points overshoots far less.
  const auto s = to_bezier(natural_cubic_spline(step, 2));
  EXPECT_LT(bounding_box_overshoot(s, step), lag / 2);
  // Chord-length parameters tame Runge's own example, 1/(1 + 25 x^2) at 15
  // equidistant x: the polynomial stays in the box (measured; with
  // equidistant parameters it would not).
  std::vector<Vec3> runge;
  for (int k = 0; k <= 14; ++k) {
    const double x = -1 + 2.0 * k / 14;
    runge.push_back({x, 1 / (1 + 25 * x * x)});
  }
  const Bezier rr = lagrange_polynomial(runge, 2);
  EXPECT_LE(bounding_box_overshoot(std::span<const Bezier>(&rr, 1), runge), 1e-9);
}

TEST(SplineInterp, Refusals) {
  const auto refusal = [](auto f) { return test::refusal_of(f); };
  const std::vector<Vec3> rep{{0, 0}, {1, 2}, {1, 2}, {3, 0}};
  auto e = refusal([&] { natural_cubic_spline(rep, 2); });
  EXPECT_EQ(e.id(), "curve.repeated-point");
  EXPECT_EQ(e.where(), "through[2]");
  EXPECT_EQ(e.message(),
            "expected a point different from through[1], found the same point (1, 2): a repeated point gives a zero "
            "chord length, so no parameter can separate the two; remove the duplicate");
  EXPECT_EQ(refusal([&] { lagrange_polynomial(rep, 2); }).where(), "through[2]");
  EXPECT_EQ(refusal([&] { periodic_cubic_spline(rep, 2); }).where(), "through[2]");
  e = refusal([&] { periodic_cubic_spline(std::vector<Vec3>{{0, 0}, {1, 0}, {0, 0}}, 2); });
  EXPECT_EQ(e.where(), "through");
  EXPECT_EQ(e.message(), "a closed spline needs at least 3 distinct points, found 2");
  std::vector<Vec3> many;
  for (int k = 0; k < 70; ++k) many.push_back({static_cast<double>(k), std::sin(k)});
  e = refusal([&] { lagrange_polynomial(many, 2); });
  EXPECT_EQ(e.id(), "curve.degree-too-high");
  EXPECT_EQ(e.message(),
            "one polynomial through 70 points would have degree 69, above the limit 64; use method "
            "\"cubic-spline\"");
}
