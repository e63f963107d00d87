#pragma once
// Internal to cam: the square grid of samples the pocket certificate
// (pocket_check.hpp) and the planner's search for material left read.
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
};

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
  /// Sets `v` on every sample within `radius` of the segment ab.
  void stamp(const Vec3& a, const Vec3& b, double radius, std::vector<uint8_t>& bits, uint8_t v) const;
  /// The points within `radius` of the segment ab.
  struct Capsule {
    Capsule(const Vec3& a_, const Vec3& b_, double r)
        : a(a_), b(b_), radius(r), l2((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y)), l(std::sqrt(l2)) {}
    Vec3 a, b;
    double radius, l2, l;
  };
  /// The rows (first, last) the capsule's samples may lie on.
  std::pair<long, long> rows(const Capsule& c) const;
  /// The capsule's samples on row j: columns from first to last (first
  /// above last when none).
  std::pair<long, long> span(const Capsule& c, long j) const;
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
};

}  // namespace bezcam::detail
