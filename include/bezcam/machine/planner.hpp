#pragma once
/// The trajectory planner of the simulated controller (docs/motion.md): how
/// a machine with a given motion model (MachineProfile::motion) executes a
/// program's blocks in time. Look-ahead over a window of blocks, entry and
/// exit speeds from a backward and a forward pass, acceleration limits
/// projected on the axes, corners blended by circular arcs within the path
/// tolerance (exact stop when it is 0), arcs with their centripetal
/// acceleration, curve blocks followed on the true curve with the feed
/// limited by curvature, and the caps of a controller that can start only
/// so many blocks per second. The same plan gives the cycle time of
/// `convert --report`, the report and motion samples of `simulate
/// --program`, and the preview by feed.
#include <functional>
#include <string>
#include <vector>

#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/motion.hpp"

namespace bezcam {

/// What takes time without moving: the planner stops exactly before it.
struct PlanPause {
  enum class Kind { dwell, tool_change, spindle_start, program_stop };
  Kind kind = Kind::dwell;
  double seconds = 0;
  int line = 0;
  size_t before_block = 0;  ///< index of the block it precedes (== blocks.size(): at the end)
};

/// A program as the planner sees it: its blocks, the path mode in force at
/// each (MachineState::path_tolerance: -1 the controller's default, 0 exact
/// stop, infinity no tolerance) and the pauses between them.
struct Timeline {
  Units units = Units::mm;
  /// Where the machine stands when the program starts (program units): the
  /// simulated controller homes at the origin. An axis a block's `from`
  /// does not know (MotionBlock::from_known) starts from here, or from
  /// where the previous block left it.
  Vec3 start{0, 0, 0};
  /// Speed along the path at the start (units/s): 0 from rest; a window
  /// of a program planned piece by piece starts at the speed the piece
  /// before left it (sim/machine_pace.hpp). Capped by the first move's.
  double start_speed = 0;
  std::vector<MotionBlock> blocks;
  std::vector<double> path_tolerance;  ///< one per block
  std::vector<PlanPause> pauses;       ///< in order of before_block
  /// One per block when the timeline was read from a program: the tool in
  /// the spindle (the T of the last M06; 0 before any). Empty otherwise.
  std::vector<int> tools;
  /// One per block, or empty: whether the block cuts along a curve whose
  /// exact path has a time-optimal bound (machine/path_bound.hpp); the
  /// plan's `path_time_s` sums their time.
  std::vector<char> on_path;
};

/// Why a block ran slower than programmed.
enum class SpeedLimit { programmed, axes, curvature, corner, segment_time, block_rate, lookahead, acceleration };
const char* to_string(SpeedLimit l);
/// Whether a limit is the controller's data starvation (not the machine's
/// dynamics): the minimum segment time, the block rate, the look-ahead.
inline bool is_starvation(SpeedLimit l) {
  return l == SpeedLimit::segment_time || l == SpeedLimit::block_rate || l == SpeedLimit::lookahead;
}

/// One executed block (per-block figures of the report).
struct PlannedBlock {
  int line = 0, first_line = 0;
  BlockKind kind = BlockKind::linear;
  double length = 0;           ///< program units
  double programmed_feed = 0;  ///< units/min (rapids: the axes' rapid rate along the move)
  double peak_feed = 0;        ///< highest speed reached, units/min
  double time_s = 0;
  SpeedLimit limit = SpeedLimit::programmed;  ///< what held its peak below the programmed feed
  bool starved = false;
  bool clamped = false;  ///< programmed feed above what the axes reach
};

/// One piece of executed path: a segment of a block or a corner's blend.
struct PlanSegment {
  enum class Shape { line, arc, block };
  struct Piece {
    Shape shape = Shape::line;
    double length = 0;
    Vec3 a, b;                     ///< line: ends
    Vec3 center, u, w;             ///< arc: centre, unit vectors to the start and 90 degrees on
    double radius = 0, angle = 0;  ///< arc
    int block = -1;                ///< block: index in Timeline::blocks
    std::vector<double> s, t;      ///< block: arc length -> block parameter table
    std::vector<Vec3> pts;         ///< curves: the points at those parameters
  };
  std::vector<Piece> pieces;
  int block = -1;  ///< the block it belongs to (blends: the block before the corner)
  bool rapid = false;
  bool blend = false;                      ///< a corner's blend arc
  double length = 0, vmax = 0, accel = 0;  ///< units/s, units/s^2 along the path
  SpeedLimit limit = SpeedLimit::programmed;
  /// Curved segments (arcs, curve pieces, blends): radius and swept angle
  /// of the circle that approximates them (corners use them).
  bool curved = false;
  Vec3 center;
  double radius = 0, angle = 0;
  /// Share of the acceleration lost to a near-tangent kink at either end.
  double kink_reduce = 0;
  /// The acceleration the move may use in all (accel is its tangential part).
  double overall_accel = 0;
  /// LinuxCNC: a parabolic blend at either end (both moves then share the
  /// acceleration: each keeps half of it).
  bool parabolic = false;
  double v0 = 0, v1 = 0, vpeak = 0;           ///< planned entry, exit, peak speed (units/s)
  double t_start = 0;                         ///< when it starts (s)
  double t_acc = 0, t_cruise = 0, t_dec = 0;  ///< phases (s)
  double time() const { return t_acc + t_cruise + t_dec; }
  /// Distance along the segment after `tau` seconds of it.
  double distance_at(double tau) const;
  /// Point at distance `s` along the segment.
  Vec3 point_at(double s, const std::vector<MotionBlock>& blocks) const;
};

struct MotionPlan {
  Units units = Units::mm;
  double period_s = 0.001;
  double cycle_time_s = 0, cutting_time_s = 0, rapid_time_s = 0, pause_time_s = 0;
  double programmed_feed_time_s = 0;  ///< every block at its programmed feed, no acceleration
  /// The time of the blocks marked Timeline::on_path and of the blends at
  /// their corners (into the first of them too); 0 when none is marked.
  double path_time_s = 0;
  double mean_feed_ratio = 1;  ///< achieved / programmed feed, length-weighted over cutting blocks
  size_t starved_blocks = 0, clamped_blocks = 0;
  double max_path_deviation = 0;  ///< program units: corner blending
  int max_deviation_line = 0;     ///< where (the line of the block before the corner)
  std::vector<PlannedBlock> blocks;
  std::vector<PlanSegment> segments;
  std::vector<PlanPause> pauses;
  std::vector<MotionBlock> motion;    ///< the timeline's blocks (segments refer to them)
  std::vector<double> pause_start_s;  ///< when each pause starts
};

/// How much of a plan to keep. `full`: segments with their curve tables,
/// per-block figures, pauses and the blocks (simulate, preview, sampling).
/// `summary`: the scalar figures only (cycle, cutting, rapid, pause and
/// programmed-feed times, mean feed ratio, starved and clamped blocks,
/// path deviation), the same as a full plan's; the vectors are left empty
/// and the curve tables (arc length -> parameter, points) are never built,
/// so a long program's plan takes a fraction of the memory.
enum class PlanDetail { full, summary };

/// Plans `tl` on a machine with `model`. Limits are in mm and converted to
/// the program's units. Throws std::invalid_argument only for a model out
/// of range (profiles are validated when read).
MotionPlan plan_motion(const Timeline& tl, const MotionModel& model, PlanDetail detail = PlanDetail::full);
/// The same for a timeline made for this plan (`plan_motion(program_timeline(p), ...)`):
/// a summary plans in it, without a copy of its blocks.
MotionPlan plan_motion(Timeline&& tl, const MotionModel& model, PlanDetail detail = PlanDetail::full);

/// Calls its argument with each block of a timeline, in order, and the same
/// blocks every time it is called.
using BlockStream = std::function<void(const std::function<void(MotionBlock&)>& each)>;
/// The summary plan (PlanDetail::summary) of `tl` with the blocks `blocks`
/// makes (`tl.blocks` is not read): the same figures as plan_motion() of
/// the timeline holding them, without ever holding them all (a long
/// program's blocks are the larger part of its plan's memory). `blocks`
/// is called twice.
MotionPlan plan_motion_summary(Timeline tl, const BlockStream& blocks, const MotionModel& model);

/// One sample per `plan.period_s` from t = 0 to the cycle's end (included):
/// time, position and speed (units/min).
void sample_plan(const MotionPlan& plan, const std::function<void(double t, const Vec3& p, double feed)>& out);

}  // namespace bezcam
