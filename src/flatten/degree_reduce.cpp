#include "bezcam/flatten/degree_reduce.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "flatten/search.hpp"

namespace bezcam {

namespace {

// A polynomial Bézier in 4D: (N.x, N.y, N.z, W) of parametric_distance().
using C4 = std::array<double, 4>;
using Poly4 = std::vector<C4>;

C4 lerp4(const C4& a, const C4& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t, a[3] + (b[3] - a[3]) * t};
}

// de Casteljau split at 1/2; returns the value at the split point too.
C4 split4(const Poly4& p, Poly4& left, Poly4& right) {
  const size_t n = p.size();
  Poly4 q = p;
  left.resize(n);
  right.resize(n);
  left[0] = q[0];
  right[n - 1] = q[n - 1];
  for (size_t r = 1; r < n; ++r) {
    for (size_t i = 0; i + r < n; ++i) q[i] = lerp4(q[i], q[i + 1], 0.5);
    left[r] = q[0];
    right[n - 1 - r] = q[n - 1 - r];
  }
  return q[0];
}

double ratio_at(const C4& c) { return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / c[3]; }

// max |N_k / W_k|: N / W is a rational Bézier curve with homogeneous control
// points (N_k, W_k), W_k > 0, so it lies in the convex hull of the points
// N_k / W_k (the convex hull property of rational curves with positive
// weights), and its norm is at most theirs. Converges quadratically under
// subdivision, like the control polygon.
double hull_ratio(const Poly4& p) {
  double m = 0;
  for (const auto& c : p) {
    if (!(c[3] > 0)) return std::numeric_limits<double>::infinity();
    m = std::max(m, ratio_at(c));
  }
  return m;
}

// Least-squares fit of degree `m` to b on [0,1] with the end constraints of
// reduce_degree(); parameters correspond (the fit is parametric).
Bezier fit_reduced(const Bezier& b, int m) {
  const Vec3 P0 = b.front(), Pm = b.back();
  Bezier r;
  r.dim = b.dim;
  r.points.assign(m + 1, P0);
  r.points[m] = Pm;
  if (m == 1) return r;
  // Tangent directions at the ends, scaled so that 1 means equal derivatives.
  Vec3 d0 = derivative(b, 0) / m, d1 = derivative(b, 1) / m;
  const double scale = std::max({max_abs(P0), max_abs(Pm), 1e-300});
  const bool t0 = m >= 3 && norm(d0) > 1e-9 * scale, t1 = m >= 3 && norm(d1) > 1e-9 * scale;
  // Unknowns: alpha (P1 = P0 + alpha d0), beta (P_{m-1} = Pm - beta d1), and
  // the free inner points, 3 coordinates each.
  std::vector<int> free_pts;
  for (int i = 1; i < m; ++i)
    if (!((i == 1 && t0) || (i == m - 1 && t1))) free_pts.push_back(i);
  const int nu = (t0 ? 1 : 0) + (t1 ? 1 : 0) + 3 * static_cast<int>(free_pts.size());
  const int K = 4 * (b.degree() + m) + 8;  // samples
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * (K - 1), nu);
  Eigen::VectorXd rhs(3 * (K - 1));
  for (int j = 1; j < K; ++j) {
    const double s = double(j) / K;
    const Vec3 target = evaluate(b, s);
    std::vector<double> B(m + 1);
    for (int i = 0; i <= m; ++i) B[i] = bernstein(m, i, s);
    Vec3 fixed = P0 * B[0] + Pm * B[m];
    if (t0) fixed += P0 * B[1];
    if (t1) fixed += Pm * B[m - 1];
    for (int c = 0; c < 3; ++c) {
      const int row = 3 * (j - 1) + c;
      rhs(row) = target[c] - fixed[c];
      int col = 0;
      if (t0) A(row, col++) = B[1] * d0[c];
      if (t1) A(row, col++) = -B[m - 1] * d1[c];
      for (size_t f = 0; f < free_pts.size(); ++f) A(row, col + 3 * static_cast<int>(f) + c) = B[free_pts[f]];
    }
  }
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(rhs);
  int col = 0;
  if (t0) r.points[1] = P0 + d0 * x(col++);
  if (t1) r.points[m - 1] = Pm - d1 * x(col++);
  for (size_t f = 0; f < free_pts.size(); ++f)
    r.points[free_pts[f]] = {x(col + 3 * static_cast<int>(f)), x(col + 3 * static_cast<int>(f) + 1),
                             x(col + 3 * static_cast<int>(f) + 2)};
  if (b.dim == 2)
    for (auto& p : r.points) p.z = 0;
  return r;
}

bool reduce_rec(const Bezier& b, int target, double budget, int depth, double t0, double t1,
                std::vector<ReducedPiece>& out) {
  const Bezier r = fit_reduced(b, target);
  const double d = parametric_distance(b, r, budget);
  if (d <= budget) {
    out.push_back({r, b, t0, t1, d});
    return true;
  }
  if (depth <= 0) return false;
  auto [left, right] = split(b, 0.5);
  const double tm = 0.5 * (t0 + t1);
  return reduce_rec(left, target, budget, depth - 1, t0, tm, out) &&
         reduce_rec(right, target, budget, depth - 1, tm, t1, out);
}

}  // namespace

double parametric_distance(const Bezier& a, const Bezier& b, double budget, double resolution) {
  const int m = a.degree(), n = b.degree();
  // N_k = sum_{i+j=k} c_ijk wa_i wb_j (Pa_i - Pb_j), W_k = sum c_ijk wa_i wb_j,
  // c_ijk = C(m,i) C(n,j) / C(m+n,k): the Bernstein product formula.
  Poly4 p(static_cast<size_t>(m + n + 1), C4{0, 0, 0, 0});
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      const double c = binomial(m, i) * binomial(n, j) / binomial(m + n, i + j) * a.weight(i) * b.weight(j);
      const Vec3 d = a.points[i] - b.points[j];
      C4& q = p[static_cast<size_t>(i + j)];
      q[0] += c * d.x;
      q[1] += c * d.y;
      q[2] += c * d.z;
      q[3] += c;
    }
  const double lb = std::max(ratio_at(p.front()), ratio_at(p.back()));
  return flatten_detail::sup_branch_and_bound(
      std::move(p), lb, {budget, 1e-3, resolution, 4000}, [](const Poly4& q) { return hull_ratio(q); },
      [](const Poly4& q, Poly4& l, Poly4& r) { return ratio_at(split4(q, l, r)); });
}

std::optional<std::vector<ReducedPiece>> reduce_degree(const Bezier& b, int target, double budget, int max_depth) {
  std::vector<ReducedPiece> out;
  if (target < 1) return std::nullopt;
  if (!b.rational() && b.degree() <= target) {
    Bezier e = b;
    while (e.degree() < target) e = elevate(e);  // exact
    out.push_back({e, b, 0, 1, 0});
  } else if (!reduce_rec(b, target, budget, max_depth, 0, 1, out)) {
    return std::nullopt;
  }
  return out;
}

Bezier standard_form(const Bezier& b) {
  if (!b.rational()) return b;
  Bezier s = b;
  const int n = b.degree();
  const double w0 = b.weights.front(), wn = b.weights.back();
  for (int i = 0; i <= n; ++i)
    s.weights[i] = b.weights[i] / (std::pow(w0, double(n - i) / n) * std::pow(wn, double(i) / n));
  s.weights.front() = 1;
  s.weights.back() = 1;
  return s;
}

}  // namespace bezcam
