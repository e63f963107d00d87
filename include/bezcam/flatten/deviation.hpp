#pragma once
/// Measuring, not assuming: the two-sided distance between true Bézier
/// pieces and a polyline, computed independently of the flattener.
///
/// The curve is sampled by recursive subdivision until every sub-curve's
/// control polygon lies within `resolution` of its chord (all samples are on
/// the curve), the polyline is sampled at steps of `resolution`, nearest
/// distances are taken both ways, and the worst candidates are refined on
/// the true curve by golden-section search. The result is accurate to about
/// `resolution` (and usually to floating-point precision).
#include <span>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct Deviation {
  double curve_to_path = 0;  ///< max over curve points of distance to the polyline
  double path_to_curve = 0;  ///< max over polyline points of distance to the curve
  double max() const { return curve_to_path > path_to_curve ? curve_to_path : path_to_curve; }
};

/// Share of the `tolerance` argument at which measure_deviation() samples:
/// its readings are accurate to about this much of it.
inline constexpr double kMeasureResolution = 1e-3;

/// `tolerance`: the bound being checked; sampling resolution is
/// kMeasureResolution of it. Nearest-point searches look in a window along the path first and
/// over everything when the windowed answer exceeds the tolerance, so any
/// reading above the tolerance is a true (set) distance.
Deviation measure_deviation(std::span<const Bezier> pieces, std::span<const Vec3> polyline,
                            double tolerance);

}  // namespace bezcam
