#pragma once
/// Degree reduction of Bézier pieces within a proven bound, and the
/// rigorous parametric distance between two Bézier curves that proves it
/// (and proves how far rounding of printed control points and weights moves
/// an exact curve block).
///
/// A parametric distance sup_t |a(t) - b(t)| bounds the two-sided
/// (Hausdorff) distance between the two curves: every point a(t) has the
/// point b(t) that near, and conversely.
#include <optional>
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

/// Upper bound of sup over t in [0,1] of |a(t) - b(t)| (both 2D/3D, either
/// polynomial or rational with positive weights). Method: a(t) - b(t) =
/// N(t) / W(t) with N = A wb - B wa and W = wa wb (A, B the homogeneous
/// numerators), all products of Bernstein polynomials computed exactly in
/// the Bernstein basis of degree deg a + deg b; N / W is then a rational
/// Bézier curve with weights W_k > 0, inside the convex hull of its points
/// N_k / W_k, so |N / W| <= max_k |N_k| / W_k on each sub-interval, refined
/// by subdivision. Early exits as elsewhere: with `budget` >= 0 a result <=
/// budget is proven and a result above it is a proven lower bound; with
/// `budget` < 0 the bound is refined to within `resolution` or 0.1 %.
double parametric_distance(const Bezier& a, const Bezier& b, double budget, double resolution = 0);

/// Polynomial pieces of degree `target` (1 <= target) that follow `b` within
/// `budget` (parametric distance, so within it both ways), end to end: the
/// first starts at b's start, the last ends at b's end, and each joint lies
/// on b. For target >= 3 the end tangents of every piece point along b's
/// (least squares over the two tangent lengths and the free inner control
/// points, with those end constraints), so a G1 curve stays G1; target 2
/// fits the middle point by least squares; target 1 gives chords. Pieces
/// that do not fit are split in half (de Casteljau), at most `max_depth`
/// times. Returns nothing when even that does not fit.
struct ReducedPiece {
  Bezier approx;          ///< polynomial, degree `target`
  Bezier source;          ///< the part of the input it replaces, same parameter
  double t0 = 0, t1 = 1;  ///< that part's interval of the input's parameter
  double bound = 0;       ///< proven parametric distance approx vs source
};
std::optional<std::vector<ReducedPiece>> reduce_degree(const Bezier& b, int target, double budget, int max_depth = 10);

/// The same rational piece in standard form: first and last weights 1
/// (w_i -> w_i / (w_0^(n-i)/n w_n^(i/n)), a change of parameter that keeps
/// the curve). Polynomial pieces are returned unchanged.
Bezier standard_form(const Bezier& b);

}  // namespace bezcam
