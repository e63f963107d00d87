#pragma once
/// Flattening with a proven bound: Bézier pieces become a polyline whose
/// two-sided (Hausdorff) distance to the true curve, after rounding of the
/// vertices to the printed decimals, is at most the tolerance.
///
/// Method (bezcam's own; see docs/flattening.md):
///  * With `on_curve`, vertices lie on the curve (before rounding). For a
///    chord [A, B] = [M(t0), M(t1)] the distance of the sub-curve to the chord is bounded
///    by `chord_deviation()`, which is exact (closed form) for polynomial
///    pieces of degree <= 3 and a rigorous convex-hull branch-and-bound bound
///    otherwise. Because the sub-curve runs continuously from A to B, its
///    projection covers the chord, so the chord's distance to the curve is at
///    most the curve's distance to the chord: one number bounds both sides.
///  * Rounding A and B to A', B' moves every point of the chord by at most
///    max(|A'-A|, |B'-B|) (points correspond by the same affine parameter),
///    so the printed chord is within deviation + that displacement.
///  * Chords are chosen greedily, each as long as possible (to within a few
///    per cent) under that bound, which keeps the count near the greedy
///    maximal-chord minimum while never exceeding the tolerance.
///  * The band (default): inner vertices move off the curve, up to the
///    tolerance towards its convex side, and chords get about 1.4 times
///    longer. Its search takes the first proven chord of at least 84 % of
///    the longest (few tries per chord, a few per cent more chords). Each such chord is proven by band_deviation(): a
///    parametric distance between the sub-curve and the chord reparametrised as a Bézier curve of the same degree,
///    which bounds both directions.
#include <functional>
#include <span>
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/units.hpp"
#include "bezcam/limits.hpp"

namespace bezcam {

struct FlattenOptions {
  /// Largest allowed distance between curve and printed polyline (model units).
  double tolerance = kDefaultToleranceMm;
  /// Decimals the vertices will be printed with; -1: no rounding.
  int decimals = -1;
  /// Most vertices one flattening may produce (limits.hpp): more is refused
  /// with InputError "limit.segments", up front when estimate_segments()
  /// predicts it, else as soon as it happens.
  std::size_t max_vertices = kMaxProgramLines;
  /// false (default): the tolerance is a band on both sides of the curve,
  /// and inner vertices may leave the curve by up to the tolerance on its
  /// convex side (docs/flattening.md, "The band"); the ends of every piece
  /// stay exact. true: every vertex lies on the curve (before rounding), for
  /// callers that sample a curve or need each vertex's parameter.
  bool on_curve = false;
};

/// One emitted vertex: the rounded point, and for diagnostics the piece and
/// parameter it came from (a band vertex lies off the curve, across from
/// that parameter's point).
struct FlatVertex {
  Vec3 point;
  size_t piece = 0;
  double t = 0;
};

struct FlattenResult {
  std::vector<Vec3> points;  ///< rounded vertices, first = start of first piece
  double bound = 0;          ///< certified upper bound of the deviation
};

/// Upper bound of max over t in [t0,t1] of dist(M(t), segment [M(t0), M(t1)]),
/// exact up to floating-point error for polynomial pieces of degree <= 3, by
/// branch and bound on convex hulls otherwise. With a `budget` >= 0 the
/// search may stop as soon as the answer is certain: a result <= budget is a
/// proven bound, one above it a proven lower bound of the deviation.
double chord_deviation(const Bezier& piece, double t0, double t1, double budget = -1);

/// Upper bound of the two-sided (Hausdorff) distance between the piece on
/// [t0, t1] and the segment [A, B], for any A and B (on the curve or not):
/// sup_t |M(t) - L(t)|, L the segment as a Bézier curve of the piece's
/// degree and weights with L(0) = A, L(1) = B and inner control points the
/// projections of the sub-curve's onto the line AB, clamped to the segment
/// (parametric_distance(), degree_reduce.hpp). With a `budget` >= 0 the
/// answer is certain on its side of the budget, as for chord_deviation();
/// for planar polynomial pieces of degree <= 3 it is then decided first by
/// a root-free sufficient test (the part of the difference across the
/// chord bounded by its control values after one split at 1/2), then in
/// closed form (that part exactly, the part along the chord by its end
/// values), subdividing only when neither can decide. A result within the
/// budget is a proven bound, not necessarily the smallest.
double band_deviation(const Bezier& piece, double t0, double t1, const Vec3& A, const Vec3& B, double budget = -1);

/// About how many chords a flattening within `tolerance` needs: at least
/// one per piece, and along a piece the integral of sqrt(k / (8 tolerance))
/// ds (a chord of length l where the curvature is k deviates by about
/// k l^2 / 8), sampled at 16 points per piece. Asymptotically exact for
/// small tolerances, where counts explode; not a bound. That is the count
/// with vertices on the curve; for the band (FlattenOptions), whose chords
/// may deviate by the tolerance on either side, pass twice the tolerance.
double estimate_segments(std::span<const Bezier> pieces, double tolerance);

/// Callback core: emits the vertices of the polyline in order (the first
/// vertex is the start of the first piece). Returns the certified bound.
/// Throws InputError when `decimals` cannot honour the tolerance, and
/// "limit.segments" when more than opt.max_vertices vertices are needed.
double flatten_pieces(std::span<const Bezier> pieces, const FlattenOptions& opt,
                      const std::function<void(const FlatVertex&)>& emit);

/// flatten_pieces() appending each vertex's point to `out` (which keeps what
/// it held): the same vertices, without a call through `emit` per vertex.
/// On an error `out` may hold the vertices emitted before it.
double flatten_into(std::span<const Bezier> pieces, const FlattenOptions& opt, std::vector<Vec3>& out);

/// Collecting wrapper around flatten_into().
FlattenResult flatten(std::span<const Bezier> pieces, const FlattenOptions& opt);
inline FlattenResult flatten(const Bezier& b, const FlattenOptions& opt) {
  return flatten(std::span<const Bezier>(&b, 1), opt);
}

}  // namespace bezcam
