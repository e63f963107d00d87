#pragma once
/// The time-optimal bound of an exact path (docs/motion-bound.md): the
/// shortest time in which a machine with the motion model's axis limits
/// could follow the exact curve, from rest to rest, never above the feed.
/// A lower bound: no motion that stays on the curve within the limits
/// takes less. It is the forward-backward pass on the curve's curvature of
/// a relaxed problem (every constraint replaced by a weaker one over short
/// stretches of the curve whose geometry is enclosed by interval
/// arithmetic on the Bézier pieces), solved exactly.
#include <span>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/units.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {

/// Lower bound (seconds) of the time to follow `pieces` (end to end, in
/// program units `units`) at speeds up to `feed` (units/min), within
/// `model`'s axis velocities and accelerations: from rest to rest, or
/// (`from_rest` false) entering and leaving at any speed the path allows
/// there (the moves before and after may be blended into it). The jerk
/// limit is not counted (the bound holds with or without one). Corners
/// between pieces cost nothing (a controller may blend them). Returns 0
/// for no pieces or a feed <= 0.
double exact_path_time_bound(std::span<const Bezier> pieces, double feed, const MotionModel& model, Units units,
                             bool from_rest = true);

/// Whether the cuts of a program on `model` start and end at rest: the
/// plunge and the retract meet the curve at a corner, where a controller
/// without a path tolerance (blend_tolerance_mm 0: exact stop) stops.
inline bool cuts_from_rest(const MotionModel& model) { return !(model.blend_tolerance_mm > 0); }

}  // namespace bezcam
