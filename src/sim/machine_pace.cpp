#include "bezcam/sim/machine_pace.hpp"

#include <algorithm>

#include "bezcam/gcode/timeline.hpp"

namespace bezcam::sim {

MachinePace::MachinePace(const MotionModel& model)
    : model_(model),
      look_(static_cast<std::size_t>(std::max(1, model.lookahead_blocks))),
      window_(2 * look_) {}

void MachinePace::add(const std::vector<MotionBlock>& blocks, const MachineState& before, const MachineState& after,
                      int line) {
  add_to_timeline(pending_, blocks, before, after, line);
}

void MachinePace::commit(bool dry) {
  if (pending_.blocks.empty() && pending_.pauses.empty()) return;
  // The window, from where and at the speed the machine left the last one.
  Timeline tl = pending_;
  tl.start = start_;
  tl.start_speed = speed_;
  const std::size_t n = pending_.blocks.size();
  if (n == 0) dry = true;  // only pauses: they are taken now
  // Commit all but the look-ahead's worth: the planner limits each committed
  // block by what it sees ahead, and all of that is in the window.
  const std::size_t take = dry ? n : std::max<std::size_t>(1, n > look_ ? n - look_ : 1);
  const MotionPlan plan = plan_motion(tl, model_);
  // Time to the first block left (pauses before it included), and the
  // speed there.
  double t1 = plan.cycle_time_s;
  speed_ = 0;
  if (!dry)
    for (const PlanSegment& s : plan.segments)
      if (static_cast<std::size_t>(s.block) >= take) {
        t1 = s.t_start;
        speed_ = s.v0;
        break;
      }
  until_ += std::max(0.0, t1);
  if (take > 0) start_ = pending_.blocks[take - 1].to;
  pending_.blocks.erase(pending_.blocks.begin(), pending_.blocks.begin() + static_cast<long>(take));
  pending_.path_tolerance.erase(pending_.path_tolerance.begin(), pending_.path_tolerance.begin() + static_cast<long>(take));
  std::vector<PlanPause> left;
  for (PlanPause p : pending_.pauses)
    if (!dry && p.before_block >= take) {
      p.before_block -= take;
      left.push_back(p);
    }
  pending_.pauses = std::move(left);
}

}  // namespace bezcam::sim
