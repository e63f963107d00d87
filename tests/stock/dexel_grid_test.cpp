#include "bezcam/stock/dexel_grid.hpp"

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "bezcam/error.hpp"

using namespace bezcam;

namespace {

// A little of everything: lines (horizontal, sloped, plunges), arcs in the
// three planes (circles, helices, spirals) and a polyline, with every shape.
void mixed_program(DexelGrid& g) {
  const ToolShape ball = ToolShape::ball(6), flat = ToolShape::flat(4), bull = ToolShape::bull(8, 1),
                  vee = ToolShape::vee(6, 90), drill = ToolShape::drill(5, 118);
  std::vector<Sweep> raster;
  for (int p = 0; p < 12; ++p)
    for (int b = 0; b < 40; ++b)
      raster.push_back(Sweep::line({2 + b * 0.9, 3 + p * 2.5, -1 - 0.01 * b},
                                   {2 + (b + 1) * 0.9, 3 + p * 2.5, -1 - 0.01 * (b + 1)}));
  g.cut(raster, ball);
  g.cut(Sweep::line({5, 5, 2}, {5, 5, -6}), drill);
  g.cut(Sweep::line({10, 30, -0.5}, {35, 8, -3}), flat);
  g.cut(Sweep::arc(Arc{{25, 20, -2}, {20, 25.004, -3}, {20, 20, 0}, true, Plane::xy}), bull);
  g.cut(Sweep::arc(Arc{{15, 10, -1}, {5, 10, -1}, {10, 10, -1}, false, Plane::zx}), ball);
  g.cut(Sweep::arc(Arc{{30, 10, -1}, {30, 16, -1.0003}, {30, 13, -1}, true, Plane::yz}), vee);
  g.cut(Sweep::polyline({{3, 35, -0.3}, {12, 38, -0.8}, {20, 33, -0.4}}, 0.002), vee);
}

}  // namespace

TEST(DexelGrid, ColumnsAndCentres) {
  DexelGrid g({0, 0, -10, 100, 100, 0}, 0.05);
  EXPECT_EQ(g.nx(), 2000u);  // 100 / 0.05 counts as 2000, not 2001
  EXPECT_EQ(g.ny(), 2000u);
  EXPECT_DOUBLE_EQ(g.x_center(0), 0.025);
  DexelGrid h({0, 0, -1, 10.01, 3, 0}, 1);
  EXPECT_EQ(h.nx(), 11u);  // the last cell reaches past x1
  EXPECT_EQ(h.ny(), 3u);
  EXPECT_EQ(h.floor(10, 2), 0);
}

TEST(DexelGrid, RefusesBadBoxesAndCells) {
  auto id = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.id() + " " + e.where();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(id([] { DexelGrid({0, 0, 0, 0, 10, 1}, 0.1); }), "stock.box box");
  EXPECT_EQ(id([] { DexelGrid({0, 0, 1, 10, 10, 0}, 0.1); }), "stock.box box");
  EXPECT_EQ(id([] { DexelGrid({0, 0, 0, NAN, 10, 1}, 0.1); }), "stock.box box");
  EXPECT_EQ(id([] { DexelGrid({0, 0, 0, 10, 10, 1}, 0); }), "stock.cell cell");
  EXPECT_EQ(id([] { DexelGrid({0, 0, 0, 10, 10, 1}, -1); }), "stock.cell cell");
}

TEST(DexelGrid, RefusesAGridOverTheMemoryLimitBeforeAllocating) {
  // 4 M columns fit well within the default 1 GiB.
  const StockGridSize s = stock_grid_size({0, 0, -10, 100, 100, 0}, 0.05);
  EXPECT_EQ(s.nx * s.ny, 4000000u);
  EXPECT_LT(s.bytes, 40.0 * 1024 * 1024);
  // A micrometre over a metre square would be 10^12 columns (8 TB): refused
  // at once, naming the cell and the cell that would fit.
  const auto t0 = std::chrono::steady_clock::now();
  try {
    DexelGrid g({0, 0, -10, 1000, 1000, 0}, 0.001);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "stock.memory");
    EXPECT_EQ(e.where(), "cell");
    EXPECT_NE(e.message().find("1000000 x 1000000 columns"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("use a cell of at least"), std::string::npos) << e.message();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  // An explicit limit: 32 MB of floors do not fit 16 MiB, fit 64 MiB; the
  // cell the message proposes fits.
  try {
    DexelGrid g({0, 0, -10, 100, 100, 0}, 0.05, 16u << 20);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const auto at = e.message().find("at least ");
    ASSERT_NE(at, std::string::npos);
    const double cell = std::stod(e.message().substr(at + 9));
    EXPECT_GT(cell, 0.05);
    EXPECT_NO_THROW(DexelGrid({0, 0, -10, 100, 100, 0}, cell, 16u << 20));
  }
  EXPECT_NO_THROW(DexelGrid({0, 0, -10, 100, 100, 0}, 0.05, 64u << 20));
}

TEST(DexelGrid, AMoveThatCutsNothingLeavesTheStockUntouched) {
  DexelGrid g({0, 0, -5, 40, 40, 0}, 0.1);
  const std::string fresh = g.hash_hex();
  const ToolShape ball = ToolShape::ball(6);
  g.cut(Sweep::line({5, 5, 0.001}, {35, 30, 3}), ball);           // above the top
  g.cut(Sweep::line({-10, -10, -3}, {-10, 50, -3}), ball);        // beyond reach, off the box
  g.cut(Sweep::line({42.9501, 5, -3}, {42.9501, 30, -3}), ball);  // 3.0001 from the last columns (x 39.95)
  g.cut(Sweep::arc(Arc{{20, 50, -2}, {20, 60, -2}, {20, 55, -2}, true, Plane::xy}), ball);
  EXPECT_EQ(g.hash_hex(), fresh);
  EXPECT_EQ(g.removed_volume(), 0);
  EXPECT_EQ(g.deepest().z, 0);
  g.cut(Sweep::line({42.9499, 5, -3}, {42.9499, 30, -3}), ball);  // 2.9999 away: now it grazes them
  EXPECT_NE(g.hash_hex(), fresh);
}

TEST(DexelGrid, SameFloorsForAnyThreadCount) {
  std::vector<double> first;
  std::string hash;
  for (unsigned threads : {1u, 2u, 8u}) {
    DexelGrid g({0, 0, -8, 40, 40, 0}, 0.05);
    g.set_threads(threads);
    mixed_program(g);
    const auto f = g.floors();
    if (first.empty()) {
      first.assign(f.begin(), f.end());
      hash = g.hash_hex();
      EXPECT_GT(g.removed_volume(), 100);
      continue;
    }
    EXPECT_EQ(g.hash_hex(), hash) << threads << " threads";
    EXPECT_TRUE(std::equal(f.begin(), f.end(), first.begin())) << threads << " threads";
  }
}

TEST(DexelGrid, OrderOfMovesDoesNotMatter) {
  DexelGrid a({0, 0, -8, 40, 40, 0}, 0.1), b({0, 0, -8, 40, 40, 0}, 0.1);
  const ToolShape t = ToolShape::bull(6, 1);
  std::vector<Sweep> moves = {Sweep::line({3, 3, -1}, {30, 20, -2}), Sweep::line({30, 3, -0.5}, {3, 30, -2.5}),
                              Sweep::arc(Arc{{25, 20, -1}, {15, 20, -2}, {20, 20, 0}, true, Plane::xy})};
  a.cut(moves, t);
  for (auto it = moves.rbegin(); it != moves.rend(); ++it) b.cut(*it, t);
  EXPECT_EQ(a.hash_hex(), b.hash_hex());
}

TEST(DexelGrid, FlatSlotRemovesItsAnalyticVolume) {
  // A 6 mm flat end mill 2 mm deep from (10, 20) to (40, 20): a stadium of
  // length 30 and radius 3, 2 deep. The grid's volume may differ by the
  // cells along the stadium's outline: at most its perimeter x C x depth.
  const double C = 0.05, L = 30, R = 3, depth = 2;
  DexelGrid g({0, 0, -10, 50, 40, 0}, C);
  g.cut(Sweep::line({10, 20, 5}, {10, 20, -depth}), ToolShape::flat(2 * R));
  g.cut(Sweep::line({10, 20, -depth}, {40, 20, -depth}), ToolShape::flat(2 * R));
  const double want = depth * (2 * R * L + std::numbers::pi * R * R);
  const double perimeter = 2 * L + 2 * std::numbers::pi * R;
  EXPECT_NEAR(g.removed_volume(), want, perimeter * C * depth);
  EXPECT_NEAR(g.removed_volume(), want, 0.05 * perimeter * C * depth);  // in fact far closer
  EXPECT_EQ(g.deepest().z, -depth);
}

TEST(DexelGrid, FloorsStopAtTheStockBottom) {
  DexelGrid g({0, 0, -3, 10, 10, 0}, 0.5);
  g.cut(Sweep::line({5, 5, 1}, {5, 5, -8}), ToolShape::flat(2));
  EXPECT_EQ(g.deepest().z, -3);
  for (double f : g.floors()) EXPECT_GE(f, -3);
  EXPECT_NEAR(g.removed_volume(), 3 * 0.25 * 12, 1e-12);  // 12 columns within 1 of (5, 5)
}

TEST(DexelGrid, DeepestFloorAndWhere) {
  DexelGrid g({0, 0, -10, 20, 20, 0}, 0.5);
  g.cut(Sweep::line({4.25, 7.75, 0}, {4.25, 7.75, -4}), ToolShape::ball(3));
  const auto d = g.deepest();
  EXPECT_EQ(d.z, -4);
  EXPECT_EQ(d.x, 4.25);
  EXPECT_EQ(d.y, 7.75);
  EXPECT_EQ(d.i, 8u);
  EXPECT_EQ(d.j, 15u);
}

TEST(DexelGrid, HashIsFnv1aOverMicrometres) {
  // Computed here from the definition, over a small grid.
  DexelGrid g({0, 0, -2, 3, 2, 0}, 1);
  g.cut(Sweep::line({0.5, 0.5, -1.23456}, {2.5, 0.5, -1.23456}), ToolShape::flat(0.5));
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto feed = [&](std::int64_t v) {
    for (int b = 0; b < 8; ++b) {
      h ^= (static_cast<std::uint64_t>(v) >> (8 * b)) & 0xff;
      h *= 0x100000001b3ull;
    }
  };
  feed(3);
  feed(2);
  for (int k = 0; k < 3; ++k) feed(-1235);  // row 0: -1.23456 mm is -1235 um
  for (int k = 0; k < 3; ++k) feed(0);
  EXPECT_EQ(g.hash(), h);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  EXPECT_EQ(g.hash_hex(), hex);
}

TEST(DexelGrid, PolylinesReportTheirBound) {
  DexelGrid g({0, 0, -5, 20, 20, 0}, 0.2);
  g.cut(Sweep::line({1, 1, -1}, {5, 5, -1}), ToolShape::ball(2));
  EXPECT_EQ(g.added_error(), 0);
  g.cut(Sweep::polyline({{2, 2, -1}, {8, 3, -1}, {12, 9, -1.5}}, 0.003), ToolShape::ball(2));
  g.cut(Sweep::polyline({{2, 12, -1}, {8, 13, -1}}, 0.001), ToolShape::ball(2));
  EXPECT_EQ(g.added_error(), 0.003);
  // the polyline is swept exactly: as its lines are
  DexelGrid h({0, 0, -5, 20, 20, 0}, 0.2);
  h.cut(Sweep::line({1, 1, -1}, {5, 5, -1}), ToolShape::ball(2));
  h.cut(Sweep::line({2, 2, -1}, {8, 3, -1}), ToolShape::ball(2));
  h.cut(Sweep::line({8, 3, -1}, {12, 9, -1.5}), ToolShape::ball(2));
  h.cut(Sweep::line({2, 12, -1}, {8, 13, -1}), ToolShape::ball(2));
  EXPECT_EQ(g.hash(), h.hash());
}
