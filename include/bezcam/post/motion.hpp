#pragma once
/// A program's motion as absolute blocks. The canonical moves of a built
/// Program become the MotionBlock type that the G-code reader produces, so
/// that the report and the preview measure and draw a program built from a
/// job and a program read back from text in one way.
#include <span>
#include <vector>

#include "bezcam/post/gcode_reader.hpp"
#include "bezcam/post/toolpath.hpp"

namespace bezcam {

/// One motion block and the entity it belongs to.
struct ToolMotion {
  MotionBlock block;
  int entity = -1;  ///< index in the job's entities; -1 when unknown or none
};

/// The motion blocks of `p`, in order, in program coordinates (job units).
/// Axis words are modal: a move that sets only some axes keeps the others.
/// Axes no move has set yet (the first retract sets only Z) count as being
/// already at the target, so a block never starts from an invented origin.
/// Comments, tool changes and spindle moves produce no block.
std::vector<ToolMotion> program_motion(const Program& p);

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

}  // namespace bezcam
