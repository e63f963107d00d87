// Bézier kernel: the digest's facts (seeds-digest.md §2) and the agreement of
// its five forms on seeded random curves up to degree 20.
#include "bezcam/kernel/bezier.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>
#include <vector>

#include "bezcam/error.hpp"

using namespace bezcam;

namespace {

Bezier random_bezier(std::mt19937_64& rng, int degree, int dim, bool rational) {
  std::uniform_real_distribution<double> c(-100, 100), w(0.2, 5);
  std::vector<Vec3> pts;
  std::vector<double> ws;
  for (int i = 0; i <= degree; ++i) {
    pts.push_back({c(rng), c(rng), dim == 3 ? c(rng) : 0});
    ws.push_back(w(rng));
  }
  return Bezier::make(pts, rational ? ws : std::vector<double>{}, dim);
}

void expect_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

const Bezier cube = Bezier::make({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}, {}, 3);
const Bezier semicircle = Bezier::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0}});

}  // namespace

TEST(Bernstein, PartitionOfUnityAndPeakAtKOverN) {
  for (int n = 1; n <= 20; ++n) {
    for (double t = 0; t <= 1; t += 1.0 / 64) {
      double s = 0;
      for (int k = 0; k <= n; ++k) s += bernstein(n, k, t);
      EXPECT_NEAR(s, 1, 1e-12) << "n=" << n << " t=" << t;
    }
    // P_k has the most influence at t = k/n.
    for (int k = 0; k <= n; ++k) {
      const double peak = bernstein(n, k, double(k) / n);
      for (double t = 0; t <= 1; t += 1.0 / 97) EXPECT_LE(bernstein(n, k, t), peak + 1e-15);
    }
  }
}

TEST(Bezier, FiveFormsAgreeOnRandomCurvesUpToDegree20) {
  std::mt19937_64 rng(20261121);
  for (int degree = 1; degree <= 20; ++degree) {
    for (int dim : {2, 3}) {
      const Bezier b = random_bezier(rng, degree, dim, false);
      const auto power = power_coefficients(b);
      for (double t : {0.0, 0.1, 0.25, 1.0 / 3, 0.5, 0.77, 0.9, 1.0}) {
        const Vec3 m = evaluate(b, t);                   // 2. de Casteljau
        expect_near(evaluate_bernstein(b, t), m, 1e-9);  // 1. Bernstein sum
        expect_near(evaluate_durand(b, t), m, 1e-9);     // 5. f-functions
        // 4. power form loses precision with degree (cancellation of large
        // binomial terms): allow for it, as the digest warns.
        expect_near(evaluate_power(power, t), m, degree <= 10 ? 1e-7 : 1e-1);
        // 3. derivative from the cascade vs the hodograph.
        const Vec3 d = derivative_from_cascade(b, t);
        expect_near(d, evaluate(hodograph(b), t), 1e-8);
        // ... and vs a central difference.
        if (t > 0.01 && t < 0.99) {
          const double h = 1e-6;
          const Vec3 fd = (evaluate(b, t + h) - evaluate(b, t - h)) / (2 * h);
          EXPECT_NEAR(norm(d - fd), 0, 1e-4 * std::max(1.0, norm(d)));
        }
      }
    }
  }
}

TEST(Bezier, EndPointsAndEndTangents) {
  std::mt19937_64 rng(7);
  for (int degree = 1; degree <= 20; ++degree) {
    const Bezier b = random_bezier(rng, degree, 3, false);
    const int n = degree;
    EXPECT_EQ(evaluate(b, 0), b.points.front());
    EXPECT_EQ(evaluate(b, 1), b.points.back());
    expect_near(derivative(b, 0), (b.points[1] - b.points[0]) * n, 1e-9);
    expect_near(derivative(b, 1), (b.points[n] - b.points[n - 1]) * n, 1e-9);
  }
}

TEST(Bezier, CubicCascadeSplitsIntoTheDigestsHalves) {
  const Vec3 A{0, 0}, B{1, 0}, C{2, 1}, D{0, 1};
  const Bezier b = Bezier::make({A, B, C, D});
  for (double t : {0.5, 0.3}) {
    const double s = 1 - t;
    const Vec3 E = s * A + t * B, F = s * B + t * C, G = s * C + t * D;
    const Vec3 H = s * E + t * F, I = s * F + t * G, M = s * H + t * I;
    auto [l, r] = split(b, t);
    const std::vector<Vec3> left{A, E, H, M}, right{M, I, G, D};
    for (int i = 0; i < 4; ++i) {
      expect_near(l.points[i], left[i], 1e-15);
      expect_near(r.points[i], right[i], 1e-15);
    }
    // M'(t) = 3 (I - H).
    expect_near(derivative(b, t), 3 * (I - H), 1e-14);
    // The halves trace the same curve.
    for (double u = 0; u <= 1; u += 0.125) {
      expect_near(evaluate(l, u), evaluate(b, t * u), 1e-14);
      expect_near(evaluate(r, u), evaluate(b, t + (1 - t) * u), 1e-14);
    }
  }
}

TEST(Bezier, DigestMatrixFormsAndExpandedCubic) {
  const Vec3 A{-3, 0}, B{-3, 4}, C{3, 4}, D{3, 0};
  const double m[4][4] = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}};
  const Vec3 P[4] = {A, B, C, D};
  for (double t = 0; t <= 1; t += 0.0625) {
    const double T[4] = {t * t * t, t * t, t, 1};
    Vec3 r;
    for (int i = 0; i < 4; ++i) {
      double c = 0;
      for (int j = 0; j < 4; ++j) c += m[i][j] * T[j];
      r += P[i] * c;
    }
    expect_near(r, evaluate(semicircle, t), 1e-13);
    const Vec3 expanded =
        A + 3 * (B - A) * t + 3 * (A - 2 * B + C) * (t * t) + (-1 * A + 3 * B - 3 * C + D) * (t * t * t);
    expect_near(expanded, evaluate(semicircle, t), 1e-13);
  }
  // Quadratic matrix [[1,-2,1],[-2,2,0],[1,0,0]] with [t^2, t, 1].
  const Bezier q = Bezier::make({{0, 0}, {2, -1}, {1, 1}});
  const double mq[3][3] = {{1, -2, 1}, {-2, 2, 0}, {1, 0, 0}};
  for (double t = 0; t <= 1; t += 0.1) {
    const double T[3] = {t * t, t, 1};
    Vec3 r;
    for (int i = 0; i < 3; ++i) {
      double c = 0;
      for (int j = 0; j < 3; ++j) c += mq[i][j] * T[j];
      r += q.points[i] * c;
    }
    expect_near(r, evaluate(q, t), 1e-14);
  }
}

TEST(Bezier, DurandFFunctionsAreTheDigests) {
  for (double t = 0; t <= 1; t += 0.05) {
    EXPECT_NEAR(durand_f(3, 1, t), 3 * t - 3 * t * t + t * t * t, 1e-14);
    EXPECT_NEAR(durand_f(3, 2, t), 3 * t * t - 2 * t * t * t, 1e-14);
    EXPECT_NEAR(durand_f(3, 3, t), t * t * t, 1e-14);
    EXPECT_NEAR(durand_f(3, 0, t), 1, 1e-14);
    // The Bernstein polynomials are the differences f_k - f_{k+1}.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(bernstein(3, k, t), durand_f(3, k, t) - durand_f(3, k + 1, t), 1e-14);
  }
}

TEST(Bezier, CubeCurveIsBeziersFirstBaseCurve) {
  // x = f1, y = f2, z = t^3; M(1/2) = (0.875, 0.5, 0.125).
  expect_near(evaluate(cube, 0.5), {0.875, 0.5, 0.125}, 1e-15);
  for (double t = 0; t <= 1; t += 0.05) {
    const Vec3 m = evaluate(cube, t);
    EXPECT_NEAR(m.x, durand_f(3, 1, t), 1e-14);
    EXPECT_NEAR(m.y, durand_f(3, 2, t), 1e-14);
    EXPECT_NEAR(m.z, t * t * t, 1e-14);
    // It approximates the intersection of the cylinders x^2+(y-1)^2=1 and
    // (z-1)^2+y^2=1 (within 0.047 of both).
    EXPECT_LT(std::abs(m.x * m.x + (m.y - 1) * (m.y - 1) - 1), 0.047);
    EXPECT_LT(std::abs((m.z - 1) * (m.z - 1) + m.y * m.y - 1), 0.047);
  }
  // Tangent to Ox at the origin and to Oz at (1,1,1).
  const Vec3 d0 = derivative(cube, 0), d1 = derivative(cube, 1);
  EXPECT_GT(d0.x, 0);
  EXPECT_EQ(d0.y, 0);
  EXPECT_EQ(d0.z, 0);
  EXPECT_EQ(d1.x, 0);
  EXPECT_EQ(d1.y, 0);
  EXPECT_GT(d1.z, 0);
}

TEST(Bezier, SemicircleRadialErrorIsAtMost0_0551) {
  expect_near(evaluate(semicircle, 0.5), {0, 3}, 1e-15);
  double worst = 0;
  for (int i = 0; i <= 20000; ++i) worst = std::max(worst, std::abs(norm(evaluate(semicircle, i / 20000.0)) - 3));
  EXPECT_LE(worst, 0.0551);
  EXPECT_GE(worst, 0.0550);  // "about 1.8 % of the radius", not a hundredth
  // Handle length 4 = (4/3) tan(theta/4) r with theta = pi.
  EXPECT_NEAR(4.0 / 3 * std::tan(std::numbers::pi / 4) * 3, norm(semicircle.points[1] - semicircle.points[0]), 1e-14);
}

TEST(Bezier, ExercisePolygonsShowCuspsAndInflections) {
  // Exercise 5: (0,0) (2,2) (2,0) (0,2) has a cusp at t = 1/2: M'(1/2) =
  // 3/4 (P3 + P2 - P1 - P0) = 0.
  const Bezier ex5 = Bezier::make({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  EXPECT_EQ(norm(derivative(ex5, 0.5)), 0);
  // Exercises 7, 8 and 9 have one inflection each; 4 and 6 none.
  auto inflections = [](const Bezier& b) {
    int changes = 0;
    double prev = 0;
    for (int i = 0; i <= 4000; ++i) {
      const double t = i / 4000.0;
      const double c = cross(derivative(b, t), second_derivative(b, t)).z;
      if (std::abs(c) < 1e-9) continue;
      if (prev != 0 && (c > 0) != (prev > 0)) ++changes;
      prev = c;
    }
    return changes;
  };
  EXPECT_EQ(inflections(Bezier::make({{0, 0}, {2, 2}, {1, 0}, {3, 1}})), 1);
  EXPECT_EQ(inflections(Bezier::make({{0, 0}, {2, 0}, {-2, 2}, {0, 2}})), 1);
  EXPECT_EQ(inflections(Bezier::make({{0, -1}, {1, 1}, {0, 0}, {-1, 0}, {0, 1}})), 1);
  EXPECT_EQ(inflections(Bezier::make({{0, 0}, {1, 0}, {2, 1}, {0, 1}})), 0);
  EXPECT_EQ(inflections(Bezier::make({{0, 0}, {2, 0}, {2, 2}, {0, 2}})), 0);
}

TEST(Bezier, QuadraticIsAParabolaArc) {
  // Constant second derivative: 2 (P0 - 2 P1 + P2).
  const Bezier q = Bezier::make({{0, 0}, {2, 0}, {1, 1}});
  for (double t = 0; t <= 1; t += 0.1)
    expect_near(second_derivative(q, t), 2 * (q.points[0] - 2 * q.points[1] + q.points[2]), 1e-13);
}

TEST(Bezier, DegreeElevationKeepsTheCurve) {
  std::mt19937_64 rng(3);
  for (bool rational : {false, true}) {
    for (int degree = 1; degree <= 12; ++degree) {
      const Bezier b = random_bezier(rng, degree, 3, rational);
      const Bezier e = elevate(b);
      ASSERT_EQ(e.degree(), degree + 1);
      for (double t = 0; t <= 1; t += 0.1) expect_near(evaluate(e, t), evaluate(b, t), 1e-9);
    }
  }
}

TEST(Bezier, RepeatingAControlPointPullsTheCurveTowardsIt) {
  const Bezier b = Bezier::make({{0, 0}, {1, 2}, {2, 0}});
  const Bezier r = Bezier::make({{0, 0}, {1, 2}, {1, 2}, {2, 0}});
  EXPECT_LT(dist(evaluate(r, 0.5), {1, 2}), dist(evaluate(b, 0.5), {1, 2}));
}

TEST(Bezier, RationalQuarterCircleIsExact) {
  const double w = std::sqrt(0.5);
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, w, 1});
  for (double t = 0; t <= 1; t += 1.0 / 128) EXPECT_NEAR(norm(evaluate(q, t)), 10, 1e-12);
  // Bernstein form and derivatives of the rational curve agree with de Casteljau.
  for (double t = 0.05; t < 1; t += 0.1) {
    expect_near(evaluate_bernstein(q, t), evaluate(q, t), 1e-12);
    const double h = 1e-6;
    expect_near(derivative(q, t), (evaluate(q, t + h) - evaluate(q, t - h)) / (2 * h), 1e-5);
    EXPECT_NEAR(dot(derivative(q, t), evaluate(q, t)), 0, 1e-9);  // tangent of a circle
    const Vec3 d2 = second_derivative(q, t);
    const Vec3 fd2 = (derivative(q, t + h) - derivative(q, t - h)) / (2 * h);
    expect_near(d2, fd2, 1e-4);
  }
  // Splitting a rational curve keeps it on the circle.
  auto [l, r] = split(q, 0.3);
  for (double t = 0; t <= 1; t += 0.1) {
    EXPECT_NEAR(norm(evaluate(l, t)), 10, 1e-12);
    EXPECT_NEAR(norm(evaluate(r, t)), 10, 1e-12);
  }
  EXPECT_NEAR(length(q), 10 * std::numbers::pi / 2, 1e-9);
}

TEST(Bezier, SubcurveAndBoundsAndLength) {
  std::mt19937_64 rng(11);
  for (int degree = 1; degree <= 8; ++degree) {
    const Bezier b = random_bezier(rng, degree, 3, degree % 2 == 0);
    const Bezier s = subcurve(b, 0.2, 0.7);
    for (double u = 0; u <= 1; u += 0.1) expect_near(evaluate(s, u), evaluate(b, 0.2 + 0.5 * u), 1e-9);
    // bounds() contains every point and is touched by the curve.
    const Box3 box = bounds(b);
    Box3 sampled;
    for (int i = 0; i <= 20000; ++i) sampled.add(evaluate(b, i / 20000.0));
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(box.lo[k], sampled.lo[k] + 1e-9);
      EXPECT_GE(box.hi[k], sampled.hi[k] - 1e-9);
      EXPECT_NEAR(box.lo[k], sampled.lo[k], 1e-3);
      EXPECT_NEAR(box.hi[k], sampled.hi[k], 1e-3);
    }
    // Length against a fine polyline (a lower bound converging from below).
    double poly = 0;
    for (int i = 1; i <= 200000; ++i) poly += dist(evaluate(b, (i - 1) / 200000.0), evaluate(b, i / 200000.0));
    EXPECT_NEAR(length(b), poly, 1e-6 * poly);
    EXPECT_GE(length(b), poly - 1e-9);
  }
  EXPECT_NEAR(length(Bezier::make({{0, 0}, {3, 4}})), 5, 1e-12);
}

TEST(Bezier, FactoryRefusesBadInputNamingTheIndex) {
  auto expect_error = [](auto f, const std::string& id, const std::string& where) {
    try {
      f();
      FAIL() << "expected " << id;
    } catch (const InputError& e) {
      EXPECT_EQ(e.id(), id);
      EXPECT_EQ(e.where(), where);
    }
  };
  expect_error([] { Bezier::make({{0, 0}}); }, "curve.too-few-points", "points");
  expect_error([] { Bezier::make({{0, 0}, {NAN, 1}}); }, "curve.not-finite", "points[1]");
  expect_error([] { Bezier::make({{0, 0}, {1, 1}}, {1, 0}); }, "curve.weight", "weights[1]");
  expect_error([] { Bezier::make({{0, 0}, {1, 1}}, {1, -2}); }, "curve.weight", "weights[1]");
  expect_error([] { Bezier::make({{0, 0}, {1, 1}}, {1}); }, "curve.weights-count", "weights");
  expect_error([] { Bezier::make(std::vector<Vec3>(kMaxBezierDegree + 2, Vec3{})); }, "curve.degree-too-high",
               "points");
  // Equal weights are a polynomial curve.
  EXPECT_FALSE(Bezier::make({{0, 0}, {1, 1}}, {2, 2}).rational());
}

TEST(Bezier, InflectionsOfPlanarCubics) {
  // An S curve symmetric about its middle inflects there, exactly.
  EXPECT_EQ(inflections(Bezier::make({{0, 0}, {1, 1}, {2, -1}, {3, 0}})), std::vector<double>{0.5});
  // A C, a quadratic, a line: none; a straight cubic has M' x M'' = 0 exactly.
  EXPECT_TRUE(inflections(Bezier::make({{0, 0}, {1, 0}, {2, 1}, {0, 1}})).empty());
  EXPECT_TRUE(inflections(Bezier::make({{0, 0}, {1, 2}, {3, 0}})).empty());
  EXPECT_TRUE(inflections(Bezier::make({{0, 0}, {3, 1}})).empty());
  EXPECT_TRUE(inflections(Bezier::make({{0, 0}, {1, 0}, {2, 0}, {3, 0}})).empty());
  // The inflections, ascending, where the curvature changes sign (read
  // from the sign of M' x M'' on either side), and nowhere else.
  for (const Bezier& b :
       {Bezier::make({{0, 0}, {4, 4}, {-1, 4}, {3, 0}}), Bezier::make({{0, 0}, {10, 10}, {20, -10}, {30, 0}}),
        Bezier::make({{0, 0}, {2, 2}, {1, 0}, {3, 1}}), Bezier::make({{0, 0}, {3, 5}, {0, -5}, {3, 0}})}) {
    const std::vector<double> t = inflections(b);
    auto turn = [&](double s) { return cross(derivative(b, s), second_derivative(b, s)).z; };
    int changes = 0;
    for (int i = 1; i <= 4000; ++i) changes += (turn((i - 1) / 4000.0) > 0) != (turn(i / 4000.0) > 0);
    EXPECT_EQ(static_cast<int>(t.size()), changes);
    EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
    for (const double s : t) {
      EXPECT_NEAR(turn(s), 0, 1e-9 * norm(derivative(b, s)) * norm(second_derivative(b, s)) + 1e-12);
      EXPECT_LT(turn(s - 1e-4) * turn(s + 1e-4), 0);
    }
  }
}
