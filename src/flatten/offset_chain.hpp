#pragma once
// The last stage of offset_curve() (private to src/flatten/): the pieces of
// the cut offset path that were kept, chained end to end into the path's
// chains, with the crumbs a crossing leaves absorbed.
#include <vector>

#include "bezcam/flatten/offset.hpp"

namespace bezcam::flatten_detail {

/// How near two ends must be to be one point.
struct ChainTolerances {
  double eps = 0;   ///< the floating-point margin of the offset's tests
  double link = 0;  ///< the farthest a piece's end may be from the next's start
  double fit = 0;   ///< how close the arc spline follows the curve
};

/// Chains `kept` (in the order of the raw path) into `res.chains` and
/// `res.closed`: each piece continues with the kept piece that starts where
/// it ends, the next one along the raw path first.
void chain_pieces(const std::vector<ArcSeg>& kept, bool closed, const ChainTolerances& tol, OffsetResult& res);

}  // namespace bezcam::flatten_detail
