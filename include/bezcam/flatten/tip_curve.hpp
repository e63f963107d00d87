#pragma once
/// Tool-tip curves on surfaces: flattened with a proven bound, and measured.
///
/// The tool tip follows tip(t) = P(t) + r (N(t) - z) along an exact curve
/// P on the surface (an iso-parameter pass, a border, a mapped (u, v)
/// curve), N the oriented unit normal, r the ball radius; r = 0 means the
/// tip follows the surface.
///
/// Bound for r = 0: the curve is exact Bézier pieces; flatten_pieces()
/// (flatten_curve.hpp) proves the bound, rounding included.
///
/// Bound for r > 0 (tip curves are not polynomial): on a parameter
/// interval mapped to s in [0,1], the chord from tip(0) to tip(1) and the
/// linear interpolant L(s) satisfy |tip(s) - L(s)| <= max|tip''| / 8
/// (apply the scalar interpolation error bound s(1-s)/2 max|f''| to
/// f = <e, tip - L>, e the unit vector of the error at s). Every point of
/// the curve is that close to a chord point and every chord point L(s) that
/// close to a curve point, so the two-sided distance is bounded. max|tip''|
/// <= max|P''| + r max|N''|, and every term is bounded rigorously from the
/// Bézier control points of the exact sub-curves of P and of the exact
/// polynomial normal direction n (N = n / |n|):
///   |N''| <= sqrt((|n''|/s + 2|n'|^2/s^2)^2 + (|n'|^2/s^2)^2), s = min|n|,
/// (from n = |n| N: the part of N'' across N is (n'' - 2|n|' N')/|n| minus
/// its N component, and <N'', N> = -|N'|^2, |N'| <= |n'|/|n|); max |n'|,
/// |n''| are n's hodograph control points' largest norms, min|n| the least
/// projection of n's control points on n(mid)'s direction (convex hull).
/// Rational P: P'' = (H'' - w''(P-c) - 2w'P')/w with H = w(P - c) bounded
/// the same way. Rounding of the vertices adds its displacement, as for
/// curves.
#include <span>
#include <vector>

#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/kernel/surface.hpp"

namespace bezcam {

/// The tool tip at the curve's parameter t. Throws InputError
/// ("surface.normal-undefined", naming u and v) when r > 0 and the normal
/// vanishes there.
Vec3 tip_point(const SurfaceCurve& c, double radius, double t);

/// Upper bound of the two-sided distance between the tip curve of one
/// piece (exact point piece, exact normal direction piece or null when
/// r = 0) on [t0, t1] and its chord; +infinity when the normal may vanish.
double tip_chord_bound(const Bezier& point, const Bezier* normal, double radius, double t0, double t1);

/// A flattened tip curve.
struct TipPolyline {
  std::vector<Vec3> points;    ///< vertices as printed (rounded)
  std::vector<double> params;  ///< the curve parameter each vertex came from
  double bound = 0;            ///< proven bound of the two-sided distance to the tip curve
};

/// Flattens the tip curve within opt.tolerance after rounding to
/// opt.decimals. Throws InputError when the decimals cannot honour the
/// tolerance, or when the normal vanishes on the curve (r > 0).
TipPolyline flatten_tip(const SurfaceCurve& c, double radius, const FlattenOptions& opt);

/// Measures the two-sided distance between the tip curve and a polyline
/// from flatten_tip(), independently of the bound: true curve points are
/// evaluated along each polyline segment's parameter range and the extremes
/// refined by golden-section search (parameters found to about 1e-10).
Deviation measure_tip(const SurfaceCurve& c, double radius, const TipPolyline& p);

}  // namespace bezcam
