#pragma once
/// The tool-centre path at distance r from a planar curve, with a proven
/// bound (docs/offset.md).
///
/// Method (bezcam's own):
///  1. The curve C is replaced by an arc spline A (arcs and lines, fit_arcs()
///     without rounding) whose two-sided distance to C is at most `fit`.
///  2. Every primitive of A is offset exactly: a line by a parallel line, an
///     arc by the concentric arc of radius R -/+ r (an arc tighter than the
///     tool turns inside out and is clipped in step 4).
///  3. Where consecutive offsets do not meet (a corner, or the small kink
///     between two fitted arcs), they are joined by an arc of radius r about
///     the joint: the tool rolls round the corner.
///  4. The raw path is cut at all its self-intersections; a piece is kept
///     when its points are at distance >= r from every primitive of A (it is
///     at exactly r from its own). What is left chains into the path; what
///     was cut away from a primitive's offset marks part of the curve the
///     tool cannot reach (material left).
/// Every kept point p has dist(p, A) = r, and since A and C are within `fit`
/// of each other both ways, | dist(p, C) - r | <= fit (+ the floating-point
/// margin the validity test allows, in `bound`).
#include <span>
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// A line or a circular arc in the XY plane, travelled from `a` to `b`.
struct ArcSeg {
  bool arc = false;
  Vec3 a, b;          ///< ends (exact: point(0) == a, point(1) == b)
  Vec3 c;             ///< arcs: centre
  double radius = 0;  ///< arcs
  double a0 = 0;      ///< arcs: angle of `a` about `c`
  double sweep = 0;   ///< arcs: signed swept angle (counter-clockwise > 0)

  static ArcSeg line(const Vec3& a, const Vec3& b);
  /// Arc from `a` about `c` through the signed `sweep`, ending at `b`.
  static ArcSeg make_arc(const Vec3& a, const Vec3& b, const Vec3& c, double sweep);
  Vec3 point(double s) const;
  /// Unit direction of travel at s.
  Vec3 tangent(double s) const;
  double length() const;
  /// The same path travelled from b to a.
  ArcSeg reversed() const;
  /// The part on [s0, s1] (s0 < s1).
  ArcSeg sub(double s0, double s1) const;
};

/// Distance from p to the segment or arc.
double distance(const ArcSeg& s, const Vec3& p);
/// Parameters (on `p`, on `q`) where the two cross, both in [0, 1].
std::vector<std::pair<double, double>> intersections(const ArcSeg& p, const ArcSeg& q);

/// The exact Bézier pieces of a chain: lines of degree 1, arcs as rational
/// quadratic pieces of at most 90 degrees (standard form, end weights 1).
std::vector<Bezier> bezier_pieces(std::span<const ArcSeg> chain);

struct OffsetOptions {
  double distance = 0;  ///< r > 0
  int side = 1;         ///< +1: left of the direction of travel, -1: right
  double fit = 0.005;   ///< how close the arc spline A follows the curve (two-sided)
  /// A in tangent chains (ArcFitOptions::tangent): its arcs meet
  /// tangentially, so their offsets meet with no joint arc between them
  /// (a few more arcs; the path turns smoothly where a controller's
  /// planner would slow at each small joint).
  bool tangent = false;
};

/// A stretch of the curve the tool cannot touch (a bend tighter than the
/// tool, an inner corner, a gap narrower than the tool): material is left
/// there.
struct MaterialLeft {
  Vec3 from, to;      ///< on the curve (its arc spline)
  double length = 0;  ///< of the stretch along the curve
  /// How far the curve stands from the tool's reach there (its distance
  /// from the path less r, at sampled points): what a finishing tool
  /// would still have to take.
  double depth = 0;
  std::vector<Vec3> points;  ///< along the stretch (from, inner points, to), for drawing
};

struct OffsetResult {
  std::vector<std::vector<ArcSeg>> chains;  ///< in the curve's direction
  std::vector<bool> closed;
  /// Proven: every point of every chain is within [r - bound, r + bound] of
  /// the curve.
  double bound = 0;
  std::vector<MaterialLeft> left;
  size_t fitted = 0;  ///< primitives of the arc spline A
};

/// Offsets the planar curve (pieces end to end; `closed`: the last ends where
/// the first starts).
OffsetResult offset_curve(std::span<const Bezier> pieces, bool closed, const OffsetOptions& opt);

/// The signed area the closed curve bounds (> 0: counter-clockwise), from
/// a fine flattening; for orientation only.
double signed_area(std::span<const Bezier> pieces);

}  // namespace bezcam
