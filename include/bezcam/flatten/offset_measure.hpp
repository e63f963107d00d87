#pragma once
/// Measuring an offset path, independently of the code that built it
/// (offset.hpp): how far each point of a printed path lies from the true
/// curve, and how much material it leaves where its tool reaches the part.
///
/// The curve and the path are each sampled on their own (adaptive
/// subdivision, samples on them, chords within a quarter of the
/// resolution) and indexed. The polylines say where the extremes lie: the
/// smallest distance is found per path chord (its nearest approach to the
/// curve's chords); the largest at path points, a chord halved (at the
/// middle of its stretch of the path) only while no single curve chord
/// proves it holds nothing farther (the distance to one chord is convex
/// along a line) and it is longer than 2 resolutions. The extremes are then
/// read again exactly: the distance from a point of the printed path to
/// the nearest point of the curve (or from a point of the curve to the
/// nearest point of the path), minimised on the pieces near it. So every
/// reading is a distance between two real points, to rounding: the largest
/// distance never reads above the true largest, the smallest never below
/// the true smallest, the material left never above the true one, whatever
/// the resolution, which decides only how near the true extreme the read
/// point lies (about the resolution).
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "bezcam/kernel/arc.hpp"
#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct OffsetReading {
  double min_distance = 0;  ///< smallest distance of a path point from the curve
  double max_distance = 0;  ///< largest
  /// How much material the path leaves where its tool reaches the part:
  /// the largest dist(c, path) - r over the curve's points c whose tool
  /// position c + (r + middle) normal (on the side) is not folded away, i.e.
  /// is no nearer than r + middle to the whole curve (to rounding), and on
  /// the tool's side of a closed curve; 0 when there is none. A stretch of
  /// the path missing, or cut short of a corner, shows here.
  double coverage = 0;
  /// The reading against r: max(|min - r|, |max - r|, coverage).
  double deviation(double r) const;
};

struct OffsetMeasure {
  double r = 0;  ///< the tool's offset from the curve
  int side = 0;  ///< +1 left, -1 right of the curve's direction (where the tool is); 0: no coverage
  /// Where the band of a one-sided tolerance has its middle, less r (half
  /// the tolerance away from the part with "waste"): the tool reaches
  /// where the offset at r + middle is not folded away. 0 for a two-sided band.
  double middle = 0;
  double resolution = 0;  ///< the sampling of the curve and of the path
  bool distances = true;  ///< false: coverage only (min and max read r)
};

/// One piece of a printed path as the controller draws it, in XY: a Bézier
/// piece (a line is one of degree 1; exact-curve blocks), or a printed arc
/// (its radius may run from the start's to the end's, Arc::point()).
struct PathPiece {
  Bezier curve;
  std::optional<Arc> arc;
  static PathPiece line(const Vec3& a, const Vec3& b);
  static PathPiece of(const Bezier& b);
  static PathPiece of(const Arc& a);
};

/// `path`: the printed path, its pieces in order; a piece need not start
/// where the one before ends (the separate stretches of the offset of a
/// part that falls apart where it narrows): the distances of every
/// stretch, and the material left by all of them together. `curves`:
/// several curves may make one part (the distances are to all of them; the
/// coverage is read along the first).
OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const PathPiece> path,
                             const OffsetMeasure& how);
/// The same for a path given as polylines (each chord a line), one per
/// separate stretch.
OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const std::vector<Vec3>> paths,
                             const OffsetMeasure& how);
/// The same for a path in one stretch.
OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const Vec3> path,
                             const OffsetMeasure& how);

/// Distances to a part read as measure_offset() reads them, the part
/// sampled once for many questions (the curves must outlive it).
class PartDistance {
 public:
  PartDistance(std::span<const std::vector<Bezier>> curves, double resolution);
  ~PartDistance();
  PartDistance(const PartDistance&) = delete;
  PartDistance& operator=(const PartDistance&) = delete;
  /// The point of the curves nearest to p.
  Vec3 nearest(const Vec3& p);
  /// The smallest distance of the path from the curves (HUGE_VAL for no path).
  double min_distance(std::span<const PathPiece> path);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bezcam
