#pragma once
/// A circular arc in one of the three planes (G17 XY, G18 ZX, G19 YZ) as a
/// program prints it: start, end, centre, direction and plane. The one definition of the arc's sweep, its points,
/// its extent and its exact Bézier pieces, shared by the G-code reader, the
/// motion model, the program checks and the arc fitter.
///
/// Printed ends may sit at slightly different distances from the centre
/// (within a controller's arc tolerance); the path is then the spiral whose
/// radius runs linearly with the angle from the start's to the end's, as
/// LinuxCNC draws it. The plane's axis (Z in G17, Y in G18, X in G19) runs
/// linearly with the angle too (a helix when the ends differ).
///
/// The three planes are cyclic permutations of the axes: G17 (x, y, z),
/// G18 (z, x, y), G19 (y, z, x), the last being the plane's axis. In the
/// permuted coordinates (a, b, h) every plane is G17: G03 turns from a to b,
/// G02 the other way (RS274/NGC's rule, seen from the positive axis). One
/// implementation works in those plane coordinates.
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// The arc plane: G17, G18 or G19.
enum class Plane : unsigned char { xy = 0, zx = 1, yz = 2 };

/// The G number of the plane: 17, 18 or 19.
int g_number(Plane p);
/// World coordinates (x, y, z) to the plane's (a, b, h), h along its axis.
Vec3 to_plane(const Vec3& p, Plane pl);
/// Plane coordinates (a, b, h) back to world (x, y, z).
Vec3 from_plane(const Vec3& q, Plane pl);
/// Index (0 x, 1 y, 2 z) of the world axis that is the plane's k-th
/// coordinate (k = 0 a, 1 b, 2 the plane's axis).
int world_axis(Plane pl, int k);

/// A plane arc: from `from` to `to` around `center` (its coordinate along
/// the plane's axis is ignored).
struct Arc {
  Vec3 from, to, center;  ///< as printed (center = from + the centre words)
  bool ccw = true;        ///< G03 when true, G02 otherwise
  Plane plane = Plane::xy;

  /// Swept angle in (0, 2 pi], in the arc's direction; ends at the same XY
  /// position make a full circle (LinuxCNC, Grbl and Fanuc agree).
  double sweep() const;
  /// Angle of the start around the centre (atan2), in [-pi, pi].
  double start_angle() const;
  /// In-plane distance of the start and of the end from the centre.
  double r_start() const;
  double r_end() const;
  /// Point of the path at s in [0,1]: angle start_angle() + s * sweep() in
  /// the arc's direction, radius and axis linear in s; s <= 0 gives `from`
  /// and s >= 1 gives `to` exactly.
  Vec3 point(double s) const;
};

/// An arc's points at many parameters: Arc::point() with the centre, the
/// angles and the radii taken once (the same arithmetic, so the same
/// points bit for bit), for the loops that sample or search one arc.
class ArcPoints {
 public:
  explicit ArcPoints(const Arc& a);
  Vec3 at(double s) const;

 private:
  Vec3 from_, to_, c_;  // c_: the centre in plane coordinates
  double a0_ = 0, w_ = 0, r0_ = 0, r1_ = 0, z0_ = 0, z1_ = 0;
  bool ccw_ = true;
  Plane plane_ = Plane::xy;
};

/// Extent of the arc's path: both ends plus the points where the path
/// crosses an axis direction of its plane (0, 90, 180, 270 degrees) inside
/// the sweep.
Box3 arc_extent(const Arc& a);

/// The exact rational quadratic Bézier pieces (3D) of a planar arc, each of
/// at most 90 degrees, on the circle through `from` around `center` (exact
/// when `to` lies on it); the first piece starts at `from`, the last ends at
/// `to`. Precondition: the ends share their coordinate along the plane's
/// axis (helices have no such pieces).
std::vector<Bezier> bezier_pieces(const Arc& a);

}  // namespace bezcam
