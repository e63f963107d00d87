#pragma once
// A closed curve's arc spline (private to src/flatten/, offset_curve()'s
// first stage): made tangent where it closes on itself.
#include <vector>

#include "bezcam/flatten/offset.hpp"

namespace bezcam::flatten_detail {

/// A closed curve's arc spline A in tangent chains meets its own start at
/// a small angle: its first move starts free, and its last, which goes on
/// from the chain, cannot also end along the first. The offsets of the two
/// then meet with a join arc of micrometres, which the printed path
/// carries as a move turning by its rounding. Replaces A's last move (over
/// `last_piece` from `t_from` to 1) by a biarc from its start, in its
/// direction, to A's start, in the first move's direction, when both arcs
/// are proven within `budget` of the curve's span; returns their bound, or
/// a negative value when A is left as it was (tangent already, a corner of
/// the curve, or no biarc that fits).
double close_tangentially(std::vector<ArcSeg>& A, const Bezier& last_piece, double t_from, double budget);

}  // namespace bezcam::flatten_detail
