// A program's motion as blocks: modal axes, exact lengths of lines, arcs and
// helices, and exact-curve blocks measured against closed forms.
#include "bezcam/machine/motion.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "bezcam/cam/program_motion.hpp"

namespace bezcam {
namespace {

constexpr double kPi = std::numbers::pi;

Move rapid(Vec3 to, unsigned axes = 7) {
  RapidMove m;
  m.to = to;
  m.axes = axes;
  return {m};
}
Move line(Vec3 to, double f, int entity = 0) {
  LineMove m;
  m.to = to;
  m.feed = f;
  return {m, entity};
}

TEST(ProgramMotion, FollowsModalAxesAndSkipsNonMotion) {
  Program p;
  p.moves.push_back(rapid({0, 0, 5}, 4));  // Z only: X and Y still unknown
  p.moves.push_back({ToolChange{1}});
  p.moves.push_back(rapid({10, 0, 0}, 3));  // X Y only: Z stays 5
  p.moves.push_back(line({10, 0, -1}, 100));
  p.moves.push_back({Comment{"a comment"}});
  ArcMove arc;
  arc.to = {0, 10, -1};
  arc.feed = 200;
  arc.ccw = true;
  arc.center = {0, 0, 0};
  p.moves.push_back({arc, 0});

  const auto m = program_motion(p);
  ASSERT_EQ(m.size(), 4u);
  // Unknown axes count as already at the target: no invented travel.
  EXPECT_EQ(m[0].from, (Vec3{0, 0, 5}));
  EXPECT_EQ(block_length(m[0]), 0.0);
  EXPECT_EQ(m[1].from, (Vec3{10, 0, 5}));
  EXPECT_EQ(m[1].to, (Vec3{10, 0, 5}));
  EXPECT_EQ(m[2].from, (Vec3{10, 0, 5}));
  EXPECT_EQ(m[2].to, (Vec3{10, 0, -1}));
  EXPECT_EQ(m[2].feed, 100);
  EXPECT_EQ(m[2].entity, 0);
  EXPECT_EQ(block_length(m[2]), 6.0);
  EXPECT_EQ(m[3].kind, BlockKind::arc_ccw);
  EXPECT_NEAR(block_length(m[3]), 10 * kPi / 2, 1e-12);
  EXPECT_EQ(m[0].feed, 0);  // rapids carry no feed
}

MotionBlock arc_block(BlockKind k, Vec3 from, Vec3 to, Vec3 c) {
  MotionBlock b;
  b.kind = k;
  b.from = from;
  b.to = to;
  b.center = c;
  b.feed = 100;
  return b;
}

TEST(BlockLength, ArcsByDirectionFullCircleAndHelix) {
  // A quarter counter-clockwise, three quarters clockwise between the same ends.
  EXPECT_NEAR(block_length(arc_block(BlockKind::arc_ccw, {5, 0, 0}, {0, 5, 0}, {0, 0, 0})), 2.5 * kPi, 1e-12);
  EXPECT_NEAR(block_length(arc_block(BlockKind::arc_cw, {5, 0, 0}, {0, 5, 0}, {0, 0, 0})), 7.5 * kPi, 1e-12);
  // Equal ends: a full circle.
  EXPECT_NEAR(block_length(arc_block(BlockKind::arc_cw, {3, 0, 0}, {3, 0, 0}, {0, 0, 0})), 6 * kPi, 1e-12);
  // A helix: half a turn of radius 2 rising 4.
  EXPECT_NEAR(block_length(arc_block(BlockKind::arc_ccw, {2, 0, 0}, {-2, 0, 4}, {0, 0, 0})), std::hypot(2 * kPi, 4.0),
              1e-12);
}

// Arcs whose ends lie at different radii (rounding; the controllers run
// the radius linearly with the angle) against a sum of a million chords of
// evaluate_block's points: near circles, a wide spiral, helical, in G18,
// one starting almost at its centre, and the full turn.
TEST(BlockLength, SpiralArcsAgreeWithADenseChordSum) {
  std::vector<MotionBlock> spirals{
      arc_block(BlockKind::arc_ccw, {5, 0, 0}, {0, 5.0001, 0}, {0, 0, 0}),
      arc_block(BlockKind::arc_cw, {5, 0, 0}, {-1, -3, 0}, {0, 0, 0}),
      arc_block(BlockKind::arc_ccw, {2, 0, 0}, {-2.5, 0, 4}, {0, 0, 0}),
      arc_block(BlockKind::arc_ccw, {1e-6, 0, 0}, {0, 3, -1}, {0, 0, 0}),
      arc_block(BlockKind::arc_cw, {3, 0, 0}, {3.2, 0, 0.5}, {0, 0, 0}),
  };
  spirals.push_back(arc_block(BlockKind::arc_ccw, {1, 0, 5}, {1, 3, 8}, {1, 0, 7}));
  spirals.back().plane = Plane::zx;
  for (size_t k = 0; k < spirals.size(); ++k) {
    const MotionBlock& b = spirals[k];
    double sum = 0;
    Vec3 prev = b.from;
    const int n = 1000000;
    for (int i = 1; i <= n; ++i) {
      const Vec3 q = evaluate_block(b, double(i) / n);
      sum += dist(prev, q);
      prev = q;
    }
    // Chords fall short of the arc by O(1/n^2) of its length.
    EXPECT_NEAR(block_length(b), sum, 1e-9 * sum) << k;
    EXPECT_GE(block_length(b), sum) << k;
  }
}

TEST(SampleBlock, ArcChordsStayWithinTheRequestedError) {
  const auto b = arc_block(BlockKind::arc_ccw, {10, 0, 0}, {-10, 0, 0}, {0, 0, 0});
  for (double chord : {1e-1, 1e-3}) {
    const auto s = sample_block(b, chord);
    EXPECT_EQ(s.front(), b.from);
    EXPECT_EQ(s.back(), b.to);
    for (size_t i = 1; i < s.size(); ++i) {
      EXPECT_NEAR(std::hypot(s[i].x, s[i].y), 10, 1e-12);
      // Sagitta of the chord between consecutive samples.
      const double half = dist(s[i - 1], s[i]) / 2;
      EXPECT_LE(10 - std::sqrt(100 - half * half), chord * (1 + 1e-9));
      EXPECT_GE(s[i].y, -1e-12);  // counter-clockwise from +X to -X passes +Y
    }
  }
  // Lines are their two ends.
  MotionBlock l;
  l.kind = BlockKind::linear;
  l.from = {1, 2, 3};
  l.to = {4, 6, 3};
  EXPECT_EQ(sample_block(l, 1e-6), (std::vector<Vec3>{{1, 2, 3}, {4, 6, 3}}));
  EXPECT_EQ(block_length(l), 5.0);
}

TEST(BlockLength, ExactCurveBlocksAgreeWithTheKernel) {
  // The rational quadratic quarter circle of radius 10 as a NURBS block.
  MotionBlock n;
  n.kind = BlockKind::nurbs;
  n.order = 3;
  n.ctrl = {{10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  n.weights = {1, std::sqrt(0.5), 1};
  n.knots = {0, 0, 0, 1, 1, 1};
  n.from = n.ctrl.front();
  n.to = n.ctrl.back();
  EXPECT_NEAR(block_length(n), 5 * kPi, 5 * kPi * 1e-9);
  for (const auto& p : sample_block(n, 1e-4)) EXPECT_NEAR(std::hypot(p.x, p.y), 10, 1e-9);

  // A cubic Bézier block (LinuxCNC G5) against the kernel's quadrature.
  MotionBlock z;
  z.kind = BlockKind::bezier;
  z.ctrl = {{0, 0, 0}, {1, 2, 0}, {3, -1, 0}, {4, 1, 0}};
  z.order = 4;
  z.from = z.ctrl.front();
  z.to = z.ctrl.back();
  const double exact = length(Bezier::make(z.ctrl, {}, 3));
  EXPECT_NEAR(block_length(z), exact, exact * 1e-9);
  // Samples lie on the curve: the nearest curve point (grid, then a
  // ternary search around the best grid point) is at distance ~0.
  const Bezier bz = Bezier::make(z.ctrl, {}, 3);
  const auto s = sample_block(z, 1e-3);
  EXPECT_GT(s.size(), 8u);
  EXPECT_EQ(s.back(), z.to);
  for (const Vec3& p : s) {
    double best_t = 0, best = HUGE_VAL;
    for (int i = 0; i <= 2000; ++i)
      if (const double d = dist(evaluate(bz, i / 2000.0), p); d < best) best = d, best_t = i / 2000.0;
    double a = std::max(0.0, best_t - 1e-3), b = std::min(1.0, best_t + 1e-3);
    for (int it = 0; it < 100; ++it) {
      const double m1 = a + (b - a) / 3, m2 = b - (b - a) / 3;
      if (dist(evaluate(bz, m1), p) < dist(evaluate(bz, m2), p))
        b = m2;
      else
        a = m1;
    }
    EXPECT_LT(dist(evaluate(bz, (a + b) / 2), p), 1e-12);
  }
}

}  // namespace
}  // namespace bezcam
