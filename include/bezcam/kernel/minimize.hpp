#pragma once
/// One-dimensional minimisation on an interval by Brent's method: golden-
/// section steps that keep a bracket, and parabolic steps through the three
/// best points where the function is smooth, so that a smooth minimum is
/// pinned down in about a dozen evaluations where golden section alone
/// takes fifty. Measurements use it on squared distances (smooth even
/// where the distance reaches 0) and on distances near their peaks.
///
/// As golden section, it finds a local minimum: the caller brackets the one
/// it wants (from samples). Header-only, so that the function is inlined.
#include <cmath>
#include <utility>

namespace bezcam {

struct MinimumFound {
  double x = 0;  ///< where
  double f = 0;  ///< the function's value there, the smallest evaluated
};

/// The minimum of f on [a, b], located to within about `xtol` (absolute,
/// > 0) plus a few ulps of x. At most `max_evals` evaluations.
template <class F>
MinimumFound brent_min(double a, double b, F&& f, double xtol, int max_evals = 100) {
  constexpr double kGold = 0.3819660112501051;  // 2 - golden ratio
  constexpr double kUlp = 3e-16;
  if (b < a) std::swap(a, b);
  double x = a + kGold * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double step = 0, prev_step = 0;  // this step and the one before the last
  for (int evals = 1; evals < max_evals; ++evals) {
    const double mid = 0.5 * (a + b);
    const double tol = kUlp * std::abs(x) + xtol, tol2 = 2 * tol;
    if (std::abs(x - mid) <= tol2 - 0.5 * (b - a)) break;  // bracket within 2 tol of x
    bool parabolic = false;
    if (std::abs(prev_step) > tol) {
      // Vertex of the parabola through (v, fv), (w, fw), (x, fx), as x + p / q.
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double older = prev_step;
      prev_step = step;
      // Accepted when it falls inside the bracket and moves less than half
      // the step before last (so the steps shrink, or golden section takes over).
      if (std::abs(p) < std::abs(0.5 * q * older) && p > q * (a - x) && p < q * (b - x)) {
        step = p / q;
        const double u = x + step;
        if (u - a < tol2 || b - u < tol2) step = mid > x ? tol : -tol;
        parabolic = true;
      }
    }
    if (!parabolic) {
      prev_step = x >= mid ? a - x : b - x;
      step = kGold * prev_step;
    }
    const double u = std::abs(step) >= tol ? x + step : x + (step > 0 ? tol : -tol);
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? a : b) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return {x, fx};
}

}  // namespace bezcam
