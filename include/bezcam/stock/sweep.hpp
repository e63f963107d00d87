#pragma once
/// A move of the tool's tip to sweep through the stock: a line, an arc or
/// helix (G17, G18 or G19), or a polyline that stands for a curve within a
/// proven bound.
///
/// Coordinates are the tool tip's, in the stock's unit (millimetres for the
/// verifier). An arc is the kernel's Arc (bezcam/kernel/arc.hpp): its path is
/// the one the G-code reader and the motion model follow, the angle running
/// from the start's around the centre in the arc's direction, the radius
/// linearly from the start's to the end's (the spiral of an arc whose
/// printed ends sit at slightly different radii) and the plane's axis
/// linearly (a helix).
///
/// A polyline's `bound` is the largest distance between the path it stands
/// for and the polyline (both ways, e.g. the certified bound of bezcam's
/// flattening). The floors are exact for the polyline; the machined surface
/// of the true path lies within `bound` of them (the grid reports the largest
/// bound swept as added error).
#include <span>
#include <vector>

#include "bezcam/kernel/arc.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

enum class SweepKind { line, arc, polyline };

class Sweep {
 public:
  /// A straight move from `from` to `to` (a plunge when only z changes, a
  /// move of length 0 when equal). Refuses coordinates that are not finite
  /// (InputError `stock.move`, setting `move`).
  static Sweep line(const Vec3& from, const Vec3& to);
  /// An arc or helix. Refuses coordinates that are not finite and ends that
  /// sit on the centre (no radius), InputError `stock.move`.
  static Sweep arc(const Arc& a);
  /// A polyline through `points` (at least one) standing for a path within
  /// `bound` (finite, >= 0). InputError `stock.move` otherwise.
  static Sweep polyline(std::vector<Vec3> points, double bound);
  /// Exact curve pieces (3D Bézier, end to end) swept along bezcam's
  /// certified flattening within `tolerance`: a polyline whose bound is the
  /// flattening's proven bound (flatten_curve.hpp).
  static Sweep curve(std::span<const Bezier> pieces, double tolerance);

  SweepKind kind() const { return kind_; }
  /// Line: its ends; arc: the arc's ends; polyline: its first and last point.
  const Vec3& from() const { return from_; }
  const Vec3& to() const { return to_; }
  /// The arc (kind() == arc).
  const Arc& arc() const { return arc_; }
  /// The polyline's points (kind() == polyline).
  const std::vector<Vec3>& points() const { return points_; }
  /// The polyline's bound; 0 for lines and arcs (swept exactly).
  double bound() const { return bound_; }
  /// Box of the tip's path (arcs: every point of the spiral or helix).
  Box3 extent() const;

 private:
  SweepKind kind_ = SweepKind::line;
  Vec3 from_, to_;
  Arc arc_;
  std::vector<Vec3> points_;
  double bound_ = 0;
};

}  // namespace bezcam
