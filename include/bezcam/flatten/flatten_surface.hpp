#pragma once
/// Finishing passes on surfaces: tool-tip curves flattened with a proven
/// bound, passes spaced so that neighbours are never farther apart than
/// the stepover (verified on the emitted polylines), and gouge detection
/// for ball-end tools.
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

/// Rigorous upper bound of the two-sided (Hausdorff) distance between two
/// polylines: each is sampled at spacing <= `resolution` and
/// dist(., other polyline) is 1-Lipschitz, so the largest sampled distance
/// plus resolution / 2 bounds it. Samples are matched through `params`
/// first (a windowed search gives an upper bound of the nearest distance)
/// and searched in full whenever the windowed value would exceed `limit`.
double polyline_gap_bound(const TipPolyline& a, const TipPolyline& b, double resolution, double limit);

struct PassOptions {
  char direction = 'u';     ///< parameter that varies along a pass
  double stepover = 1;      ///< largest distance allowed between neighbouring passes (units)
  double tolerance = 0.01;  ///< chord tolerance (units)
  int decimals = -1;        ///< printed decimals, -1 none
  double tool_radius = 0;
};

struct Pass {
  double at = 0;        ///< the fixed parameter (v for direction u)
  SurfaceCurve curve;   ///< exact, with normals when r > 0
  TipPolyline poly;
};

struct PassPlan {
  std::vector<Pass> passes;  ///< by increasing `at`, from 0 to 1
  double gap_bound = 0;      ///< proven bound of the largest distance between neighbouring polylines
  size_t refined = 0;        ///< passes inserted by the verification
  double bound = 0;          ///< largest flattening bound
};

/// Adaptive passes: each next pass is placed as far as the estimated
/// distance to the previous one allows (perpendicular distance between the
/// tip curves, sampled densely along the pass, aiming at 97 % of
/// stepover - 2 tolerance, since each polyline may stray by the tolerance).
/// Every neighbouring pair of polylines is then verified with
/// polyline_gap_bound(); a pair over the stepover gets a pass midway,
/// until all pairs pass. Throws InputError when stepover < 4 tolerance.
PassPlan plan_passes(const SurfaceGeometry& s, const PassOptions& o);
/// The baseline: the fewest uniformly spaced passes (in the parameter) for
/// which every neighbouring pair verifies the same way.
PassPlan plan_uniform_passes(const SurfaceGeometry& s, const PassOptions& o);

/// A stretch of a curve on the surface where a ball-end tool would gouge:
/// the concave curvature 1/r is exceeded (the tool is larger than the
/// curvature radius of a valley) or the normal faces down (undercut).
struct GougeSpan {
  double t0 = 0, t1 = 0;       ///< parameter interval of the curve (sampled, ends refined by bisection)
  double worst_t = 0, worst_u = 0, worst_v = 0;
  double curvature_radius = 0; ///< smallest concave radius in the span (0 for an undercut)
  bool undercut = false;
};
/// Samples the curve at `samples` + 1 uniform parameters (ends of bad runs
/// refined to 1e-9). Empty when radius = 0.
std::vector<GougeSpan> find_gouges(const SurfaceGeometry& s, const SurfaceCurve& c, double radius, int samples);

}  // namespace bezcam
