#include "bezcam/sim/machine_pace.hpp"

#include <algorithm>

#include "bezcam/gcode/timeline.hpp"

namespace bezcam::sim {

namespace {

int first_line_of(const MotionBlock& b) { return b.first_line > 0 ? b.first_line : b.line; }

}  // namespace

MachinePace::MachinePace(const MotionModel& model)
    : model_(model), look_(static_cast<std::size_t>(std::max(1, model.lookahead_blocks))), window_(2 * look_) {}

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
  const auto plan = std::make_shared<const MotionPlan>(plan_motion(tl, model_));
  // The committed part ends where the first block left starts, or a pause
  // before it (the pause stays with that block and is planned with it),
  // and the machine is at that block's entry speed there.
  double t1 = plan->cycle_time_s;
  std::size_t segments = plan->segments.size();
  speed_ = 0;
  if (!dry) {
    for (std::size_t k = 0; k < plan->segments.size(); ++k)
      if (static_cast<std::size_t>(plan->segments[k].block) >= take) {
        t1 = plan->segments[k].t_start;
        speed_ = plan->segments[k].v0;
        segments = k;
        break;
      }
    for (std::size_t k = 0; k < plan->pauses.size(); ++k)
      if (plan->pauses[k].before_block >= take) {
        t1 = std::min(t1, plan->pause_start_s[k]);
        break;
      }
  }
  t1 = std::max(0.0, t1);
  // The committed work in execution order, each piece with the machine
  // time it is finished (a pause before its block; a block when its last
  // segment, a blend into the next included, is).
  const double t0 = until_;
  std::vector<double> block_end(take, t0);
  for (std::size_t k = 0; k < segments; ++k) {
    const PlanSegment& s = plan->segments[k];
    const auto b = static_cast<std::size_t>(s.block);
    if (b < take) block_end[b] = std::max(block_end[b], t0 + s.t_start + s.time());
  }
  double last = t0;
  std::size_t p = 0;
  auto pause_done = [&](std::size_t k) {
    last = std::max(last, t0 + plan->pause_start_s[k] + plan->pauses[k].seconds);
    items_.push_back({plan->pauses[k].line, last, false});
  };
  for (std::size_t i = 0; i < take; ++i) {
    while (p < plan->pauses.size() && plan->pauses[p].before_block <= i) pause_done(p++);
    last = std::max(last, block_end[i]);
    items_.push_back({first_line_of(pending_.blocks[i]), last, true});
  }
  if (dry)
    while (p < plan->pauses.size()) pause_done(p++);
  windows_.push_back({t0, t0 + t1, plan, segments});
  until_ += t1;
  if (take > 0) start_ = pending_.blocks[take - 1].to;
  pending_.blocks.erase(pending_.blocks.begin(), pending_.blocks.begin() + static_cast<long>(take));
  pending_.path_tolerance.erase(pending_.path_tolerance.begin(),
                                pending_.path_tolerance.begin() + static_cast<long>(take));
  std::vector<PlanPause> left;
  for (PlanPause q : pending_.pauses)
    if (!dry && q.before_block >= take) {
      q.before_block -= take;
      left.push_back(q);
    }
  pending_.pauses = std::move(left);
}

Vec3 MachinePace::position(double t) const {
  Vec3 at = rest_;
  for (const Window& w : windows_) {
    if (t < w.t0) return at;  // the machine stood still between the windows
    const std::vector<PlanSegment>& segs = w.plan->segments;
    const auto first = segs.begin(), end = segs.begin() + static_cast<long>(w.segments);
    if (t < w.t1) {
      // The last committed segment started by then; before the first, a
      // pause holds the machine where it was.
      const double tau = t - w.t0;
      const auto it = std::upper_bound(first, end, tau, [](double v, const PlanSegment& s) { return v < s.t_start; });
      if (it == first) return at;
      const PlanSegment& s = *(it - 1);
      return s.point_at(s.distance_at(tau - s.t_start), w.plan->motion);
    }
    if (w.segments > 0) at = segs[w.segments - 1].point_at(segs[w.segments - 1].length, w.plan->motion);
  }
  return at;
}

MachinePace::Progress MachinePace::progress(double t) const {
  Progress p;
  p.blocks_done = blocks_forgotten_;
  for (const Item& i : items_) {
    if (i.end <= t)
      p.blocks_done += i.block ? 1 : 0;
    else
      p.open_line = std::min(p.open_line, i.line);
  }
  for (const MotionBlock& b : pending_.blocks) p.open_line = std::min(p.open_line, first_line_of(b));
  for (const PlanPause& q : pending_.pauses) p.open_line = std::min(p.open_line, q.line);
  p.pos = position(t);
  return p;
}

void MachinePace::forget(double t) {
  while (!items_.empty() && items_.front().end <= t) {
    blocks_forgotten_ += items_.front().block ? 1 : 0;
    items_.pop_front();
  }
  while (!windows_.empty() && windows_.front().t1 <= t) {
    const Window& w = windows_.front();
    if (w.segments > 0) {
      const PlanSegment& s = w.plan->segments[w.segments - 1];
      rest_ = s.point_at(s.length, w.plan->motion);
    }
    windows_.pop_front();
  }
}

}  // namespace bezcam::sim
