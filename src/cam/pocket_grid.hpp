#pragma once
// Internal to cam: the square grid of samples the pocket certificate
// (pocket_check.hpp) and the planner's search for material left read.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "bezcam/cam/pocket_check.hpp"

namespace bezcam::detail {

/// A straight piece of the tool centre's path.
struct Piece {
  Vec3 a, b;
  bool rapid = false;
  size_t move = 0;      ///< the move it comes from
  bool measure = true;  ///< engagement: read along it (else it only removes material)
  double bulge = 0;     ///< a chord of an arc: the arc lies within this of it (its sagitta)
};

/// The point of the segment ab nearest p in XY (z = 0).
Vec3 segment_point(const Vec3& p, const Vec3& a, const Vec3& b);
/// Distance from p to the segment ab in XY.
double point_segment(const Vec3& p, const Vec3& a, const Vec3& b);

/// Samples at the centres of `cell` x `cell` squares covering the loops'
/// bounds (plus a cell); the cell grows until there are at most
/// `max_cells`.
struct PocketGrid {
  PocketGrid(const PocketLoops& bounds, double cell, size_t max_cells);
  double cell = 0, x0 = 0, y0 = 0;
  long nx = 0, ny = 0;
  size_t size() const { return static_cast<size_t>(nx * ny); }
  Vec3 sample(size_t k) const;
  /// 1 for the samples inside the loops (even-odd), 0 elsewhere.
  std::vector<uint8_t> fill(const PocketLoops& loops) const;
  /// 1 for the samples inside the loops (even-odd) or within `radius` of
  /// them: the loops' area grown by `radius`, exactly (the reach of a disk
  /// whose centre stays in the area).
  std::vector<uint8_t> fill_within(const PocketLoops& loops, double radius) const;
  /// Sets `v` on every sample within `radius` of the segment ab.
  void stamp(const Vec3& a, const Vec3& b, double radius, std::vector<uint8_t>& bits, uint8_t v) const;
  /// The points within `radius` of the segment ab, with what each row's
  /// span needs that does not change from row to row.
  struct Capsule {
    Capsule(const Vec3& a_, const Vec3& b_, double r) : a(a_), b(b_), radius(r) {
      dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy, l = std::sqrt(l2), r2 = r * r;
      along0 = (-a.x) * dx, across0 = (-a.x) * -dy;
      if (l2 > 0) along1 = dx / l2, across1 = -dy / l;
    }
    Vec3 a, b;
    double radius, dx = 0, dy = 0, l2 = 0, l = 0;
    double r2 = 0, along0 = 0, across0 = 0, along1 = 0, across1 = 0;
  };
  /// The rows (first, last) the capsule's samples may lie on.
  std::pair<long, long> rows(const Capsule& c) const;
  /// The capsule's samples on row j: columns from first to last (first
  /// above last when none).
  std::pair<long, long> span(const Capsule& c, long j) const {
    const double y = y0 + (static_cast<double>(j) + 0.5) * cell;
    // The capsule meets the row in one interval: the union of the end
    // disks and the band along the segment.
    double lo = 1e300, hi = -1e300;
    disk(c.a, c.r2, y, lo, hi);
    disk(c.b, c.r2, y, lo, hi);
    if (c.l2 > 0) {
      double blo = -1e300, bhi = 1e300;
      clip((c.along0 + (y - c.a.y) * c.dy) / c.l2, c.along1, 0, 1, blo, bhi);
      clip((c.across0 + (y - c.a.y) * c.dx) / c.l, c.across1, -c.radius, c.radius, blo, bhi);
      if (blo <= bhi) lo = std::min(lo, blo), hi = std::max(hi, bhi);
    }
    if (lo > hi) return {0, -1};
    return {std::max(0L, static_cast<long>(std::ceil((lo - x0) / cell - 0.5))),
            std::min(nx - 1, static_cast<long>(std::floor((hi - x0) / cell - 0.5)))};
  }
  /// The 4-connected pieces of set samples of at least `min` samples: a
  /// sample of each (the one farthest from the piece's edge) and its count,
  /// largest first.
  std::vector<std::pair<Vec3, size_t>> components(const std::vector<uint8_t>& bits, size_t min) const;
  /// Each sample's distance to the nearest set sample: the 8-connected
  /// chamfer distance, at least the Euclidean one and at most 1.09 times it.
  std::vector<double> distance(const std::vector<uint8_t>& bits) const;
  /// The samples within `d` of a set sample by that distance.
  std::vector<uint8_t> dilated(const std::vector<uint8_t>& bits, double d) const;
  /// The engagement read along the pieces in order against `material`
  /// (copied; cleared as the tool sweeps it): the largest angle (degrees)
  /// and where; the largest at positions not `in_zone` (corners sharper
  /// than the tool) and where; and the positions in the zone above
  /// `limit`, at most one per 2 r (the largest).
  struct Engagement {
    double deg = 0, away_deg = 0;
    Vec3 at, away_at;
    std::vector<std::pair<double, Vec3>> zone_over;
  };
  Engagement engagement(const std::vector<Piece>& pieces, double r, std::vector<uint8_t> material,
                        const std::function<bool(const Vec3&)>& in_zone, double limit) const;

 private:
  // The x where the linear function c0 + c1 x satisfies lo <= f <= hi,
  // intersected into [x_lo, x_hi].
  static void clip(double c0, double c1, double lo, double hi, double& x_lo, double& x_hi) {
    if (c1 == 0) {
      if (c0 < lo || c0 > hi) x_lo = 1, x_hi = 0;
      return;
    }
    double u = (lo - c0) / c1, v = (hi - c0) / c1;
    if (u > v) std::swap(u, v);
    x_lo = std::max(x_lo, u), x_hi = std::min(x_hi, v);
  }
  // Widens [lo, hi] by where the disk of radius sqrt(r2) about c meets the line y.
  static void disk(const Vec3& c, double r2, double y, double& lo, double& hi) {
    const double h = r2 - (y - c.y) * (y - c.y);
    if (h < 0) return;
    const double w = std::sqrt(h);
    lo = std::min(lo, c.x - w), hi = std::max(hi, c.x + w);
  }
};

}  // namespace bezcam::detail
