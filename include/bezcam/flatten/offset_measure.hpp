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
  /// Largest distance from a point of the true offset (curve point + r on
  /// the side, where that point is at least r - tolerance from the whole
  /// curve, i.e. not folded away) to the path.
  double coverage = 0;
  /// The reading against r: max(|min - r|, |max - r|, coverage).
  double deviation(double r) const;
};

/// `path`: the printed path as a dense polyline (XY). `side`: +1 left, -1
/// right of the curve's direction (the side the true offset is on); 0: do
/// not measure coverage. `curves`: several curves may make one part (the
/// distances are to all of them). `distances` false: coverage only (min
/// and max read r).
OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const Vec3> path, double r,
                             int side, double tolerance, double resolution, bool distances = true);

}  // namespace bezcam
