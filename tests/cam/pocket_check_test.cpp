// The pocket certificate (cam/pocket_check.hpp) on programs made by hand:
// it must find the material, the rapids and the wall contacts they hold.
#include "bezcam/cam/pocket_check.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace bezcam {
namespace {

TEST(PocketCheck, FindsTheCentreThatPlainRingsLeave) {
  // The classic failure: rings at 5 mm from the first at r leave the
  // centre of the 16 mm square. A program of that ring alone is caught.
  PocketCheckInput in;
  in.walls = {{{0, 0, 0}, {16, 0, 0}, {16, 16, 0}, {0, 16, 0}}};
  in.radius = 3.175;
  in.tolerance = 0.01;
  in.levels = {-3};
  std::vector<Move> moves;
  auto line = [&](double x, double y, double z) {
    LineMove l;
    l.to = {x, y, z};
    l.feed = 100;
    moves.push_back({l});
  };
  line(3.175, 3.175, -3);
  line(12.825, 3.175, -3);
  line(12.825, 12.825, -3);
  line(3.175, 12.825, -3);
  line(3.175, 3.175, -3);
  in.moves = &moves;
  in.to = moves.size();
  in.start = {3.175, 3.175, 5};
  const PocketCertificate c = check_pocket(in);
  EXPECT_FALSE(c.covered());
  EXPECT_NEAR(c.uncut_at.x, 8, 2);
  EXPECT_NEAR(c.uncut_at.y, 8, 2);
  // Left: the middle of the square, farther than r from the ring (its
  // corner at 3.175 from the ring's sides, the square's centre 4.825 off).
  EXPECT_GT(c.uncut_area, 2);
  EXPECT_EQ(c.rapids_in_material, 0u);
  EXPECT_NEAR(c.wall_distance, 3.175, 1e-9);
  // A rapid across at depth, and a pass into the wall, are caught too.
  RapidMove r;
  r.to = {8, 8, -3};
  moves.push_back({r});
  line(1, 8, -3);
  in.to = moves.size();
  const PocketCertificate d = check_pocket(in);
  EXPECT_EQ(d.rapids_in_material, 1u);
  EXPECT_NEAR(d.wall_distance, 1, 1e-9);
  EXPECT_FALSE(d.walls_kept(3.175, 0, 0.01));
}

TEST(PocketCheck, AnArcsNearestApproachIsNeverAboveItsTrueOne) {
  // A full circle of radius 6.9 about the middle of a 20 mm square, from 0.7
  // rad round: it comes within 10 - 6.9 = 3.1 of each side at 0, 90, 180
  // and 270 degrees, between the ends of the chords the check reads it by.
  PocketCheckInput in;
  in.walls = {{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}}};
  in.radius = 3;
  in.tolerance = 0.01;
  in.levels = {-3};
  const double a = 0.7, rad = 6.9;
  ArcMove arc;
  arc.to = {10 + rad * std::cos(a), 10 + rad * std::sin(a), -3};
  arc.center = {10, 10, -3};
  arc.ccw = true;
  arc.feed = 100;
  std::vector<Move> moves{{arc}};
  in.moves = &moves;
  in.to = moves.size();
  in.start = arc.to;
  const PocketCertificate c = check_pocket(in);
  EXPECT_LE(c.wall_distance, 10 - rad);
  EXPECT_GE(c.wall_distance, 10 - rad - in.tolerance / 100 - 1e-12);
}

TEST(PocketCheck, TheRingAtRLeavesOnlyTheCornersOfAFullCut) {
  // A 16 mm square cut by the ring at r and a cross through the middle:
  // every reachable point is within r; what is left is the four corners,
  // r^2 (1 - pi/4) each, and the report places them there.
  PocketCheckInput in;
  in.walls = {{{0, 0, 0}, {16, 0, 0}, {16, 16, 0}, {0, 16, 0}}};
  in.radius = 3.175;
  in.tolerance = 0.01;
  in.levels = {-3};
  std::vector<Move> moves;
  auto line = [&](double x, double y) {
    LineMove l;
    l.to = {x, y, -3};
    l.feed = 100;
    moves.push_back({l});
  };
  for (auto [x, y] : {std::pair{12.825, 3.175},
                      {12.825, 12.825},
                      {3.175, 12.825},
                      {3.175, 3.175},
                      {12.825, 12.825},
                      {12.825, 3.175},
                      {3.175, 12.825}})
    line(x, y);
  in.moves = &moves;
  in.to = moves.size();
  in.start = {3.175, 3.175, -3};
  const PocketCheckInput copy = in;
  const PocketCertificate c = check_pocket(copy);
  EXPECT_TRUE(c.covered()) << c.uncut_area << " at " << c.uncut_at.x << ", " << c.uncut_at.y;
  ASSERT_EQ(c.unreachable.size(), 4u);
  // Within the check's own error: a cell along the piece's edge, which is
  // 2 r + r pi / 2 long.
  const double edge = 3.175 * (2 + std::numbers::pi / 2);
  for (const auto& u : c.unreachable) {
    EXPECT_NEAR(u.area, 3.175 * 3.175 * (1 - std::numbers::pi / 4), c.cell * edge);
    EXPECT_TRUE(u.at.x < 1.5 || u.at.x > 14.5) << u.at.x;
    EXPECT_TRUE(u.at.y < 1.5 || u.at.y > 14.5) << u.at.y;
  }
  // Counted on the samples too: within a cell along R's four rounded corners.
  EXPECT_NEAR(c.reachable_area, 256 - 4 * 3.175 * 3.175 * (1 - std::numbers::pi / 4),
              c.cell * 2 * std::numbers::pi * 3.175);
  // The diagonals cut through the middle: a full slot there.
  EXPECT_GE(c.engagement_deg, 170);
}

}  // namespace
}  // namespace bezcam
