#pragma once
/// Measuring, not assuming: the two-sided distance between true Bézier
/// pieces and a polyline, computed independently of the flattener (its
/// chords, its bound and its vertices' parameters are not used; vertices
/// may stand anywhere, on the curve or off it).
///
/// Each direction is a branch and bound over intervals:
/// - curve -> polyline: arcs of each piece (a coarse grid, then halves).
///   Each end is read against the nearest segment found (a descent from
///   the segment of the point before). Over the arc, the distance is at
///   most the lower of the two ends' segments' distances interpolated
///   along the chord (convex there), plus the arc's sag: for polynomial
///   pieces up to degree 3, h^2 / 8 max |C''| spread as the parabola
///   4 s l (1 - l) over the arc's fraction l; otherwise (rational pieces,
///   degree > 3) the sub-curve's control polygon's distance from its chord
///   (a rational quadratic's: w d / (1 + w), d its middle point's, w its
///   normalised middle weight), the sub-curve split on the stack by a
///   homogeneous de Casteljau cascade (no allocation below degree 16).
/// - polyline -> curve: stretches of each segment (two per segment, then
///   halves). Each end is read against a foot on the curve (Newton steps
///   from a neighbour's foot, along the pieces, over a corner to the next
///   piece when the distance falls along it). Over the stretch, the
///   distance is at most the interpolated ends' distances plus the sag of
///   the curve between the two feet (and never more than it can change
///   moving along the segment).
/// An interval whose bound is within kMeasureGap x tolerance of the
/// largest reading so far is done; others are halved (at most 60 times;
/// one still open then counts with its bound).
///
/// Accuracy: each reading is a distance to a real point (of the polyline
/// or of the curve), so never below the true distance there; the largest
/// one is read again by an exact search (every segment; a branch and bound
/// over every piece), and where that is lower the search runs again with
/// that true distance as its floor and every reading above it taken
/// exactly, so that its largest reading is a true distance. Any reading
/// above the tolerance is exact from the start. So each of the two results is within kMeasureGap
/// x tolerance of the true distance (never finer than 1e-14 of the control
/// points' magnitude; below it by at most the bounds' gap, above it by at
/// most a foot's last Newton step, far less): a flattening that is over
/// the tolerance by more than that reads over it. On the flattener test's
/// hard curves a reading was seen 5e-6 x tolerance below a brute force:
/// that was the brute force's error, not a loose bound here. It reads
/// path -> curve against a chain of 20,000 chords of the curve, and a
/// point outside a convex stretch is farther from its chords than from
/// it, by up to the chain's sag (2.4e-5 x tolerance on that cusp); against
/// nearest points refined on the curve the reading agrees to 1e-10 x
/// tolerance (deviation_test.cpp, AgreesWithTheTrueDistanceOnHardCurves).
/// The accuracy stated for callers stays the coarser kMeasureResolution.
#include <span>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct Deviation {
  double curve_to_path = 0;  ///< max over curve points of distance to the polyline
  double path_to_curve = 0;  ///< max over polyline points of distance to the curve
  double max() const { return curve_to_path > path_to_curve ? curve_to_path : path_to_curve; }
};

/// Share of the `tolerance` argument that measure_deviation() is accurate
/// to, stated coarsely: callers sample printed arcs into chords at a tenth
/// of it (src/cam/measure_path.hpp). The readings are finer (kMeasureGap).
inline constexpr double kMeasureResolution = 1e-3;

/// Share of the `tolerance` argument at which the search stops (an
/// interval whose bound is this near the largest reading is done).
inline constexpr double kMeasureGap = 1e-6;

/// `tolerance`: the bound being checked. Readings above it are true
/// distances; see the accuracy above.
Deviation measure_deviation(std::span<const Bezier> pieces, std::span<const Vec3> polyline, double tolerance);

}  // namespace bezcam
