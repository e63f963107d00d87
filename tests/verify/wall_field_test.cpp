#include "verify/wall_field.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace bezcam;
using namespace bezcam::verify_detail;

TEST(WallField, ReachAgreesWithTheDisksDrawnOneByOne) {
  std::mt19937 rng(7);
  const Region r{0, 0, 57, 43};
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<char> centres(r.size(), 0);
    std::bernoulli_distribution pick(0.01 + 0.01 * trial);
    for (auto& c : centres) c = pick(rng);
    const double radius = 0.3 + 0.17 * trial, cell = 0.1;
    const std::vector<double> dist = reach(r, centres, cell);
    for (std::size_t k = 0; k < r.size(); ++k) {
      bool want = false;
      for (std::size_t m = 0; m < r.size() && !want; ++m) {
        if (!centres[m]) continue;
        const double dx = (double(k % r.ni) - double(m % r.ni)) * cell,
                     dy = (double(k / r.ni) - double(m / r.ni)) * cell;
        want = std::sqrt(dx * dx + dy * dy) <= radius * (1 + 1e-12);
      }
      ASSERT_EQ(dist[k] <= radius * (1 + 1e-12), want) << "trial " << trial << " column " << k;
    }
  }
}

TEST(WallField, ClosedWallsKnowTheirSidesOpenWallsTheirEnds) {
  DexelGrid g({-10, -10, -1, 10, 10, 0}, 0.5);
  Wall sq;
  sq.points = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
  sq.closed = true;
  sq.waste_inside_or_left = true;
  const WallField f = wall_field(g, sq, 2);
  for (std::size_t k = 0; k < f.region.size(); ++k) {
    const double x = g.x_center(f.region.i0 + k % f.region.ni), y = g.y_center(f.region.j0 + k / f.region.ni);
    const bool inside = std::abs(x) < 5 && std::abs(y) < 5;
    EXPECT_EQ(f.side[k], inside ? 1 : -1) << x << " " << y;
    const double d = inside ? 5 - std::max(std::abs(x), std::abs(y))
                            : std::hypot(std::max(0.0, std::abs(x) - 5), std::max(0.0, std::abs(y) - 5));
    if (d <= 2) EXPECT_NEAR(f.distance[k], d, 1e-12) << x << " " << y;
  }
  EXPECT_EQ(f.outside_side, -1);
  Wall open;
  open.points = {{-5, 0, 0}, {5, 0, 0}};
  open.waste_inside_or_left = true;
  const WallField o = wall_field(g, open, 2);
  for (std::size_t k = 0; k < o.region.size(); ++k) {
    const double x = g.x_center(o.region.i0 + k % o.region.ni), y = g.y_center(o.region.j0 + k / o.region.ni);
    if (std::abs(x) > 5)
      EXPECT_EQ(o.side[k], 0);
    else if (o.distance[k] <= 2)
      EXPECT_EQ(o.side[k], y > 0 ? 1 : -1);
  }
}
