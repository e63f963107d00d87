#include "bezcam/flatten/degree_reduce.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"

namespace bezcam {
namespace {

double sampled_distance(const Bezier& a, const Bezier& b) {
  double m = 0;
  for (int i = 0; i <= 2000; ++i) m = std::max(m, dist(evaluate(a, i / 2000.0), evaluate(b, i / 2000.0)));
  return m;
}

TEST(ParametricDistance, TranslatedSegmentIsTheTranslation) {
  const Bezier a = Bezier::make({{0, 0}, {1, 0}});
  const Bezier b = Bezier::make({{0, 0.3}, {1, 0.3}});
  EXPECT_NEAR(parametric_distance(a, b, -1), 0.3, 1e-15);
}

TEST(ParametricDistance, ElevatedCurveIsTheSameCurve) {
  const Bezier a = Bezier::make({{0, 0}, {2, 0}, {-2, 2}, {0, 2}});
  EXPECT_LT(parametric_distance(a, elevate(elevate(a)), -1, 1e-12), 1e-12);
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, std::sqrt(0.5), 1});
  EXPECT_LT(parametric_distance(q, elevate(q), -1, 1e-12), 1e-12);
}

TEST(ParametricDistance, BoundsTheSampledMaximumTightly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> c(-10, 10), w(0.2, 4), small(-0.05, 0.05);
  for (int trial = 0; trial < 40; ++trial) {
    const int da = 1 + trial % 5, db = 1 + (trial / 5) % 4;
    const bool ra = trial % 3 == 0, rb = trial % 4 == 0;
    std::vector<Vec3> pa, pb;
    std::vector<double> wa, wb;
    for (int i = 0; i <= da; ++i) pa.push_back({c(rng), c(rng), c(rng)}), ra ? wa.push_back(w(rng)) : void();
    for (int i = 0; i <= db; ++i) pb.push_back({c(rng), c(rng), c(rng)}), rb ? wb.push_back(w(rng)) : void();
    const Bezier a = Bezier::make(pa, wa, 3), b = Bezier::make(pb, wb, 3);
    const double s = sampled_distance(a, b);
    const double d = parametric_distance(a, b, -1);
    EXPECT_GE(d, s * (1 - 1e-12)) << trial;
    EXPECT_LE(d, s * 1.003) << trial;
    // Early exits agree with the refined value.
    EXPECT_LE(parametric_distance(a, b, d * 1.01), d * 1.01);
    EXPECT_GT(parametric_distance(a, b, s * 0.99), s * 0.99);
  }
}

TEST(ParametricDistance, WeightRoundingOfAQuarterCircle) {
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, std::sqrt(0.5), 1});
  const Bezier r = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, 0.7071, 1});
  const double d = parametric_distance(q, r, -1, 1e-12);
  EXPECT_NEAR(d, sampled_distance(q, r), 1e-3 * d);
  EXPECT_GT(d, 0);
  EXPECT_LT(d, 1e-4);
}

TEST(StandardForm, KeepsTheCurveAndSetsEndWeightsToOne) {
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {2, 3, 0.5});
  const Bezier s = standard_form(q);
  EXPECT_EQ(s.weights.front(), 1);
  EXPECT_EQ(s.weights.back(), 1);
  // Same conic: the point set agrees (measured two ways).
  const Bezier* pa = &q;
  const auto poly = flatten(s, {1e-6, -1}).points;
  EXPECT_LT(measure_deviation(std::span(pa, 1), poly, 1e-5).max(), 1.1e-6);
}

TEST(ReduceDegree, QuarticExerciseBecomesG1CubicsWithinBudget) {
  const Bezier b = Bezier::make({{0, -1}, {1, 1}, {0, 0}, {-1, 0}, {0, 1}});
  const auto r = reduce_degree(b, 3, 0.001, 10);
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->empty());
  EXPECT_EQ(r->front().approx.front(), b.front());
  EXPECT_EQ(r->back().approx.back(), b.back());
  EXPECT_EQ(r->front().t0, 0);
  EXPECT_EQ(r->back().t1, 1);
  for (size_t i = 0; i < r->size(); ++i) {
    const auto& p = (*r)[i];
    EXPECT_LE(p.bound, 0.001);
    EXPECT_EQ(p.approx.degree(), 3);
    // The source part is the input on [t0, t1].
    EXPECT_LT(dist(p.source.points[2], subcurve(b, p.t0, p.t1).points[2]), 1e-12);
    if (i > 0) {
      EXPECT_EQ(p.t0, (*r)[i - 1].t1);
      EXPECT_EQ(p.approx.front(), (*r)[i - 1].approx.back());
      // G1: the legs at the joint are parallel and point the same way.
      const auto& q = (*r)[i - 1].approx;
      const Vec3 u = q.points[3] - q.points[2], v = p.approx.points[1] - p.approx.points[0];
      EXPECT_LT(std::abs(cross(u, v).z), 1e-9 * norm(u) * norm(v));
      EXPECT_GT(dot(u, v), 0);
    }
  }
  // Independent two-sided measurement.
  std::vector<Vec3> poly;
  for (const auto& rp : *r) {
    const auto f = flatten(rp.approx, {1e-6, -1}).points;
    poly.insert(poly.end(), poly.empty() ? f.begin() : f.begin() + 1, f.end());
  }
  EXPECT_LE(measure_deviation(std::span(&b, 1), poly, 0.001).max(), 0.001 + 1e-6);
  // A looser budget needs no more pieces.
  EXPECT_LE(reduce_degree(b, 3, 0.01)->size(), r->size());
}

TEST(ReduceDegree, ElevatedQuadraticReducesExactlyInOnePiece) {
  const Bezier q = Bezier::make({{0, 0}, {3, 4}, {6, 0}});
  const Bezier c = elevate(q);
  const auto r = reduce_degree(c, 2, 1e-9, 3);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->size(), 1u);
  EXPECT_LT((*r)[0].bound, 1e-9);
  EXPECT_NEAR((*r)[0].approx.points[1].x, 3, 1e-9);
  EXPECT_NEAR((*r)[0].approx.points[1].y, 4, 1e-9);
}

TEST(ReduceDegree, RationalToPolynomialCubics) {
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, std::sqrt(0.5), 1});
  const auto r = reduce_degree(q, 3, 1e-4, 10);
  ASSERT_TRUE(r);
  for (const auto& p : *r) {
    EXPECT_LE(p.bound, 1e-4);
    EXPECT_FALSE(p.approx.rational());
  }
  // The distance is parametric (the rational parameter is not polynomial),
  // so this takes more pieces than the geometric optimum (2), but a bounded
  // number, and they honour the budget when measured geometrically.
  EXPECT_LE(r->size(), 16u);
  std::vector<Vec3> poly;
  for (const auto& p : *r) {
    const auto f = flatten(p.approx, {1e-7, -1}).points;
    poly.insert(poly.end(), poly.empty() ? f.begin() : f.begin() + 1, f.end());
  }
  EXPECT_LE(measure_deviation(std::span(&q, 1), poly, 1e-4).max(), 1e-4);
}

TEST(ReduceDegree, ImpossibleBudgetGivesNothing) {
  const Bezier b = Bezier::make({{0, -1}, {1, 1}, {0, 0}, {-1, 0}, {0, 1}});
  EXPECT_FALSE(reduce_degree(b, 3, 1e-14, 2));
  EXPECT_FALSE(reduce_degree(b, 0, 1));
}

}  // namespace
}  // namespace bezcam
