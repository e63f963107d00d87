#include "bezcam/kernel/spline_interp.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <cmath>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/kernel/knot_vector.hpp"

namespace bezcam {

namespace {

std::string through_at(size_t k) { return "through[" + std::to_string(k) + "]"; }

double scale_of(std::span<const Vec3> pts) {
  double s = 0;
  for (const auto& p : pts) s = std::max(s, max_abs(p));
  return std::max(s, 1e-300);
}

// Solves the square sparse system A X = B (one column per coordinate).
Eigen::MatrixXd solve(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success)
    throw InputError(errc::curve_ill_conditioned, Place::at_json("through"),
                     "the interpolation system is singular; check the points");
  return lu.solve(B);
}

std::vector<Vec3> rows_to_points(const Eigen::MatrixXd& X, int dim) {
  std::vector<Vec3> out(static_cast<size_t>(X.rows()));
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    out[static_cast<size_t>(i)] = {X(i, 0), X(i, 1), dim == 3 ? X(i, 2) : 0.0};
  return out;
}

}  // namespace

std::vector<double> chord_length_parameters(std::span<const Vec3> pts) {
  std::vector<double> t(pts.size(), 0.0);
  for (size_t k = 0; k < pts.size(); ++k) {
    const Vec3& p = pts[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(errc::curve_not_finite, Place::at_json(through_at(k)), "expected finite coordinates");
    if (k == 0) continue;
    const double d = dist(p, pts[k - 1]);
    // A chord below 1e-12 of the coordinates is rounding noise, not a step.
    if (d <= 1e-12 * std::max({max_abs(p), max_abs(pts[k - 1]), 1e-300}))
      throw InputError(errc::curve_repeated_point, Place::at_json(through_at(k)),
                       "expected a point different from through[" + std::to_string(k - 1) + "], found the same point " +
                           fmt_point(p, pts[k].z != 0 || pts[k - 1].z != 0 ? 3 : 2) +
                           ": a repeated point gives a zero chord length, so no parameter can separate the two; "
                           "remove the duplicate");
    t[k] = t[k - 1] + d;
  }
  return t;
}

namespace {

// The cubic spline through `pts` by global interpolation: natural end
// conditions (C'' = 0) without `ends`, the given end derivatives with them.
NurbsCurve cubic_spline(std::span<const Vec3> pts, int dim, const std::pair<Vec3, Vec3>* ends) {
  if (pts.size() < 2)
    throw InputError(errc::curve_too_few_points, Place::at_json("through"),
                     "expected at least 2 points to pass through, found " + std::to_string(pts.size()));
  const std::vector<double> t = chord_length_parameters(pts);
  const size_t n = pts.size() - 1;  // points Q_0..Q_n
  // Knots: t_0 four times, the interior parameters, t_n four times.
  std::vector<double> U(4, t.front());
  for (size_t k = 1; k < n; ++k) U.push_back(t[k]);
  U.insert(U.end(), 4, t.back());
  const size_t N = n + 3;  // control points
  // Rows: C''(t_0) = 0, C(t_k) = Q_k for k = 0..n, C''(t_n) = 0.
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(N), 3);
  auto add_row = [&](size_t row, double u, int deriv, double weight) {
    const int span = find_span(U, 3, u);
    const auto d = basis_derivatives(U, 3, span, u, deriv);
    for (int j = 0; j <= 3; ++j)
      if (d[deriv][j] != 0) trip.emplace_back(static_cast<int>(row), span - 3 + j, d[deriv][j] * weight);
  };
  // Derivative rows are scaled by the end spans (squared for the second
  // derivative) so that all rows have entries of order one (the
  // parameters are lengths).
  const double h0 = t[1] - t[0], hn = t[n] - t[n - 1];
  if (ends) {
    add_row(0, t.front(), 1, h0);
    B.row(0) << ends->first.x * h0, ends->first.y * h0, ends->first.z * h0;
  } else {
    add_row(0, t.front(), 2, h0 * h0);
  }
  for (size_t k = 0; k <= n; ++k) {
    add_row(k + 1, t[k], 0, 1.0);
    B.row(static_cast<Eigen::Index>(k + 1)) << pts[k].x, pts[k].y, pts[k].z;
  }
  if (ends) {
    add_row(N - 1, t.back(), 1, hn);
    B.row(static_cast<Eigen::Index>(N - 1)) << ends->second.x * hn, ends->second.y * hn, ends->second.z * hn;
  } else {
    add_row(N - 1, t.back(), 2, hn * hn);
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(N), static_cast<Eigen::Index>(N));
  A.setFromTriplets(trip.begin(), trip.end());
  const Eigen::MatrixXd X = solve(A, B);
  std::vector<Vec3> P = rows_to_points(X, dim);
  // The ends are the first and last points exactly (clamped knots).
  P.front() = pts.front();
  P.back() = pts.back();
  return NurbsCurve::make(3, std::move(P), std::move(U), {}, dim);
}

}  // namespace

NurbsCurve natural_cubic_spline(std::span<const Vec3> pts, int dim) { return cubic_spline(pts, dim, nullptr); }

NurbsCurve clamped_cubic_spline(std::span<const Vec3> pts, const Vec3& d0, const Vec3& dn, int dim) {
  for (const Vec3* d : {&d0, &dn})
    if (!std::isfinite(d->x) || !std::isfinite(d->y) || !std::isfinite(d->z))
      throw InputError(errc::curve_not_finite, Place::at_json("end_tangents"), "expected finite end tangents");
  const std::pair<Vec3, Vec3> ends{d0, dn};
  return cubic_spline(pts, dim, &ends);
}

std::vector<Bezier> hermite_pieces(std::span<const Vec3> pts, std::span<const Vec3> tangents, bool closed, int dim) {
  if (pts.size() < 2)
    throw InputError(errc::curve_too_few_points, Place::at_json("through"),
                     "expected at least 2 points to pass through, found " + std::to_string(pts.size()));
  if (tangents.size() != pts.size())
    throw InputError(errc::curve_tangent_count, Place::at_json("tangents"),
                     "expected one tangent per point (" + std::to_string(pts.size()) + "), found " +
                         std::to_string(tangents.size()));
  for (size_t k = 0; k < tangents.size(); ++k)
    if (!std::isfinite(tangents[k].x) || !std::isfinite(tangents[k].y) || !std::isfinite(tangents[k].z))
      throw InputError(errc::curve_not_finite, Place::at_json("tangents[" + std::to_string(k) + "]"),
                       "expected a finite tangent");
  std::vector<Bezier> out;
  const size_t n = pts.size();
  for (size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i) {
    const size_t j = (i + 1) % n;
    out.push_back(Bezier::make({pts[i], pts[i] + tangents[i] / 3.0, pts[j] - tangents[j] / 3.0, pts[j]}, {}, dim));
  }
  return out;
}

NurbsCurve periodic_cubic_spline(std::span<const Vec3> input, int dim) {
  std::span<const Vec3> pts = input;
  if (pts.size() >= 2 && pts.front() == pts.back()) pts = pts.first(pts.size() - 1);
  if (pts.size() < 3)
    throw InputError(errc::curve_too_few_points, Place::at_json("through"),
                     "a closed spline needs at least 3 distinct points, found " + std::to_string(pts.size()));
  const std::vector<double> t0 = chord_length_parameters(pts);
  const size_t n = pts.size();
  const double closing = dist(pts.back(), pts.front());
  if (closing <= 1e-12 * scale_of(pts))  // unreachable after dropping an exact repeat, kept for near repeats
    throw InputError(errc::curve_repeated_point, Place::at_json(through_at(input.size() - 1)),
                     "the last point repeats the first up to rounding: give it exactly equal, or drop it");
  // Parameters t_0..t_n with t_n = T (back at the first point), extended
  // periodically by three on each side.
  std::vector<double> t = t0;
  t.push_back(t0.back() + closing);
  const double T = t.back();
  std::vector<double> U;
  for (int j = -3; j <= static_cast<int>(n) + 3; ++j) {
    const int k = ((j % static_cast<int>(n)) + static_cast<int>(n)) % static_cast<int>(n);
    const double shift = std::floor(static_cast<double>(j) / static_cast<double>(n)) * T;
    U.push_back(t[static_cast<size_t>(k)] + shift);
  }
  // Control points P_0..P_{n+2}, P_{n+r} = P_r: unknowns c_0..c_{n-1}.
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd B(static_cast<Eigen::Index>(n), 3);
  for (size_t k = 0; k < n; ++k) {
    const double u = t[k];
    const int span = find_span(U, 3, u);
    std::vector<double> N(4);
    basis_functions(U, 3, span, u, N);
    for (int j = 0; j <= 3; ++j)
      if (N[j] != 0) trip.emplace_back(static_cast<int>(k), (span - 3 + j) % static_cast<int>(n), N[j]);
    B.row(static_cast<Eigen::Index>(k)) << pts[k].x, pts[k].y, pts[k].z;
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(trip.begin(), trip.end());  // duplicates (n = 3 wraps) are summed
  const std::vector<Vec3> c = rows_to_points(solve(A, B), dim);
  std::vector<Vec3> P(c);
  for (size_t r = 0; r < 3; ++r) P.push_back(c[r % n]);
  return NurbsCurve::make(3, std::move(P), std::move(U), {}, dim);
}

Bezier lagrange_polynomial(std::span<const Vec3> pts, int dim) {
  if (pts.size() < 2)
    throw InputError(errc::curve_too_few_points, Place::at_json("through"),
                     "expected at least 2 points to pass through, found " + std::to_string(pts.size()));
  if (pts.size() > static_cast<size_t>(kMaxBezierDegree) + 1)
    throw InputError(errc::curve_degree_too_high, Place::at_json("through"),
                     "one polynomial through " + std::to_string(pts.size()) + " points would have degree " +
                         std::to_string(pts.size() - 1) + ", above the limit " + std::to_string(kMaxBezierDegree) +
                         "; use method \"cubic-spline\"");
  const std::vector<double> t = chord_length_parameters(pts);
  const int n = static_cast<int>(pts.size()) - 1;
  Eigen::MatrixXd M(n + 1, n + 1), Q(n + 1, 3);
  for (int k = 0; k <= n; ++k) {
    const double s = t[static_cast<size_t>(k)] / t.back();
    for (int j = 0; j <= n; ++j) M(k, j) = bernstein(n, j, s);
    Q.row(k) << pts[static_cast<size_t>(k)].x, pts[static_cast<size_t>(k)].y, pts[static_cast<size_t>(k)].z;
  }
  const Eigen::MatrixXd X = M.fullPivLu().solve(Q);
  std::vector<Vec3> P = rows_to_points(X, dim);
  P.front() = pts.front();  // B_{n,0}(0) = 1 and B_{n,n}(1) = 1: exact
  P.back() = pts.back();
  for (const auto& p : P)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(errc::curve_ill_conditioned, Place::at_json("through"),
                       "the polynomial through these points cannot be computed in double precision; use method "
                       "\"cubic-spline\"");
  Bezier b = Bezier::make(std::move(P), {}, dim);
  // Check that it really passes through the points.
  const double scale = scale_of(pts);
  double worst = 0;
  for (int k = 0; k <= n; ++k)
    worst = std::max(worst, dist(evaluate(b, t[static_cast<size_t>(k)] / t.back()), pts[static_cast<size_t>(k)]));
  if (worst > 1e-9 * scale)
    throw InputError(errc::curve_ill_conditioned, Place::at_json("through"),
                     "one polynomial through " + std::to_string(n + 1) + " points misses them by " + fmt_num(worst) +
                         " in double precision (the system is too ill-conditioned); use method \"cubic-spline\"");
  return b;
}

double bounding_box_overshoot(std::span<const Bezier> curve, std::span<const Vec3> pts) {
  Box3 box;
  for (const auto& p : pts) box.add(p);
  Box3 cb;
  for (const auto& b : curve) cb.add(bounds(b));
  double over = 0;
  for (int a = 0; a < 3; ++a) over = std::max({over, box.lo[a] - cb.lo[a], cb.hi[a] - box.hi[a]});
  return over;
}

}  // namespace bezcam
