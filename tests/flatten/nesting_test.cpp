// Nesting of closed curves by the even-odd rule, decided on the exact
// curves (flatten/nesting.hpp).
#include "bezcam/flatten/nesting.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace bezcam {
namespace {

// The nesting itself, on exact curves: circles tangent inside and outside,
// a square whose edge runs along another's, a point far below the
// flattening's first bound from the curve.
TEST(Nesting, TouchingAndSharedEdgesCountAsInsideCrossingAsNeither) {
  const auto circle = [](double cx, double cy, double r) {
    std::vector<Bezier> c;
    const double w = std::sqrt(0.5);
    const Vec3 o{cx, cy};
    const Vec3 p[] = {{r, 0}, {r, r}, {0, r}, {-r, r}, {-r, 0}, {-r, -r}, {0, -r}, {r, -r}, {r, 0}};
    for (int k = 0; k < 4; ++k)
      c.push_back(Bezier::make({o + p[2 * k], o + p[2 * k + 1], o + p[2 * k + 2]}, {1, w, 1}));
    return c;
  };
  const auto square = [](double x0, double y0, double x1, double y1) {
    return std::vector<Bezier>{Bezier::make({{x0, y0}, {x1, y0}}), Bezier::make({{x1, y0}, {x1, y1}}),
                               Bezier::make({{x1, y1}, {x0, y1}}), Bezier::make({{x0, y1}, {x0, y0}})};
  };
  const std::vector<std::vector<Bezier>> cs = {
      circle(0, 0, 10),         // 0
      circle(0, 7, 3),          // 1: tangent to 0 from inside
      circle(0, 13 + 1e-9, 3),  // 2: outside 0, 1e-9 from touching it
      square(-5, -5, 0, 0),     // 3: inside 0
      square(-5, -5, 0, -2),    // 4: inside 3, along three of its edges
      square(8, -1, 12, 1),     // 5: crosses 0
  };
  const Nesting n = nest_closed_curves(cs);
  EXPECT_EQ(n.depth, (std::vector<int>{0, 1, 0, 1, 2, 0}));
  EXPECT_EQ(n.parent[1], std::optional<size_t>(0));
  EXPECT_EQ(n.parent[4], std::optional<size_t>(3));
  EXPECT_EQ(n.crossing, (std::vector<std::pair<size_t, size_t>>{{0, 5}}));
}

}  // namespace
}  // namespace bezcam
