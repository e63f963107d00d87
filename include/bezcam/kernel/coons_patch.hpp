#pragma once
/// Coons patches from four boundary curves (seeds digest §5):
///   S(u,v) = P(u,0) f0(v) + P(u,1) f1(v) + P(0,v) f0(u) + P(1,v) f1(u)
///          - P(0,0) f0(u) f0(v) - P(0,1) f0(u) f1(v)
///          - P(1,0) f1(u) f0(v) - P(1,1) f1(u) f1(v)
/// with the linear, cubic or quintic blends of the digest. Boundaries are
/// exact chains of Bézier pieces (from `bezier` or `bspline` objects), so the
/// patch is exactly a grid of (rational) Bézier patches: to_bezier_cells()
/// builds it, and the rest of bezcam works on that grid.
#include <vector>

#include "bezcam/kernel/bezier_patch.hpp"

namespace bezcam {

enum class CoonsBlend { linear, cubic, quintic };
const char* to_string(CoonsBlend b);
/// Degree of the blend polynomials: 1, 3 or 5.
int blend_degree(CoonsBlend b);
/// f0(t) and f1(t) = 1 - f0(t), and their derivatives (order 0, 1 or 2).
double blend_f0(CoonsBlend b, double t, int order = 0);
double blend_f1(CoonsBlend b, double t, int order = 0);

/// One boundary: Bézier pieces end to end over a partition of [0,1]
/// (piece k covers [breaks[k], breaks[k+1]]; for a B-spline the partition
/// is its knot spans, normalised).
struct BoundaryCurve {
  std::vector<Bezier> pieces;
  std::vector<double> breaks;  ///< pieces.size() + 1 values, 0 ... 1, strictly increasing

  /// Throws InputError when empty, breaks are not a partition of [0,1] of
  /// the right count, or a piece is not 3D.
  static BoundaryCurve make(std::vector<Bezier> pieces, std::vector<double> breaks);
  /// Uniform partition (each piece an equal share of [0,1]).
  static BoundaryCurve make(std::vector<Bezier> pieces);
  const Vec3& front() const { return pieces.front().front(); }
  const Vec3& back() const { return pieces.back().back(); }
};
/// Point (order 0) or derivative of the boundary at global t.
Vec3 evaluate(const BoundaryCurve& c, double t, int order = 0);

struct CoonsPatch {
  BoundaryCurve v0;  ///< S(u,0), from S(0,0) to S(1,0)
  BoundaryCurve v1;  ///< S(u,1), from S(0,1) to S(1,1)
  BoundaryCurve u0;  ///< S(0,v), from S(0,0) to S(0,1)
  BoundaryCurve u1;  ///< S(1,v), from S(1,0) to S(1,1)
  CoonsBlend blend = CoonsBlend::cubic;

  /// Validating factory: the corners must meet within 1e-9 of the
  /// coordinate magnitude. Throws InputError whose place names the
  /// boundary (`boundaries.u0`) with the corner, both points and the gap
  /// (and a hint when the curve looks reversed).
  static CoonsPatch make(BoundaryCurve v0, BoundaryCurve v1, BoundaryCurve u0, BoundaryCurve u1, CoonsBlend blend);

  /// Corners: P(0,0), P(1,0), P(0,1), P(1,1) (taken from v0 and v1).
  Vec3 corner(int u, int v) const {
    return v == 0 ? (u == 0 ? v0.front() : v0.back()) : (u == 0 ? v1.front() : v1.back());
  }
};

/// S(u,v) by the digest's formula (independent of to_bezier_cells()).
Vec3 evaluate(const CoonsPatch& s, double u, double v);
/// Point and partial derivatives by differentiating the formula.
PatchDerivs evaluate_derivs(const CoonsPatch& s, double u, double v);

/// The patch, exactly, as a grid of Bézier patches: one cell per pair of
/// boundary spans (the u partition is the union of v0's and v1's, the v
/// partition the union of u0's and u1's). Polynomial boundaries give
/// polynomial cells of degree max(boundary degrees, blend degree); rational
/// ones give rational cells (common denominator w_v0 w_v1 w_u0 w_u1).
PatchGrid to_bezier_cells(const CoonsPatch& s);

}  // namespace bezcam
