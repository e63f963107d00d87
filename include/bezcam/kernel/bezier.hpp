#pragma once
/// Bézier curves of any degree, 2D or 3D, polynomial or rational.
///
/// M(t) = sum_k B(n,k)(t) w_k P_k / sum_k B(n,k)(t) w_k, t in [0,1]; without
/// weights every w_k is 1 (seeds digest §2). Evaluation is de Casteljau's
/// cascade (in homogeneous coordinates for rational curves), the form the
/// digest calls numerically the most robust; the other forms are provided so
/// that tests can show all five agree.
#include <span>
#include <utility>
#include <vector>

#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// Degree above which a Bézier curve is refused (the Bernstein basis of
/// higher degree loses all precision in double arithmetic).
inline constexpr int kMaxBezierDegree = 64;

struct Bezier {
  int dim = 2;                  ///< 2 or 3; a 2D curve keeps z = 0
  std::vector<Vec3> points;     ///< n + 1 control points
  std::vector<double> weights;  ///< empty (polynomial) or n + 1 values > 0

  /// Validating factory: throws InputError when there are fewer than two
  /// points, a non-finite coordinate, a weight count that does not match, a
  /// weight <= 0 or not finite, a degree above kMaxBezierDegree, or dim not
  /// 2 or 3. The error's place names the offending index (`points[2]`).
  static Bezier make(std::vector<Vec3> points, std::vector<double> weights = {}, int dim = 2);

  int degree() const { return static_cast<int>(points.size()) - 1; }
  bool rational() const { return !weights.empty(); }
  double weight(int i) const { return weights.empty() ? 1.0 : weights[i]; }
  const Vec3& front() const { return points.front(); }
  const Vec3& back() const { return points.back(); }
};

/// Point at t by de Casteljau (homogeneous for rational curves).
/// Checks control points (finite; z = 0 when dim is 2) and weights (none,
/// or one finite weight > 0 per point), throwing InputError naming
/// points[i] or weights[i]. Shared by Bézier and NURBS curves.
void validate_control_points(std::span<const Vec3> pts, std::span<const double> w, int dim);
/// Largest coordinate magnitude among the control points of `pieces` (the
/// scale floating-point margins are taken against).
double control_magnitude(std::span<const Bezier> pieces);

Vec3 evaluate(const Bezier& b, double t);
/// First derivative dM/dt at t (quotient rule for rational curves).
Vec3 derivative(const Bezier& b, double t);
/// Second derivative at t.
Vec3 second_derivative(const Bezier& b, double t);
/// k-th derivative at t (k >= 0).
Vec3 derivative_k(const Bezier& b, double t, int k);

/// The hodograph n (P_{k+1} - P_k) of a polynomial curve: a Bézier curve of
/// degree n - 1 (a single point for n = 1). Precondition: not rational.
Bezier hodograph(const Bezier& b);

/// Splits at t into the curves on [0,t] and [t,1] (the de Casteljau cascade's
/// left and right edges: (A,E,H,M) and (M,I,G,D) for a cubic).
std::pair<Bezier, Bezier> split(const Bezier& b, double t);
/// The same curve restricted to [t0, t1], reparametrised on [0,1].
Bezier subcurve(const Bezier& b, double t0, double t1);
/// The same curve with one more control point (exact degree elevation).
Bezier elevate(const Bezier& b);
/// Same curve, reversed direction.
Bezier reversed(const Bezier& b);
/// Pieces end to end, travelled the other way (last piece first, each reversed).
std::vector<Bezier> reversed(std::span<const Bezier> pieces);
/// Tight axis-aligned bounds of the curve (not of its control polygon),
/// accurate to 1e-12 of the box size.
Box3 bounds(const Bezier& b);
/// Box of the control points (contains the curve: convex hull property).
Box3 control_bounds(const Bezier& b);
/// Arc length by adaptive Gauss-Legendre quadrature, relative accuracy 1e-10.
double length(const Bezier& b);

/// A polynomial curve of degree <= 3 in power form, M(t) = c0 + c1 t +
/// c2 t^2 + c3 t^3 (a lower degree elevated to 3 first, exactly): the form
/// the closed forms for cubics work on.
struct CubicPowerForm {
  Vec3 c0, c1, c2, c3;
  /// Precondition: b is polynomial, of degree <= 3.
  static CubicPowerForm of(const Bezier& b);
  /// Where the curve inflects in the XY plane: the roots in [0, 1] of
  /// (M' x M'').z = 2 (c1 x c2).z + 6 (c1 x c3).z t + 6 (c2 x c3).z t^2
  /// (quadratic_roots01(), kernel/roots.hpp), ascending, written to out;
  /// returns how many. The curvature changes sign at a simple root; it
  /// touches 0 at a double one, which is written twice. A quadratic or a
  /// line has none, unless its points are collinear: M' x M'' is then 0
  /// to rounding, and so are the roots, rounding noise.
  int inflections(double out[2]) const;
};

/// The parameters in [0, 1] where a planar polynomial curve of degree <= 3
/// inflects (CubicPowerForm::inflections()), ascending.
std::vector<double> inflections(const Bezier& b);

// ---- The other forms of the digest (for tests and for teaching) ----------
/// Binomial coefficient C(n, k) as a double.
double binomial(int n, int k);
/// Bernstein polynomial B(n,k)(t) = C(n,k) t^k (1-t)^(n-k).
double bernstein(int n, int k, double t);
/// Form 1: the Bernstein sum (weighted for rational curves).
Vec3 evaluate_bernstein(const Bezier& b, double t);
/// Form 3: the derivative as n times the difference of the last two points
/// of the cascade (polynomial curves).
Vec3 derivative_from_cascade(const Bezier& b, double t);
/// Form 4: the matrix (power) form: coefficients c_j with M(t) = sum c_j t^j
/// (polynomial curves). For a cubic this is the digest's matrix product.
std::vector<Vec3> power_coefficients(const Bezier& b);
Vec3 evaluate_power(const std::vector<Vec3>& coeffs, double t);
/// Form 5: Bézier's "vector puppet" form with f-functions
/// f_k(t) = sum_{j>=k} B(n,j)(t): M(t) = P0 + sum_k f_k(t) (P_k - P_{k-1}).
double durand_f(int n, int k, double t);
Vec3 evaluate_durand(const Bezier& b, double t);

}  // namespace bezcam
