#pragma once
/// Numerical integration of smooth functions on an interval: the 7-point
/// Gauss-Legendre rule, and its adaptive form, which halves an interval
/// until the rule on the two halves agrees with the rule on the whole to
/// the interval's share of the tolerance. Lengths are integrals of a speed:
/// a Bézier curve's (kernel/bezier.hpp, `length`) and a controller's spiral
/// arc (machine/motion.cpp) both come here.
///
/// Header-only so that the integrand is inlined: no std::function, no
/// allocation (the recursion is at most `detail::kMaxQuadratureDepth` deep).
#include <array>
#include <cmath>

namespace bezcam {

/// The 7-point Gauss-Legendre rule for f on [a, c] (exact for polynomials
/// of degree 13).
template <class F>
double gauss_legendre7(F&& f, double a, double c) {
  static constexpr std::array<double, 7> x = {0.0,
                                              0.4058451513773972,
                                              -0.4058451513773972,
                                              0.7415311855993945,
                                              -0.7415311855993945,
                                              0.9491079123427585,
                                              -0.9491079123427585};
  static constexpr std::array<double, 7> w = {0.4179591836734694, 0.3818300505051189, 0.3818300505051189,
                                              0.2797053914892766, 0.2797053914892766, 0.1294849661688697,
                                              0.1294849661688697};
  const double h = (c - a) / 2, m = (a + c) / 2;
  double s = 0;
  for (int i = 0; i < 7; ++i) s += w[i] * f(m + h * x[i]);
  return s * h;
}

namespace detail {
inline constexpr int kMaxQuadratureDepth = 30;
template <class F>
double integrate_halves(F& f, double a, double c, double whole, double tol, int depth) {
  const double m = (a + c) / 2;
  const double l = gauss_legendre7(f, a, m), r = gauss_legendre7(f, m, c);
  if (depth > kMaxQuadratureDepth || std::abs(l + r - whole) <= tol) return l + r;
  return integrate_halves(f, a, m, l, tol / 2, depth + 1) + integrate_halves(f, m, c, r, tol / 2, depth + 1);
}
}  // namespace detail

/// The integral of f on [a, c] to about `tol` (absolute): adaptive halving
/// of the 7-point rule, each half given half the tolerance; intervals
/// deeper than 30 halvings are taken as they are.
template <class F>
double integrate(F&& f, double a, double c, double tol) {
  return detail::integrate_halves(f, a, c, gauss_legendre7(f, a, c), tol, 0);
}

}  // namespace bezcam
