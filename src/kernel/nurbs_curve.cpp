#include "bezcam/kernel/nurbs_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/kernel/knot_vector.hpp"

namespace bezcam {

namespace {

// Homogeneous point (w P, w): B-spline algorithms on these are exact for
// NURBS (The NURBS Book, section 4.2).
struct HPoint {
  Vec3 p;
  double w = 1;
  HPoint operator*(double s) const { return {p * s, w * s}; }
  HPoint operator+(const HPoint& o) const { return {p + o.p, w + o.w}; }
};

std::vector<HPoint> homogeneous(const NurbsCurve& c) {
  std::vector<HPoint> hs(c.points.size());
  for (size_t i = 0; i < hs.size(); ++i) {
    const double w = c.weight(i);
    hs[i] = {c.points[i] * w, w};
  }
  return hs;
}

NurbsCurve from_homogeneous(const NurbsCurve& like, const std::vector<HPoint>& hs, std::vector<double> knots) {
  NurbsCurve out;
  out.dim = like.dim;
  out.degree = like.degree;
  out.knots = std::move(knots);
  out.points.resize(hs.size());
  for (size_t i = 0; i < hs.size(); ++i) out.points[i] = hs[i].p / hs[i].w;
  if (like.rational()) {
    out.weights.resize(hs.size());
    for (size_t i = 0; i < hs.size(); ++i) out.weights[i] = hs[i].w;
  }
  return out;
}

double clamp_to_domain(const NurbsCurve& c, double u) { return std::clamp(u, c.domain_start(), c.domain_end()); }

}  // namespace

NurbsCurve NurbsCurve::make(int degree, std::vector<Vec3> pts, std::vector<double> knots, std::vector<double> w,
                            int dim) {
  if (dim != 2 && dim != 3)
    throw InputError(errc::curve_dimension, Place{}, "expected dimension 2 or 3, found " + std::to_string(dim));
  if (degree > kMaxBezierDegree)
    throw InputError(
        errc::curve_degree_too_high, Place::at_json("degree"),
        "expected a degree of at most " + std::to_string(kMaxBezierDegree) + ", found " + std::to_string(degree));
  validate_control_points(pts, w, dim);
  validate_knots(knots, degree, pts.size());
  NurbsCurve c;
  c.dim = dim;
  c.degree = degree;
  c.points = std::move(pts);
  c.weights = std::move(w);
  c.knots = std::move(knots);
  return c;
}

bool NurbsCurve::clamped() const { return is_clamped(knots, degree); }

Vec3 evaluate(const NurbsCurve& c, double u) {
  // A4.1: C(u) = sum N_{i,p}(u) Pw_i, projected.
  const int p = c.degree;
  u = clamp_to_domain(c, u);
  const int span = find_span(c.knots, p, u);
  std::vector<double> N(p + 1);
  basis_functions(c.knots, p, span, u, N);
  HPoint sum{{0, 0, 0}, 0};
  for (int j = 0; j <= p; ++j) {
    const size_t i = static_cast<size_t>(span - p + j);
    const double w = c.weight(i);
    sum = sum + HPoint{c.points[i] * w, w} * N[j];
  }
  return sum.p / sum.w;
}

std::vector<Vec3> derivatives(const NurbsCurve& c, double u, int d) {
  const int p = c.degree;
  u = clamp_to_domain(c, u);
  // At the domain's end, find_span gives the last span, whose left-sided
  // derivatives are the ones that exist there.
  const int span = find_span(c.knots, p, u);
  const auto nd = basis_derivatives(c.knots, p, span, u, std::min(d, p));
  // A3.2 on homogeneous points: A^(k) (vector part) and w^(k).
  std::vector<HPoint> ders(d + 1, HPoint{{0, 0, 0}, 0});
  for (int k = 0; k <= std::min(d, p); ++k)
    for (int j = 0; j <= p; ++j) {
      const size_t i = static_cast<size_t>(span - p + j);
      const double w = c.weight(i);
      ders[k] = ders[k] + HPoint{c.points[i] * w, w} * nd[k][j];
    }
  // A4.2: C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w.
  std::vector<Vec3> ck(d + 1);
  for (int k = 0; k <= d; ++k) {
    Vec3 v = ders[k].p;
    for (int i = 1; i <= k; ++i) v -= ck[k - i] * (binomial(k, i) * ders[i].w);
    ck[k] = v / ders[0].w;
  }
  return ck;
}

Vec3 derivative(const NurbsCurve& c, double u) { return derivatives(c, u, 1)[1]; }

NurbsCurve insert_knot(const NurbsCurve& c, double u, int r) {
  const int p = c.degree;
  const auto& UP = c.knots;
  if (r < 1) return c;
  if (!(u >= UP.front() && u < UP.back()))
    throw std::invalid_argument("insert_knot: u = " + fmt_num(u) + " outside [" + fmt_num(UP.front()) + ", " +
                                fmt_num(UP.back()) + ")");
  const int s = multiplicity(UP, u);
  if (s + r > p) throw std::invalid_argument("insert_knot: multiplicity would exceed the degree");
  // k: the raw span U[k] <= u < U[k+1] of the whole vector.
  const int k = static_cast<int>(std::upper_bound(UP.begin(), UP.end(), u) - UP.begin()) - 1;
  const int np = static_cast<int>(c.points.size()) - 1;
  const int mp = np + p + 1;
  const std::vector<HPoint> Pw = homogeneous(c);
  // A5.1.
  std::vector<double> UQ(static_cast<size_t>(mp + r + 1));
  for (int i = 0; i <= k; ++i) UQ[i] = UP[i];
  for (int i = 1; i <= r; ++i) UQ[k + i] = u;
  for (int i = k + 1; i <= mp; ++i) UQ[i + r] = UP[i];
  std::vector<HPoint> Qw(static_cast<size_t>(np + r + 1));
  for (int i = 0; i <= k - p; ++i) Qw[i] = Pw[i];
  for (int i = k - s; i <= np; ++i) Qw[i + r] = Pw[i];
  std::vector<HPoint> Rw(static_cast<size_t>(p - s + 1));
  for (int i = 0; i <= p - s; ++i) Rw[i] = Pw[k - p + i];
  int L = 0;
  for (int j = 1; j <= r; ++j) {
    L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      const double alpha = (u - UP[L + i]) / (UP[i + k + 1] - UP[L + i]);
      Rw[i] = Rw[i + 1] * alpha + Rw[i] * (1.0 - alpha);
    }
    Qw[L] = Rw[0];
    Qw[k + r - j - s] = Rw[p - j - s];
  }
  for (int i = L + 1; i < k - s; ++i) Qw[i] = Rw[i - L];
  return from_homogeneous(c, Qw, std::move(UQ));
}

NurbsCurve clamp(const NurbsCurve& c) {
  if (c.clamped()) return c;
  const int p = c.degree;
  const double a = c.domain_start(), b = c.domain_end();
  NurbsCurve q = c;
  // Raise the multiplicity of each domain end to p: the curve then passes
  // through a control point there (eq. 5.x of the book: knot insertion
  // leaves the curve unchanged).
  if (const int s = multiplicity(q.knots, a); s < p) q = insert_knot(q, a, p - s);
  if (const int s = multiplicity(q.knots, b); s < p && b < q.knots.back()) q = insert_knot(q, b, p - s);
  const auto& U = q.knots;
  // Last index holding a, first index holding b.
  const size_t ia = static_cast<size_t>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1;
  const size_t ib = static_cast<size_t>(std::lower_bound(U.begin(), U.end(), b) - U.begin());
  // C(a) = P[ia - p] and C(b) = P[ib - 1]; the knots before a and after b
  // only shape basis functions that vanish on [a, b], so replacing them by
  // a and b keeps the curve.
  NurbsCurve out;
  out.dim = c.dim;
  out.degree = p;
  out.knots.assign(static_cast<size_t>(p) + 1, a);
  out.knots.insert(out.knots.end(), U.begin() + static_cast<std::ptrdiff_t>(ia) + 1,
                   U.begin() + static_cast<std::ptrdiff_t>(ib));
  out.knots.insert(out.knots.end(), static_cast<size_t>(p) + 1, b);
  out.points.assign(q.points.begin() + static_cast<std::ptrdiff_t>(ia) - p,
                    q.points.begin() + static_cast<std::ptrdiff_t>(ib));
  if (q.rational())
    out.weights.assign(q.weights.begin() + static_cast<std::ptrdiff_t>(ia) - p,
                       q.weights.begin() + static_cast<std::ptrdiff_t>(ib));
  return out;
}

std::vector<Bezier> to_bezier(const NurbsCurve& curve) {
  const NurbsCurve c = clamp(curve);
  const int p = c.degree;
  const auto& U = c.knots;
  const int m = static_cast<int>(U.size()) - 1;
  const std::vector<HPoint> Pw = homogeneous(c);
  // A5.6 (DecomposeCurve): insert every interior knot up to multiplicity p,
  // reading off one Bézier segment per span as it completes.
  std::vector<std::vector<HPoint>> Qw(1, std::vector<HPoint>(static_cast<size_t>(p) + 1));
  std::vector<double> alphas(static_cast<size_t>(p) + 1);
  int a = p, b = p + 1, nb = 0;
  for (int i = 0; i <= p; ++i) Qw[0][i] = Pw[i];
  while (b < m) {
    const int i = b;
    while (b < m && U[b + 1] == U[b]) ++b;
    const int mult = b - i + 1;
    const bool more = b < m;  // false once the end knots are reached
    if (more) Qw.emplace_back(static_cast<size_t>(p) + 1);
    if (mult < p) {
      const double numer = U[b] - U[a];
      for (int j = p; j > mult; --j) alphas[j - mult - 1] = numer / (U[a + j] - U[a]);
      const int r = p - mult;
      for (int j = 1; j <= r; ++j) {
        const int save = r - j, s = mult + j;
        for (int k = p; k >= s; --k) {
          const double alpha = alphas[k - s];
          Qw[nb][k] = Qw[nb][k] * alpha + Qw[nb][k - 1] * (1.0 - alpha);
        }
        if (more) Qw[nb + 1][save] = Qw[nb][p];
      }
    }
    ++nb;
    if (more) {
      for (int k = p - mult; k <= p; ++k) Qw[nb][k] = Pw[b - p + k];
      a = b;
      ++b;
    }
  }
  std::vector<Bezier> out;
  out.reserve(Qw.size());
  for (const auto& seg : Qw) {
    Bezier z;
    z.dim = c.dim;
    z.points.resize(seg.size());
    for (size_t k = 0; k < seg.size(); ++k) z.points[k] = seg[k].p / seg[k].w;
    if (c.dim == 2)
      for (auto& q : z.points) q.z = 0;  // exact zero, whatever the division gave
    if (c.rational()) {
      z.weights.resize(seg.size());
      for (size_t k = 0; k < seg.size(); ++k) z.weights[k] = seg[k].w / seg[0].w;
    }
    out.push_back(std::move(z));
  }
  return out;
}

NurbsCurve from_bezier(const Bezier& b) {
  NurbsCurve c;
  c.dim = b.dim;
  c.degree = b.degree();
  c.points = b.points;
  c.weights = b.weights;
  c.knots.assign(static_cast<size_t>(c.degree) + 1, 0.0);
  c.knots.insert(c.knots.end(), static_cast<size_t>(c.degree) + 1, 1.0);
  return c;
}

}  // namespace bezcam
