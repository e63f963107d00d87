// The kernel's G17 arc: sweep in (0, 2 pi], points on the (spiral, helical)
// path, the XY extent and the exact rational quadratic pieces.
#include "bezcam/kernel/arc.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace bezcam;

namespace {

constexpr double kPi = std::numbers::pi;

Vec3 polar(double r, double a, double z = 0) { return {r * std::cos(a), r * std::sin(a), z}; }

TEST(Arc, SweepInDirection) {
  const Arc ccw{polar(5, 0), polar(5, kPi / 2), {0, 0, 0}, true};
  EXPECT_NEAR(ccw.sweep(), kPi / 2, 1e-15);
  Arc cw = ccw;
  cw.ccw = false;
  EXPECT_NEAR(cw.sweep(), 3 * kPi / 2, 1e-15);
}

TEST(Arc, EqualEndsAreAFullCircle) {
  const Arc a{{3, 4, 0}, {3, 4, -1}, {0, 0, 0}, false};
  EXPECT_EQ(a.sweep(), 2 * kPi);
  EXPECT_EQ(a.r_start(), 5);
  EXPECT_EQ(a.r_end(), 5);
}

TEST(Arc, PointEndsExactAndHelixInBetween) {
  const Arc a{polar(2, 0, 1), polar(3, kPi, -1), {0, 0, 7}, true};
  EXPECT_EQ(a.point(0).x, a.from.x);
  EXPECT_EQ(a.point(1).y, a.to.y);
  const Vec3 m = a.point(0.5);  // radius 2.5 at 90 degrees, z halfway
  EXPECT_NEAR(m.x, 0, 1e-12);
  EXPECT_NEAR(m.y, 2.5, 1e-12);
  EXPECT_NEAR(m.z, 0, 1e-15);
}

TEST(Arc, BoxHoldsTheAxisExtremesPassed) {
  // From 45 to 225 degrees counter-clockwise passes 90 and 180 degrees.
  const Arc a{polar(1, kPi / 4), polar(1, 5 * kPi / 4), {10, 20, 0}, true};
  Arc moved = a;
  moved.from = a.from + a.center;
  moved.to = a.to + a.center;
  const Box3 b = arc_extent(moved);
  EXPECT_NEAR(b.hi.y, 21, 1e-12);
  EXPECT_NEAR(b.lo.x, 9, 1e-12);
  EXPECT_NEAR(b.hi.x, moved.from.x, 0);
  EXPECT_NEAR(b.lo.y, moved.to.y, 0);
  // The other way round passes 0 and 270 degrees instead.
  moved.ccw = false;
  const Box3 c = arc_extent(moved);
  EXPECT_NEAR(c.hi.x, 11, 1e-12);
  EXPECT_NEAR(c.lo.y, 19, 1e-12);
}

TEST(Arc, BezierPiecesAreExact) {
  const Arc a{polar(4, 0.3), polar(4, 0.3 + 3.5), {0, 0, 0}, true};  // 200 degrees
  const auto pieces = bezier_pieces(a);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces.front().points.front().x, a.from.x);
  EXPECT_EQ(pieces.back().points.back().y, a.to.y);
  for (const auto& p : pieces)
    for (double t : {0.1, 0.37, 0.5, 0.9}) {
      const Vec3 q = evaluate(p, t);
      EXPECT_NEAR(std::hypot(q.x, q.y), 4, 1e-12);
    }
  // A full circle: four quarter pieces.
  const Arc full{polar(1, 0), polar(1, 0), {0, 0, 0}, false};
  EXPECT_EQ(bezier_pieces(full).size(), 4u);
}

}  // namespace
