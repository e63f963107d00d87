// The kernel's numerical tools: adaptive Gauss-Legendre quadrature
// (kernel/quadrature.hpp) and Brent's minimisation (kernel/minimize.hpp).
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "bezcam/kernel/minimize.hpp"
#include "bezcam/kernel/quadrature.hpp"

using namespace bezcam;

TEST(Quadrature, TheSevenPointRuleIsExactUpToDegreeThirteen) {
  // The integral of x^k on [-1, 2] is (2^(k+1) - (-1)^(k+1)) / (k + 1).
  for (int k = 0; k <= 13; ++k) {
    const double exact = (std::pow(2.0, k + 1) - std::pow(-1.0, k + 1)) / (k + 1);
    EXPECT_NEAR(gauss_legendre7([&](double x) { return std::pow(x, k); }, -1, 2), exact,
                1e-12 * std::abs(exact) + 1e-13)
        << "x^" << k;
  }
  // Degree 14 is not integrated exactly by one rule: the adaptive form is
  // needed, and gets there.
  const double exact = (std::pow(2.0, 15) + 1) / 15;
  EXPECT_GT(std::abs(gauss_legendre7([](double x) { return std::pow(x, 14); }, -1, 2) - exact), 1e-6);
  EXPECT_NEAR(integrate([](double x) { return std::pow(x, 14); }, -1, 2, 1e-9), exact, 1e-8);
}

TEST(Quadrature, TheAdaptiveFormReachesItsToleranceOnAnEndpointSingularity) {
  // sqrt(x) on [0, 1]: 2/3, with a derivative that is infinite at 0.
  int calls = 0;
  const double v = integrate(
      [&](double x) {
        ++calls;
        return std::sqrt(x);
      },
      0, 1, 1e-10);
  EXPECT_NEAR(v, 2.0 / 3, 1e-9);
  EXPECT_LT(calls, 2000);
  // A circle's quarter by its speed in the angle: pi r / 2.
  EXPECT_NEAR(
      integrate([](double t) { return std::hypot(-3 * std::sin(t), 3 * std::cos(t)); }, 0, std::numbers::pi / 2, 1e-12),
      1.5 * std::numbers::pi, 1e-11);
}

TEST(Minimize, ASmoothMinimumIsFoundInAFewEvaluations) {
  int calls = 0;
  // (A minimum of value 1 is located to about sqrt(epsilon) at best: the
  // function is flat to the last bit closer than that.)
  const auto m = brent_min(
      -1, 3,
      [&](double x) {
        ++calls;
        return std::cosh(x - 0.7) + 0.25 * std::pow(x - 0.7, 4);
      },
      1e-7);
  EXPECT_NEAR(m.x, 0.7, 1e-6);
  EXPECT_NEAR(m.f, 1.0, 1e-14);
  EXPECT_LT(calls, 20) << calls;  // golden section alone needs about 36 for 1e-7 of 4
}

TEST(Minimize, ASquaredDistanceToACurveIsPinnedDownWhereTheDistanceIsZero) {
  // The point (cos 1, sin 1) on the unit circle: the squared distance is
  // smooth and 0 at t = 1, where the distance itself has a kink.
  const double px = std::cos(1.0), py = std::sin(1.0);
  int calls = 0;
  const auto m = brent_min(
      0, 2,
      [&](double t) {
        ++calls;
        return std::pow(std::cos(t) - px, 2) + std::pow(std::sin(t) - py, 2);
      },
      2e-10);
  EXPECT_NEAR(m.x, 1.0, 1e-8);
  EXPECT_LT(std::sqrt(m.f), 1e-8);
  EXPECT_LT(calls, 30);
}

TEST(Minimize, KinksAndEndsFallBackToTheBracket) {
  // A V (no parabola fits): golden-section steps still converge.
  const auto v = brent_min(
      0, 1, [](double x) { return std::abs(x - 0.3141); }, 1e-9);
  EXPECT_NEAR(v.x, 0.3141, 1e-8);
  // A decreasing function: the minimum at the bracket's end.
  const auto e = brent_min(
      0, 1, [](double x) { return -x; }, 1e-9);
  EXPECT_NEAR(e.x, 1.0, 1e-8);
  // The order of the ends does not matter; an empty bracket is its point.
  EXPECT_NEAR(brent_min(
                  1, 0, [](double x) { return (x - 0.25) * (x - 0.25); }, 1e-9)
                  .x,
              0.25, 1e-8);
  EXPECT_EQ(brent_min(
                0.5, 0.5, [](double x) { return x; }, 0)
                .x,
            0.5);
}
