#include "bezcam/stock/tool_shape.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>

#include "bezcam/error.hpp"

using namespace bezcam;

namespace {

// The refusal's id and the setting it names.
template <class F>
void expect_refused(F f, const std::string& setting) {
  try {
    f();
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "tool.shape");
    ASSERT_TRUE(e.place().setting.has_value());
    EXPECT_EQ(*e.place().setting, setting);
  }
}

}  // namespace

TEST(ToolShape, HeightProfiles) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  (void)nan;
  const ToolShape f = ToolShape::flat(6), b = ToolShape::ball(6), u = ToolShape::bull(10, 1), v = ToolShape::vee(6, 60),
                  d = ToolShape::drill(5, 118);
  EXPECT_EQ(f.height(2.9), 0);
  EXPECT_DOUBLE_EQ(b.height(0), 0);
  EXPECT_DOUBLE_EQ(b.height(3), 3);
  EXPECT_NEAR(b.height(1.5), 3 - std::sqrt(9 - 2.25), 1e-15);
  EXPECT_EQ(u.height(4), 0);                                   // the flat part, radius 4
  EXPECT_NEAR(u.height(4.6), 1 - std::sqrt(1 - 0.36), 1e-15);  // the torus
  EXPECT_DOUBLE_EQ(u.cutting_height(), 1);
  EXPECT_NEAR(v.height(1), 1 / std::tan(std::numbers::pi / 6), 1e-15);  // 60 deg included: slope cot 30
  EXPECT_NEAR(d.cutting_height(), 2.5 / std::tan(59 * std::numbers::pi / 180), 1e-14);
  EXPECT_EQ(b.height(7), 3);  // clamped to the radius
  EXPECT_EQ(u.describe(), "bull D10 r1");
  EXPECT_EQ(v.describe(), "vee D6 60deg");
  // every profile is nondecreasing and convex: check on a fine sampling
  for (const ToolShape& t : {f, b, u, v, d, ToolShape::bull(6, 3)}) {
    const int n = 1000;
    const double R = t.radius();
    for (int i = 1; i < n; ++i) {
      const double h0 = t.height(R * (i - 1) / n), h1 = t.height(R * i / n), h2 = t.height(R * (i + 1) / n);
      EXPECT_GE(h1, h0) << t.describe();
      EXPECT_GE(h0 + h2 - 2 * h1, -1e-12) << t.describe() << " at " << R * i / n;
    }
  }
  // a bull whose corner is its radius is a ball
  EXPECT_NEAR(ToolShape::bull(6, 3).height(2), ToolShape::ball(6).height(2), 1e-15);
}

TEST(ToolShape, RefusesBadDimensions) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  expect_refused([] { ToolShape::flat(0); }, "diameter");
  expect_refused([] { ToolShape::ball(-3); }, "diameter");
  expect_refused([&] { ToolShape::flat(inf); }, "diameter");
  expect_refused([&] { ToolShape::ball(nan); }, "diameter");
  expect_refused([] { ToolShape::bull(10, 0); }, "corner_radius");
  expect_refused([] { ToolShape::bull(10, 5.0001); }, "corner_radius");
  expect_refused([&] { ToolShape::bull(10, nan); }, "corner_radius");
  expect_refused([] { ToolShape::vee(6, 0); }, "angle");
  expect_refused([] { ToolShape::vee(6, 180); }, "angle");
  expect_refused([] { ToolShape::drill(5, 200); }, "point_angle");
  expect_refused([&] { ToolShape::drill(5, nan); }, "point_angle");
  EXPECT_NO_THROW(ToolShape::bull(10, 5));
  EXPECT_NO_THROW(ToolShape::vee(6, 179.9));
}
