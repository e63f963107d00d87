#pragma once
// Internal to cam: areas bounded by polygons (outline, islands, pockets in
// islands) and their offsets, over Boost.Geometry (docs/pocket.md).
#include <memory>
#include <vector>

#include "bezcam/cam/pocket_check.hpp"

namespace bezcam::detail {

class Area {
 public:
  Area();
  /// From closed loops, even-odd.
  explicit Area(const PocketLoops& loops);
  /// Eroded by d (> 0; < 0 grows), within 2 `sag` of the true offset: round
  /// corners drawn as chords within `sag` of their arcs, the loops
  /// simplified within `sag` first.
  Area eroded(double d, double sag) const;
  PocketLoops loops() const;
  /// The connected pieces.
  std::vector<Area> pieces() const;
  bool empty() const;
  double area() const;
  /// The closed boundary rings: each piece's outer ring, then its holes.
  std::vector<std::vector<Vec3>> rings() const;
  /// Whether the segment, the closed polygon or the point lies in the area
  /// (its boundary included).
  bool covers(const Vec3& a, const Vec3& b) const;
  bool covers_polygon(const std::vector<Vec3>& closed) const;
  bool covers(const Vec3& p) const;

  struct Impl;

 private:
  explicit Area(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace bezcam::detail
