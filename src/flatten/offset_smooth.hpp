#pragma once
// A curve's arc spline (private to src/flatten/, offset_curve()'s first
// stage): made tangent where its chains start again.
#include <vector>

#include "bezcam/flatten/offset.hpp"

namespace bezcam::flatten_detail {

/// A curve's arc spline A in tangent chains starts a chain again, where
/// the chain cannot go on far, with a joint at a small angle (and a closed
/// curve's chain comes back to its start at one): the offsets of the two
/// moves then meet with a join arc of micrometres, or cross at a corner,
/// which the printed path carries in every pass. Replaces A[k] (over
/// `piece` from `t_from` to `t_to`, ending where the next move starts in
/// unit direction `next_dir`) by a biarc from its start, in its direction,
/// to its end, in `next_dir`, when both arcs are proven within `budget` of
/// the curve's span; returns their bound, or a negative value when A is
/// left as it was (tangent already, a turn over 0.05 rad, or no biarc that
/// fits).
double smooth_joint(std::vector<ArcSeg>& A, size_t k, const Vec3& next_dir, const Bezier& piece, double t_from,
                    double t_to, double budget);

}  // namespace bezcam::flatten_detail
