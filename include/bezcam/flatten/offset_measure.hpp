#pragma once
/// Measuring an offset path, independently of the code that built it
/// (offset.hpp): how far each point of a printed path lies from the true
/// curve, and whether every point of the true offset is reached.
///
/// The curve is sampled densely on its own (adaptive subdivision, samples
/// on the curve, chords within `resolution`); distances are taken to that
/// polyline through an index of its segments. The smallest distance of the
/// path is exact against it (each path segment's nearest approach); the
/// largest is read at path points, a segment halved only while no single
/// curve segment proves it holds nothing farther (the distance to one
/// segment is convex along a line) and it is longer than 2 `resolution`.
/// Readings are accurate to about `resolution`.
#include <span>
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct OffsetReading {
  double min_distance = 0;  ///< smallest distance of a path point from the curve
  double max_distance = 0;  ///< largest
  /// How much material the path leaves where its tool reaches the part:
  /// the largest dist(c, path) - r over the curve's points c whose tool
  /// position c + (r + middle) normal (on the side) is not folded away, i.e.
  /// is at least r + middle from the whole curve (less the resolution); 0
  /// when there is none. A stretch of the path missing, or cut short of a
  /// corner, shows here.
  double coverage = 0;
  /// The reading against r: max(|min - r|, |max - r|, coverage).
  double deviation(double r) const;
};

struct OffsetMeasure {
  double r = 0;     ///< the tool's offset from the curve
  int side = 0;     ///< +1 left, -1 right of the curve's direction (where the tool is); 0: no coverage
  /// Where the band of a one-sided tolerance has its middle, less r (half
  /// the tolerance away from the part with "waste"): the tool reaches
  /// where the offset at r + middle is not folded away. 0 for a two-sided band.
  double middle = 0;
  double resolution = 0;   ///< the curve's sampling and the readings' accuracy
  bool distances = true;   ///< false: coverage only (min and max read r)
};

/// `paths`: the printed path as dense polylines (XY), one per separate
/// stretch (the offset of a part that falls apart where it narrows): the
/// distances of every stretch, and the material left by all of them
/// together. `curves`: several curves may make one part (the distances are
/// to all of them; the coverage is read along the first).
OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const std::vector<Vec3>> paths,
                             const OffsetMeasure& how);
/// The same for a path in one stretch.
OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const Vec3> path,
                             const OffsetMeasure& how);

}  // namespace bezcam
