#pragma once
/// The cut-order planner (job key `order: "shortest"`, docs/cut-order.md):
/// contours nested inside a closed contour are cut before it (holes before
/// the outline that holds them), and otherwise the order, the start vertex
/// of closed contours and the direction of reversible open contours are
/// chosen to shorten the rapid moves between contours. Deterministic: the
/// same input gives the same plan (no randomness, ties broken by index).
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// One contour to be ordered: its path in XY (z is ignored).
struct OrderContour {
  /// The path as a polyline in cutting order; for a closed contour
  /// front() == back() (a closed outline without the repeated vertex is
  /// accepted too: then every vertex is a start candidate). Not empty.
  std::vector<Vec3> outline;
  /// Closed: may start at any of its vertices (same direction), and may
  /// enclose other contours (nesting applies).
  bool closed = false;
  /// Open only: may be cut from its end to its start.
  bool reversible = false;
  /// false: keeps its place in the written order, with its written start
  /// and direction (a barrier: no other contour moves across it).
  bool movable = true;
  /// Closed only: the outline vertices where it may start (for example the
  /// joints between its curve pieces, so that no piece is split); empty:
  /// every distinct vertex. Indices below the distinct vertex count.
  std::vector<size_t> starts;
};

/// One cut of the plan.
struct OrderStep {
  size_t contour = 0;       ///< index into the input
  size_t start_vertex = 0;  ///< outline vertex where cutting starts (size()-1 for a reversed open contour)
  bool reversed = false;    ///< open contour cut from its end to its start
  bool operator==(const OrderStep&) const = default;
};

struct CutOrder {
  std::vector<OrderStep> steps;  ///< every contour exactly once
  /// XY rapid length from `home` to the first start and from the end of
  /// each contour to the start of the next, in the written order with the
  /// written starts.
  double rapid_as_written = 0;
  /// The same for the written order made valid: contours that the written
  /// order cuts after a closed contour enclosing them are moved before it
  /// (stable, written starts). Equals rapid_as_written when the written
  /// order already cuts inner contours first.
  double rapid_baseline = 0;
  /// The same for `steps`; never more than rapid_baseline.
  double rapid_planned = 0;
  /// Every nesting (inner, outer): `inner` lies within the closed contour
  /// `outer`; sorted. See find_nesting().
  std::vector<std::pair<size_t, size_t>> nesting;
  /// Nestings that `steps` cuts in the wrong order (outer first): only
  /// possible when a contour that is not movable stands between them.
  size_t unmet_nesting = 0;
  /// The plan is the written order with its written starts (the optimiser
  /// found nothing shorter than rapid_baseline and the written order was valid).
  bool kept_as_written = false;
};

struct CutOrderOptions {
  /// Distance within which a vertex counts as touching a closed contour's
  /// boundary (neither inside nor outside). <= 0: automatic, 1e-9 times the
  /// largest coordinate (at least 1e-9). Pass the chord tolerance when the
  /// outlines are flattened curves that may touch.
  double touch_tolerance = 0;
  /// A run of at most this many movable contours is solved exactly (every
  /// order that keeps the nesting, with the best starts and directions for
  /// each) when that stays small: about e n! c^2 <= 2e7 steps, c the most
  /// start choices of one contour. 0: always the heuristic.
  size_t exact_up_to = 8;
};

/// The nestings of `contours`: (inner, outer) pairs, sorted, where `outer`
/// is closed (at least 3 distinct vertices, non-zero area) and every vertex
/// and every segment midpoint of `inner` (closed or open) is inside `outer`
/// or on its boundary (within the tolerance); a contour lying wholly on
/// another's boundary counts as inside it. A closed inner must also be smaller: (area, index) below the
/// outer's, so that identical contours nest by index (the lower inside) and
/// the relation never has a cycle. Bounding boxes reject most pairs.
std::vector<std::pair<size_t, size_t>> find_nesting(std::span<const OrderContour> contours,
                                                    const CutOrderOptions& options = {});

/// Plans the cut order (docs/cut-order.md). Every contour is cut before each
/// closed contour that encloses it (within a run of movable contours); a
/// small run is solved exactly (CutOrderOptions::exact_up_to), otherwise the
/// order is built by nearest neighbour under that rule and improved by
/// Or-opt and 2-opt moves that keep it, with start vertices of closed
/// contours and directions of reversible open ones re-chosen. The written
/// order (made valid) is improved the same way, and the shorter plan wins;
/// it is returned unchanged when nothing beats it. Throws
/// std::invalid_argument on an empty outline, a non-finite coordinate, or
/// `starts` on an open contour or past the distinct vertices.
CutOrder plan_cut_order(std::span<const OrderContour> contours, Vec3 home, const CutOrderOptions& options = {});

}  // namespace bezcam
