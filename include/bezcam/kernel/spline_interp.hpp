#pragma once
/// Curves through given points (seeds digest §4): the natural cubic spline,
/// its closed (periodic) form, and the single Lagrange polynomial.
///
/// All are parametrised by chord length: t_0 = 0, t_{k+1} = t_k +
/// |Q_{k+1} - Q_k| (in model units), the classic choice that keeps the
/// parameter speed close to the arc length. The splines are built directly
/// as cubic B-splines whose knots are these parameters (The NURBS Book,
/// section 9.2.1, global interpolation, with the natural end conditions
/// C''(t_0) = C''(t_n) = 0 instead of given end tangents), so they are C2,
/// pass through every point, and decompose exactly into cubic Bézier
/// pieces, one per pair of neighbouring points.
#include <span>
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {

/// Chord-length parameters of the points. Throws InputError at `through[k]`
/// when point k repeats point k - 1 (a zero chord: no parameter can tell
/// them apart), or has a non-finite coordinate.
std::vector<double> chord_length_parameters(std::span<const Vec3> pts);

/// The natural C2 cubic spline through >= 2 points (2 points give the
/// segment), as a clamped cubic B-spline with knots t_0 (x4), t_1, ...,
/// t_{n-1}, t_n (x4). Throws InputError at `through` / `through[k]`.
NurbsCurve natural_cubic_spline(std::span<const Vec3> pts, int dim);

/// The clamped C2 cubic spline through >= 2 points with the end
/// derivatives `d0` at the first point and `dn` at the last, derivatives
/// with respect to the chord-length parameter (so a unit tangent runs at
/// the speed of the chords): the same B-spline as natural_cubic_spline()
/// with C'(t_0) = d0 and C'(t_n) = dn as end conditions. Throws InputError
/// at `through` / `through[k]`.
NurbsCurve clamped_cubic_spline(std::span<const Vec3> pts, const Vec3& d0, const Vec3& dn, int dim);

/// The piecewise cubic Hermite curve through >= 2 points with the given
/// derivatives (one per point; `closed` adds the piece from the last point
/// back to the first): piece i runs over its own t in [0, 1] from pts[i]
/// to pts[i+1] with derivatives tangents[i] and tangents[i+1] (the classic
/// Hermite basis), so its Bézier control points are pts[i],
/// pts[i] + tangents[i] / 3, pts[i+1] - tangents[i+1] / 3, pts[i+1]. C1.
/// Throws InputError at `through[k]` for a non-finite point or tangent.
std::vector<Bezier> hermite_pieces(std::span<const Vec3> pts, std::span<const Vec3> tangents, bool closed, int dim);

/// The periodic C2 cubic spline through >= 3 distinct points and back to
/// the first (the last point may repeat the first; it is then dropped), as
/// an unclamped cubic B-spline on [0, T] (T: the closed polygon's length)
/// whose last three control points repeat the first three. C2 at the
/// closing point too. Throws InputError at `through` / `through[k]`.
NurbsCurve periodic_cubic_spline(std::span<const Vec3> pts, int dim);

/// The polynomial of degree n through n + 1 points (2 <= n + 1 <= 65),
/// parameters normalised to [0, 1], in Bézier form (the Bernstein
/// collocation system, solved with full pivoting). Throws InputError at
/// `through` when the system is too ill-conditioned to pass through the
/// points within 1e-9 of their size (many points: use the cubic spline).
Bezier lagrange_polynomial(std::span<const Vec3> pts, int dim);

/// How far a curve leaves the bounding box of `pts` (0 when it stays
/// inside): the largest excess over the box on any axis, from the curve's
/// tight bounds. Runge's phenomenon makes a Lagrange polynomial through
/// many points overshoot badly.
double bounding_box_overshoot(std::span<const Bezier> curve, std::span<const Vec3> pts);

}  // namespace bezcam
