#pragma once
// Internal to machine: the trajectory planner's working state (planner.cpp
// runs it): Builder turns a timeline into segments (planner_segments.cpp),
// joins them at corners (planner_corners.cpp), gives them speeds and sums
// their times (planner_speeds.cpp).
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "bezcam/machine/planner.hpp"

namespace bezcam::planner_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPi = 3.14159265358979323846;
// Share of the acceleration a curved move gives to its normal part (the
// tangential part keeps 1/2 of it): sqrt(1 - 0.5^2).
inline constexpr double kNormalShare = 0.8660254037844386;
inline constexpr double kTangentialShare = 0.5;
// A blend may take at most this fraction of each neighbouring line.
inline constexpr double kBlendFraction = 0.5;
// The path tolerance of a blend is at most this fraction of a line.
inline constexpr double kToleranceFraction = 0.25;
// A remnant of a line between two blends shorter than this many periods at
// the blend's speed is absorbed into the blend.
inline constexpr double kGapPeriods = 4;
// Directions closer than this (radians) meet tangentially: no corner.
inline constexpr double kTangentAngle = 1e-3;
// Share of the acceleration a near-tangent kink may use within one period.
inline constexpr double kKinkShare = 0.25;
// LinuxCNC: a kink whose acceleration spike is below this share of the
// limits is taken as tangent (at the cost of as much acceleration).
inline constexpr double kKinkRatio = 0.1;
// Blends at arcs are refused below this half-angle between the secants.
inline constexpr double kMinBlendTheta = kPi / 12;

struct Limits {
  Vec3 vmax;  // units/s per axis
  Vec3 amax;  // units/s^2
  Vec3 jmax;  // units/s^3 (0: none)
  bool jerk = false;
};

/// The most a move along unit `u` may reach when each axis is bounded by `b`.
double along(const Vec3& u, const Vec3& b);
/// The most any direction of the plane with unit normal `n` may reach: the
/// radius of the circle inscribed in the box's section by the plane.
double in_plane(const Vec3& n, const Vec3& b);
Vec3 unit(const Vec3& v);
/// Tangent of a block at its start (end = false) or end, by a short chord
/// for curves (their derivative is not at hand for every form).
Vec3 block_tangent(const MotionBlock& b, bool end);
/// Radius of the circle through three points (infinity when collinear).
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c);
/// How many pieces the planner cuts a curve block into (Builder::add_block).
int curve_pieces(const MotionBlock& b);

// What the speed passes and the totals read of a segment, packed:
// they run over every segment of a long program, and a summary keeps only
// this of a segment once no blend can reach it (PlanSegment holds its
// geometry too, several times the size).
struct Lean {
  double length = 0, vmax = 0, accel = 0;  // accel: tangential, the kinks' share taken off
  int block = -1;
  std::uint8_t limit = 0;  // a SpeedLimit
  bool rapid = false;
  bool blend = false;
};
static_assert(sizeof(Lean) <= 32);

// A segment's speed profile between its entry and exit speeds (speeds()'s
// speed_): made from them when totals() reads it, never stored.
struct Profile {
  double vpeak = 0, t_acc = 0, t_cruise = 0, t_dec = 0;
  double time() const { return t_acc + t_cruise + t_dec; }
};

struct Builder {
  Builder(const Timeline& t, const MotionModel& m, bool summary_only)
      : tl(t), model(m), summary(summary_only), period(m.period_s), scale(mm_per_unit(t.units)) {}
  const Timeline& tl;
  const MotionModel& model;
  bool summary;  // PlanDetail::summary: no curve tables (only sampling reads them)
  Limits lim{};
  double period;
  double scale;  // mm per program unit
  std::vector<PlanSegment> segs;
  std::vector<double> junction;    // junction[i]: largest speed entering segs[i] (0: stop)
  std::vector<PlanSegment> mine_;  // build(): the block's segments before they join segs
  // Every segment's speed figures, in order (speeds(), totals()). A summary
  // moves a segment here once no blend can reach it and drops it from
  // `segs`, which then holds only the last few; a full plan keeps `segs`
  // whole and fills this from it.
  std::vector<Lean> lean;
  size_t most_segments = 0;  // at most this many segments (plan_timed())
  size_t block_count = 0;    // the timeline's blocks (build()): totals() reads no block

  MotionPlan plan;
  double junction_pending_ = 0;
  std::vector<bool> lookahead_limited_;
  // LinuxCNC's parabolic blends: at junction i (0 on paper: each move
  // plans to stop there) the speed at which the next move starts while the
  // one before still decelerates; 0 elsewhere.
  std::vector<double> overlap_;

  // ---- segments (planner_segments.cpp) ----
  // The segment's figures for the passes, the share its kinks take off its
  // acceleration applied (to the segment too: a full plan keeps it).
  void add_lean(PlanSegment& sg);
  double path_tolerance(size_t block) const;
  // The feed a block asks, units/s, and whether the axes cap it.
  void block_speed(const MotionBlock& b, const Vec3& dir, double& v, SpeedLimit& why, bool& clamped) const;
  PlanSegment line_segment(int bi, const Vec3& a, const Vec3& b, bool rapid);
  bool linuxcnc() const { return model.planner == MotionModel::Planner::linuxcnc; }

  // The acceleration a curved move may use in all: the plane's.
  double arc_accel(double a_plane) const { return a_plane; }
  // Speed and tangential acceleration of a curved move of radius R asking
  // speed v with acceleration a in all, the machine's top speed in its
  // plane being vm (planner_segments.cpp).
  void curved_limits(PlanSegment& s, double v, SpeedLimit why, double R, double a, double vm) const;
  // LinuxCNC: the share of the acceleration an arc of radius R keeps for
  // the tangent, sized for the top speed vm: 1/2, or what vm^2/R leaves.
  static double linuxcnc_tangential_share(double R, double a, double vm);
  // Segments of one block, appended to `out`.
  void add_block(int bi, std::vector<PlanSegment>& out);
  // The segment of an arc block, and the segments of a curve block, of
  // block `bi` (add_block()).
  void add_arc_segment(int bi, PlannedBlock& pb, std::vector<PlanSegment>& out);
  void add_curve_segments(int bi, PlannedBlock& pb, std::vector<PlanSegment>& out);
  // A segment's top speed capped by the time the controller needs to take it.
  void cap_segment_time(PlanSegment& s) const;

  // ---- corners (planner_corners.cpp) ----
  // Every block's segments, joined at their corners.
  void build();
  // build() in steps, for blocks made one at a time (plan_motion_summary()):
  // begin_build(count), take_block() with each in order, end_build().
  void begin_build(size_t blocks);
  void take_block(size_t bi, const MotionBlock& b);
  void end_build();
  // Block `bi`: the timeline's, or when streamed the one being taken or
  // the last one that moved (all a corner reads).
  const MotionBlock& block(size_t bi) const;
  bool streamed_ = false;
  const MotionBlock* current_ = nullptr;
  size_t current_index_ = 0;
  MotionBlock last_moving_;
  size_t pause_ = 0;
  bool stop_before_ = true;  // the machine is at rest
  // Why the machine stops between two moves.
  enum class Stop { end, pause, exact_mode, corner };
  // A segment that ends in a stop: the acceleration LinuxCNC plans it with.
  void exact_stop_end(Stop why);
  // The corner between the last segment (a line) and `next` (a line)
  // blended; -1 when a blend arc was inserted, else the junction's speed.
  double blend_lines(PlanSegment& next, double tol, double nominal_prev, double nominal_next, int line);
  // Whether the two moves meet tangentially enough to pass without a blend,
  // and at what speed.
  bool tangent(PlanSegment& prev, PlanSegment& next, const Vec3& u1, const Vec3& u2, double phi, double& vj,
               double& kink_scale) const;
  // LinuxCNC: whether a blend arc can join the two moves at all: the
  // corner's plane must be the arcs' plane (their normals and the normal of
  // the two directions parallel within 1e-6 rad).
  bool blend_arc_plane(const PlanSegment& prev, const PlanSegment& next, const Vec3& u1, const Vec3& u2) const;
  // LinuxCNC: the speed of a parabolic blend between the two moves (both
  // overlapping, each with half its acceleration; when `rating`, as
  // LinuxCNC weighs it against the other blends: a kink's share off too).
  double parabolic_speed(const PlanSegment& prev, const PlanSegment& next, const Vec3& u1, const Vec3& u2,
                         const Vec3& P, double tol, bool rating, double* v_first = nullptr) const;
  // LinuxCNC: the corner taken as a parabolic blend: both moves keep half
  // their acceleration (an arc's speed cap follows) and each plans to stop
  // at the corner; the next starts once the first has slowed to the
  // blend's speed, and the two then run together. Records that speed for
  // the junction about to be pushed.
  void parabolic_corner(PlanSegment& prev, PlanSegment& next, const Vec3& u1, const Vec3& u2, const Vec3& P,
                        double tol);
  // The speed of a corner where an arc or a curve meets another move; -1
  // when no blend fits.
  double curved_corner(const PlanSegment& prev, const PlanSegment& next, const MotionBlock& pbk, const MotionBlock&,
                       const Vec3& u1, const Vec3& u2, double phi, double tol);

  // ---- speeds (planner_speeds.cpp) ----
  // Every junction's speed (speed_).
  void speeds();
  std::vector<double> speed_;  // speed_[i]: entering lean[i]; then the end
  double jerk() const { return lim.jerk ? std::min({lim.jmax.x, lim.jmax.y, lim.jmax.z}) : 0; }
  // One segment from v0 to v1: the highest peak that fits its length.
  static Profile profile_one(const Lean& s, double v0, double v1, double j, std::array<char, 4> f);
  class Profiles;  // every segment's profile, in order
  // Every segment's profile (a full plan's segments take theirs), the
  // plan's times and per-block figures.
  void totals();
  // The profiles and times of lean's segments [0, n), added to the plan's
  // (the time goes on from the segments timed before), and the end: the
  // pauses left, the cycle, the per-block figures.
  void totals_part(size_t n);
  void totals_end();
  // A summary times its segments in parts as the blocks come: the ones
  // before a stop whose look-ahead windows all lie in `lean` are timed and
  // dropped (their speeds depend on nothing after the stop), so `lean`
  // never holds a long program whole.
  void time_done_part();
  size_t next_part_at_ = size_t{1} << 16;  // lean's size at which to look for one
  double t_done_ = 0, cut_done_ = 0, at_feed_done_ = 0;
  size_t pause_done_ = 0;
  bool timed_any_ = false;
  std::vector<std::uint8_t> why_;  // per block: the limit of its fastest segment
  std::vector<double> top_;        // per block: that segment's top speed
};

}  // namespace bezcam::planner_detail
