// The floors the grid computes against an independent reference: each
// column's lowest point of the swept tool found by sampling the move's
// parameter densely, locating every edge of the tool's reach by bisection
// and refining every sampled local minimum by golden-section search,
// with the tool's profile written out here again. Closed forms derived here
// (the capsule of a ball along a line, the cone of a plunging drill) check
// the reference and the grid alike.
#include "stock/floors.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <memory>
#include <numbers>
#include <random>

#include "bezcam/stock/dexel_grid.hpp"

using namespace bezcam;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The tool's profile, written independently of the library.
struct RefTool {
  ToolShapeKind kind;
  double R, rc = 0, half_angle_deg = 0;
  double h(double rho) const {
    switch (kind) {
      case ToolShapeKind::flat: return 0;
      case ToolShapeKind::ball: return R - std::sqrt(R * R - rho * rho);
      case ToolShapeKind::bull: {
        const double x = rho - (R - rc);
        return x <= 0 ? 0 : rc - std::sqrt(rc * rc - x * x);
      }
      default: return rho / std::tan(half_angle_deg * std::numbers::pi / 180);
    }
  }
  ToolShape shape() const {
    switch (kind) {
      case ToolShapeKind::flat: return ToolShape::flat(2 * R);
      case ToolShapeKind::ball: return ToolShape::ball(2 * R);
      case ToolShapeKind::bull: return ToolShape::bull(2 * R, rc);
      case ToolShapeKind::vee: return ToolShape::vee(2 * R, 2 * half_angle_deg);
      default: return ToolShape::drill(2 * R, 2 * half_angle_deg);
    }
  }
};

std::vector<RefTool> tools() {
  return {{ToolShapeKind::flat, 3},      {ToolShapeKind::ball, 3},       {ToolShapeKind::bull, 5, 1},
          {ToolShapeKind::bull, 3, 1.5}, {ToolShapeKind::vee, 3, 0, 30}, {ToolShapeKind::drill, 2.5, 0, 59},
          {ToolShapeKind::vee, 2, 0, 15}};
}

using Path = std::function<Vec3(double)>;

double golden(const std::function<double(double)>& g, double a, double b, double best) {
  const double r = (std::sqrt(5.0) - 1) / 2;
  double c = b - r * (b - a), d = a + r * (b - a), fc = g(c), fd = g(d);
  best = std::min({best, fc, fd});
  for (int it = 0; it < 120 && b - a > 1e-17; ++it) {
    if (fc <= fd) {
      b = d, d = c, fd = fc, c = b - r * (b - a), fc = g(c);
      best = std::min(best, fc);
    } else {
      a = c, c = d, fc = fd, d = a + r * (b - a), fd = g(d);
      best = std::min(best, fd);
    }
  }
  return best;
}

// min over s in [0, 1] of z(s) + h(d(s)), d the horizontal distance of the
// column to path(s), where d <= R; +inf when the tool never reaches it.
double reference_floor(const Path& path, const RefTool& t, double px, double py, int n = 2000) {
  auto g = [&](double s) {
    const Vec3 P = path(std::clamp(s, 0.0, 1.0));
    const double d = std::hypot(px - P.x, py - P.y);
    return d > t.R ? kInf : P.z + t.h(d);
  };
  std::vector<double> v(n + 1);
  for (int i = 0; i <= n; ++i) v[i] = g(static_cast<double>(i) / n);
  double best = *std::min_element(v.begin(), v.end());
  // The edge of reach between an unreachable sample and a reachable one,
  // by bisection: the last reachable point, and golden section from there.
  auto edge = [&](double out, double in) {
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (out + in);
      if (mid == out || mid == in) break;
      (std::isfinite(g(mid)) ? in : out) = mid;
    }
    best = std::min(best, g(in));
    return in;
  };
  for (int i = 0; i <= n; ++i) {
    if (!std::isfinite(v[i])) continue;
    const double si = static_cast<double>(i) / n;
    double lo = std::max(0.0, (i - 1.0) / n), hi = std::min(1.0, (i + 1.0) / n);
    const bool l_out = i > 0 && !std::isfinite(v[i - 1]), r_out = i < n && !std::isfinite(v[i + 1]);
    if (l_out) lo = edge(lo, si);
    if (r_out) hi = edge(hi, si);
    const double l = i > 0 ? v[i - 1] : kInf, r = i < n ? v[i + 1] : kInf;
    if ((v[i] <= l && v[i] <= r) || l_out || r_out) best = golden(g, lo, hi, best);
  }
  return best;
}

Path line_path(Vec3 a, Vec3 b) {
  return [=](double s) { return lerp(a, b, s); };
}
Path arc_path(const Arc& a) {
  // ArcPoints: Arc::point() bit for bit, the arc's angles taken once
  auto pts = std::make_shared<ArcPoints>(a);
  return [pts](double s) { return pts->at(s); };
}

// Sweeps `move` over a grid of about n x n columns covering its reach and
// compares every column with the reference; returns the columns compared.
int compare(const Sweep& move, const Path& path, const RefTool& t, int n = 18, double tol = 1e-9) {
  const Box3 e = move.extent();
  const double pad = t.R * 1.05;
  StockBox box{e.lo.x - pad, e.lo.y - pad, e.lo.z - 50, e.hi.x + pad, e.hi.y + pad, e.hi.z + 50};
  const double cell = std::max(box.x1 - box.x0, box.y1 - box.y0) / n;
  DexelGrid grid(box, cell);
  grid.cut(move, t.shape());
  int touched = 0;
  for (std::size_t j = 0; j < grid.ny(); ++j)
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double ref = reference_floor(path, t, grid.x_center(i), grid.y_center(j));
      const double got = grid.floor(i, j);
      if (!std::isfinite(ref)) {
        EXPECT_EQ(got, box.z1) << "column " << i << "," << j << " is out of reach";
        continue;
      }
      ++touched;
      EXPECT_NEAR(got, ref, tol) << to_string(t.kind) << " R" << t.R << " column " << i << "," << j << " at ("
                                 << grid.x_center(i) << ", " << grid.y_center(j) << ")";
    }
  return touched;
}

}  // namespace

TEST(StockFloors, LinesMatchTheReferenceForEveryShape) {
  const std::vector<std::pair<Vec3, Vec3>> lines = {
      {{0, 0, 0}, {10, 0, 0}},    // horizontal along x
      {{0, 0, 0}, {7, 4, 0}},     // horizontal, diagonal
      {{0, 0, 0}, {8, 3, -2}},    // descending gently
      {{1, 2, -3}, {-6, 5, 1}},   // ascending
      {{0, 0, 0}, {2, 1, -6}},    // steep: steeper than the cones
      {{0, 0, 0}, {0.5, 0, -9}},  // nearly a plunge
      {{2, 3, 1}, {2, 3, -4}},    // plunge
  };
  for (const RefTool& t : tools())
    for (const auto& [a, b] : lines) {
      SCOPED_TRACE(std::string(to_string(t.kind)) + " from (" + std::to_string(a.x) + "," + std::to_string(a.y) + "," +
                   std::to_string(a.z) + ") to (" + std::to_string(b.x) + "," + std::to_string(b.y) + "," +
                   std::to_string(b.z) + ")");
      EXPECT_GT(compare(Sweep::line(a, b), line_path(a, b), t), 15);
    }
}

TEST(StockFloors, BallOnASlopedLineIsTheCapsulesLowerEnvelope) {
  // The ball's centre runs along the segment A + (0,0,R) .. B + (0,0,R); the
  // floor over a column is where the vertical line through it first meets
  // the capsule of radius R around that segment. Closed form: the line
  // (p, z) meets the infinite cylinder where |(P - C0) x u| = R (a quadratic
  // in z), kept when the foot lies within the segment, else the end spheres.
  const double R = 3;
  const Vec3 A{0, 0, 0}, B{9, 4, -3};
  const Vec3 C0 = A + Vec3{0, 0, R}, C1 = B + Vec3{0, 0, R};
  const Vec3 u = (C1 - C0) / norm(C1 - C0);
  const double len = norm(C1 - C0);
  auto capsule = [&](double px, double py) {
    double best = kInf;
    for (const Vec3& c : {C0, C1}) {  // end spheres: lowest point
      const double d2 = (px - c.x) * (px - c.x) + (py - c.y) * (py - c.y);
      if (d2 <= R * R) best = std::min(best, c.z - std::sqrt(R * R - d2));
    }
    // cylinder: w(z) = (p - C0) + z e_z; |w - (w.u) u|^2 = R^2
    const Vec3 w0{px - C0.x, py - C0.y, -C0.z};
    const Vec3 ez{0, 0, 1};
    const Vec3 a = w0 - u * dot(w0, u), b = ez - u * dot(ez, u);
    const double qa = dot(b, b), qb = 2 * dot(a, b), qc = dot(a, a) - R * R;
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      const double z = (-qb - std::sqrt(disc)) / (2 * qa);  // the lower crossing
      const Vec3 w = w0 + ez * z;
      const double foot = dot(w, u);
      if (foot >= 0 && foot <= len) best = std::min(best, z);
    }
    return best;
  };
  const RefTool t{ToolShapeKind::ball, R};
  StockBox box{-4, -4, -20, 13, 8, 10};
  DexelGrid grid(box, 0.25);
  grid.cut(Sweep::line(A, B), t.shape());
  int n = 0;
  for (std::size_t j = 0; j < grid.ny(); ++j)
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double px = grid.x_center(i), py = grid.y_center(j);
      const double c = capsule(px, py);
      if (!std::isfinite(c)) {
        EXPECT_EQ(grid.floor(i, j), box.z1);
        continue;
      }
      ++n;
      EXPECT_NEAR(grid.floor(i, j), c, 1e-9) << px << "," << py;
      if (n % 37 == 0) EXPECT_NEAR(reference_floor(line_path(A, B), t, px, py), c, 1e-9) << px << "," << py;
    }
  EXPECT_GT(n, 500);
}

TEST(StockFloors, DrillPlungeLeavesItsCone) {
  // A 118-degree drill plunged to z = -5 at (1, 2): floor = -5 + rho / tan(59 deg).
  const ToolShape d = ToolShape::drill(5, 118);
  StockBox box{-2, -1, -10, 4, 5, 0};
  DexelGrid grid(box, 0.1);
  grid.cut(Sweep::line({1, 2, 3}, {1, 2, -5}), d);
  int n = 0;
  for (std::size_t j = 0; j < grid.ny(); ++j)
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double rho = std::hypot(grid.x_center(i) - 1, grid.y_center(j) - 2);
      const double want = rho > 2.5 ? 0.0 : std::min(0.0, -5 + rho / std::tan(59 * std::numbers::pi / 180));
      EXPECT_NEAR(grid.floor(i, j), want, 1e-12);
      n += rho <= 2.5;
    }
  EXPECT_GT(n, 1900);
}

namespace {

// Arcs on exact circles: ends with whole coordinates at radius 5 around (1, -2).
Arc arc17(Vec3 from_off, Vec3 to_off, double z0, double z1, bool ccw) {
  const Vec3 c{1, -2, 0};
  return Arc{c + Vec3{from_off.x, from_off.y, z0}, c + Vec3{to_off.x, to_off.y, z1}, c, ccw, Plane::xy};
}

}  // namespace

TEST(StockFloors, G17ArcsAndHelicesMatchTheReference) {
  const std::vector<Arc> arcs = {
      arc17({3, 4}, {-4, 3}, 0, 0, true),    // planar, 90 degrees
      arc17({5, 0}, {-3, -4}, 0, 0, false),  // planar, clockwise, 233 degrees
      arc17({3, 4}, {4, -3}, 1, -2, true),   // helix down, 270 degrees
      arc17({0, 5}, {0, 5}, 0, -3, true),    // full turn of a helix
      arc17({-5, 0}, {3, 4}, -4, 1, false),  // helix up, clockwise
  };
  for (const RefTool& t : tools())
    for (const Arc& a : arcs) {
      SCOPED_TRACE(std::string(to_string(t.kind)) + (a.ccw ? " G03" : " G02") + " to (" + std::to_string(a.to.x) + "," +
                   std::to_string(a.to.y) + "," + std::to_string(a.to.z) + ")");
      ASSERT_EQ(a.r_start(), a.r_end());
      EXPECT_GT(compare(Sweep::arc(a), arc_path(a), t), 40);
    }
}

TEST(StockFloors, SpiralsFromRoundedEndsMatchTheReference) {
  // Printed ends at slightly different radii: the path is the spiral whose
  // radius runs linearly with the angle (the reader's and LinuxCNC's path).
  const Vec3 c{10, 20, 0};
  const std::vector<Arc> arcs = {
      Arc{{15, 20, 0}, {10, 25.003, 0}, c, true, Plane::xy},
      Arc{{13, 24, 2}, {6.0004, 17.0003, -1}, c, true, Plane::xy},
      Arc{{10, 15, 0}, {10.0007, 14.9, -4}, c, false, Plane::xy},
  };
  for (const RefTool& t : tools())
    for (const Arc& a : arcs) {
      SCOPED_TRACE(std::string(to_string(t.kind)) + " to (" + std::to_string(a.to.x) + "," + std::to_string(a.to.y) +
                   ")");
      ASSERT_NE(a.r_start(), a.r_end());
      EXPECT_GT(compare(Sweep::arc(a), arc_path(a), t), 40);
    }
}

TEST(StockFloors, G18AndG19ArcsMatchTheReference) {
  // The tool moves in a vertical plane: G18 (ZX, axis Y), G19 (YZ, axis X).
  const std::vector<Arc> arcs = {
      Arc{{4, 0, 0}, {-4, 0, 0}, {0, 0, 0}, false, Plane::zx},  // a half circle under the centre's height? (G02 in ZX)
      Arc{{4, 0, 0}, {-4, 0, 0}, {0, 0, 0}, true, Plane::zx},   // the other half
      Arc{{3, 1, 4}, {-4, 3, -3}, {0, 1, 0}, true, Plane::zx},  // with travel along Y
      Arc{{0, 5, 0}, {0, 0, -5}, {0, 0, 0}, true, Plane::yz},   // quarter in YZ
      Arc{{2, -3, 4}, {-1, 4, 3.0002}, {0, 0, 0}, false, Plane::yz},  // spiral with travel along X
  };
  for (const RefTool& t : tools())
    for (const Arc& a : arcs) {
      SCOPED_TRACE(std::string(to_string(t.kind)) + " G" + std::to_string(g_number(a.plane)) + (a.ccw ? "3" : "2") +
                   " to (" + std::to_string(a.to.x) + "," + std::to_string(a.to.y) + "," + std::to_string(a.to.z) +
                   ")");
      EXPECT_GT(compare(Sweep::arc(a), arc_path(a), t), 40);
    }
}

TEST(StockFloors, VeeOnAHelixMatchesTheReference) {
  // A 60-degree vee engraving down a helix: the cone's envelope, with the
  // column centres on a fine grid over the groove.
  const RefTool t{ToolShapeKind::vee, 3, 0, 30};
  const Arc a = arc17({3, 4}, {-3, -4}, 0, -1.5, true);
  EXPECT_GT(compare(Sweep::arc(a), arc_path(a), t, 40), 400);
}

TEST(StockFloors, ClosedFormAndCertifiedSearchAgreeOnCircles) {
  // Two independent ways to the same floors: the closed forms of the G17
  // circle and the certified search (which spirals and G18/G19 use).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  const std::vector<Arc> arcs = {arc17({3, 4}, {-4, 3}, 0, -2, true), arc17({5, 0}, {0, -5}, 1, 1, false),
                                 arc17({-3, 4}, {-3, 4}, 0, -4, true)};
  for (const RefTool& t : tools()) {
    if (t.kind == ToolShapeKind::bull) continue;  // no closed form on arcs
    const stock_detail::Profile p(t.shape());
    for (const Arc& a : arcs) {
      const stock_detail::ArcPrep prep = stock_detail::prepare_arc(a);
      ASSERT_TRUE(prep.circle);
      stock_detail::FloorStats st;
      for (int k = 0; k < 3000; ++k) {
        const double px = 1 + 9 * U(rng), py = -2 + 9 * U(rng);
        const double c = stock_detail::arc_floor_closed(prep, p, px, py, kInf);
        const double s = stock_detail::arc_floor_search(prep, p, px, py, kInf, st);
        if (!std::isfinite(c) || !std::isfinite(s)) {
          EXPECT_EQ(std::isfinite(c), std::isfinite(s)) << px << "," << py;
          continue;
        }
        EXPECT_NEAR(c, s, 1e-10) << to_string(t.kind) << " at " << px << "," << py;
      }
      EXPECT_EQ(st.depth_limited, 0u) << to_string(t.kind);
    }
  }
}
