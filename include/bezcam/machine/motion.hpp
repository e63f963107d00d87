#pragma once
/// A program's motion as the controller executes it: absolute blocks
/// (MotionBlock). A program built from a job (cam/program_motion.hpp) and a
/// program read back from text (gcode/reader.hpp) become the same blocks, so
/// that the planner, the report and the preview measure and draw both in one
/// way.
#include <span>
#include <vector>

#include "bezcam/kernel/arc.hpp"

namespace bezcam {

enum class BlockKind { rapid, linear, arc_cw, arc_ccw, nurbs, bezier };

/// One executed motion in absolute program coordinates (program units).
struct MotionBlock {
  BlockKind kind = BlockKind::linear;
  int line = 0;        ///< 1-based line of the program where the block ends
  int first_line = 0;  ///< where it starts (NURBS blocks span lines)
  Vec3 from, to;
  /// Axes of `from` known before the move (X 1, Y 2, Z 4); an unknown axis
  /// of `from` holds the value of `to` (no motion assumed along it).
  unsigned from_known = 7;
  double feed = 0;  ///< units/min (0 for rapids)
  /// Seconds the machine dwells once the block has ended (a canned cycle's
  /// G82 P- at the bottom of the hole); 0: none.
  double dwell_s = 0;
  Vec3 center;                         ///< arcs
  Plane plane = Plane::xy;             ///< arcs: G17, G18 or G19
  int order = 0;                       ///< nurbs: degree + 1; bezier: degree + 1
  std::vector<Vec3> ctrl;              ///< nurbs / bezier control points, ctrl[0] == from
  std::vector<double> weights, knots;  ///< nurbs (LinuxCNC G5.2: the interpreter's clamped uniform knots)
  /// Index of the job entity the block cuts (program_motion()); -1 when
  /// unknown (a program read from text) or none (a tool change's retract).
  int entity = -1;
};

/// G2 or G3.
inline bool is_arc(const MotionBlock& b) { return b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw; }

/// Point of a block at t in [0,1] (arcs by angle, NURBS over the knot domain).
/// Arcs: the radius runs linearly from the start's to the end's (they may
/// differ within the arc tolerance) and the plane's axis linearly (helix); t = 0 and t = 1
/// give `from` and `to` exactly.
Vec3 evaluate_block(const MotionBlock& b, double t);

/// The exact Bézier pieces (3D) of a block, end to end: lines as degree 1,
/// G5/G5.1 as they are, NURBS blocks decomposed (to_bezier), planar arcs as
/// rational quadratic pieces of at most 90 degrees on the circle through
/// `from` around `center` (exact when `to` lies on it; the last piece ends
/// at `to`). Helical arcs (the plane's axis varies) throw std::invalid_argument, as do
/// NURBS blocks that cannot be decomposed (lint-recovered bad knots).
std::vector<Bezier> block_to_bezier(const MotionBlock& b);

/// The printed arc of an arc block (arc_cw or arc_ccw).
Arc block_arc(const MotionBlock& b);

/// Swept angle of an arc block, in (0, 2 pi] (equal ends: a full circle).
double arc_sweep(const MotionBlock& b);

/// Length of a block in program units: exact for lines and arcs (helical
/// arcs included); NURBS and Bézier blocks (and arcs whose ends sit at
/// different radii) by chord sums with Richardson extrapolation, halving
/// until successive sums agree to 1e-9 of the block's size.
double block_length(const MotionBlock& b);

/// Points along a block from `from` to `to` (both included). Lines give their
/// two ends; arcs and exact-curve blocks are sampled so that each chord
/// stays within `chord` (program units, > 0) of the block (arcs exactly,
/// curves by subdivision until chord midpoints agree).
std::vector<Vec3> sample_block(const MotionBlock& b, double chord);

/// Whether the block moves at a feed (everything but rapids).
inline bool is_feed(const MotionBlock& b) { return b.kind != BlockKind::rapid; }

/// Lengths and times of a set of motion blocks (program units).
struct MotionTotals {
  double feed_length = 0;   ///< blocks at a feed: cutting and plunging
  double rapid_length = 0;  ///< rapid blocks
  double feed_time_s = 0;   ///< sum of length / feed, in seconds
  double rapid_time_s = 0;  ///< rapid_length / rapid rate, in seconds
  size_t feed_blocks = 0, rapid_blocks = 0;
  /// Estimated run time: feeds and rapids at their rates, with no
  /// acceleration, dwell or tool-change time (so a lower bound).
  double time_s() const { return feed_time_s + rapid_time_s; }
};

/// Sums the blocks of `motion` whose entity is `entity` (all blocks when
/// `entity` is kAllEntities). `rapid_rate`: units/min assumed for rapids
/// (> 0). Feeds of 0 (a reader that saw no F word) count no time.
inline constexpr int kAllEntities = -2;
MotionTotals motion_totals(std::span<const MotionBlock> motion, double rapid_rate, int entity = kAllEntities);

}  // namespace bezcam
