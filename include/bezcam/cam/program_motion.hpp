#pragma once
/// A built program's motion as the controller executes it: the canonical
/// moves of a Program become the MotionBlocks the G-code reader produces,
/// and the timeline (blocks and pauses) the planner plans.
#include <functional>
#include <vector>

#include "bezcam/cam/program.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam {

/// The motion blocks of `p`, in order, in program coordinates (job units).
/// Axis words are modal: a move that sets only some axes keeps the others.
/// Axes no move has set yet (the first retract sets only Z) count as being
/// already at the target, so a block never starts from an invented origin.
/// Comments, tool changes and spindle moves produce no block.
std::vector<MotionBlock> program_motion(const Program& p);
/// The same, with the index in `p.moves` of the move each block comes
/// from written to `source` (one per block).
std::vector<MotionBlock> program_motion(const Program& p, std::vector<size_t>& source);
/// The same blocks, one at a time, in order, each with the index in
/// `p.moves` of the move it comes from: `each` may move from the block.
void for_each_motion_block(const Program& p, const std::function<void(MotionBlock&, size_t source)>& each);

/// The blocks and pauses of a program's motion built by bezcam (a
/// Program): tool changes, spindle starts and dwells become pauses. The
/// blocks that cut an entity with a time-optimal bound
/// (EntityReport::cut_first, cut_end) are marked Timeline::on_path.
Timeline program_timeline(const Program& p);

/// The time-optimal bound of the program's cutting path: the sum of its
/// entities' (EntityReport::time_bound_s); 0 when none has one.
double exact_path_bound_s(const Program& p);

/// plan_motion(program_timeline(p), model, PlanDetail::summary), the same
/// figures, without holding the program's blocks (plan_motion_summary()).
MotionPlan plan_program_summary(const Program& p, const MotionModel& model);

}  // namespace bezcam
