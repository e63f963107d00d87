#include "bezcam/kernel/knot_vector.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {
std::string knot_at(size_t i) { return "knots[" + std::to_string(i) + "]"; }
}  // namespace

void validate_knots(std::span<const double> knots, int degree, size_t n_points) {
  if (degree < 1)
    throw InputError(errc::curve_degree, Place::at_json("degree"),
                     "expected a degree >= 1, found " + std::to_string(degree));
  if (n_points < static_cast<size_t>(degree) + 1)
    throw InputError(errc::curve_too_few_points, Place::at_json("degree"),
                     "a curve of degree " + std::to_string(degree) + " needs at least " + std::to_string(degree + 1) +
                         " control points, found " + std::to_string(n_points) + "; lower the degree or add points");
  const size_t want = n_points + static_cast<size_t>(degree) + 1;
  if (knots.size() != want)
    throw InputError(errc::curve_knot_count, Place::at_json("knots"),
                     "expected " + std::to_string(want) + " knots (" + std::to_string(n_points) + " points + degree " +
                         std::to_string(degree) + " + 1), found " + std::to_string(knots.size()));
  for (size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i]))
      throw InputError(errc::curve_not_finite, Place::at_json(knot_at(i)),
                       "expected a finite knot, found " + fmt_num(knots[i]));
    if (i > 0 && knots[i] < knots[i - 1])
      throw InputError(
          errc::curve_knot_order, Place::at_json(knot_at(i)),
          "expected a knot >= " + fmt_num(knots[i - 1]) + " (knots must not decrease), found " + fmt_num(knots[i]));
  }
  const size_t p = static_cast<size_t>(degree), m = knots.size() - 1;
  const double a = knots[p], b = knots[m - p];
  if (!(a < b))
    throw InputError(errc::curve_knot_domain, Place::at_json("knots"),
                     "the curve's domain [knots[" + std::to_string(p) + "], knots[" + std::to_string(m - p) + "]] = [" +
                         fmt_num(a) + ", " + fmt_num(b) + "] is empty; the knots must increase somewhere in between");
  // Runs of equal knots: at most p + 1 anywhere, at most p strictly inside
  // the domain (p + 1 there would let the curve jump between two points).
  for (size_t i = 0; i < knots.size();) {
    size_t j = i;
    while (j + 1 < knots.size() && knots[j + 1] == knots[i]) ++j;
    const size_t mult = j - i + 1;
    const bool inside = knots[i] > a && knots[i] < b;
    const size_t limit = inside ? p : p + 1;
    if (mult > limit)
      throw InputError(errc::curve_knot_multiplicity, Place::at_json(knot_at(i + limit)),
                       "knot " + fmt_num(knots[i]) + " appears " + std::to_string(mult) + " times; " +
                           (inside ? "inside the domain a knot may repeat at most degree (" + std::to_string(p) +
                                         ") times, or the curve would break apart there"
                                   : "a knot may repeat at most degree + 1 (" + std::to_string(p + 1) + ") times"));
    i = j + 1;
  }
}

int find_span(std::span<const double> U, int p, double u) {
  const int m = static_cast<int>(U.size()) - 1;
  const int n = m - p - 1;
  if (u >= U[n + 1]) {
    // The last non-empty span (the end knot may be repeated).
    int k = n;
    while (k > p && U[k] == U[n + 1]) --k;
    return k;
  }
  if (u <= U[p]) {
    int k = p;
    while (k < n && U[k + 1] == U[p]) ++k;
    return k;
  }
  // Binary search for U[k] <= u < U[k+1] (A2.1).
  int lo = p, hi = n + 1;
  int mid = (lo + hi) / 2;
  while (u < U[mid] || u >= U[mid + 1]) {
    if (u < U[mid])
      hi = mid;
    else
      lo = mid;
    mid = (lo + hi) / 2;
  }
  return mid;
}

void basis_functions(std::span<const double> U, int p, int i, double u, std::span<double> N) {
  // A2.2: triangular table computed in place with left/right differences.
  std::vector<double> left(p + 1), right(p + 1);
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

std::vector<std::vector<double>> basis_derivatives(std::span<const double> U, int p, int i, double u, int n) {
  // A2.3: ndu holds the basis functions (upper triangle) and the knot
  // differences (lower triangle); derivatives follow from eq. 2.9.
  std::vector<std::vector<double>> ndu(p + 1, std::vector<double>(p + 1)), a(2, std::vector<double>(p + 1));
  std::vector<double> left(p + 1), right(p + 1);
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  std::vector<std::vector<double>> ders(n + 1, std::vector<double>(p + 1, 0.0));
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= std::min(n, p); ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  double f = p;
  for (int k = 1; k <= std::min(n, p); ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= f;
    f *= (p - k);
  }
  return ders;
}

int multiplicity(std::span<const double> knots, double u) {
  return static_cast<int>(std::count(knots.begin(), knots.end(), u));
}

bool is_clamped(std::span<const double> U, int p) {
  const size_t m = U.size() - 1;
  for (size_t k = 1; k <= static_cast<size_t>(p); ++k)
    if (U[k] != U[0] || U[m - k] != U[m]) return false;
  return true;
}

std::vector<double> clamped_uniform_knots(size_t n_points, int degree, double a, double b) {
  std::vector<double> U;
  const size_t p = static_cast<size_t>(degree);
  const size_t spans = n_points - p;
  U.assign(p + 1, a);
  for (size_t k = 1; k < spans; ++k) U.push_back(a + (b - a) * static_cast<double>(k) / static_cast<double>(spans));
  U.insert(U.end(), p + 1, b);
  return U;
}

}  // namespace bezcam
