// The proven offset (offset.hpp), checked by the independent measurement
// (offset_measure.hpp), never by the code that built it.
#include "bezcam/flatten/offset.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/offset_measure.hpp"

namespace bezcam {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Bezier> circle(double cx, double cy, double R, bool ccw = true) {
  std::vector<Bezier> out;
  const double w = std::cos(kPi / 4);
  for (int k = 0; k < 4; ++k) {
    const double s = (ccw ? 1 : -1) * k * kPi / 2, e = (ccw ? 1 : -1) * (k + 1) * kPi / 2, m = (s + e) / 2;
    out.push_back(Bezier::make({{cx + R * std::cos(s), cy + R * std::sin(s)},
                                {cx + R / w * std::cos(m), cy + R / w * std::sin(m)},
                                {cx + R * std::cos(e), cy + R * std::sin(e)}},
                               {1, w, 1}));
  }
  out.back().points.back() = out.front().points.front();
  return out;
}

std::vector<Bezier> polygon(std::vector<Vec3> pts) {
  std::vector<Bezier> out;
  for (size_t i = 0; i < pts.size(); ++i) out.push_back(Bezier::make({pts[i], pts[(i + 1) % pts.size()]}));
  return out;
}

// Dense polyline of the offset chains (the drawn path, no rounding).
std::vector<Vec3> dense(const OffsetResult& r, size_t chain = 0) {
  return flatten(bezier_pieces(r.chains.at(chain)), {1e-6, -1}).points;
}

OffsetReading measure(const std::vector<Bezier>& part, const OffsetResult& res, double r, int side, double tol) {
  const std::vector<std::vector<Bezier>> curves{part};
  const auto path = dense(res);
  return measure_offset(curves, path, {.r = r, .side = side, .resolution = tol * 1e-2});
}

TEST(Offset, CircleOutsideAndInsideAreConcentricCircles) {
  const auto part = circle(10, 5, 20);
  for (int side : {1, -1}) {  // ccw circle: left is inside
    const auto res = offset_curve(part, true, {3, side, 0.005});
    ASSERT_EQ(res.chains.size(), 1u);
    EXPECT_TRUE(res.closed[0]);
    const auto m = measure(part, res, 3, side, 0.01);
    EXPECT_LE(m.deviation(3), 0.005 + 1e-4) << side;
    EXPECT_LE(res.bound, 0.0051);
    EXPECT_TRUE(res.left.empty());
  }
}

TEST(Offset, SquareOutsideRollsRoundTheCornersInsideLeavesThem) {
  const auto part = polygon({{0, 0}, {40, 0}, {40, 30}, {0, 30}});  // ccw
  const auto out = offset_curve(part, true, {5, -1, 0.005});
  ASSERT_EQ(out.chains.size(), 1u);
  size_t arcs = 0;
  for (const auto& s : out.chains[0]) arcs += s.arc;
  EXPECT_EQ(arcs, 4u);  // one roll per corner
  EXPECT_LE(measure(part, out, 5, -1, 0.01).deviation(5), 0.006);
  EXPECT_TRUE(out.left.empty());

  const auto in = offset_curve(part, true, {5, 1, 0.005});
  ASSERT_EQ(in.chains.size(), 1u);
  EXPECT_EQ(in.chains[0].size(), 4u);  // a smaller rectangle
  EXPECT_LE(measure(part, in, 5, 1, 0.01).deviation(5), 0.006);
  EXPECT_EQ(in.left.size(), 4u);  // material in every inner corner
}

TEST(Offset, OpenCubicBothSidesWithinTheFit) {
  const std::vector<Bezier> part{Bezier::make({{0, 0}, {30, 40}, {60, -40}, {90, 0}})};
  for (int side : {1, -1}) {
    const auto res = offset_curve(part, false, {2, side, 0.004});
    ASSERT_EQ(res.chains.size(), 1u);
    EXPECT_FALSE(res.closed[0]);
    const auto m = measure(part, res, 2, side, 0.01);
    EXPECT_LE(m.deviation(2), 0.0045) << side << " min " << m.min_distance << " max " << m.max_distance << " cov "
                                      << m.coverage;
  }
}

// The largest turn between consecutive moves of a closed chain, the
// closing joint included.
double largest_turn(const std::vector<ArcSeg>& chain) {
  double worst = 0;
  for (size_t i = 0; i < chain.size(); ++i) {
    const Vec3 u = chain[i].tangent(1), v = chain[(i + 1) % chain.size()].tangent(0);
    worst = std::max(worst, std::atan2(std::abs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y));
  }
  return worst;
}

TEST(Offset, ClosedSmoothCurveInTangentChainsIsTangentWhereItCloses) {
  // An ellipse of four cubics, tangent at every joint: its arc spline in
  // tangent chains starts free and closes on itself, and where the last
  // arc met the first at a small angle the offsets met with a join arc of
  // micrometres, a kink of the printed path in every pass. The last move
  // is a biarc into the first: every joint is tangent, the bound kept.
  const double k = 0.5522847498, a = 30, b = 17;
  const std::vector<Bezier> part{Bezier::make({{a, 0}, {a, k * b}, {k * a, b}, {0, b}}),
                                 Bezier::make({{0, b}, {-k * a, b}, {-a, k * b}, {-a, 0}}),
                                 Bezier::make({{-a, 0}, {-a, -k * b}, {-k * a, -b}, {0, -b}}),
                                 Bezier::make({{0, -b}, {k * a, -b}, {a, -k * b}, {a, 0}})};
  for (int side : {1, -1}) {
    SCOPED_TRACE(side);
    const auto res = offset_curve(part, true, {3, side, 0.002, true});
    ASSERT_EQ(res.chains.size(), 1u);
    EXPECT_TRUE(res.closed[0]);
    EXPECT_LE(largest_turn(res.chains[0]), 1e-9);
    EXPECT_LE(res.bound, 0.002);
    EXPECT_LE(measure(part, res, 3, side, 0.002).deviation(3), res.bound + 1e-5);
  }
}

TEST(Offset, NotchTighterThanTheToolIsTrimmedAndSaid) {
  // A 40 x 30 block with a 4 mm wide slot 10 deep in its top edge (ccw).
  const auto part = polygon({{0, 0}, {40, 0}, {40, 30}, {22, 30}, {22, 20}, {18, 20}, {18, 30}, {0, 30}});
  // Outside with r = 3: the slot (4 wide) is narrower than the tool (6).
  const auto res = offset_curve(part, true, {3, -1, 0.005});
  ASSERT_EQ(res.chains.size(), 1u);
  const auto m = measure(part, res, 3, -1, 0.01);
  EXPECT_GE(m.min_distance, 3 - 0.006);
  EXPECT_LE(m.max_distance, 3 + 0.006);
  double left = 0;
  for (const auto& l : res.left) left += l.length;
  EXPECT_GE(left, 20);  // the slot's walls and floor are not reached
  // The path never crosses itself.
  const auto path = dense(res);
  for (size_t i = 0; i + 1 < path.size(); ++i)
    for (size_t j = i + 2; j + 1 < path.size(); ++j) {
      if (i == 0 && j + 2 == path.size()) continue;
      const Vec3 a = path[i], b = path[i + 1], c = path[j], d = path[j + 1];
      const double d1 = cross(b - a, c - a).z, d2 = cross(b - a, d - a).z;
      const double d3 = cross(d - c, a - c).z, d4 = cross(d - c, b - c).z;
      ASSERT_FALSE(d1 * d2 < 0 && d3 * d4 < 0) << i << " " << j;
    }
}

TEST(Offset, ToolLargerThanTheHoleLeavesNothing) {
  const auto part = circle(0, 0, 2);
  const auto res = offset_curve(part, true, {3, 1, 0.005});
  EXPECT_TRUE(res.chains.empty());
}

TEST(Offset, OrientationFromTheArea) {
  EXPECT_GT(signed_area(circle(0, 0, 10)), 0);
  EXPECT_LT(signed_area(circle(0, 0, 10, false)), 0);
  EXPECT_NEAR(signed_area(polygon({{0, 0}, {40, 0}, {40, 30}, {0, 30}})), 1200, 1e-9);
}

TEST(Offset, TheMeasurementCatchesAWrongOffset) {
  const auto part = circle(0, 0, 20);
  auto res = offset_curve(part, true, {3, -1, 0.005});
  // Move one stretch of the path 0.05 outwards: the reading must show it.
  auto path = dense(res);
  for (size_t i = path.size() / 3; i < path.size() / 3 + 20; ++i) path[i] = path[i] * (23.05 / 23);
  const std::vector<std::vector<Bezier>> curves{part};
  EXPECT_GE(measure_offset(curves, path, {.r = 3, .side = -1, .resolution = 1e-4}).deviation(3), 0.049);
  // A missing stretch shows as coverage.
  auto cut = dense(res);
  cut.resize(cut.size() / 2);
  EXPECT_GE(measure_offset(curves, cut, {.r = 3, .side = -1, .resolution = 1e-4}).coverage, 0.04);
}

// Long path segments, whose nearest and farthest points from the curve lie
// inside them, read against the exact distance to a circle (| |x - c| - R |,
// brute force along each segment): the smallest and largest within the
// resolution plus the sampled curve's own chord error.
TEST(Offset, TheMeasurementReadsLongSegmentsWithinItsResolution) {
  const double R = 20, res = 1e-3;
  const auto part = circle(0, 0, R);
  const std::vector<std::vector<Bezier>> curves{part};
  const std::vector<std::vector<Vec3>> paths{
      {{-30, 23}, {30, 23}},                                    // passes 3 from the circle at its middle
      {{-30, 23}, {30, 23}, {30, -24}, {-31, -22}, {-30, 23}},  // a quadrilateral round it
      {{-25, 0}, {25, 1}},                                      // crosses it twice
      {{0, 0}, {5, 5}, {-3, 7}},                                // inside
      {{-15, 0.5}, {15, 0.5}},                                  // farthest at its middle
  };
  for (size_t k = 0; k < paths.size(); ++k) {
    const auto& path = paths[k];
    double lo = HUGE_VAL, hi = 0;
    for (size_t i = 1; i < path.size(); ++i)
      for (int j = 0; j <= 200000; ++j) {
        const Vec3 x = lerp(path[i - 1], path[i], j / 200000.0);
        const double d = std::abs(std::hypot(x.x, x.y) - R);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    const OffsetReading m = measure_offset(curves, path, {.r = 3, .resolution = res});
    EXPECT_NEAR(m.min_distance, lo, 2 * res) << k;
    EXPECT_NEAR(m.max_distance, hi, 2 * res) << k;
    // A reading is a real point's distance to the sampled curve (chords within res of it).
    EXPECT_LE(m.max_distance, hi + res) << k;
  }
}

// The smallest distance from p to the polygon's edges (closed).
double to_polygon(const std::vector<Vec3>& poly, const Vec3& p) {
  double best = HUGE_VAL;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec3 a = poly[i], b = poly[(i + 1) % poly.size()], d = b - a;
    const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
    best = std::min(best, dist(p, a + d * t));
  }
  return best;
}

// Artwork whose outline turns back on itself: a spur of zero width on the
// top edge (the edge comes in below it, turns back at the tip, returns a
// hair below the top, crossing the way in, and turns back again along the
// top), the shape of a glitch in document-open-symbolic.svg. The other
// side of the return stroke faces the pocket there, so the offset inside
// must be cut against that side too: every point of the path within the fit
// of r (the path used to run 0.024 inside it), one closed path.
TEST(Offset, ASpurThatTurnsBackOnItselfKeepsThePathInTheBand) {
  const std::vector<Vec3> pts{{0, 0},           {100, 0},         {100, 60},      {79.6, 79.13}, {73.518, 80.186},
                              {73.373, 80.169}, {74.024, 80.193}, {51.9, 80.193}, {0, 80.193}};
  const auto part = polygon(pts);
  ASSERT_GT(signed_area(part), 0);
  for (double r : {0.5, 1.5, 3.0}) {
    const auto res = offset_curve(part, true, {r, 1, 0.0045});
    ASSERT_EQ(res.chains.size(), 1u) << r;
    EXPECT_TRUE(res.closed[0]) << r;
    double lo = HUGE_VAL, hi = 0;
    for (const ArcSeg& s : res.chains[0])
      for (int k = 0; k <= 64; ++k) {
        const double d = to_polygon(pts, s.point(k / 64.0));
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    EXPECT_GE(lo, r - res.bound) << r;
    EXPECT_LE(hi, r + res.bound) << r;
  }
}

// A channel as wide as twice the offset: the offsets of its two walls
// coincide along its middle, and the path runs into it and back (a spur),
// not past its mouth.
TEST(Offset, ChannelAsWideAsTheToolKeepsItsSpur) {
  const std::vector<Bezier> part{
      Bezier::make({{11, 6}, {0, 6}}),
      Bezier::make({{0, 6}, {0, 0}}),
      Bezier::make({{0, 0}, {5, 0}}),
      Bezier::make({{5, 0}, {5, -6}, {11, -6}}),
      Bezier::make({{11, -6}, {17, -6}, {17, 0}}),
      Bezier::make({{17, 0}, {17, 6}, {11, 6}}),
  };
  const auto res = offset_curve(part, true, {3.0, 1, 0.005});
  ASSERT_EQ(res.chains.size(), 1u);
  double reach = HUGE_VAL;
  for (const ArcSeg& s : res.chains[0]) reach = std::min({reach, s.a.x, s.b.x});
  EXPECT_NEAR(reach, 3.0, 1e-9);
}

// A rectangle whose outline holds cubics that run down a line and back up
// it (control points on the line: the curve turns back exactly, half a
// turn, inside the piece), as preferences-system-network-proxy-symbolic.svg
// draws it. Outside, the path keeps its band whatever the tool.
TEST(Offset, ACubicThatRunsBackAlongItsLineKeepsTheBand) {
  const std::vector<Bezier> part{
      Bezier::make({{0, 37.402}, {31.168, 37.402}}),
      Bezier::make({{31.168, 37.402}, {31.168, 35.426}, {31.168, 39.372}, {31.168, 37.402}}),
      Bezier::make({{31.168, 37.402}, {31.168, 0}}),
      Bezier::make({{31.168, 0}, {0, 0}}),
      Bezier::make({{0, 0}, {0, 0}, {0, -0.274}, {0, 0}}),
      Bezier::make({{0, 0}, {0, 37.402}}),
      Bezier::make({{0, 37.402}, {0, 37.676}, {0, 37.402}, {0, 37.402}}),
  };
  // The curve as a fine polyline (within 1e-6 of it), for the distances.
  const std::vector<Vec3> fine = flatten(part, {1e-6, -1}).points;
  ASSERT_LT(signed_area(part), 0);  // clockwise: the outside is on the left
  for (double r : {0.5, 1.5, 3.0}) {
    const auto res = offset_curve(part, true, {r, 1, 0.0045});
    ASSERT_FALSE(res.chains.empty()) << r;
    double lo = HUGE_VAL, hi = 0;
    for (const auto& chain : res.chains)
      for (const ArcSeg& s : chain)
        for (int k = 0; k <= 64; ++k) {
          const double d = to_polygon(fine, s.point(k / 64.0));
          lo = std::min(lo, d);
          hi = std::max(hi, d);
        }
    EXPECT_GE(lo, r - res.bound - 1e-6) << r;
    EXPECT_LE(hi, r + res.bound + 1e-6) << r;
  }
}

// Readings are distances between real points, found exactly (not read off
// chords): a printed path that is the true offset reads r to rounding,
// whatever the resolution, and a path farther by 0.001 over a stretch reads
// exactly that.
TEST(Offset, TheMeasurementReadsTrueDistancesNotChords) {
  const auto part = circle(0, 0, 20);
  const std::vector<std::vector<Bezier>> curves{part};
  auto arc = [](double R, double a0, double a1) {
    return PathPiece::of(
        Arc{{R * std::cos(a0), R * std::sin(a0), 0}, {R * std::cos(a1), R * std::sin(a1), 0}, {0, 0, 0}, true});
  };
  std::vector<PathPiece> path;
  for (int k = 0; k < 4; ++k) path.push_back(arc(23, k * kPi / 2, (k + 1) * kPi / 2));
  for (double res : {1e-2, 1e-4}) {
    const OffsetReading m = measure_offset(curves, path, {.r = 3, .side = -1, .resolution = res});
    EXPECT_NEAR(m.min_distance, 3, 1e-12) << res;
    EXPECT_NEAR(m.max_distance, 3, 1e-12) << res;
    EXPECT_LE(m.coverage, 1e-12) << res;
  }
  path[1] = arc(23.001, kPi / 2, kPi);  // a quarter 0.001 out, joined by its ends' radii
  const OffsetReading m = measure_offset(curves, path, {.r = 3, .side = -1, .resolution = 1e-2});
  EXPECT_NEAR(m.max_distance, 3.001, 1e-12);
  EXPECT_NEAR(m.min_distance, 3, 1e-12);
}

}  // namespace
}  // namespace bezcam
