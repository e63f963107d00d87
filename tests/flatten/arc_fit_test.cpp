#include "bezcam/flatten/arc_fit.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <random>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"

namespace bezcam {
namespace {

constexpr double kPi = std::numbers::pi;

// Exact rational quadratic of the arc of radius r around c from angle a0 to a1 (|a1 - a0| < pi).
Bezier exact_arc(Vec3 c, double r, double a0, double a1) {
  const double h = (a1 - a0) / 2;
  const Vec3 p0 = c + Vec3{std::cos(a0), std::sin(a0)} * r;
  const Vec3 p2 = c + Vec3{std::cos(a1), std::sin(a1)} * r;
  const double am = (a0 + a1) / 2;
  const Vec3 p1 = c + Vec3{std::cos(am), std::sin(am)} * (r / std::cos(h));
  return Bezier::make({p0, p1, p2}, {1, std::cos(h), 1});
}

// The path a controller draws, densely: arcs by the spiral model in the
// result's plane (or `plane` when given), lines as they are.
std::vector<Vec3> drawn(const ArcFitResult& r, double sagitta, std::optional<Plane> plane = std::nullopt) {
  std::vector<Vec3> out{r.start};
  Vec3 from = r.start;
  for (const auto& m : r.moves) {
    if (m.kind == FitKind::line) {
      out.push_back(m.to);
    } else {
      PrintedArc a{from, m.to, m.center, m.kind == FitKind::arc_ccw, plane.value_or(r.plane)};
      auto pts = sample_arc(a, sagitta);
      out.insert(out.end(), pts.begin() + 1, pts.end());
    }
    from = m.to;
  }
  return out;
}

size_t count_arcs(const ArcFitResult& r) {
  size_t n = 0;
  for (const auto& m : r.moves) n += m.kind != FitKind::line;
  return n;
}

// Every printed arc is one a controller accepts, and the result honours the
// tolerance when measured independently.
void check_result(std::span<const Bezier> pieces, const ArcFitOptions& o, const ArcFitResult& r) {
  Vec3 from = r.start;
  for (const auto& m : r.moves) {
    EXPECT_EQ(quantize(m.to, o.decimals), m.to);
    if (m.kind != FitKind::line) {
      PrintedArc a{from, m.to, m.center, m.kind == FitKind::arc_ccw};
      EXPECT_LE(std::abs(a.r_start() - a.r_end()), o.radius_tolerance);
      EXPECT_LT(a.sweep(), kPi);
      EXPECT_EQ(quantize(m.ij.x, o.decimals), m.ij.x);
      EXPECT_EQ(quantize(m.ij.y, o.decimals), m.ij.y);
      EXPECT_EQ(m.center.x, from.x + m.ij.x);
      EXPECT_EQ(m.center.y, from.y + m.ij.y);
    }
    EXPECT_LE(m.bound, o.tolerance);
    from = m.to;
  }
  EXPECT_LE(r.bound, o.tolerance);
  const auto poly = drawn(r, o.tolerance * 1e-4);
  // The measurement (accurate to ~1e-3 tol, plus the sampling sagitta) never
  // exceeds the proven bound. measure_deviation() reads true distances above
  // its `tolerance` argument (below it a windowed search may read high), so
  // it is asked about the bound itself.
  const double check = r.bound + 2e-3 * o.tolerance;
  EXPECT_LE(measure_deviation(pieces, poly, check).max(), check);
}

TEST(ArcFit, ExactQuarterCircleIsOneArcAroundTheTrueCentre) {
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, std::sqrt(0.5), 1});
  ArcFitOptions o{0.01, 3, 0.002};
  const auto r = fit_arcs(std::span(&q, 1), o);
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].kind, FitKind::arc_ccw);
  EXPECT_EQ(r.moves[0].to, Vec3(0, 10));
  EXPECT_EQ(r.moves[0].center, Vec3(0, 0));
  EXPECT_EQ(r.moves[0].ij, Vec3(-10, 0));
  EXPECT_LT(r.bound, 1e-5);
  check_result(std::span(&q, 1), o, r);
}

TEST(ArcFit, ClockwiseArcIsG02) {
  const Bezier q = reversed(exact_arc({5, 5}, 20, 0.3, 2.1));
  ArcFitOptions o{0.01, 3, 0.002};
  const auto r = fit_arcs(std::span(&q, 1), o);
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].kind, FitKind::arc_cw);
  EXPECT_NEAR(r.moves[0].center.x, 5, 1.5e-3);
  EXPECT_NEAR(r.moves[0].center.y, 5, 1.5e-3);
  check_result(std::span(&q, 1), o, r);
}

TEST(ArcFit, FullCircleOfFourPiecesIsFourArcs) {
  std::vector<Bezier> ps;
  for (int k = 0; k < 4; ++k) ps.push_back(exact_arc({1, 2}, 7, k * kPi / 2, (k + 1) * kPi / 2));
  ArcFitOptions o{0.005, 4, 0.002};
  const auto r = fit_arcs(ps, o);
  EXPECT_EQ(r.moves.size(), 4u);
  EXPECT_EQ(count_arcs(r), 4u);
  check_result(ps, o, r);
}

TEST(ArcFit, ArcSpanDeviationIsExactForConcentricCircles) {
  // The true arc has radius 10, the printed one 10.01 around the same centre
  // with the same angles: the distance is 0.01 everywhere.
  const Bezier q = exact_arc({0, 0}, 10, 0.2, 1.4);
  PrintedArc a{Vec3{std::cos(0.2), std::sin(0.2)} * 10.01, Vec3{std::cos(1.4), std::sin(1.4)} * 10.01, {0, 0}, true};
  // Proven at most 0.2 % above, and proven not below.
  EXPECT_LE(arc_span_deviation(q, 0, 1, a, 0.01 * 1.002), 0.01 * 1.002);
  EXPECT_GT(arc_span_deviation(q, 0, 1, a, 0.01 * 0.999), 0.01 * 0.999);
  // Against itself: nothing but floating point.
  PrintedArc same{q.front(), q.back(), {0, 0}, true};
  EXPECT_LE(arc_span_deviation(q, 0, 1, same, 1e-6), 1e-6);
  EXPECT_LE(arc_span_deviation(q, 0, 1, same, -1, 1e-6), 2e-6);
  EXPECT_NEAR(arc_span_deviation(q, 0, 1, a, -1, 1e-9), 0.01, 1e-5);
  // The wrong direction is the long way round: refused.
  PrintedArc wrong = same;
  wrong.ccw = false;
  EXPECT_GT(arc_span_deviation(q, 0, 1, wrong, 1.0), 1.0);
}

TEST(ArcFit, SemicircleNeedsFarFewerBlocksThanLines) {
  const Bezier s = Bezier::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0}});
  ArcFitOptions o{0.005, 3, 0.002};
  const auto r = fit_arcs(std::span(&s, 1), o);
  const auto lines = flatten(s, {0.005, 3});
  EXPECT_LT(r.moves.size() * 3, lines.points.size() - 1) << r.moves.size() << " arcs vs " << lines.points.size() - 1;
  check_result(std::span(&s, 1), o, r);
}

TEST(ArcFit, StraightPieceIsOneLine) {
  const Bezier l = Bezier::make({{0, 0}, {1, 1}, {3, 3}});
  const auto r = fit_arcs(std::span(&l, 1), {0.01, 3, 0.002});
  ASSERT_EQ(r.moves.size(), 1u);
  EXPECT_EQ(r.moves[0].kind, FitKind::line);
}

TEST(ArcFit, NonPlanarPiecesGetLinesOnly) {
  const Bezier c = Bezier::make({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}, {}, 3);
  EXPECT_FALSE(planar_xy(c));
  ArcFitOptions o{0.001, 4, 0.002};
  const auto r = fit_arcs(std::span(&c, 1), o);
  EXPECT_EQ(count_arcs(r), 0u);
  check_result(std::span(&c, 1), o, r);
}

TEST(ArcFit, PlanarThreeDimensionalPieceCountsTheRoundedZ) {
  // z = 0.12345 printed with 3 decimals is 0.123: 0.00045 of the budget.
  const Bezier c = Bezier::make({{0, 0, 0.12345}, {10, 0, 0.12345}, {10, 10, 0.12345}}, {}, 3);
  EXPECT_TRUE(planar_xy(c));
  ArcFitOptions o{0.01, 3, 0.002};
  const auto r = fit_arcs(std::span(&c, 1), o);
  EXPECT_GT(count_arcs(r), 0u);
  for (const auto& m : r.moves) {
    EXPECT_EQ(m.to.z, 0.123);
    EXPECT_GE(m.bound, 0.00045 - 1e-12);
  }
}

TEST(ArcFit, ToleranceBelowRoundingIsRefused) {
  const Bezier s = Bezier::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0}});
  try {
    fit_arcs(std::span(&s, 1), ArcFitOptions{0.005, 2, 0.01});
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "flatten.tolerance-below-rounding");
    EXPECT_NE(e.message().find("2 decimals"), std::string::npos);
  }
}

TEST(ArcFit, RandomPlanarCurvesStayWithinToleranceAfterRounding) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> coord(-20, 20), weight(0.3, 3);
  int arcs = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int degree = 2 + trial % 4;  // 2..5
    const bool rational = trial % 3 == 0;
    std::vector<Vec3> pts;
    std::vector<double> w;
    for (int i = 0; i <= degree; ++i) {
      pts.push_back({coord(rng), coord(rng)});
      if (rational) w.push_back(weight(rng));
    }
    const Bezier b = Bezier::make(pts, w);
    const ArcFitOptions o{trial % 2 ? 0.01 : 0.02, 3 + trial % 2, trial % 4 == 1 ? 0.001 : 0.002};
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto r = fit_arcs(std::span(&b, 1), o);
    arcs += static_cast<int>(count_arcs(r));
    check_result(std::span(&b, 1), o, r);
  }
  EXPECT_GT(arcs, 24);  // arcs are actually used, not only the G01 fallback
}

TEST(ArcFit, PathOfSeveralPiecesStartsEachPieceFromThePrintedPoint) {
  std::vector<Bezier> ps{Bezier::make({{0, 0}, {20, 10}, {30, 20}, {30, 30}}),
                         Bezier::make({{30, 30}, {30, 40}, {20, 45}, {10, 40}}),
                         Bezier::make({{10, 40}, {0, 35}, {-10, 20}, {0, 0}})};
  ArcFitOptions o{0.01, 3, 0.002};
  const auto r = fit_arcs(ps, o);
  EXPECT_EQ(r.moves.back().to, Vec3(0, 0));
  check_result(ps, o, r);
  size_t piece = 0;
  for (const auto& m : r.moves) {
    EXPECT_GE(m.piece, piece);
    piece = m.piece;
  }
  EXPECT_EQ(piece, 2u);
}

// One turn of a helix round the axis of `pl` (radius 10, rising 2 a
// quarter turn), as four cubic quarter turns in world coordinates: the
// classic circle handles (within 2.7e-4 of the radius) and h linear in t.
std::vector<Bezier> helix_turn(Plane pl) {
  const double k = 10 * 4.0 / 3 * (std::sqrt(2.0) - 1);
  std::vector<Bezier> ps;
  for (int q = 0; q < 4; ++q) {
    const double a0 = q * kPi / 2, a1 = a0 + kPi / 2, h0 = 2.0 * q;
    const Vec3 u0{std::cos(a0), std::sin(a0)}, u1{std::cos(a1), std::sin(a1)};
    const Vec3 t0{-u0.y, u0.x}, t1{-u1.y, u1.x};
    std::vector<Vec3> pts{u0 * 10, u0 * 10 + t0 * k, u1 * 10 - t1 * k, u1 * 10};
    for (int i = 0; i < 4; ++i) pts[i] = from_plane(pts[i] + Vec3{0, 0, h0 + 2.0 * i / 3}, pl);
    ps.push_back(Bezier::make(pts, {}, 3));
  }
  return ps;
}

TEST(ArcFit, HelicalArcsInEachPlaneFollowAHelixRoundItsAxis) {
  for (const Plane pl : {Plane::xy, Plane::zx, Plane::yz}) {
    SCOPED_TRACE(g_number(pl));
    const auto ps = helix_turn(pl);
    // The axis spreads 8, the plane 20 each way: the plane is chosen.
    EXPECT_EQ(least_climb_plane(ps), pl);
    ArcFitOptions o{0.01, 3, 0.002};
    const auto r = fit_helical_arcs(ps, o, pl);
    EXPECT_EQ(r.plane, pl);
    EXPECT_EQ(r.start, quantize(ps.front().front(), 3));
    EXPECT_EQ(r.moves.back().to, quantize(ps.back().back(), 3));
    // A handful of arcs where lines need many times more.
    EXPECT_GE(count_arcs(r), 4u);
    EXPECT_LT(r.moves.size() * 4, fit_arcs(ps, o).moves.size());
    const int h = world_axis(pl, 2);
    Vec3 from = r.start;
    for (const auto& m : r.moves) {
      if (m.kind != FitKind::line) {
        // World points; the centre at the start's height along the axis,
        // the printed centre words in the plane's (a, b).
        EXPECT_EQ(m.center[h], from[h]);
        const Vec3 d = to_plane(m.center - from, pl);
        EXPECT_NEAR(d.x, m.ij.x, 1e-9);
        EXPECT_NEAR(d.y, m.ij.y, 1e-9);
        const PrintedArc a{from, m.to, m.center, m.kind == FitKind::arc_ccw, pl};
        EXPECT_LE(std::abs(a.r_start() - a.r_end()), o.radius_tolerance);
      }
      EXPECT_LE(m.bound, o.tolerance);
      from = m.to;
    }
    EXPECT_LE(r.bound, o.tolerance);
    // Measured independently along the arcs drawn in their plane.
    const double check = r.bound + 2e-3 * o.tolerance;
    EXPECT_LE(measure_deviation(ps, drawn(r, o.tolerance * 1e-4), check).max(), check);
    // The same words drawn in another plane are far off: the measurement
    // sees the plane.
    const Plane other = pl == Plane::xy ? Plane::zx : Plane::xy;
    EXPECT_GT(measure_deviation(ps, drawn(r, o.tolerance * 1e-4, other), o.tolerance).max(), 1.0);
  }
}

}  // namespace
}  // namespace bezcam
