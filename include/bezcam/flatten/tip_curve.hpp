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
#include <functional>
#include <optional>
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

/// The tip curve as Bézier pieces that follow it in the same parameter, for
/// exact-curve output. With r = 0 (or no normals) the pieces are the curve's
/// own (bound 0). With r > 0, on each piece (split in halves where needed)
/// the unit normal N = n / |n| is replaced by n / w, w the quadratic that
/// interpolates |n| at both ends and the middle:
///   A(t) = P(t) + r (n(t) / w(t) - z),
/// a rational Bézier piece (numerator w H + r n h - r z w h, weight w h,
/// for P = H / h; its weights are positive where w's coefficients are).
/// Its distance to the tip at the same parameter is
///   r |1 - |n| / w| = r | |n|^2 - w^2 | / (w (|n| + w)) <= r max|D_i| / min(w_i)^2,
/// D the Bernstein coefficients of n.n - w^2 (convex hull: |D| <= max|D_i|,
/// w >= min w_i > 0). Pieces are halved until that bound is within `budget`
/// (at most 12 times); nothing when it cannot be reached.
struct TipApprox {
  std::vector<Bezier> pieces;  ///< end to end, 3D
  std::vector<double> breaks;  ///< pieces.size() + 1 parameters of the curve (0 ... 1)
  double bound = 0;            ///< proven sup over t of |tip(t) - pieces(t)|
};
std::optional<TipApprox> approximate_tip(const SurfaceCurve& c, double radius, double budget);

/// Measures the two-sided distance between the tip curve and a polyline
/// from flatten_tip(), independently of the bound: true curve points are
/// evaluated along each polyline segment's parameter range and the extremes
/// refined by golden-section search (parameters found to about 1e-10).
Deviation measure_tip(const SurfaceCurve& c, double radius, const TipPolyline& p);

/// Measures the two-sided distance between the tip curve and a printed
/// path of curve pieces that follow it in the same parameter (piece j over
/// [breaks[j], breaks[j+1]] of c's parameter, as approximate_tip() and the
/// blocks made from it do), independently of any bound: on each piece, 32
/// points of each curve and their nearest point on the other (golden-section
/// search in a window of a sixteenth of the piece's interval around the same
/// parameter), every local maximum among them refined by golden-section
/// search; the printed curve is evaluated exactly, not sampled into chords.
Deviation measure_tip_pieces(const SurfaceCurve& c, double radius, std::span<const Bezier> pieces,
                             std::span<const double> breaks);

/// The same measurement for `n` printed moves that do not follow the curve
/// in its parameter (circular and helical arcs, lines): printed(j, s) is the
/// point of move j at s in [0, 1]; the move runs from the tip at breaks[j]
/// to the tip at breaks[j+1]. Nearest points are searched over the whole
/// move, and over its curve interval widened by a quarter either side: each
/// move must be short enough (an arc of less than half a turn) for the
/// distance along it to a point near it to have a single minimum.
Deviation measure_tip_moves(const SurfaceCurve& c, double radius, size_t n,
                            const std::function<Vec3(size_t, double)>& printed, std::span<const double> breaks);

}  // namespace bezcam
