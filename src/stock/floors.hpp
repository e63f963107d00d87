#pragma once
// The floor a move leaves over one column: min over the move's parameter of
// z(t) + h(d(t)), d the column's horizontal distance to the tool's axis.
// Lines in closed form (bull: a convex minimisation to machine precision),
// G17 circles and helices of one radius in closed form (flat, ball, vee,
// drill), every other arc (spirals, G18/G19, bull) by a certified
// branch-and-bound over interval enclosures (docs/verify.md).
#include <cstdint>
#include <limits>

#include "bezcam/kernel/arc.hpp"
#include "bezcam/stock/tool_shape.hpp"

namespace bezcam::stock_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The tool's height as a function of the squared distance D = rho^2.
struct Profile {
  ToolShapeKind kind = ToolShapeKind::flat;
  double R = 0, R2 = 0;    // radius, radius squared
  double a0 = 0;           // bull: radius of the flat part (R - rc)
  double rc = 0, rc2 = 0;  // bull: corner radius
  double k = 0;            // vee, drill: slope 1 / tan(angle / 2)
  explicit Profile(const ToolShape& t);
  bool cone() const { return kind == ToolShapeKind::vee || kind == ToolShapeKind::drill; }
  double H(double D) const;   // h(sqrt(D)), D clamped to [0, R2]
  double H1(double D) const;  // dH/dD (may be +inf at the ends)
  double H2(double D) const;  // d2H/dD2
};

// Counters of the work done (benchmarks, docs): summed per thread.
struct FloorStats {
  std::uint64_t columns = 0;  // column evaluations (all paths)
  std::uint64_t generic_columns = 0;
  std::uint64_t generic_nodes = 0;  // intervals examined by the certified search
  std::uint64_t depth_limited = 0;  // intervals closed at the depth limit (ulp-wide)
};

struct LinePrep {
  double ax = 0, ay = 0, az = 0, bx = 0, by = 0, bz = 0;
  double vx = 0, vy = 0, L2 = 0, L = 0, invL2 = 0, nx = 0, ny = 0, dz = 0, m = 0;
  double zmin = 0;
  bool plunge = false;      // no horizontal motion
  bool horizontal = false;  // no vertical motion
};
LinePrep prepare_line(const Vec3& a, const Vec3& b);
// Floor of the line over column (px, py); +inf when the tool misses it.
double line_floor(const LinePrep& l, const Profile& p, double px, double py);
// The x-range of the row at y that the tool can reach (conservative by a
// rounding margin); false when it reaches none of the row.
bool line_row_range(const LinePrep& l, double R, double y, double& xlo, double& xhi);
// floors[i] = min(floors[i], floor at column i) for i in [i0, i1], column i's
// centre at x = x0 + (i + 0.5) * C.
void line_row(const LinePrep& l, const Profile& p, double y, double x0, double C, int i0, int i1, double* floors,
              FloorStats& st);

struct ArcPrep {
  Arc arc;
  int ix = 0, iy = 1, iz = 2;        // which plane coordinate (a, b, h) is world x, y, z
  double ca = 0, cb = 0;             // centre in the plane
  double th0 = 0, dir = 1, T = 0;    // start angle, direction (+1 ccw), sweep (rad)
  double r0 = 0, r1 = 0, eps = 0;    // radii at the ends, dr / dtau
  double h0 = 0, h1 = 0, kappa = 0;  // the plane's axis at the ends, dh / dtau
  bool circle = false;               // G17 and one radius: closed forms apply
  double rmin = 0, rmax = 0;
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0, zmin = 0;  // box of the tip's path
};
ArcPrep prepare_arc(const Arc& a);
// min(best, floor of the arc over column (px, py)).
double arc_floor(const ArcPrep& a, const Profile& p, double px, double py, double best, FloorStats& st);
// The same by the closed form (a.circle and not bull) and by the certified
// search (any arc), for the tests that compare them.
double arc_floor_closed(const ArcPrep& a, const Profile& p, double px, double py, double best);
double arc_floor_search(const ArcPrep& a, const Profile& p, double px, double py, double best, FloorStats& st);
bool arc_row_range(const ArcPrep& a, double R, double y, double& xlo, double& xhi);
void arc_row(const ArcPrep& a, const Profile& p, double y, double x0, double C, int i0, int i1, double* floors,
             FloorStats& st);

}  // namespace bezcam::stock_detail
