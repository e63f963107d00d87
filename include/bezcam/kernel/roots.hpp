#pragma once
/// Roots of low-degree polynomials on [0, 1], in the numerically stable
/// forms: what the closed forms for cubic Bézier curves (their inflections,
/// a chord's extreme distances) come down to.
///
/// Header-only and forced inline: the flattener calls it in its innermost
/// loops.
#include <algorithm>
#include <cmath>

namespace bezcam {

/// The roots in [0, 1] of a + b s + c s^2, written to out[0..n), n
/// returned, in no particular order. The quadratic term is dropped when
/// |c| <= 1e-14 max(|a|, |b|, |c|) (a linear equation then); a double root
/// is written twice; there is none when a, b and c are all 0. Infinities
/// and NaN are never kept.
inline __attribute__((always_inline)) int quadratic_roots01(double a, double b, double c, double out[2]) {
  int n = 0;
  // (without a branch: the slot is written whether the root is kept or not;
  // the comparisons also leave out infinities and NaN)
  auto keep = [&](double s) {
    out[n] = s;
    n += int(s >= 0) & int(s <= 1);
  };
  const double scale = std::max(std::max(std::abs(a), std::abs(b)), std::abs(c));
  if (scale == 0) return 0;
  if (std::abs(c) <= 1e-14 * scale) {
    if (b != 0) keep(-a / b);
    return n;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q != 0) {
    keep(q / c);
    keep(a / q);
  } else {
    keep(0);
  }
  return n;
}

}  // namespace bezcam
