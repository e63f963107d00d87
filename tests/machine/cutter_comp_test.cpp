// Cutter radius compensation (machine/cutter_comp.hpp): the tool-centre path a
// controller makes of a G41/G42 program. The corner rules are LinuxCNC's;
// LinuxcncRs274 checks the whole model against LinuxCNC's own interpreter.
#include "bezcam/machine/cutter_comp.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace bezcam {
namespace {

MotionBlock line(Vec3 a, Vec3 b) {
  MotionBlock m;
  m.kind = BlockKind::linear;
  m.from = a;
  m.to = b;
  m.feed = 100;
  return m;
}
MotionBlock arc(Vec3 a, Vec3 b, Vec3 c, bool ccw) {
  MotionBlock m = line(a, b);
  m.kind = ccw ? BlockKind::arc_ccw : BlockKind::arc_cw;
  m.center = c;
  return m;
}

std::vector<MotionBlock> run(int side, double r, const std::vector<MotionBlock>& in) {
  CutterComp c;
  c.on(side, r);
  std::vector<MotionBlock> out;
  for (const auto& b : in)
    for (auto& x : c.push(b)) out.push_back(x);
  for (auto& x : c.off()) out.push_back(x);
  return out;
}

void expect_near(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(CutterComp, OutsideCornerRollsRoundOnAnArcInsideCornerMeetsAtTheCrossing) {
  // G42 (tool on the right). Entry down -Y to (0,0), then -X: a right turn,
  // the tool inside: the entry's offset x = -1 and the next's y = 1 meet at
  // (-1, 1). Then -Y again: a left turn, the tool outside: an arc round
  // (-10, 0) from (-10, 1) to (-11, 0).
  const auto out =
      run(-1, 1, {line({0, 5, 0}, {0, 0, 0}), line({0, 0, 0}, {-10, 0, 0}), line({-10, 0, 0}, {-10, -10, 0})});
  ASSERT_EQ(out.size(), 4u);
  expect_near(out[0].from, {0, 5, 0});
  expect_near(out[0].to, {-1, 1, 0});
  expect_near(out[1].from, {-1, 1, 0});
  expect_near(out[1].to, {-10, 1, 0});
  EXPECT_EQ(out[2].kind, BlockKind::arc_ccw);
  expect_near(out[2].center, {-10, 0, 0});
  expect_near(out[2].to, {-11, 0, 0});
  expect_near(out[3].from, {-11, 0, 0});
  expect_near(out[3].to, {-11, -10, 0});  // G40: its own offset end
}

TEST(CutterComp, ArcsChangeRadiusByTheToolAndTooTightAnArcIsRefused) {
  // A counter-clockwise half circle of radius 5 with the tool inside (G41).
  const auto out = run(1, 2, {line({5, -5, 0}, {5, 0, 0}), arc({5, 0, 0}, {-5, 0, 0}, {0, 0, 0}, true)});
  ASSERT_EQ(out.size(), 2u);
  expect_near(out[0].to, {3, 0, 0});
  expect_near(out[1].to, {-3, 0, 0});
  EXPECT_THROW(run(1, 6, {line({5, -9, 0}, {5, 0, 0}), arc({5, 0, 0}, {-5, 0, 0}, {0, 0, 0}, true)}),
               CompensationError);
}

TEST(CutterComp, NearlyStraightJointsAreNotCornersAsInLinuxcnc) {
  // A turn of 0.02 rad (under 0.05): the next move starts where the tool is.
  const double a = 0.02;
  const Vec3 b{10, 0, 0}, c{10 + 10 * std::cos(a), 10 * std::sin(a), 0};
  const auto out = run(1, 1, {line({-5, 0, 0}, {0, 0, 0}), line({0, 0, 0}, b), line(b, c)});
  ASSERT_EQ(out.size(), 3u);
  expect_near(out[1].to, {10, 1, 0});
  expect_near(out[2].from, {10, 1, 0});
}

TEST(CutterComp, RefusesWhatAControllerRefuses) {
  CutterComp c;
  c.on(1, 3);
  EXPECT_THROW(c.push(arc({0, 0, 0}, {10, 0, 0}, {5, 0, 0}, true)), CompensationError);  // arc entry
  CutterComp d;
  d.on(1, 3);
  EXPECT_THROW(d.push(line({0, 0, 0}, {2, 0, 0})), CompensationError);  // entry not longer than r
  CutterComp e;
  e.on(1, 1);
  (void)e.push(line({0, 0, 0}, {5, 0, 0}));
  MotionBlock curve = line({5, 0, 0}, {9, 0, 0});
  curve.kind = BlockKind::nurbs;
  EXPECT_THROW(e.push(curve), CompensationError);  // no NURBS in compensation
  CutterComp f;
  f.on(-1, 1);
  (void)f.push(line({0, 0, 0}, {5, 0, 0}));
  (void)f.off();
  EXPECT_THROW(f.push(arc({5, 0, 0}, {9, 0, 0}, {7, 0, 0}, true)), CompensationError);  // arc exit
  CutterComp g;
  g.on(1, 1);
  EXPECT_THROW(g.on(-1, 1), CompensationError);  // G42 while G41 is on
}

TEST(CutterComp, ZMovesKeepTheToolWhereTheCornerPutsIt) {
  MotionBlock up = line({10, 0, 0}, {10, 0, 2});
  const auto out =
      run(1, 1, {line({0, -5, 0}, {0, 0, 0}), line({0, 0, 0}, {10, 0, 0}), up, line({10, 0, 2}, {20, 0, 2})});
  // Entry going +Y, tool left (-X); the +X move turns right: outside,
  // an arc round (0,0) from (-1,0) to (0,1).
  ASSERT_EQ(out.size(), 5u);
  expect_near(out[0].to, {-1, 0, 0});
  EXPECT_EQ(out[1].kind, BlockKind::arc_cw);
  expect_near(out[2].to, {10, 1, 0});
  expect_near(out[3].from, {10, 1, 0});
  expect_near(out[3].to, {10, 1, 2});
  expect_near(out[4].to, {20, 1, 2});
}

}  // namespace
}  // namespace bezcam
