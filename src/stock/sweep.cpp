#include "bezcam/stock/sweep.hpp"

#include <cmath>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"

namespace bezcam {

namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw InputError(errc::stock_move, Place::at_setting("move"), what);
}

std::string str(const Vec3& p) { return "(" + fmt_num(p.x) + ", " + fmt_num(p.y) + ", " + fmt_num(p.z) + ")"; }

}  // namespace

Sweep Sweep::line(const Vec3& from, const Vec3& to) {
  if (!all_finite(from) || !all_finite(to)) refuse("a line's ends must be finite, not " + str(from) + " to " + str(to));
  Sweep s;
  s.kind_ = SweepKind::line;
  s.from_ = from;
  s.to_ = to;
  return s;
}

Sweep Sweep::arc(const Arc& a) {
  if (!all_finite(a.from) || !all_finite(a.to) || !all_finite(a.center))
    refuse("an arc's ends and centre must be finite, not " + str(a.from) + " to " + str(a.to) + " around " +
           str(a.center));
  if (!(a.r_start() > 0) || !(a.r_end() > 0))
    refuse("an arc's ends must lie off its centre " + str(a.center) + " (G" + std::to_string(g_number(a.plane)) +
           "): " + str(a.from) + " to " + str(a.to));
  Sweep s;
  s.kind_ = SweepKind::arc;
  s.arc_ = a;
  s.from_ = a.from;
  s.to_ = a.to;
  return s;
}

Sweep Sweep::polyline(std::vector<Vec3> points, double bound) {
  if (points.empty()) refuse("a polyline needs at least one point");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!all_finite(points[i])) refuse("a polyline's point " + std::to_string(i) + " is not finite: " + str(points[i]));
  if (!std::isfinite(bound) || bound < 0)
    refuse("a polyline's bound must be a finite number >= 0, not " + fmt_num(bound));
  Sweep s;
  s.kind_ = SweepKind::polyline;
  s.from_ = points.front();
  s.to_ = points.back();
  s.points_ = std::move(points);
  s.bound_ = bound;
  return s;
}

Sweep Sweep::curve(std::span<const Bezier> pieces, double tolerance) {
  if (pieces.empty()) refuse("a curve needs at least one piece");
  FlattenOptions opt;
  opt.tolerance = tolerance;
  const FlattenResult f = flatten(pieces, opt);
  return polyline(f.points, f.bound);
}

Box3 Sweep::extent() const {
  Box3 b;
  switch (kind_) {
    case SweepKind::line:
      b.add(from_);
      b.add(to_);
      break;
    case SweepKind::arc: {
      // arc_extent() holds the ends and the axis crossings; the radius runs
      // between the ends' radii, so the spiral's extreme may lie up to their
      // difference beyond the crossing points.
      b = arc_extent(arc_);
      const double dr = std::abs(arc_.r_end() - arc_.r_start());
      for (int k = 0; k < 2; ++k) {
        const int w = world_axis(arc_.plane, k);
        b.lo[w] -= dr;
        b.hi[w] += dr;
      }
      break;
    }
    case SweepKind::polyline:
      for (const Vec3& p : points_) b.add(p);
      break;
  }
  return b;
}

}  // namespace bezcam
