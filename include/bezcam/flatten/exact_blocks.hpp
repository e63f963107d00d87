#pragma once
/// Exact-curve blocks for `--output nurbs` (docs/gcode-dialects.md):
/// the plan of which part of a curve entity becomes which block, with the
/// numbers exactly as they will be printed and a proven bound of how far the
/// curve the controller evaluates from those numbers lies from the true one.
///
///  * Fanuc-style (G06.2 / G06.3): a `bspline` segment of degree <= rank - 1
///    is one block with its own knots (mapped affinely to [0, spans], so
///    uniform knots print as integers) when rounding of knots, weights and
///    points keeps it within tolerance; otherwise, and for Bézier segments,
///    runs of pieces of equal degree form one block whose interior knots
///    have multiplicity = degree (integers: exact at any decimals). Rational
///    pieces are put in standard form (end weights 1), so neighbouring
///    pieces agree on their shared weight.
///  * LinuxCNC: one move per Bézier piece: G5 (planar cubic), G5.1 (planar
///    quadratic), G5.2/G5.3 with P weights and L order (planar rational);
///    the interpreter's clamped uniform knots make each a single Bézier.
///  * Degree 1 pieces are G01 lines (exact). Pieces of higher degree than the
///    dialect takes are degree-reduced (degree_reduce.hpp) within the budget
///    left by rounding; where that fails, and for LinuxCNC pieces whose z
///    varies, the piece is left to the arc/line fallback.
///
/// Bounds: for every block, the parametric distance (degree_reduce.hpp)
/// between each true piece and the piece the controller evaluates from the
/// printed numbers (control points, first = the printed current position;
/// weights; knots via the printed knot vector's own Bézier decomposition).
#include <string>
#include <vector>

#include "bezcam/kernel/curve.hpp"
#include "bezcam/kernel/units.hpp"

namespace bezcam {

/// Which exact-curve words a controller understands (docs/gcode-dialects.md).
enum class NurbsDialect {
  none,      ///< lines and arcs only
  fanuc,     ///< G06.2-style block (start word configurable: G06.2 / G06.3)
  linuxcnc,  ///< G5 / G5.1 Bézier moves and G5.2 / G5.3 NURBS
};

struct ExactOptions {
  NurbsDialect dialect = NurbsDialect::fanuc;  ///< fanuc or linuxcnc
  int max_rank = 4;                            ///< Fanuc P limit (2..4)
  double tolerance = kDefaultToleranceMm;      ///< model units
  int decimals = 3;                            ///< coordinates (and I, J, P, Q)
  int knot_decimals = 4, weight_decimals = 4;  ///< K and R (Fanuc), P (G5.2)
};

enum class ExactKind {
  line,      ///< G01 to ctrl[1]
  bezier,    ///< LinuxCNC G5 (4 points) / G5.1 (3 points)
  nurbs,     ///< Fanuc block, or LinuxCNC G5.2 (knots = the interpreter's)
  fallback,  ///< `source` is cut by the arc/line emitter
};

struct ExactBlock {
  ExactKind kind = ExactKind::line;
  /// Printed control points in model coordinates; ctrl[0] is the printed
  /// point before the block (the current position). Empty for fallbacks.
  std::vector<Vec3> ctrl;
  std::vector<double> weights;  ///< printed weights (nurbs), one per point
  std::vector<double> knots;    ///< printed knots (nurbs)
  int order = 0;                ///< nurbs: degree + 1
  std::vector<Bezier> printed;  ///< the curve the controller evaluates, as Bézier pieces
  /// The true pieces this block cuts (for a fallback, its first point is
  /// the exact end of the block before, moved by at most `snap`).
  std::vector<Bezier> source;
  double snap = 0;
  double bound = 0;  ///< proven bound, printed vs true (fallbacks: 0, their emitter proves theirs)
  std::string note;  ///< why this form was chosen when it is not the plain exact one
};

/// Plans the blocks of a curve entity, end to end: the first block starts at
/// the rounded start of the first piece, each next one where the one before
/// ends as printed. Throws InputError when the tolerance is below what the
/// decimals can honour (as flatten_pieces does).
std::vector<ExactBlock> plan_exact_blocks(const CurveGeometry& g, const ExactOptions& o);

}  // namespace bezcam
