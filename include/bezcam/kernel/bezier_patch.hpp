#pragma once
/// Tensor-product Bézier patches, polynomial or rational (seeds digest §5).
///
/// On a net A(i,j), 0 <= i <= n (the u direction), 0 <= j <= m (the v
/// direction), with optional weights w(i,j) > 0:
///   S(u,v) = sum_i sum_j B(n,i)(u) B(m,j)(v) w(i,j) A(i,j)
///            / sum_i sum_j B(n,i)(u) B(m,j)(v) w(i,j),   (u,v) in [0,1]^2.
/// In the job file the net is `points[i][j]` = A(i,j): each row i holds
/// A(i, 0..m), so a row runs along v and row 0 is the control polygon of
/// the border curve S(0,v); column 0 is the one of S(u,0). Iso-parameter
/// curves are Bézier curves of the same degree (rational when the patch
/// is), extracted here exactly.
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct BezierPatch {
  int nu = 0, nv = 0;           ///< degrees in u (rows) and v (along a row)
  std::vector<Vec3> points;     ///< (nu+1)(nv+1) points, A(i,j) at i * (nv+1) + j
  std::vector<double> weights;  ///< empty (polynomial) or one per point, > 0

  /// Validating factory from rows (row i = A(i, 0..m)). Throws InputError
  /// when there are fewer than 2 rows or 2 points per row, rows of unequal
  /// length (place `points[i]`), a non-finite coordinate (`points[i][j]`), a
  /// weight grid of another shape or a weight <= 0 (`weights[i][j]`), or a
  /// degree above kMaxBezierDegree. Equal weights are dropped (polynomial).
  static BezierPatch make(const std::vector<std::vector<Vec3>>& rows,
                          const std::vector<std::vector<double>>& weights = {});

  const Vec3& at(int i, int j) const { return points[size_t(i) * (nv + 1) + j]; }
  double weight(int i, int j) const { return weights.empty() ? 1.0 : weights[size_t(i) * (nv + 1) + j]; }
  bool rational() const { return !weights.empty(); }
};

/// Point and partial derivatives up to second order at (u, v).
struct PatchDerivs {
  Vec3 p, su, sv, suu, suv, svv;
};

/// S(u,v) by de Casteljau in homogeneous coordinates (rows, then column).
Vec3 evaluate(const BezierPatch& s, double u, double v);
/// S(u,v) as the digest's double Bernstein sum (for tests).
Vec3 evaluate_bernstein(const BezierPatch& s, double u, double v);
/// Point and partials (quotient rule for rational patches).
PatchDerivs evaluate_derivs(const BezierPatch& s, double u, double v);

/// The exact iso-parameter curve: dir 'u' gives u -> S(u, at), dir 'v'
/// gives v -> S(at, v). Degree nu (resp. nv); rational when the patch is.
/// At 0 and 1 these are the border curves of the net's border columns/rows.
Bezier iso_curve(const BezierPatch& s, char dir, double at);

/// Exact polynomial along the same iso-curve whose direction is the normal
/// Su x Sv (not unit; for a rational patch it is Su x Sv times w^4 > 0, so
/// the direction is the same). Degree 2n-1 (4n-1 when rational), n the
/// degree along the curve.
Bezier iso_normal(const BezierPatch& s, char dir, double at);

/// The patch restricted to [u0,u1] x [v0,v1], reparametrised on [0,1]^2.
BezierPatch subpatch(const BezierPatch& s, double u0, double u1, double v0, double v1);

/// Box of the control net (contains the patch: convex hull property).
Box3 control_bounds(const BezierPatch& s);
/// Bounds of the patch itself (not its net) by subdivision, accurate to
/// 1e-9 of the box size; always contains the patch.
Box3 bounds(const BezierPatch& s);

/// The exact polynomial normal field n(u,v) = Su x Sv (times w^4 for a
/// rational patch), as a polynomial patch of degrees (2nu-1, 2nv-1), or
/// (4nu-1, 4nv-1) when rational.
BezierPatch normal_patch(const BezierPatch& s);

/// The curve w -> S(c(w)) for a curve c in the parameter square, exactly:
/// a Bézier curve of degree (nu + nv) d, d the degree of c, rational when
/// the patch or c is. Precondition: c's control points lie in [0,1]^2
/// (then every weight of the result is positive).
Bezier compose(const BezierPatch& s, const Bezier& uv);
/// The same composition for a polynomial patch's vector field, without
/// dividing by the curve's weight: for normal_patch() this is a polynomial
/// curve parallel to the normal along S(c(w)) (the division is by a positive
/// function, which does not change directions).
Bezier compose_direction(const BezierPatch& field, const Bezier& uv);

/// A surface as a grid of Bézier patches (cells) on a partition of the
/// parameter square: cell (a, b) covers [ubreaks[a], ubreaks[a+1]] x
/// [vbreaks[b], vbreaks[b+1]] in its own [0,1]^2. A Bézier patch is a 1 x 1
/// grid; a Coons patch with B-spline boundaries has one cell per pair of
/// knot spans.
struct PatchGrid {
  std::vector<double> ubreaks{0, 1}, vbreaks{0, 1};  ///< strictly increasing, 0 ... 1
  std::vector<BezierPatch> cells;                    ///< cells[a * (vbreaks.size()-1) + b]

  size_t cells_u() const { return ubreaks.size() - 1; }
  size_t cells_v() const { return vbreaks.size() - 1; }
  const BezierPatch& cell(size_t a, size_t b) const { return cells[a * cells_v() + b]; }
};

/// Index of the span of `breaks` holding t (the last span for t = 1) and
/// t's local parameter in it.
std::pair<size_t, double> locate_span(const std::vector<double>& breaks, double t);

/// Point and partials of the grid at global (u, v) (derivatives with
/// respect to the global parameters).
PatchDerivs evaluate_derivs(const PatchGrid& g, double u, double v);

}  // namespace bezcam
