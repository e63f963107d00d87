#pragma once
/// A circular arc in the XY plane (G17) as a program prints it: start, end,
/// centre and direction. The one definition of the arc's sweep, its points,
/// its extent and its exact Bézier pieces, shared by the G-code reader, the
/// motion model, the program checks and the arc fitter.
///
/// Printed ends may sit at slightly different distances from the centre
/// (within a controller's arc tolerance); the path is then the spiral whose
/// radius runs linearly with the angle from the start's to the end's, as
/// LinuxCNC draws it. Z runs linearly too (a helix when the ends differ).
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// A G17 arc: from `from` to `to` around `center` (its z is ignored).
struct Arc {
  Vec3 from, to, center;  ///< as printed (center = from + I/J)
  bool ccw = true;        ///< G03 when true, G02 otherwise

  /// Swept angle in (0, 2 pi], in the arc's direction; ends at the same XY
  /// position make a full circle (LinuxCNC, Grbl and Fanuc agree).
  double sweep() const;
  /// Angle of the start around the centre (atan2), in [-pi, pi].
  double start_angle() const;
  /// XY distance of the start and of the end from the centre.
  double r_start() const;
  double r_end() const;
  /// Point of the path at s in [0,1]: angle start_angle() + s * sweep() in
  /// the arc's direction, radius and z linear in s; s <= 0 gives `from`
  /// and s >= 1 gives `to` exactly.
  Vec3 point(double s) const;
};

/// Extent of the arc's path: both ends plus the points where the path
/// crosses an axis direction (0, 90, 180, 270 degrees) inside the sweep.
Box3 xy_box(const Arc& a);

/// The exact rational quadratic Bézier pieces (3D) of a planar arc, each of
/// at most 90 degrees, on the circle through `from` around `center` (exact
/// when `to` lies on it); the first piece starts at `from`, the last ends at
/// `to`. Precondition: from.z == to.z (helices have no such pieces).
std::vector<Bezier> bezier_pieces(const Arc& a);

}  // namespace bezcam
