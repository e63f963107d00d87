#pragma once
// Internal to the post layer: the independent measurement of a printed path
// against its true curve, for the report (EntityReport::measured).
#include <algorithm>
#include <span>
#include <vector>

#include "bezcam/flatten/deviation.hpp"

namespace bezcam::detail {

/// Share of the tolerance within which a printed arc or curve is sampled
/// into chords for the measurement: a tenth of what the measurement itself
/// resolves (kMeasureResolution), so that the sampling does not show in it.
/// (Finer sampling only costs time: a 900 mm arc at 1e-5 of 0.01 mm took
/// 3000 chords per arc and a second per curve.)
inline constexpr double kSampleShare = 0.1 * kMeasureResolution;

/// measure_deviation() of `path` against `pieces` at the tolerance `tol`.
/// Its readings above its `tolerance` argument are true distances, but one
/// below it may read high (a windowed nearest-point search); a reading above
/// the proven `bound` (plus the measurement's own resolution) is therefore
/// asked again about that bound itself, and the smaller answer is kept. A
/// true excess over the bound survives both readings.
inline double measure_printed(std::span<const Bezier> pieces, std::span<const Vec3> path, double tol, double bound) {
  double m = measure_deviation(pieces, path, tol).max();
  const double claim = bound + 1e-3 * tol;
  if (m > claim && claim < tol) m = std::min(m, measure_deviation(pieces, path, claim).max());
  return m;
}

}  // namespace bezcam::detail
