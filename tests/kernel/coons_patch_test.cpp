// Coons patches: the digest's facts exactly (the patch reproduces its four
// boundaries; linear blending of four straight edges is the bilinear
// surface), then the exact Bézier cells against the formula.
#include "bezcam/kernel/coons_patch.hpp"

#include <gtest/gtest.h>
#include <random>

#include "bezcam/error.hpp"
#include "support/surface_fixtures.hpp"

namespace bezcam {
namespace {

const CoonsBlend kBlends[] = {CoonsBlend::linear, CoonsBlend::cubic, CoonsBlend::quintic};

TEST(CoonsBlend, BlendFunctionsMatchTheDigest) {
  for (CoonsBlend b : kBlends) {
    EXPECT_EQ(blend_f0(b, 0), 1);
    EXPECT_EQ(blend_f0(b, 1), 0);
    EXPECT_EQ(blend_f1(b, 0), 0);
    EXPECT_EQ(blend_f1(b, 1), 1);
    for (double t : {0.1, 0.37, 0.5, 0.9}) EXPECT_NEAR(blend_f0(b, t) + blend_f1(b, t), 1, 1e-15);
  }
  // Cubic: tangent continuity (f' = 0 at the ends); quintic: curvature too.
  for (double t : {0.0, 1.0}) {
    EXPECT_EQ(blend_f0(CoonsBlend::cubic, t, 1), 0);
    EXPECT_EQ(blend_f0(CoonsBlend::quintic, t, 1), 0);
    EXPECT_EQ(blend_f0(CoonsBlend::quintic, t, 2), 0);
  }
  EXPECT_NEAR(blend_f0(CoonsBlend::cubic, 0.25), 2 * 0.015625 - 3 * 0.0625 + 1, 1e-15);
  EXPECT_NEAR(blend_f1(CoonsBlend::quintic, 0.5), 0.5, 1e-15);
}

TEST(CoonsPatch, ReproducesItsFourBoundaries) {
  for (CoonsBlend b : kBlends) {
    const CoonsPatch s = fixtures::curved_coons(b);
    const PatchGrid g = to_bezier_cells(s);
    for (int k = 0; k <= 50; ++k) {
      const double t = k / 50.0;
      const Vec3 e0 = evaluate(s.v0, t), e1 = evaluate(s.v1, t), e2 = evaluate(s.u0, t), e3 = evaluate(s.u1, t);
      EXPECT_LE(dist(evaluate(s, t, 0), e0), 1e-12);
      EXPECT_LE(dist(evaluate(s, t, 1), e1), 1e-12);
      EXPECT_LE(dist(evaluate(s, 0, t), e2), 1e-12);
      EXPECT_LE(dist(evaluate(s, 1, t), e3), 1e-12);
      // The exact cells too.
      EXPECT_LE(dist(evaluate_derivs(g, t, 0).p, e0), 1e-11);
      EXPECT_LE(dist(evaluate_derivs(g, t, 1).p, e1), 1e-11);
      EXPECT_LE(dist(evaluate_derivs(g, 0, t).p, e2), 1e-11);
      EXPECT_LE(dist(evaluate_derivs(g, 1, t).p, e3), 1e-11);
    }
  }
}

TEST(CoonsPatch, LinearBlendOfStraightEdgesIsTheBilinearSurface) {
  const Vec3 p00{0, 0, 1}, p10{10, 1, 3}, p01{-1, 8, 2}, p11{12, 9, -4};
  const CoonsPatch s = CoonsPatch::make(BoundaryCurve::make({fixtures::line3(p00, p10)}),
                                        BoundaryCurve::make({fixtures::line3(p01, p11)}),
                                        BoundaryCurve::make({fixtures::line3(p00, p01)}),
                                        BoundaryCurve::make({fixtures::line3(p10, p11)}), CoonsBlend::linear);
  const PatchGrid g = to_bezier_cells(s);
  ASSERT_EQ(g.cells.size(), 1u);
  EXPECT_EQ(g.cells[0].nu, 1);
  EXPECT_EQ(g.cells[0].nv, 1);
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) {
      const double u = i / 10.0, v = j / 10.0;
      const Vec3 bil = p00 * ((1 - u) * (1 - v)) + p10 * (u * (1 - v)) + p01 * ((1 - u) * v) + p11 * (u * v);
      EXPECT_LE(dist(evaluate(s, u, v), bil), 1e-14);
      EXPECT_LE(dist(evaluate(g.cells[0], u, v), bil), 1e-14);
    }
}

TEST(CoonsPatch, BezierCellsEqualTheFormulaWithDerivatives) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> t(0, 1);
  for (CoonsBlend b : kBlends) {
    const CoonsPatch s = fixtures::curved_coons(b);
    const PatchGrid g = to_bezier_cells(s);
    EXPECT_EQ(g.cells[0].nu, std::max(3, blend_degree(b)));
    EXPECT_FALSE(g.cells[0].rational());
    for (int k = 0; k < 30; ++k) {
      const double u = t(rng), v = t(rng);
      const PatchDerivs a = evaluate_derivs(s, u, v), c = evaluate_derivs(g, u, v);
      EXPECT_LE(dist(a.p, c.p), 1e-11);
      EXPECT_LE(dist(a.su, c.su), 1e-10);
      EXPECT_LE(dist(a.sv, c.sv), 1e-10);
      EXPECT_LE(dist(a.suu, c.suu), 1e-9);
      EXPECT_LE(dist(a.suv, c.suv), 1e-9);
      EXPECT_LE(dist(a.svv, c.svv), 1e-9);
    }
  }
}

// A boundary made of several pieces on a non-uniform partition (as a
// B-spline's knot spans give), and rational arcs: the cells are still exact.
TEST(CoonsPatch, MultiPieceAndRationalBoundariesGiveExactCells) {
  const Bezier whole = fixtures::cubic3({0, 0, 0}, {30, -10, 12}, {70, 10, 14}, {100, 0, 5});
  auto [a, b] = split(whole, 0.3);
  const BoundaryCurve v0 = BoundaryCurve::make({a, b}, {0, 0.3, 1});
  // v1: a rational quarter-ellipse-like arc from (0,80,8) to (100,80,0).
  const Bezier arc = Bezier::make({{0, 80, 8}, {0, 80, 40}, {100, 80, 0}}, {1, 0.7, 1}, 3);
  const BoundaryCurve v1 = BoundaryCurve::make({arc});
  const BoundaryCurve u0 = BoundaryCurve::make({fixtures::cubic3({0, 0, 0}, {-8, 25, 10}, {8, 55, 15}, {0, 80, 8})});
  auto [c, d] = split(fixtures::cubic3({100, 0, 5}, {110, 30, 12}, {95, 50, 9}, {100, 80, 0}), 0.6);
  const BoundaryCurve u1 = BoundaryCurve::make({c, d}, {0, 0.6, 1});
  for (CoonsBlend bl : kBlends) {
    const CoonsPatch s = CoonsPatch::make(v0, v1, u0, u1, bl);
    const PatchGrid g = to_bezier_cells(s);
    EXPECT_EQ(g.ubreaks, (std::vector<double>{0, 0.3, 1}));
    EXPECT_EQ(g.vbreaks, (std::vector<double>{0, 0.6, 1}));
    ASSERT_EQ(g.cells.size(), 4u);
    EXPECT_TRUE(g.cells[0].rational());
    for (const auto& cell : g.cells)
      for (double w : cell.weights) EXPECT_GT(w, 0);
    for (int i = 0; i <= 12; ++i)
      for (int j = 0; j <= 12; ++j) {
        const double u = i / 12.0, v = j / 12.0;
        EXPECT_LE(dist(evaluate(s, u, v), evaluate_derivs(g, u, v).p), 1e-10) << u << " " << v;
      }
    // The boundary with the non-uniform partition is the original cubic in
    // its own parameter.
    for (double t : {0.1, 0.3, 0.55, 0.9}) EXPECT_LE(dist(evaluate_derivs(g, t, 0).p, evaluate(whole, t)), 1e-11);
  }
}

TEST(CoonsPatch, CornersThatDoNotMeetAreRefusedNamingTheBoundary) {
  const Vec3 p00{0, 0, 0}, p10{10, 0, 0}, p01{0, 10, 0}, p11{10, 10, 0};
  auto L = [](Vec3 a, Vec3 b) { return BoundaryCurve::make({fixtures::line3(a, b)}); };
  try {
    CoonsPatch::make(L(p00, p10), L(p01, p11), L(p00, p01), L(p10, {10, 10, 1}), CoonsBlend::cubic);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "coons.corner");
    EXPECT_EQ(e.where(), "boundaries.u1");
    EXPECT_NE(e.message().find("S(1,1)"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("1 away"), std::string::npos) << e.message();
  }
  // u0 given backwards: the message says so.
  try {
    CoonsPatch::make(L(p00, p10), L(p01, p11), L(p01, p00), L(p10, p11), CoonsBlend::cubic);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "boundaries.u0");
    EXPECT_NE(e.message().find("reverse the points of u0"), std::string::npos) << e.message();
  }
  // v1 given backwards: blamed on v1.
  try {
    CoonsPatch::make(L(p00, p10), L(p11, p01), L(p00, p01), L(p10, p11), CoonsBlend::cubic);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("reverse the points of v1"), std::string::npos) << e.message();
  }
}

}  // namespace
}  // namespace bezcam
