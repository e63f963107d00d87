// fit_arcs() with the band (ArcFitOptions::band): span ends inside a piece
// may leave the curve. Every result is checked against a brute-force
// two-sided distance between dense points of the drawn path and of the curve.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/tolerance.hpp"

namespace bezcam {
namespace {

// Distance from p to the segment [a, b].
double to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double l2 = dot(d, d);
  const double s = l2 > 0 ? std::clamp(dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
  return dist(p, a + d * s);
}

// Largest distance from a point of `from` to the polyline `to` (brute force).
double one_side(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  double worst = 0;
  for (const auto& p : from) {
    double best = dist(p, to.front());
    for (size_t i = 1; i < to.size() && best > 0; ++i) best = std::min(best, to_segment(p, to[i - 1], to[i]));
    worst = std::max(worst, best);
  }
  return worst;
}

struct Drawn {
  std::vector<Vec3> path;  // dense points of the drawn path
  size_t blocks = 0, arcs = 0;
};

Drawn draw(const ArcFitResult& r, double sagitta) {
  Drawn d;
  d.path.push_back(r.start);
  Vec3 from = r.start;
  for (const auto& m : r.moves) {
    ++d.blocks;
    if (m.kind == FitKind::line) {
      // Lines are subdivided too, so that the curve-to-path side sees
      // points all along them.
      for (int k = 1; k <= 64; ++k) d.path.push_back(from + (m.to - from) * (k / 64.0));
    } else {
      ++d.arcs;
      const auto pts = sample_arc(PrintedArc{from, m.to, m.center, m.kind == FitKind::arc_ccw}, sagitta);
      d.path.insert(d.path.end(), pts.begin() + 1, pts.end());
    }
    from = m.to;
  }
  return d;
}

std::vector<Vec3> dense_curve(std::span<const Bezier> pieces, int per_piece) {
  std::vector<Vec3> out;
  for (const auto& b : pieces)
    for (int k = 0; k <= per_piece; ++k) out.push_back(evaluate(b, static_cast<double>(k) / per_piece));
  return out;
}

// Checks a band fit: bounds within the tolerance, the brute-force two-sided
// distance within each proven bound (up to the sampling), the first and
// last points and every piece's end exact (within rounding). Returns the
// drawing.
Drawn check_band(std::span<const Bezier> pieces, const ArcFitOptions& o) {
  const auto r = fit_arcs(pieces, o);
  EXPECT_LE(r.bound, o.tolerance);
  for (const auto& m : r.moves) EXPECT_LE(m.bound, o.tolerance);
  EXPECT_EQ(r.start, quantize(pieces.front().front(), o.decimals));
  EXPECT_EQ(r.moves.back().to, quantize(pieces.back().back(), o.decimals));
  for (const auto& m : r.moves)
    if (m.t >= 1) EXPECT_EQ(m.to, quantize(pieces[m.piece].back(), o.decimals)) << "piece " << m.piece;
  const double sag = 1e-4 * o.tolerance;
  const Drawn d = draw(r, sag);
  const auto curve = dense_curve(pieces, 3000);
  // The curve's samples are no denser than the curve: its polyline lies
  // within its own sagitta of it, which the check allows for.
  const double curve_sag = 2e-4 * o.tolerance;
  EXPECT_LE(one_side(d.path, curve), r.bound + sag + curve_sag);
  EXPECT_LE(one_side(curve, d.path), r.bound + sag + curve_sag);
  return d;
}

ArcFitOptions band_options(double tol, int decimals) {
  ArcFitOptions o{tol, decimals, 0.002};
  o.band = true;
  return o;
}

TEST(ArcFitBand, PlanarPiecesKeepTheirOnCurveFit) {
  // Arcs and the lines between them stay on the curve (arc_fit.cpp says
  // why): the band changes nothing on planar pieces, and the checks hold.
  std::mt19937 rng(151515);
  std::uniform_real_distribution<double> coord(-20, 20), weight(0.3, 3);
  for (int trial = 0; trial < 12; ++trial) {
    const int degree = 2 + trial % 4;  // 2..5
    std::vector<Vec3> pts;
    std::vector<double> w;
    for (int i = 0; i <= degree; ++i) {
      pts.push_back({coord(rng), coord(rng)});
      if (trial % 3 == 0) w.push_back(weight(rng));
    }
    // Every fourth curve nearly straight, so that lines and arcs alternate.
    if (trial % 4 == 3)
      for (auto& p : pts) p.y *= 0.01;
    const Bezier b = Bezier::make(pts, w);
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto o = band_options(trial % 2 ? 0.01 : 0.003, 4);
    check_band(std::span(&b, 1), o);
    ArcFitOptions oc = o;
    oc.band = false;
    const auto band = fit_arcs(std::span(&b, 1), o), on = fit_arcs(std::span(&b, 1), oc);
    ASSERT_EQ(band.moves.size(), on.moves.size());
    for (size_t k = 0; k < on.moves.size(); ++k) EXPECT_EQ(band.moves[k].to, on.moves[k].to);
  }
}

TEST(ArcFitBand, PiecesThatAreNotPlanarGetLongerLines) {
  // A ramp and a twisted cubic: G01 only, whose inner ends leave the curve.
  const std::vector<Bezier> cases{Bezier::make({{0, 0, 0}, {10, 0, 1}, {10, 10, 2}, {0, 10, 3}}, {}, 3),
                                  Bezier::make({{0, 0, 0}, {5, 0, 0}, {5, 5, 0}, {5, 5, 5}}, {}, 3)};
  for (size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE("case " + std::to_string(k));
    const auto o = band_options(0.005, 4);
    const Drawn d = check_band(std::span(&cases[k], 1), o);
    EXPECT_EQ(d.arcs, 0u);
    ArcFitOptions oc = o;
    oc.band = false;
    const size_t on = fit_arcs(std::span(&cases[k], 1), oc).moves.size();
    EXPECT_LT(static_cast<double>(d.blocks), 0.8 * static_cast<double>(on)) << d.blocks << " vs " << on;
    double off = 0;
    for (const auto& m : fit_arcs(std::span(&cases[k], 1), o).moves)
      if (m.t < 1) off = std::max(off, dist(m.to, evaluate(cases[k], m.t)));
    EXPECT_GT(off, 0.5 * o.tolerance);
  }
}

TEST(ArcFitBand, InflectionNearStraightAndRationalPieces) {
  const std::vector<Bezier> cases{
      Bezier::make({{0, 0}, {10, 10}, {20, -10}, {30, 0}}),                  // inflection
      Bezier::make({{0, 0}, {10, 0.01}, {20, -0.01}, {30, 0}}),              // near straight, inflected
      Bezier::make({{0, 0}, {10, 0.2}, {20, 0.2}, {30, 0}}),                 // near straight
      Bezier::make({{0, 0}, {0, 20}, {40, 20}, {40, 0}}, {1, 0.4, 2.5, 1}),  // rational
      Bezier::make({{0, 0}, {5, 30}, {10, -30}, {15, 30}, {20, 0}}),         // degree 4, wavy
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE("case " + std::to_string(k));
    check_band(std::span(&cases[k], 1), band_options(0.01, 3));
    check_band(std::span(&cases[k], 1), band_options(0.002, -1));
  }
}

TEST(ArcFitBand, CircleLikeCurvesStayOneArcPerPiece) {
  // A quarter circle as a cubic (not exact: the cubic's radius wobbles by
  // 2.7e-4 of it): at a tolerance above the wobble each piece is one arc.
  std::vector<Bezier> ps;
  const double k = 0.5522847498 * 10;
  ps.push_back(Bezier::make({{10, 0}, {10, k}, {k, 10}, {0, 10}}));
  ps.push_back(Bezier::make({{0, 10}, {-k, 10}, {-10, k}, {-10, 0}}));
  const Drawn d = check_band(ps, band_options(0.01, 3));
  EXPECT_EQ(d.blocks, 2u);
  EXPECT_EQ(d.arcs, 2u);
}

TEST(ArcFitBand, PathOfPlanarAndRampPiecesKeepsItsJointsExact) {
  // Planar, ramp, planar: the ramp's lines leave the curve, its ends and
  // the planar pieces' arcs do not.
  std::vector<Bezier> ps{Bezier::make({{0, 0, 0}, {20, 10, 0}, {30, 20, 0}, {30, 30, 0}}, {}, 3),
                         Bezier::make({{30, 30, 0}, {30, 40, -1}, {20, 45, -2}, {10, 40, -3}}, {}, 3),
                         Bezier::make({{10, 40, -3}, {0, 35, -3}, {-10, 20, -3}, {0, 0, -3}}, {}, 3)};
  const auto o = band_options(0.005, 4);
  check_band(ps, o);
  ArcFitOptions oc = o;
  oc.band = false;
  const auto band = fit_arcs(ps, o), on = fit_arcs(ps, oc);
  size_t ramp_band = 0, ramp_on = 0;
  double off = 0;
  for (const auto& m : band.moves) {
    if (m.piece != 1) continue;
    ++ramp_band;
    if (m.t < 1) off = std::max(off, dist(m.to, evaluate(ps[1], m.t)));
  }
  for (const auto& m : on.moves) ramp_on += m.piece == 1;
  EXPECT_LT(ramp_band, ramp_on);
  EXPECT_GT(off, 0.5 * o.tolerance);
  // The planar pieces' moves end on the curve (within rounding).
  for (const auto& m : band.moves)
    if (m.piece != 1) EXPECT_LE(dist(m.to, evaluate(ps[m.piece], m.t)), max_rounding_displacement(4, 3));
}

TEST(ArcFitBand, HelicalFitsIgnoreTheBand) {
  const Bezier h = Bezier::make({{10, 0, 0}, {10, 6, 1}, {6, 10, 2}, {0, 10, 3}}, {}, 3);
  ArcFitOptions o{0.01, 4, 0.002};
  o.helical = true;
  const auto plain = fit_arcs(std::span(&h, 1), o);
  o.band = true;
  const auto banded = fit_arcs(std::span(&h, 1), o);
  ASSERT_EQ(plain.moves.size(), banded.moves.size());
  for (size_t i = 0; i < plain.moves.size(); ++i) EXPECT_EQ(plain.moves[i].to, banded.moves[i].to);
}

}  // namespace
}  // namespace bezcam
