#pragma once
/// B-spline and NURBS curves of any degree, 2D or 3D, clamped or not.
///
/// C(u) = sum_i N_{i,p}(u) w_i P_i / sum_i N_{i,p}(u) w_i over the domain
/// [u_p, u_{m-p}] (knot_vector.hpp); without weights every w_i is 1. All
/// algorithms work on homogeneous points (w P, w), so a NURBS and its
/// rational Bézier pieces are the same curve exactly, up to floating-point
/// rounding (The NURBS Book, Piegl & Tiller, 2nd ed.).
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct NurbsCurve {
  int dim = 2;                  ///< 2 or 3; a 2D curve keeps z = 0
  int degree = 1;               ///< p >= 1
  std::vector<Vec3> points;     ///< n + 1 control points
  std::vector<double> weights;  ///< empty (polynomial B-spline) or n + 1 values > 0
  std::vector<double> knots;    ///< n + p + 2 non-decreasing knots

  /// Validating factory. Throws InputError naming the offending item:
  /// `degree` (< 1, above kMaxBezierDegree, or too high for the number of
  /// points), `points[i]` (non-finite, or z != 0 in 2D), `knots` /
  /// `knots[i]` (see validate_knots()), `weights` (count) and `weights[i]`
  /// (<= 0 or non-finite).
  static NurbsCurve make(int degree, std::vector<Vec3> points, std::vector<double> knots,
                         std::vector<double> weights = {}, int dim = 2);

  bool rational() const { return !weights.empty(); }
  double weight(size_t i) const { return weights.empty() ? 1.0 : weights[i]; }
  /// u_p: where the curve starts.
  double domain_start() const { return knots[static_cast<size_t>(degree)]; }
  /// u_{m-p}: where the curve ends.
  double domain_end() const { return knots[knots.size() - 1 - static_cast<size_t>(degree)]; }
  bool clamped() const;
};

/// A4.1: the point at parameter u (clamped to the domain), from the basis
/// functions of A2.2 applied to homogeneous points.
Vec3 evaluate(const NurbsCurve& c, double u);

/// Derivatives C^(k)(u) for k = 0..d (d >= 0; u clamped to the domain):
/// A3.2 on the homogeneous curve, then A4.2 for the rational quotient. At a
/// knot the derivatives are those of the span that starts there (the last
/// span at the domain's end).
std::vector<Vec3> derivatives(const NurbsCurve& c, double u, int d);
/// First derivative dC/du.
Vec3 derivative(const NurbsCurve& c, double u);

/// A5.1: inserts the knot u `times` times; the curve does not change.
/// Throws std::invalid_argument when u is outside [u_0, u_m) or the
/// multiplicity would exceed the degree.
NurbsCurve insert_knot(const NurbsCurve& c, double u, int times = 1);

/// The same curve on its domain with a clamped knot vector (first and last
/// knots repeated degree + 1 times): knots are inserted at the domain ends
/// until the curve passes through control points there, and what lies
/// outside the domain is dropped. Returns `c` unchanged when already clamped.
NurbsCurve clamp(const NurbsCurve& c);

/// A5.6: the curve as its Bézier pieces, one per non-empty knot span of
/// the domain, end to end, in order; rational pieces for a NURBS (weights
/// normalised so that each piece's first weight is 1), polynomial ones
/// otherwise. Unclamped curves are clamped first.
std::vector<Bezier> to_bezier(const NurbsCurve& c);

/// A Bézier curve as a NURBS of the same degree on [0, 1] (knots 0 and 1,
/// each degree + 1 times).
NurbsCurve from_bezier(const Bezier& b);

}  // namespace bezcam
