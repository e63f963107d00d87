#include "bezcam/flatten/exact_blocks.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/knot_vector.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {
namespace {

CurveGeometry single(const Bezier& b) {
  CurveSegment s;
  s.kind = "bezier";
  s.degree = b.degree();
  s.rational = b.rational();
  return make_single(s, {b}, b.dim);
}

CurveGeometry path(const std::vector<Bezier>& ps) {
  std::vector<CurveSegment> segs;
  for (size_t i = 0; i < ps.size(); ++i) {
    CurveSegment s;
    s.kind = "bezier";
    s.degree = ps[i].degree();
    s.rational = ps[i].rational();
    s.first_piece = i;
    s.piece_count = 1;
    segs.push_back(s);
  }
  return make_path(segs, ps, false, ps.front().dim);
}

CurveGeometry bspline(const NurbsCurve& c) {
  CurveSegment s;
  s.kind = "bspline";
  s.degree = c.degree;
  s.rational = c.rational();
  s.nurbs = std::make_shared<const NurbsCurve>(c);
  return make_single(s, to_bezier(c), c.dim);
}

ExactOptions fanuc(double tol = 0.01, int decimals = 3) {
  ExactOptions o;
  o.dialect = NurbsDialect::fanuc;
  o.tolerance = tol;
  o.decimals = decimals;
  return o;
}
ExactOptions linuxcnc(double tol = 0.01, int decimals = 4) {
  ExactOptions o = fanuc(tol, decimals);
  o.dialect = NurbsDialect::linuxcnc;
  return o;
}

// The blocks chain up as printed, obey the dialect's rules, keep their proven
// bound within the tolerance, and the printed curves measured independently
// against the source stay within that bound.
void check_plan(const CurveGeometry& g, const ExactOptions& o, const std::vector<ExactBlock>& blocks) {
  ASSERT_FALSE(blocks.empty());
  Vec3 cur = quantize(g.pieces.front().front(), o.decimals);
  std::vector<Vec3> poly{cur};
  double bound = 0;
  for (const auto& b : blocks) {
    if (b.kind == ExactKind::fallback) {
      // The fallback starts exactly at the current printed point.
      EXPECT_EQ(quantize(b.source.front().front(), o.decimals), cur);
      // It is cut by lines here (any path within tolerance would do).
      const auto f = flatten(b.source, {o.tolerance, o.decimals});
      poly.insert(poly.end(), f.points.begin() + 1, f.points.end());
      bound = std::max(bound, f.bound + b.snap);
      cur = f.points.back();
      continue;
    }
    EXPECT_EQ(b.ctrl.front(), cur);
    EXPECT_EQ(quantize(b.ctrl.back(), o.decimals), b.ctrl.back());
    if (b.kind == ExactKind::bezier) {
      // G5 / G5.1 print I, J relative to the start and P, Q relative to the end.
      const Vec3 ij = b.ctrl[1] - b.ctrl[0];
      EXPECT_NEAR(quantize(ij.x, o.decimals), ij.x, 1e-12);
      EXPECT_NEAR(quantize(ij.y, o.decimals), ij.y, 1e-12);
      if (b.ctrl.size() == 4) {
        const Vec3 pq = b.ctrl[2] - b.ctrl[3];
        EXPECT_NEAR(quantize(pq.x, o.decimals), pq.x, 1e-12);
        EXPECT_NEAR(quantize(pq.y, o.decimals), pq.y, 1e-12);
      }
    } else {
      for (const auto& p : b.ctrl) EXPECT_EQ(quantize(p, o.decimals), p);
    }
    EXPECT_LE(b.bound, o.tolerance);
    if (b.kind == ExactKind::nurbs) {
      ASSERT_EQ(b.weights.size(), b.ctrl.size());
      EXPECT_GE(b.order, 2);
      EXPECT_LE(b.order, o.dialect == NurbsDialect::fanuc ? o.max_rank : 4);
      ASSERT_EQ(b.knots.size(), b.ctrl.size() + b.order);
      // The dialect's knot rules, checked by the kernel's validation.
      EXPECT_NO_THROW(validate_knots(b.knots, b.order - 1, b.ctrl.size()));
      EXPECT_TRUE(is_clamped(b.knots, b.order - 1));
      for (double k : b.knots) EXPECT_EQ(quantize(k, o.knot_decimals), k);
      for (double w : b.weights) {
        EXPECT_GT(w, 0);
        EXPECT_EQ(quantize(w, o.weight_decimals), w);
      }
      // The printed pieces are the printed NURBS, decomposed.
      const auto n = NurbsCurve::make(b.order - 1, b.ctrl, b.knots, b.weights, g.dim);
      const auto pieces = to_bezier(n);
      ASSERT_EQ(pieces.size(), b.printed.size());
      for (size_t k = 0; k < pieces.size(); ++k)
        for (double t : {0.1, 0.5, 0.9}) EXPECT_LT(dist(evaluate(pieces[k], t), evaluate(b.printed[k], t)), 1e-9);
    }
    if (b.kind == ExactKind::bezier) EXPECT_TRUE(b.ctrl.size() == 3 || b.ctrl.size() == 4);
    if (o.dialect == NurbsDialect::linuxcnc)
      for (const auto& p : b.ctrl) EXPECT_EQ(p.z, cur.z);  // G5.x never moves Z
    for (const auto& p : b.printed) {
      const auto f = flatten(p, {o.tolerance * 1e-4, -1}).points;
      poly.insert(poly.end(), f.begin() + 1, f.end());
    }
    bound = std::max(bound, b.bound);
    cur = b.ctrl.back();
  }
  EXPECT_EQ(cur, quantize(g.pieces.back().back(), o.decimals));
  EXPECT_LE(bound, o.tolerance);
  // measure_deviation() reports true distances above its `tolerance`
  // argument (below it a windowed search may read high): asking it about
  // the proven bound makes any reading above that bound a real violation.
  const double check = bound + 2e-3 * o.tolerance;
  const double measured = measure_deviation(g.pieces, poly, check).max();
  EXPECT_LE(measured, check);
}

TEST(NurbsBlocks, FanucCubicIsOneBlockWithBezierKnots) {
  const Bezier b = Bezier::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0.00049}});
  const auto g = single(b);
  const auto blocks = plan_exact_blocks(g, fanuc());
  ASSERT_EQ(blocks.size(), 1u);
  const auto& k = blocks[0];
  EXPECT_EQ(k.kind, ExactKind::nurbs);
  EXPECT_EQ(k.order, 4);
  EXPECT_EQ(k.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(k.weights, (std::vector<double>(4, 1.0)));
  EXPECT_EQ(k.ctrl.back(), Vec3(3, 0));
  // A polynomial moves by at most its largest control point move (0.00049 here).
  EXPECT_LE(k.bound, 0.00049 + 1e-12);
  EXPECT_GT(k.bound, 0);
  check_plan(g, fanuc(), blocks);
}

TEST(NurbsBlocks, FanucPathOfCubicsIsOneBlockWithJointKnotsOfMultiplicityThree) {
  const auto g = path({Bezier::make({{0, 0}, {20, 10}, {30, 20}, {30, 30}}),
                       Bezier::make({{30, 30}, {30, 40}, {20, 45}, {10, 40}}),
                       Bezier::make({{10, 40}, {0, 35}, {-10, 20}, {0, 0}})});
  const auto blocks = plan_exact_blocks(g, fanuc());
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].ctrl.size(), 10u);
  EXPECT_EQ(blocks[0].knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3}));
  EXPECT_EQ(blocks[0].bound, 0);  // integer coordinates print exactly
  check_plan(g, fanuc(), blocks);
}

TEST(NurbsBlocks, MixedDegreesAndLinesSplitIntoBlocks) {
  const auto g = path({Bezier::make({{0, 0}, {5, 0}}), Bezier::make({{5, 0}, {8, 0}, {8, 3}}),
                       Bezier::make({{8, 3}, {8, 6}, {5, 9}, {2, 9}}), Bezier::make({{2, 9}, {0, 9}, {0, 7}})});
  const auto blocks = plan_exact_blocks(g, fanuc());
  ASSERT_EQ(blocks.size(), 4u);
  EXPECT_EQ(blocks[0].kind, ExactKind::line);
  EXPECT_EQ(blocks[1].order, 3);
  EXPECT_EQ(blocks[2].order, 4);
  EXPECT_EQ(blocks[3].order, 3);
  check_plan(g, fanuc(), blocks);
  const auto lb = plan_exact_blocks(g, linuxcnc());
  ASSERT_EQ(lb.size(), 4u);
  EXPECT_EQ(lb[0].kind, ExactKind::line);
  EXPECT_EQ(lb[1].kind, ExactKind::bezier);
  EXPECT_EQ(lb[1].ctrl.size(), 3u);  // G5.1
  EXPECT_EQ(lb[2].ctrl.size(), 4u);  // G5
  check_plan(g, linuxcnc(), lb);
}

TEST(NurbsBlocks, RationalQuarterCircleKeepsItsWeight) {
  const Bezier q = Bezier::make({{10, 0}, {10, 10}, {0, 10}}, {1, std::sqrt(0.5), 1});
  const auto g = single(q);
  for (const auto& o : {fanuc(), linuxcnc()}) {
    const auto blocks = plan_exact_blocks(g, o);
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_EQ(blocks[0].kind, ExactKind::nurbs);
    EXPECT_EQ(blocks[0].order, 3);
    EXPECT_EQ(blocks[0].weights, (std::vector<double>{1, 0.7071, 1}));
    EXPECT_EQ(blocks[0].knots, (std::vector<double>{0, 0, 0, 1, 1, 1}));
    // Only the weight moved (1/sqrt(2) - 0.7071 = 6.8e-6): the bound is the
    // parametric distance, sampled here, refined to 1e-4 of the tolerance.
    double sampled = 0;
    for (int i = 0; i <= 4000; ++i)
      sampled = std::max(sampled, dist(evaluate(q, i / 4000.0), evaluate(blocks[0].printed[0], i / 4000.0)));
    EXPECT_GT(sampled, 1e-5);
    EXPECT_GE(blocks[0].bound, sampled * (1 - 1e-9));
    EXPECT_LE(blocks[0].bound, sampled * 1.002 + 1e-4 * o.tolerance);
    check_plan(g, o, blocks);
  }
}

TEST(NurbsBlocks, StandardFormMakesNeighbouringWeightsAgree) {
  // Two rational quadratics with end weights 2 and 3: in one Fanuc block the
  // shared control point must carry one weight.
  const Bezier a = Bezier::make({{0, 0}, {1, 2}, {3, 2}}, {2, 1, 3});
  const Bezier b = Bezier::make({{3, 2}, {5, 2}, {6, 0}}, {3, 5, 2});
  const auto g = path({a, b});
  const auto blocks = plan_exact_blocks(g, fanuc(0.01, 4));
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].weights.front(), 1);
  EXPECT_EQ(blocks[0].weights[2], 1);
  EXPECT_EQ(blocks[0].weights.back(), 1);
  check_plan(g, fanuc(0.01, 4), blocks);
}

TEST(NurbsBlocks, QuarticIsReducedToCubicsWithANote) {
  const Bezier b = Bezier::make({{0, -1}, {1, 1}, {0, 0}, {-1, 0}, {0, 1}});
  const auto g = single(b);
  for (const auto& o : {fanuc(), linuxcnc()}) {
    const auto blocks = plan_exact_blocks(g, o);
    for (const auto& k : blocks) {
      EXPECT_NE(k.kind, ExactKind::fallback);
      EXPECT_NE(k.note.find("degree 4 reduced to"), std::string::npos) << k.note;
      if (k.kind == ExactKind::nurbs) EXPECT_EQ(k.order, 4);
    }
    check_plan(g, o, blocks);
  }
}

TEST(NurbsBlocks, RankThreeMachineGetsQuadratics) {
  ExactOptions o = fanuc();
  o.max_rank = 3;
  const auto g = single(Bezier::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0}}));
  const auto blocks = plan_exact_blocks(g, o);
  for (const auto& k : blocks)
    if (k.kind == ExactKind::nurbs) EXPECT_EQ(k.order, 3);
  check_plan(g, o, blocks);
  // Rank 2 takes lines only: everything falls back.
  o.max_rank = 2;
  const auto lines = plan_exact_blocks(g, o);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].kind, ExactKind::fallback);
}

TEST(NurbsBlocks, LinuxcncQuadraticWithZeroIJIsG52) {
  // I = J = 0 after rounding: G5.1 would be refused by LinuxCNC's rules.
  const auto g = single(Bezier::make({{0, 0}, {0.00004, 0}, {4, 3}}));
  const auto blocks = plan_exact_blocks(g, linuxcnc());
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].kind, ExactKind::nurbs);
  EXPECT_EQ(blocks[0].order, 3);
  EXPECT_EQ(blocks[0].weights, (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(blocks[0].knots, (std::vector<double>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(blocks[0].ctrl[1], blocks[0].ctrl[0]);
  check_plan(g, linuxcnc(), blocks);
}

TEST(NurbsBlocks, LinuxcncLeavesNonPlanarPiecesToTheFallback) {
  const Bezier c = Bezier::make({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}, {}, 3);
  const auto g = single(c);
  const auto blocks = plan_exact_blocks(g, linuxcnc(0.001));
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].kind, ExactKind::fallback);
  EXPECT_NE(blocks[0].note.find("z varies"), std::string::npos);
  check_plan(g, linuxcnc(0.001), blocks);
  // Fanuc blocks carry Z: exact.
  const auto f = plan_exact_blocks(g, fanuc(0.001));
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].kind, ExactKind::nurbs);
  check_plan(g, fanuc(0.001), f);
}

TEST(NurbsBlocks, LinuxcncPlanarPieceAtConstantZCountsTheRoundedZ) {
  const Bezier c = Bezier::make({{0, 0, 0.12345}, {10, 0, 0.12345}, {10, 10, 0.12345}, {0, 10, 0.12345}}, {}, 3);
  const auto g = single(c);
  const auto blocks = plan_exact_blocks(g, linuxcnc(0.01, 4));
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].kind, ExactKind::bezier);
  EXPECT_EQ(blocks[0].ctrl[0].z, 0.1235);
  EXPECT_GE(blocks[0].bound, 0.00005 - 1e-12);
  check_plan(g, linuxcnc(0.01, 4), blocks);
}

TEST(NurbsBlocks, BsplineSourceIsOneBlockWithItsOwnKnots) {
  // Degree 3, 6 points, uniform interior knots: spans map to 0, 1, 2, 3.
  const auto c =
      NurbsCurve::make(3, {{0, 0}, {1, 2}, {3, 3}, {5, 1}, {7, 2}, {8, 0}}, {10, 10, 10, 10, 12, 14, 16, 16, 16, 16});
  const auto g = bspline(c);
  const auto blocks = plan_exact_blocks(g, fanuc());
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].ctrl.size(), 6u);
  EXPECT_EQ(blocks[0].knots, (std::vector<double>{0, 0, 0, 0, 1, 2, 3, 3, 3, 3}));
  EXPECT_LT(blocks[0].bound, 1e-12);  // integer points: only knot insertion's rounding
  check_plan(g, fanuc(), blocks);
}

TEST(NurbsBlocks, NonUniformKnotsAreRoundedWithAProvenBound) {
  const auto c = NurbsCurve::make(2, {{0, 0}, {4, 6}, {9, 7}, {12, 1}, {16, 5}},
                                  {0, 0, 0, 0.123456789, 0.61803398875, 1, 1, 1}, {1, 1.7, 0.6, 1.3, 1});
  const auto g = bspline(c);
  ExactOptions o = fanuc(0.01, 3);
  const auto blocks = plan_exact_blocks(g, o);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].ctrl.size(), 5u);
  EXPECT_EQ(blocks[0].knots[3], quantize(0.123456789 * 3, 4));
  EXPECT_GT(blocks[0].bound, 0);
  check_plan(g, o, blocks);
  // With no decimals for knots the structure cannot survive: Bézier-chain
  // knots (exact integers) instead.
  o.knot_decimals = 0;
  const auto chain = plan_exact_blocks(g, o);
  ASSERT_EQ(chain.size(), 1u);
  EXPECT_EQ(chain[0].knots, (std::vector<double>{0, 0, 0, 1, 1, 2, 2, 3, 3, 3}));
  check_plan(g, o, chain);
}

TEST(NurbsBlocks, ToleranceBelowRoundingIsRefused) {
  const auto g = single(Bezier::make({{-3, 0}, {-3, 4}, {3, 4}, {3, 0}}));
  try {
    plan_exact_blocks(g, fanuc(0.005, 2));
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "flatten.tolerance-below-rounding");
  }
}

TEST(NurbsBlocks, RandomPathsBothDialects) {
  std::mt19937 rng(314159);
  std::uniform_real_distribution<double> coord(-12, 12), weight(0.4, 2.5);
  for (int trial = 0; trial < 12; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<Bezier> ps;
    Vec3 at{coord(rng), coord(rng)};
    for (int k = 0; k < 3; ++k) {
      const int deg = 1 + (trial + k) % 5;
      const bool rational = (trial + 2 * k) % 3 == 0 && deg > 1;
      std::vector<Vec3> pts{at};
      std::vector<double> w;
      for (int i = 1; i <= deg; ++i) pts.push_back({coord(rng), coord(rng)});
      if (rational)
        for (int i = 0; i <= deg; ++i) w.push_back(weight(rng));
      ps.push_back(Bezier::make(pts, w));
      at = pts.back();
    }
    const auto g = path(ps);
    for (const auto& o : {fanuc(0.01, 3), linuxcnc(0.005, 4)}) check_plan(g, o, plan_exact_blocks(g, o));
  }
}

}  // namespace
}  // namespace bezcam
