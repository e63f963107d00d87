#pragma once
// Internal to the post layer: where along a cut the tool runs steadily at
// its feed and where it changes speed, for controllers whose arcs
// accelerate more slowly than their lines (docs/motion.md, "Arcs where the
// tool cruises").
#include <span>
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/units.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam::detail {

/// Planned times this close are the same (the report's rounding).
inline constexpr double kSamePlannedTime = 1e-6;
/// The share of a cut's planned time that lines where the tool changes
/// speed must save before they replace arcs or exact blocks all along.
inline constexpr double kCruiseGain = 0.005;
/// How far above the cut a candidate's plan starts its plunge (mm).
inline constexpr double kPlungeDepth = 1;

/// Whether the cut with lines where the tool changes speed (planned time
/// `cruise`, `cruise_blocks`) replaces the one with arcs or exact blocks
/// all along (`plain`, `plain_blocks`): when it saves more than kCruiseGain
/// of the time, or takes the same time in fewer blocks.
inline bool take_cruise(double plain, size_t plain_blocks, double cruise, size_t cruise_blocks) {
  if (cruise < plain * (1 - kCruiseGain)) return true;
  return cruise <= plain + kSamePlannedTime && plain <= cruise + kSamePlannedTime && cruise_blocks < plain_blocks;
}

/// A run of pieces, end to end, cut from a curve's pieces at parameter
/// values (split() of the pieces it starts or ends inside).
struct SpeedStretch {
  std::vector<Bezier> pieces;
  /// true: the lines program of the stretch runs at the feed all along and
  /// an arc at the feed fits its curvature (speed_stretches() gives the
  /// rule); false: the tool speeds up or slows down there.
  bool steady = false;
};

/// How a cut begins and ends: at rest (after a plunge, before a retract),
/// or going on at the feed from, or into, a move that runs tangent to it
/// (a part's lead-in into its path, the path into its lead-out).
struct CutEnds {
  bool from_rest = true;
  bool to_rest = true;
};

/// The unit direction in XY the pieces start in (`at_end` false) or end
/// in; zero where they stand still there.
Vec3 end_direction(std::span<const Bezier> pieces, bool at_end);

/// A straight run at `feed` (units/min) on `model` long enough for the
/// lines to reach the feed from rest and to stop from it, with room to
/// spare: the tool's path before a cut that does not start at rest, or
/// after one that does not end at rest, as a plan models it.
double run_length(double feed, const MotionModel& model, Units units);

/// Whether arcs on `model` accelerate more slowly along the path than
/// lines: LinuxCNC's planner gives an arc tighter than the machine's top
/// speed allows half of its acceleration for the tangent.
bool arcs_accelerate_slower(const MotionModel& model);

/// `pieces` (planar, in the program's `units`, cut at `feed` units/min,
/// from rest or going on from a tangent run at the feed, to rest or into
/// one, as `ends` says) as alternating stretches: steady where the lines
/// program of the curve (the flattener's chords within `tolerance` at
/// `decimals`), planned on `model`, runs at the feed and the curve is no
/// tighter than an arc at the feed allows (sqrt(3)/2 of the plane's
/// acceleration), less the distance the lines need to stop from the feed
/// at each steady run's end (arcs, with less acceleration, start slowing
/// down earlier); not steady elsewhere. One stretch when the whole curve is
/// one kind.
std::vector<SpeedStretch> speed_stretches(std::span<const Bezier> pieces, double feed, const MotionModel& model,
                                          Units units, double tolerance, int decimals, CutEnds ends = {});

}  // namespace bezcam::detail
