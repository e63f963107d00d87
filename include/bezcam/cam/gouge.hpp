#pragma once
/// Gouge detection for ball-end tools on surfaces: where the tool is larger
/// than the curvature radius of a valley, or the normal faces down.
#include <vector>

#include "bezcam/kernel/surface.hpp"

namespace bezcam {

/// A stretch of a curve on the surface where a ball-end tool would gouge:
/// the concave curvature 1/r is exceeded (the tool is larger than the
/// curvature radius of a valley) or the normal faces down (undercut).
struct GougeSpan {
  double t0 = 0, t1 = 0;  ///< parameter interval of the curve (sampled, ends refined by bisection)
  double worst_t = 0, worst_u = 0, worst_v = 0;
  double curvature_radius = 0;  ///< smallest concave radius in the span (0 for an undercut)
  bool undercut = false;
};
/// Samples the curve at `samples` + 1 uniform parameters (ends of bad runs
/// refined to 1e-9). Empty when radius = 0.
std::vector<GougeSpan> find_gouges(const SurfaceGeometry& s, const SurfaceCurve& c, double radius, int samples);

}  // namespace bezcam
