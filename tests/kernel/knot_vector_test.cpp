// Knot vectors: validation that names the offending knot, span search and
// basis functions (The NURBS Book A2.1-A2.3).
#include "bezcam/kernel/knot_vector.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "bezcam/error.hpp"
#include "support/refusal.hpp"

using namespace bezcam;

namespace {

// Runs validate_knots and returns the error (fails the test if none).
InputError refusal(std::vector<double> knots, int degree, size_t n_points) {
  return test::refusal_of([&] { validate_knots(knots, degree, n_points); });
}

}  // namespace

TEST(KnotVector, AcceptsClampedAndUnclamped) {
  EXPECT_NO_THROW(validate_knots(std::vector<double>{0, 0, 0, 1, 1, 1}, 2, 3));
  EXPECT_NO_THROW(validate_knots(std::vector<double>{0, 1, 2, 3, 4, 5, 6}, 2, 4));
  // Interior multiplicity = degree is allowed (C0 corner).
  EXPECT_NO_THROW(validate_knots(std::vector<double>{0, 0, 0, 0.5, 0.5, 1, 1, 1}, 2, 5));
}

TEST(KnotVector, DecreasingKnotNamesItsIndex) {
  const auto e = refusal({0, 0, 0, 0.25, 0.5, 0.5, 0.75, 0.5, 1, 1, 1}, 2, 8);
  EXPECT_EQ(e.id(), "curve.knot-order");
  EXPECT_EQ(e.where(), "knots[7]");
  EXPECT_EQ(e.message(), "expected a knot >= 0.75 (knots must not decrease), found 0.5");
}

TEST(KnotVector, WrongCount) {
  const auto e = refusal({0, 0, 0, 1, 1}, 2, 3);
  EXPECT_EQ(e.id(), "curve.knot-count");
  EXPECT_EQ(e.where(), "knots");
  EXPECT_EQ(e.message(), "expected 6 knots (3 points + degree 2 + 1), found 5");
}

TEST(KnotVector, DegreeTooHighForThePoints) {
  const auto e = refusal({0, 0, 0, 0, 1, 1, 1}, 3, 3);
  EXPECT_EQ(e.id(), "curve.too-few-points");
  EXPECT_EQ(e.where(), "degree");
  EXPECT_EQ(e.message(),
            "a curve of degree 3 needs at least 4 control points, found 3; lower the degree or add points");
  EXPECT_EQ(refusal({0, 1}, 0, 1).id(), "curve.degree");
}

TEST(KnotVector, NonFiniteKnot) {
  const auto e = refusal({0, 0, NAN, 1, 1, 1}, 2, 3);
  EXPECT_EQ(e.id(), "curve.not-finite");
  EXPECT_EQ(e.where(), "knots[2]");
}

TEST(KnotVector, EmptyDomain) {
  const auto e = refusal({0, 1, 1, 1, 1, 2}, 2, 3);
  EXPECT_EQ(e.id(), "curve.knot-domain");
  EXPECT_EQ(e.message(),
            "the curve's domain [knots[2], knots[3]] = [1, 1] is empty; the knots must increase somewhere in between");
}

TEST(KnotVector, MultiplicityLimits) {
  // Interior knot repeated degree + 1 times: the curve could jump.
  auto e = refusal({0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 6);
  EXPECT_EQ(e.id(), "curve.knot-multiplicity");
  EXPECT_EQ(e.where(), "knots[5]");
  EXPECT_EQ(e.message(),
            "knot 0.5 appears 3 times; inside the domain a knot may repeat at most degree (2) times, or the curve "
            "would break apart there");
  // End knot repeated degree + 2 times.
  e = refusal({0, 0, 0, 0, 1, 1, 1}, 2, 4);
  EXPECT_EQ(e.where(), "knots[3]");
  EXPECT_EQ(e.message(), "knot 0 appears 4 times; a knot may repeat at most degree + 1 (3) times");
}

TEST(KnotVector, FindSpan) {
  const std::vector<double> U{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};  // The NURBS Book ex. 2.3, p = 2
  EXPECT_EQ(find_span(U, 2, 0.0), 2);
  EXPECT_EQ(find_span(U, 2, 0.5), 2);
  EXPECT_EQ(find_span(U, 2, 1.0), 3);
  EXPECT_EQ(find_span(U, 2, 2.5), 4);
  EXPECT_EQ(find_span(U, 2, 4.0), 7);  // the empty span [4,4) is skipped
  EXPECT_EQ(find_span(U, 2, 5.0), 7);  // domain end: last non-empty span
  EXPECT_EQ(find_span(U, 2, 9.0), 7);  // clamped to the domain
  EXPECT_EQ(find_span(U, 2, -1.0), 2);
  // Unclamped with a repeated knot at the domain start.
  const std::vector<double> V{0, 1, 1, 1, 3, 4, 5};
  EXPECT_EQ(find_span(V, 2, 1.0), 3);
}

TEST(KnotVector, BasisMatchesTheBookExample) {
  // The NURBS Book ex. 2.3: U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2, u = 5/2:
  // N_{2,2} = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8.
  const std::vector<double> U{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
  std::vector<double> N(3);
  basis_functions(U, 2, 4, 2.5, N);
  EXPECT_DOUBLE_EQ(N[0], 1.0 / 8);
  EXPECT_DOUBLE_EQ(N[1], 6.0 / 8);
  EXPECT_DOUBLE_EQ(N[2], 1.0 / 8);
  const auto d = basis_derivatives(U, 2, 4, 2.5, 2);
  // Ex. 2.4: N'_{2,2} = -1/2, N'_{3,2} = 0, N'_{4,2} = 1/2; second derivatives 1, -2, 1.
  EXPECT_DOUBLE_EQ(d[1][0], -0.5);
  EXPECT_NEAR(d[1][1], 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(d[1][2], 0.5);
  EXPECT_DOUBLE_EQ(d[2][0], 1);
  EXPECT_DOUBLE_EQ(d[2][1], -2);
  EXPECT_DOUBLE_EQ(d[2][2], 1);
}

TEST(KnotVector, PartitionOfUnityAndDerivativesOnRandomVectors) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int p = 1 + static_cast<int>(rng() % 5);
    const size_t n = static_cast<size_t>(p) + 1 + rng() % 6;
    std::vector<double> U;
    for (size_t i = 0; i < n + p + 1; ++i) U.push_back(uni(rng) * 10);
    std::sort(U.begin(), U.end());
    if (trial % 2 == 0) {  // clamped
      for (int k = 0; k <= p; ++k) U[k] = 0, U[U.size() - 1 - k] = 10;
    }
    const double a = U[p], b = U[U.size() - 1 - p];
    for (int s = 0; s <= 20; ++s) {
      const double u = a + (b - a) * s / 20.0;
      const int span = find_span(U, p, u);
      ASSERT_LE(U[span], u);
      ASSERT_LT(U[span], U[span + 1]);
      std::vector<double> N(p + 1);
      basis_functions(U, p, span, u, N);
      double sum = 0;
      for (double v : N) {
        EXPECT_GE(v, -1e-14);
        sum += v;
      }
      EXPECT_NEAR(sum, 1.0, 1e-13);
      // Derivative rows sum to zero (the sum of the basis is constant).
      const auto d = basis_derivatives(U, p, span, u, 2);
      for (int j = 0; j <= p; ++j) EXPECT_NEAR(d[0][j], N[j], 1e-14);
      double s1 = 0;
      for (double v : d[1]) s1 += v;
      EXPECT_NEAR(s1, 0.0, 1e-9 * (1 + std::abs(d[1][0])));
      // First derivative against a central difference inside the span.
      const double lo = U[span], hi = U[span + 1], h = 1e-6 * (hi - lo);
      const double um = std::clamp(u, lo + 2 * h, hi - 2 * h);
      std::vector<double> Np(p + 1), Nm(p + 1);
      basis_functions(U, p, span, um + h, Np);
      basis_functions(U, p, span, um - h, Nm);
      const auto dm = basis_derivatives(U, p, span, um, 1);
      for (int j = 0; j <= p; ++j) EXPECT_NEAR(dm[1][j], (Np[j] - Nm[j]) / (2 * h), 1e-4 * (1 + std::abs(dm[1][j])));
    }
  }
}

TEST(KnotVector, ClampedUniform) {
  EXPECT_EQ(clamped_uniform_knots(5, 2), (std::vector<double>{0, 0, 0, 1.0 / 3, 2.0 / 3, 1, 1, 1}));
  EXPECT_EQ(clamped_uniform_knots(4, 3, 0, 2), (std::vector<double>{0, 0, 0, 0, 2, 2, 2, 2}));
  EXPECT_TRUE(is_clamped(clamped_uniform_knots(7, 3), 3));
  EXPECT_FALSE(is_clamped(std::vector<double>{0, 1, 2, 3, 4, 5, 6}, 2));
  EXPECT_EQ(multiplicity(std::vector<double>{0, 0, 0, 0.5, 0.5, 1, 1, 1}, 0.5), 2);
}
