#pragma once
/// A curve entity as the rest of bezcam sees it: the exact decomposition into
/// Bézier pieces, end to end, whatever the source form was (a Bézier, a
/// B-spline, an interpolating spline or a path of several of these).
#include <memory>
#include <string>
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct NurbsCurve;  // bezcam/kernel/nurbs_curve.hpp

/// Continuity where two pieces meet, weakest to strongest. G1 = tangent
/// directions agree; C1 = first derivatives equal; C2 = second too.
enum class Continuity { none, C0, G1, C1, C2 };
const char* to_string(Continuity c);

/// Continuity at the joint between the end of `a` and the start of `b`;
/// `tol` is the distance within which end points count as meeting.
Continuity joint_continuity(const Bezier& a, const Bezier& b, double tol);

/// One source segment of a curve entity (a path has several).
struct CurveSegment {
  std::string kind;  ///< "bezier", "bspline", ...
  int degree = 0;
  bool rational = false;
  size_t first_piece = 0;  ///< index into CurveGeometry::pieces
  size_t piece_count = 0;
  /// The segment as a B-spline/NURBS, for exact output (knots as given, so
  /// possibly unclamped: see clamp() in nurbs_curve.hpp). Set for `bspline`
  /// segments and cubic-spline `interpolate` entities; null for Bézier
  /// segments (their pieces are the exact form). `pieces` always holds the
  /// same curve, decomposed.
  std::shared_ptr<const NurbsCurve> nurbs;
};

struct CurveGeometry {
  std::string kind;  ///< entity type: bezier, bspline, interpolate, path
  int dim = 2;
  bool closed = false;
  std::vector<Bezier> pieces;  ///< exact, end to end
  std::vector<CurveSegment> segments;
  std::vector<Continuity> joints;  ///< segments.size() - 1 entries (+1 when closed)

  int max_degree() const;
  bool rational() const;
  double length() const;
  Box3 bounds() const;
};

/// Builds the geometry of a path from its segments' pieces, checking that
/// each segment starts where the previous ended (within 1e-9 of the
/// coordinate magnitude); throws InputError naming `segments[i]` otherwise.
/// Computes the continuity at every joint.
CurveGeometry make_path(std::vector<CurveSegment> segs, std::vector<Bezier> pieces, bool closed, int dim);

/// Geometry of a single segment.
CurveGeometry make_single(CurveSegment seg, std::vector<Bezier> pieces, int dim);

}  // namespace bezcam
