#pragma once
/// Measuring, not assuming: the two-sided distance between true Bézier
/// pieces and a polyline, computed independently of the flattener.
///
/// The curve is sampled so that every arc between two samples lies within
/// `resolution` of its chord (all samples are on the curve): polynomial
/// pieces up to degree 3 in uniform steps of t bounded by their second
/// differences, evaluated in power form; others by recursive subdivision
/// until the control polygon is that flat. The polyline is sampled 64 times
/// per segment. Nearest distances are taken both ways: a quick reading at
/// every sample (a descent from the nearest segment of the previous one, an
/// upper bound), the largest read again exactly (every segment whose box
/// could be nearer), and the worst candidates refined on the true curve by
/// golden-section search. The flattener's chords and bound are not used.
/// The result is accurate to about `resolution` (and usually to
/// floating-point precision).
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
/// kMeasureResolution of it. Nearest-point searches start near the nearest
/// segment found before and look over everything when their answer exceeds
/// the tolerance, so any reading above the tolerance is a true (set) distance.
Deviation measure_deviation(std::span<const Bezier> pieces, std::span<const Vec3> polyline,
                            double tolerance);

}  // namespace bezcam
