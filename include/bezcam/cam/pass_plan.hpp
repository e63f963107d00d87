#pragma once
/// Finishing passes on surfaces: passes spaced so that neighbours are never
/// farther apart than the stepover (verified on the emitted polylines). The
/// tip curves themselves, and their proven bound, are flatten/tip_curve.hpp.
#include <vector>

#include "bezcam/flatten/tip_curve.hpp"
#include "bezcam/kernel/units.hpp"

namespace bezcam {

/// Rigorous upper bound of the two-sided (Hausdorff) distance between two
/// polylines: each is sampled at spacing <= `resolution` and
/// dist(., other polyline) is 1-Lipschitz, so the largest sampled distance
/// plus resolution / 2 bounds it. Samples are matched through `params`
/// first (a windowed search gives an upper bound of the nearest distance)
/// and searched in full whenever the windowed value would exceed `limit`.
double polyline_gap_bound(const TipPolyline& a, const TipPolyline& b, double resolution, double limit);

struct PassOptions {
  char direction = 'u';                    ///< parameter that varies along a pass
  double stepover = 1;                     ///< largest distance allowed between neighbouring passes (units)
  double tolerance = kDefaultToleranceMm;  ///< chord tolerance (units)
  int decimals = -1;                       ///< printed decimals, -1 none
  double tool_radius = 0;
};

struct Pass {
  double at = 0;       ///< the fixed parameter (v for direction u)
  SurfaceCurve curve;  ///< exact, with normals when r > 0
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

}  // namespace bezcam
