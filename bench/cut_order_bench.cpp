// The cut-order planner (docs/cut-order.md): rapid length as written and as
// planned, and planning time (nesting included), for scrambled square grids
// of circles (24 vertices, 20 apart, radius 4) and for plates with holes,
// bosses and engravings (the shape of tests/cam/cut_order_test.cpp's
// 2000-contour case, 400-vertex outlines).
//
//   build/cut_order_bench
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "bezcam/cam/cut_order.hpp"

using namespace bezcam;
using Clock = std::chrono::steady_clock;

namespace {

OrderContour polygon(double cx, double cy, double r, int n, double phase = 0) {
  OrderContour c;
  c.closed = true;
  for (int k = 0; k <= n; ++k) {
    const double a = phase + 2 * std::numbers::pi * (k % n) / n;
    c.outline.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return c;
}

std::vector<OrderContour> grid(int side) {
  std::vector<OrderContour> cs;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) cs.push_back(polygon(20.0 * i, 20.0 * j, 4, 24));
  std::mt19937 rng(1);
  std::shuffle(cs.begin(), cs.end(), rng);
  return cs;
}

std::vector<OrderContour> plates(int count) {
  std::vector<OrderContour> cs;
  std::mt19937 rng(2000);
  for (int p = 0; p < count; ++p) {
    const double ox = 300.0 * (p % 8) + 120, oy = 300.0 * (p / 8) + 120;
    cs.push_back(polygon(ox, oy, 140, 400));
    std::vector<OrderContour> inner;
    for (int h = 0; h < 20; ++h) {
      const double a = 2 * std::numbers::pi * h / 20;
      inner.push_back(polygon(ox + 110 * std::cos(a), oy + 110 * std::sin(a), 6, 16));
    }
    for (int b = 0; b < 4; ++b) {
      const double a = std::numbers::pi / 2 * b;
      inner.push_back(polygon(ox + 50 * std::cos(a), oy + 50 * std::sin(a), 20, 32));
      inner.push_back(polygon(ox + 50 * std::cos(a), oy + 50 * std::sin(a), 5, 12));
    }
    for (int l = 0; l < 8; ++l) {
      OrderContour e;
      e.outline = {{ox - 15 + 4 * l, oy - 10}, {ox - 13 + 4 * l, oy}, {ox - 12 + 4 * l, oy + 10}};
      e.reversible = l % 2 == 0;
      inner.push_back(e);
    }
    for (int e = 0; e < 10; ++e) inner.push_back(polygon(ox - 30 + 6 * e, oy + 85, 2, 8));
    std::shuffle(inner.begin(), inner.end(), rng);
    cs.insert(cs.end(), inner.begin(), inner.end());
  }
  return cs;
}

void run(const char* what, const std::vector<OrderContour>& cs) {
  size_t vertices = 0;
  for (const auto& c : cs) vertices += c.outline.size();
  const auto t0 = Clock::now();
  const CutOrder plan = plan_cut_order(cs, {-10, -10});
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf(
      "%-22s %6zu contours %7zu vertices  rapid as written %10.0f  planned %8.0f (%5.1f %%)  %3zu nestings unmet  %.3f "
      "s\n",
      what, cs.size(), vertices, plan.rapid_as_written, plan.rapid_planned,
      100 * plan.rapid_planned / plan.rapid_as_written, plan.unmet_nesting, s);
}

}  // namespace

int main() {
  run("grid 10 x 10", grid(10));
  run("grid 45 x 45", grid(45));
  run("grid 71 x 71", grid(71));
  run("grid 100 x 100", grid(100));
  run("40 plates", plates(40));
  run("200 plates", plates(200));
}
