// The time-optimal bound of an exact path (machine/path_bound.hpp): the
// closed forms of a line and a circle, and never above the time of a
// finely sampled solution of the exact (box-constrained) problem.
#include "bezcam/machine/path_bound.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

using namespace bezcam;

namespace {

constexpr double kPi = std::numbers::pi;

MotionModel model(double v_mm_min, double a) {
  MotionModel m;
  m.max_velocity_mm_min = {v_mm_min, v_mm_min, v_mm_min};
  m.max_acceleration_mm_s2 = {a, a, a};
  return m;
}

Bezier line(Vec3 a, Vec3 b) { return Bezier::make({a, b}); }

// A full circle of radius r around the origin: four rational quadratics.
std::vector<Bezier> circle(double r) {
  const double w = std::sqrt(0.5);
  std::vector<Bezier> out;
  const Vec3 c[] = {{r, 0}, {r, r}, {0, r}, {-r, r}, {-r, 0}, {-r, -r}, {0, -r}, {r, -r}, {r, 0}};
  for (int q = 0; q < 4; ++q) out.push_back(Bezier::make({c[2 * q], c[2 * q + 1], c[2 * q + 2]}, {1, w, 1}));
  return out;
}

// The exact problem sampled: at each of n points the largest u for which
// some tangential acceleration keeps every axis within its limit, then a
// forward-backward pass whose step uses the tangential acceleration
// available at the step's start. An estimate of the true minimum time
// (not a bound either way), to compare the bound with.
double sampled_minimum(const std::vector<Bezier>& pieces, double feed, double V, double A, int per_piece) {
  struct P {
    Vec3 T, K;
    double ds;
  };
  std::vector<P> pts;
  for (const Bezier& b : pieces)
    for (int i = 0; i < per_piece; ++i) {
      const double t = (i + 0.5) / per_piece;
      const Vec3 d1 = derivative(b, t), d2 = second_derivative(b, t);
      const double sp = norm(d1);
      const Vec3 T = d1 / sp;
      const Vec3 K = (d2 - T * dot(d2, T)) / (sp * sp);
      pts.push_back({T, K, sp / per_piece});
    }
  // Tangential accelerations possible at squared speed u: [lo, hi] (empty: lo > hi).
  auto range = [&](const P& p, double u, double& lo, double& hi) {
    lo = -1e300;
    hi = 1e300;
    for (int i = 0; i < 3; ++i) {
      const double n = u * p.K[i], t = p.T[i];
      if (std::abs(t) < 1e-12) {
        if (std::abs(n) > A) lo = 1, hi = 0;
        continue;
      }
      double a = (-A - n) / t, b = (A - n) / t;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a);
      hi = std::min(hi, b);
    }
  };
  const size_t m = pts.size();
  std::vector<double> cap(m);
  for (size_t k = 0; k < m; ++k) {
    double v = feed / 60;
    for (int i = 0; i < 3; ++i)
      if (std::abs(pts[k].T[i]) > 1e-12) v = std::min(v, V / 60 / std::abs(pts[k].T[i]));
    double lo = 0, hi = v * v;
    double a, b;
    range(pts[k], hi, a, b);
    if (a > b) {
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        range(pts[k], mid, a, b);
        (a <= b ? lo : hi) = mid;
      }
      cap[k] = lo;
    } else {
      cap[k] = hi;
    }
  }
  std::vector<double> u(m + 1, 0);
  for (size_t k = 0; k < m; ++k) {
    double a, b;
    range(pts[k], u[k], a, b);
    u[k + 1] = std::min(cap[k], u[k] + 2 * std::max(b, 0.0) * pts[k].ds);
  }
  u[m] = 0;
  for (size_t k = m; k-- > 0;) {
    double a, b;
    range(pts[k], u[k + 1], a, b);
    u[k] = std::min(u[k], u[k + 1] + 2 * std::max(-a, 0.0) * pts[k].ds);
  }
  double t = 0;
  for (size_t k = 0; k < m; ++k) {
    const double v = 0.5 * (std::sqrt(u[k]) + std::sqrt(u[k + 1]));
    t += pts[k].ds / std::max(v, 1e-9);
  }
  return t;
}

}  // namespace

TEST(PathBound, ALineFromRestToRestTakesLengthOverSpeedPlusSpeedOverAcceleration) {
  // 100 mm at 50 mm/s with 1000 mm/s^2 along X.
  const std::vector<Bezier> p{line({0, 0}, {100, 0})};
  EXPECT_NEAR(exact_path_time_bound(p, 3000, model(10000, 1000), Units::mm), 100.0 / 50 + 50.0 / 1000, 1e-8);
  // Too short to reach the feed: 2 sqrt(L / a).
  const std::vector<Bezier> s{line({0, 0}, {1, 0})};
  EXPECT_NEAR(exact_path_time_bound(s, 3000, model(10000, 1000), Units::mm), 2 * std::sqrt(1.0 / 1000), 1e-10);
}

TEST(PathBound, ALineAtAnAngleGetsTheAxesLimitsProjected) {
  // At 30 degrees, X limits both: v = V / cos 30, a = A / cos 30.
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6), L = 200;
  const std::vector<Bezier> p{line({0, 0}, {L * c, L * s})};
  const double v = 3000.0 / 60 / c, a = 1000 / c;
  EXPECT_NEAR(exact_path_time_bound(p, 60000, model(3000, 1000), Units::mm), L / v + v / a, 1e-7);
  // The same line in three pieces, a cubic among them (its speed along the
  // parameter varies, so its stretches' enclosures are looser): at most
  // the same, and within 1 % of it.
  const Vec3 e{L * c, L * s}, q1 = e * 0.25, q2 = e * 0.6;
  const std::vector<Bezier> three{line({0, 0}, q1), Bezier::make({q1, q1 + (q2 - q1) * 0.2, q1 + (q2 - q1) * 0.7, q2}),
                                  line(q2, e)};
  const double b3 = exact_path_time_bound(three, 60000, model(3000, 1000), Units::mm);
  EXPECT_LE(b3, L / v + v / a);
  EXPECT_GE(b3, 0.99 * (L / v + v / a));
}

TEST(PathBound, InchProgramsConvertTheLimits) {
  const std::vector<Bezier> p{line({0, 0}, {4, 0})};  // 101.6 mm
  const double L = 101.6, v = 50, a = 1000;
  EXPECT_NEAR(exact_path_time_bound(p, 3000 / 25.4, model(10000, 1000), Units::inch), L / v + v / a, 1e-8);
}

TEST(PathBound, ACircleIsHeldBySqrtOfAccelerationTimesRadius) {
  // Where the normal is along an axis the speed is at most sqrt(a R); the
  // box of accelerations allows at most sqrt(sqrt(2) a R) anywhere. The
  // bound lies between a lap at the second and one at the first with a
  // ramp from rest at the full acceleration.
  const double R = 50, A = 1000;
  const double b = exact_path_time_bound(circle(R), 1e6, model(1e6, A), Units::mm);
  const double v1 = std::sqrt(A * R), v2 = std::sqrt(std::sqrt(2.0) * A * R);
  EXPECT_GE(b, 2 * kPi * R / v2);
  EXPECT_LE(b, 2 * kPi * R / v1 + v1 / A);
  // Below sqrt(a R) the feed holds: a lap at the feed, plus less than a
  // ramp up and down at the smallest tangential acceleration (a).
  const double F = 0.5 * v1;
  const double slow = exact_path_time_bound(circle(R), F * 60, model(1e6, A), Units::mm);
  EXPECT_GE(slow, 2 * kPi * R / F);
  EXPECT_LE(slow, 2 * kPi * R / F + F / A);
}

TEST(PathBound, NeverAboveTheSampledExactProblem) {
  // Curves of several kinds: an S with an inflection, a tight loop, a
  // quarter circle (rational), a 3D cubic; on a machine whose Z is slower.
  MotionModel m = model(10000, 1000);
  m.max_velocity_mm_min[2] = 3000;
  m.max_acceleration_mm_s2[2] = 300;
  const std::vector<std::vector<Bezier>> cases{
      {Bezier::make({{0, 0}, {40, 60}, {60, -60}, {100, 0}})},
      {Bezier::make({{0, 0}, {60, 40}, {-20, 40}, {40, 0}})},
      {circle(20)[0]},
      {Bezier::make({{0, 0, 0}, {30, 10, -5}, {50, 40, -2}, {80, 20, -10}}, {}, 3)},
  };
  for (const double feed : {2000.0, 6000.0, 10000.0})
    for (size_t i = 0; i < cases.size(); ++i) {
      const double b = exact_path_time_bound(cases[i], feed, m, Units::mm);
      const double est = sampled_minimum(cases[i], feed, 10000, 1000, 20000);
      SCOPED_TRACE("case " + std::to_string(i) + " F" + std::to_string(feed));
      EXPECT_LE(b, est * 1.001);
      EXPECT_GE(b,
                est * 0.92);  // and not far below it (the relaxation decouples the normal and tangential accelerations)
    }
}

TEST(PathBound, NothingToFollowTakesNoTime) {
  EXPECT_EQ(exact_path_time_bound({}, 3000, model(10000, 1000), Units::mm), 0);
  const std::vector<Bezier> p{line({0, 0}, {10, 0})};
  EXPECT_EQ(exact_path_time_bound(p, 0, model(10000, 1000), Units::mm), 0);
}

TEST(PathBound, WithoutRestAtTheEndsALineTakesLengthOverSpeed) {
  // Entered and left at the feed (a blended plunge and retract): L / v.
  const std::vector<Bezier> p{line({0, 0}, {100, 0})};
  EXPECT_NEAR(exact_path_time_bound(p, 3000, model(10000, 1000), Units::mm, false), 100.0 / 50, 1e-8);
  MotionModel exact = model(10000, 1000);
  exact.blend_tolerance_mm = 0;
  EXPECT_TRUE(cuts_from_rest(exact));
  exact.blend_tolerance_mm = 0.01;
  EXPECT_FALSE(cuts_from_rest(exact));
}
