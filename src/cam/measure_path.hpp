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
/// (Finer sampling only costs time: a long arc would take thousands of
/// chords.)
inline constexpr double kSampleShare = 0.1 * kMeasureResolution;

/// What the independent measurement proves the deviation of printed moves
/// from `pieces` to be at least: measure_deviation() of `path` against
/// `pieces` at the tolerance `tol`, where `path` samples the printed moves
/// with chords that stray from them by at most `sampled` (0: the path is
/// the printed polyline itself). A reading is within kMeasureGap of its
/// tolerance argument of the true distance (deviation.hpp), and the printed
/// moves lie within `sampled` of the path: the reading less both is never
/// above the true deviation of what the controller draws, so never above a
/// proven bound. measure_deviation()'s readings above its `tolerance`
/// argument are true distances, but one below it may read high (a windowed
/// nearest-point search); a reading above the proven `bound` is therefore
/// asked again about that figure itself (plus `sampled`), and the smaller
/// answer is kept. A true excess over the bound survives both readings.
inline double measure_printed(std::span<const Bezier> pieces, std::span<const Vec3> path, double tol, double bound,
                              double sampled) {
  const double floor = 1e-14 * control_magnitude(pieces);  // the readings' finest accuracy
  auto read = [&](double t) { return measure_deviation(pieces, path, t).max() - std::max(kMeasureGap * t, floor); };
  double m = read(tol);
  const double claim = bound + sampled;
  if (m - sampled > bound && claim > 0 && claim < tol) m = std::min(m, read(claim));
  return std::max(0.0, m - sampled);
}

}  // namespace bezcam::detail
