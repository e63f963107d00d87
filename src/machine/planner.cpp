// The trajectory planner (machine/planner.hpp, docs/motion.md).
//
// 1. Segments. Every block becomes one or more segments with a length, a
//    top speed and a tangential acceleration: lines with the axes' limits
//    projected on their direction; arcs with the centripetal acceleration
//    v^2/R taking part of the acceleration (at most sqrt(3)/2 of it, the
//    rest tangential); curve blocks cut into pieces along the true curve,
//    each with the speed its tightest curvature allows.
// 2. Corners. Between two lines that meet at an angle, a circular blend arc
//    that stays within the path tolerance of the corner, trims at most
//    half of each line and runs at the speed its radius allows; what is
//    left of a line between two blends, if shorter than a few periods at
//    the blend's speed, is absorbed into the blend. Corners that touch an
//    arc or a curve keep their shape and are taken at the speed of an
//    equivalent blend. Exact stop where the tolerance is 0, at pauses,
//    and where rapid and feed meet.
// 3. Caps. A segment of length L runs at most at L / (min_segment_periods x
//    period) and a block at most at L_block x block_rate: the controller
//    needs that long to take each one (data starvation).
// 4. Speeds. A windowed backward pass (the controller sees only
//    lookahead_blocks ahead and must be able to stop at the window's end),
//    a backward pass and a forward pass give every junction's speed; each
//    segment is then a trapezoid (an S-curve's durations when a jerk is
//    given), which gives its time.
//
// This file runs the stages and samples the plan; the segments and their
// caps are built in planner_segments.cpp, the corners in
// planner_corners.cpp, the speeds and times in planner_speeds.cpp.
#include "bezcam/machine/planner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "planner_builder.hpp"

namespace bezcam {

using planner_detail::Builder;
using planner_detail::curve_pieces;

const char* to_string(SpeedLimit l) {
  switch (l) {
    case SpeedLimit::programmed: return "programmed";
    case SpeedLimit::axes: return "axes";
    case SpeedLimit::curvature: return "curvature";
    case SpeedLimit::corner: return "corner";
    case SpeedLimit::segment_time: return "segment-time";
    case SpeedLimit::block_rate: return "block-rate";
    case SpeedLimit::lookahead: return "lookahead";
    case SpeedLimit::acceleration: return "acceleration";
  }
  return "?";
}

double PlanSegment::distance_at(double tau) const {
  if (tau <= 0) return 0;
  if (tau < t_acc) {
    const double a = t_acc > 0 ? (vpeak - v0) / t_acc : 0;
    return v0 * tau + 0.5 * a * tau * tau;
  }
  const double d_acc = 0.5 * (v0 + vpeak) * t_acc;
  tau -= t_acc;
  if (tau < t_cruise) return d_acc + vpeak * tau;
  const double d_cr = vpeak * t_cruise;
  tau -= t_cruise;
  if (tau < t_dec) {
    const double a = t_dec > 0 ? (v1 - vpeak) / t_dec : 0;
    return d_acc + d_cr + vpeak * tau + 0.5 * a * tau * tau;
  }
  return length;
}

Vec3 PlanSegment::point_at(double s, const std::vector<MotionBlock>& blocks) const {
  for (size_t k = 0; k < pieces.size(); ++k) {
    const Piece& p = pieces[k];
    if (s > p.length && k + 1 < pieces.size()) {
      s -= p.length;
      continue;
    }
    s = std::clamp(s, 0.0, p.length);
    switch (p.shape) {
      case Shape::line: return p.length > 0 ? p.a + (p.b - p.a) * (s / p.length) : p.a;
      case Shape::arc: {
        const double ang = p.radius > 0 ? s / p.radius : 0;
        return p.center + p.u * (p.radius * std::cos(ang)) + p.w * (p.radius * std::sin(ang));
      }
      case Shape::block: {
        const MotionBlock& b = blocks[static_cast<size_t>(p.block)];
        const auto it = std::upper_bound(p.s.begin(), p.s.end(), s);
        size_t i = static_cast<size_t>(std::clamp<long>(it - p.s.begin(), 1, static_cast<long>(p.s.size()) - 1));
        const double ds = p.s[i] - p.s[i - 1];
        const double f = ds > 0 ? (s - p.s[i - 1]) / ds : 0;
        // Curves: between the points the planner sampled (a few hundred
        // per block); arcs exactly.
        if (p.pts.size() == p.s.size()) return p.pts[i - 1] + (p.pts[i] - p.pts[i - 1]) * f;
        return evaluate_block(b, p.t[i - 1] + f * (p.t[i] - p.t[i - 1]));
      }
    }
  }
  return {};
}

namespace {

// Tool changes and spindle starts take the machine's time.
void time_pauses(Timeline& tl, const MotionModel& model) {
  for (PlanPause& p : tl.pauses) {
    if (p.kind == PlanPause::Kind::tool_change) p.seconds = model.tool_change_s;
    if (p.kind == PlanPause::Kind::spindle_start) p.seconds = model.spindle_start_s;
  }
}

// The model's limits in program units; `most`: at most this many segments.
void check_model(const MotionModel& model) {
  if (!(model.period_s > 0)) throw std::invalid_argument("motion model: period_s must be > 0");
}

void set_limits(Builder& b, const MotionModel& model, size_t most) {
  b.most_segments = most;
  for (int i = 0; i < 3; ++i) {
    b.lim.vmax[i] = model.max_velocity_mm_min[static_cast<size_t>(i)] / 60 / b.scale;
    b.lim.amax[i] = model.max_acceleration_mm_s2[static_cast<size_t>(i)] / b.scale;
    if (model.max_jerk_mm_s3) b.lim.jmax[i] = (*model.max_jerk_mm_s3)[static_cast<size_t>(i)] / b.scale;
  }
  b.lim.jerk = model.max_jerk_mm_s3.has_value();
  b.plan.units = b.tl.units;
  b.plan.period_s = model.period_s;
}

// At most this many segments for a block: a segment per line, rapid or
// arc and one per curve piece, and a blend after each.
size_t most_segments(const MotionBlock& mb) {
  return 1 + (mb.kind == BlockKind::nurbs || mb.kind == BlockKind::bezier ? static_cast<size_t>(curve_pieces(mb)) : 1);
}

// Axes the program had not set yet start where the machine stands (`pos`:
// where the blocks before left it).
void start_unknown_axes(MotionBlock& mb, Vec3& pos) {
  if (mb.from_known != 7u) {
    for (int k = 0; k < 3; ++k)
      if (!(mb.from_known & (1u << k))) mb.from[k] = pos[k];
    if (!mb.ctrl.empty()) mb.ctrl.front() = mb.from;
  }
  pos = mb.to;
}

// The speed passes and totals of a built summary; its per-block figures
// dropped.
MotionPlan finish_summary(Builder& b) {
  b.speeds();
  b.totals();
  b.plan.blocks.clear();
  b.plan.blocks.shrink_to_fit();
  b.plan.pause_start_s.clear();
  return std::move(b.plan);
}

// Plans `timed`, a copy of the timeline to plan that it changes (starts of
// unknown axes, pause times). `original`: the timeline's own blocks, kept
// by a full plan (PlanDetail::full; null for a summary).
MotionPlan plan_timed(Timeline& timed, const std::vector<MotionBlock>* original, const MotionModel& model,
                      PlanDetail detail) {
  check_model(model);
  const Timeline& tl = timed;
  // Axes the program had not set yet start where the machine stands; and
  // the segments' count, at most.
  Vec3 pos = tl.start;
  size_t most = 0;
  for (MotionBlock& mb : timed.blocks) {
    start_unknown_axes(mb, pos);
    most += most_segments(mb);
  }
  time_pauses(timed, model);
  const bool summary = detail == PlanDetail::summary;
  Builder b(timed, model, summary);
  set_limits(b, model, most);
  b.build();
  if (summary) {
    // The passes over the speeds read the segments' figures only: the
    // blocks (the caller's, given up to the plan, or the copy) go before
    // the passes' own tables are made.
    // (Swapped out: assigning `{}` would keep the capacity.)
    std::vector<MotionBlock>().swap(timed.blocks);
    std::vector<double>().swap(timed.path_tolerance);
    return finish_summary(b);
  }
  b.speeds();
  b.totals();
  b.plan.segments = std::move(b.segs);
  b.plan.pauses = timed.pauses;
  b.plan.motion = *original;
  return std::move(b.plan);
}

}  // namespace

MotionPlan plan_motion(const Timeline& tl, const MotionModel& model, PlanDetail detail) {
  Timeline timed = tl;
  return plan_timed(timed, &tl.blocks, model, detail);
}

MotionPlan plan_motion_summary(Timeline tl, const BlockStream& blocks, const MotionModel& model) {
  check_model(model);
  time_pauses(tl, model);
  tl.blocks.clear();
  size_t count = 0, most = 0;
  blocks([&](MotionBlock& mb) {
    ++count;
    most += most_segments(mb);
  });
  Builder b(tl, model, true);
  set_limits(b, model, most);
  b.streamed_ = true;
  b.begin_build(count);
  Vec3 pos = tl.start;
  size_t bi = 0;
  blocks([&](MotionBlock& mb) {
    if (bi == count) throw std::logic_error("plan_motion_summary: the blocks differ from one pass to the next");
    start_unknown_axes(mb, pos);
    b.take_block(bi++, mb);
  });
  if (bi != count) throw std::logic_error("plan_motion_summary: the blocks differ from one pass to the next");
  b.end_build();
  return finish_summary(b);
}

MotionPlan plan_motion(Timeline&& tl, const MotionModel& model, PlanDetail detail) {
  if (detail == PlanDetail::full) return plan_motion(std::as_const(tl), model, detail);
  return plan_timed(tl, nullptr, model, detail);  // a summary keeps no blocks: no copy of them
}

void sample_plan(const MotionPlan& plan, const std::function<void(double, const Vec3&, double)>& out) {
  const double T = plan.period_s;
  const auto steps = static_cast<long long>(std::ceil(plan.cycle_time_s / T - 1e-9));
  size_t seg = 0;
  Vec3 last = plan.segments.empty() ? Vec3{} : plan.segments.front().point_at(0, plan.motion);
  for (long long k = 0; k <= steps; ++k) {
    const double t = std::min(static_cast<double>(k) * T, plan.cycle_time_s);
    while (seg < plan.segments.size() && plan.segments[seg].t_start + plan.segments[seg].time() < t) ++seg;
    double feed = 0;
    if (seg < plan.segments.size() && t >= plan.segments[seg].t_start) {
      const PlanSegment& s = plan.segments[seg];
      const double tau = t - s.t_start;
      last = s.point_at(s.distance_at(tau), plan.motion);
      // Speed at tau.
      if (tau < s.t_acc)
        feed = s.v0 + (s.vpeak - s.v0) * (s.t_acc > 0 ? tau / s.t_acc : 1);
      else if (tau < s.t_acc + s.t_cruise)
        feed = s.vpeak;
      else
        feed = s.vpeak + (s.v1 - s.vpeak) * (s.t_dec > 0 ? (tau - s.t_acc - s.t_cruise) / s.t_dec : 1);
      feed *= 60;
    } else if (seg > 0 && seg <= plan.segments.size()) {
      const PlanSegment& s = plan.segments[seg - 1];
      last = s.point_at(s.length, plan.motion);
    }
    out(t, last, feed);
  }
}

}  // namespace bezcam
