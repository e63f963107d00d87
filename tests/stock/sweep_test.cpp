#include "bezcam/stock/sweep.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

#include "bezcam/error.hpp"

using namespace bezcam;

namespace {

template <class F>
void expect_refused(F f) {
  try {
    f();
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "stock.move");
    EXPECT_EQ(e.where(), "move");
  }
}

}  // namespace

TEST(StockSweep, RefusesMalformedMoves) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_refused([&] { Sweep::line({0, 0, 0}, {1, nan, 0}); });
  expect_refused([] { Sweep::arc(Arc{{0, 0, 0}, {1, 1, 0}, {0, 0, 0}, true, Plane::xy}); });  // start on the centre
  expect_refused([] { Sweep::polyline({}, 0); });
  expect_refused([] { Sweep::polyline({{0, 0, 0}}, -1); });
  EXPECT_NO_THROW(Sweep::polyline({{0, 0, 0}}, 0));
}

TEST(StockSweep, ExtentHoldsTheWholePath) {
  // A spiral from radius 5 to 5.01 over 3/4 of a turn, down 2 in z.
  const Arc a{{15, 0, 0}, {10, -5.01, -2}, {10, 0, 0}, true, Plane::xy};
  const Sweep s = Sweep::arc(a);
  const Box3 e = s.extent();
  for (int i = 0; i <= 2000; ++i) {
    const Vec3 p = a.point(i / 2000.0);
    EXPECT_TRUE(e.contains(Box3{p, p})) << i;
  }
  // the axis crossings (90 degrees at radius 5 + 0.01/3, 180 at 5 + 0.02/3)
  // widened by the radii's difference at most
  EXPECT_LE(e.hi.y, 5 + 0.01 / 3 + 0.01 + 1e-9);
  EXPECT_GE(e.lo.x, 10 - (5 + 0.02 / 3) - 0.01 - 1e-9);
}

TEST(StockSweep, CurvesCarryTheFlatteningBound) {
  // A cubic in the plane: the polyline's bound is the flattening's and
  // within the tolerance; its ends are the curve's.
  Bezier b;
  b.dim = 3;
  b.points = {{0, 0, 0}, {10, 20, 0}, {30, -20, -1}, {40, 0, -1}};
  const Sweep s = Sweep::curve(std::span<const Bezier>(&b, 1), 0.01);
  EXPECT_EQ(s.kind(), SweepKind::polyline);
  EXPECT_GT(s.bound(), 0);
  EXPECT_LE(s.bound(), 0.01);
  EXPECT_GT(s.points().size(), 10u);
  EXPECT_EQ(s.from(), b.points.front());
  EXPECT_EQ(s.to(), b.points.back());
}
