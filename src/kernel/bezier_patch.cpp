#include "bezcam/kernel/bezier_patch.hpp"

#include <cmath>
#include <string>

#include "bernstein_ops.hpp"
#include "bezcam/error.hpp"

namespace bezcam {

using detail::Grid;
using detail::Hom;
using detail::Poly;

namespace {

std::string ij(size_t i, size_t j) { return "[" + std::to_string(i) + "][" + std::to_string(j) + "]"; }

// The net in homogeneous coordinates (weights 1 for a polynomial patch).
Grid<Hom> hom_grid(const BezierPatch& s) {
  Grid<Hom> g(s.nu, s.nv);
  for (int i = 0; i <= s.nu; ++i)
    for (int j = 0; j <= s.nv; ++j) g.at(i, j) = Hom::of(s.at(i, j), s.weight(i, j));
  return g;
}

Grid<Vec3> vec_grid(const BezierPatch& s) {
  Grid<Vec3> g(s.nu, s.nv);
  g.c = s.points;
  return g;
}

BezierPatch from_hom_grid(const Grid<Hom>& g, bool rational) {
  BezierPatch s;
  s.nu = g.nu;
  s.nv = g.nv;
  s.points.resize(g.c.size());
  if (rational) s.weights.resize(g.c.size());
  for (size_t k = 0; k < g.c.size(); ++k) {
    s.points[k] = rational ? g.c[k].point() : g.c[k].p;
    if (rational) s.weights[k] = g.c[k].w;
  }
  return s;
}

Poly<Vec3> points_of(const Poly<Hom>& h) {
  Poly<Vec3> r(h.size());
  for (size_t i = 0; i < h.size(); ++i) r[i] = h[i].p;
  return r;
}

// Numerators of Su and Sv along a curve of homogeneous coefficients x(t),
// given the tangent-direction polynomial `xt` = dx/dt and the
// cross-direction one `xc` = dx/d(other), all as polynomials in t. For
// S = X / w: dS = (dX w - X dw) / w^2, so the numerator is polynomial.
Poly<Vec3> quotient_numerator(const Poly<Hom>& x, const Poly<Hom>& dx, bool rational) {
  if (!rational) return points_of(dx);
  const Poly<Vec3> a = detail::bern_scale(points_of(dx), detail::weights_of(x));
  const Poly<Vec3> b = detail::bern_scale(points_of(x), detail::weights_of(dx));
  Poly<Vec3> r = detail::bern_elevate(a, std::max(detail::degree_of(a), detail::degree_of(b)));
  const Poly<Vec3> bb = detail::bern_elevate(b, detail::degree_of(r));
  for (size_t i = 0; i < r.size(); ++i) r[i] -= bb[i];
  return r;
}

}  // namespace

BezierPatch BezierPatch::make(const std::vector<std::vector<Vec3>>& rows,
                              const std::vector<std::vector<double>>& weights) {
  if (rows.size() < 2)
    throw InputError(errc::patch_too_few_rows, Place::at_json("points"),
                     "expected at least 2 rows of control points, found " + std::to_string(rows.size()));
  const size_t m1 = rows[0].size();
  if (m1 < 2)
    throw InputError(errc::patch_too_few_points, Place::at_json("points[0]"),
                     "expected at least 2 control points per row, found " + std::to_string(m1));
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].size() != m1)
      throw InputError(errc::patch_row_length, Place::at_json("points[" + std::to_string(i) + "]"),
                       "expected a row of " + std::to_string(m1) + " points like points[0], found " +
                           std::to_string(rows[i].size()) + "; every row of the net has the same length");
    for (size_t j = 0; j < m1; ++j)
      if (!all_finite(rows[i][j]))
        throw InputError(errc::patch_not_finite, Place::at_json("points" + ij(i, j)), "expected finite coordinates");
  }
  const int nu = static_cast<int>(rows.size()) - 1, nv = static_cast<int>(m1) - 1;
  if (nu > kMaxBezierDegree || nv > kMaxBezierDegree)
    throw InputError(errc::patch_degree_too_high, Place::at_json("points"),
                     "expected degrees of at most " + std::to_string(kMaxBezierDegree) + ", found " +
                         std::to_string(nu) + " x " + std::to_string(nv));
  BezierPatch s;
  s.nu = nu;
  s.nv = nv;
  for (const auto& r : rows) s.points.insert(s.points.end(), r.begin(), r.end());
  if (!weights.empty()) {
    if (weights.size() != rows.size())
      throw InputError(errc::patch_weights_shape, Place::at_json("weights"),
                       "expected one row of weights per row of points (" + std::to_string(rows.size()) + "), found " +
                           std::to_string(weights.size()));
    bool all_equal = true;
    for (size_t i = 0; i < weights.size(); ++i) {
      if (weights[i].size() != m1)
        throw InputError(errc::patch_weights_shape, Place::at_json("weights[" + std::to_string(i) + "]"),
                         "expected " + std::to_string(m1) + " weights like the row of points, found " +
                             std::to_string(weights[i].size()));
      for (size_t j = 0; j < m1; ++j) {
        const double w = weights[i][j];
        if (!(w > 0) || !std::isfinite(w))
          throw InputError(errc::patch_weight, Place::at_json("weights" + ij(i, j)),
                           "expected a finite weight > 0, found " + fmt_num(w));
        all_equal = all_equal && w == weights[0][0];
        s.weights.push_back(w);
      }
    }
    if (all_equal) s.weights.clear();  // equal weights: the patch is polynomial
  }
  return s;
}

namespace {

// Degrees up to this are evaluated in reused scratch (no allocation: the
// pass planner evaluates the surface millions of times).
constexpr int kStackDegree = 160;

// Value and first and second derivatives at t of the Bernstein polynomial
// c[0..n], by de Casteljau down to three points q0, q1, q2: f'' = n (n-1)
// (q0 - 2 q1 + q2), then r0, r1 one level lower: f' = n (r1 - r0).
// `work` holds n + 1 values.
void bern_eval2(const Hom* c, int n, double t, Hom* work, Hom& f, Hom& d1, Hom& d2) {
  if (n == 0) {
    f = c[0];
    d1 = d2 = Hom(Vec3{}, 0);
    return;
  }
  std::copy(c, c + n + 1, work);
  const double s = 1 - t;
  for (int r = 1; r <= n - 2; ++r)
    for (int i = 0; i + r <= n; ++i) work[i] = work[i] * s + work[i + 1] * t;
  Hom r0 = work[0], r1 = work[1];
  d2 = Hom(Vec3{}, 0);
  if (n >= 2) {
    d2 = (work[0] - work[1] * 2 + work[2]) * double(n * (n - 1));
    r0 = work[0] * s + work[1] * t;
    r1 = work[1] * s + work[2] * t;
  }
  d1 = (r1 - r0) * double(n);
  f = r0 * s + r1 * t;
}

// Homogeneous value and partials up to order 2: H, Hu, Hv, Huu, Huv, Hvv.
struct HomDerivs {
  Hom h, hu, hv, huu, huv, hvv;
};

HomDerivs hom_derivs(const BezierPatch& s, double u, double v) {
  HomDerivs r;
  if (s.nu > kStackDegree || s.nv > kStackDegree) {
    // Rare (very high degrees): the allocating form.
    const Grid<Hom> g = hom_grid(s);
    Poly<Hom> c0(s.nu + 1), c1(s.nu + 1), c2(s.nu + 1);
    for (int i = 0; i <= s.nu; ++i) {
      const Poly<Hom> row = g.row(i);
      const Poly<Hom> r1 = detail::bern_derivative(row);
      c0[i] = detail::bern_eval(row, v);
      c1[i] = detail::bern_eval(r1, v);
      c2[i] = detail::bern_eval(detail::bern_derivative(r1), v);
    }
    const Poly<Hom> c0u = detail::bern_derivative(c0);
    r.h = detail::bern_eval(c0, u);
    r.hu = detail::bern_eval(c0u, u);
    r.huu = detail::bern_eval(detail::bern_derivative(c0u), u);
    r.hv = detail::bern_eval(c1, u);
    r.huv = detail::bern_eval(detail::bern_derivative(c1), u);
    r.hvv = detail::bern_eval(c2, u);
    return r;
  }
  // Scratch reused across calls (a stack array of Hom would be zeroed on
  // every call, which costs more than the evaluation).
  thread_local std::vector<Hom> scratch;
  scratch.resize(size_t(5) * (kStackDegree + 1));
  Hom* row = scratch.data();
  Hom* work = row + (kStackDegree + 1);
  Hom* c0 = work + (kStackDegree + 1);
  Hom* c1 = c0 + (kStackDegree + 1);
  Hom* c2 = c1 + (kStackDegree + 1);
  for (int i = 0; i <= s.nu; ++i) {
    for (int j = 0; j <= s.nv; ++j) row[j] = Hom::of(s.at(i, j), s.weight(i, j));
    bern_eval2(row, s.nv, v, work, c0[i], c1[i], c2[i]);
  }
  Hom unused;
  bern_eval2(c0, s.nu, u, work, r.h, r.hu, r.huu);
  bern_eval2(c1, s.nu, u, work, r.hv, r.huv, unused);
  bern_eval2(c2, s.nu, u, work, r.hvv, unused, unused);
  return r;
}

}  // namespace

Vec3 evaluate(const BezierPatch& s, double u, double v) {
  if (s.nu > kStackDegree || s.nv > kStackDegree) {
    const Grid<Hom> g = hom_grid(s);
    return detail::bern_eval(detail::grid_at(g, 'v', v), u).point();
  }
  // de Casteljau on every row at v, then on the column of results at u.
  thread_local std::vector<Hom> scratch;
  scratch.resize(size_t(2) * (kStackDegree + 1));
  Hom* col = scratch.data();
  Hom* row = col + (kStackDegree + 1);
  const double su = 1 - u, sv = 1 - v;
  for (int i = 0; i <= s.nu; ++i) {
    for (int j = 0; j <= s.nv; ++j) row[j] = Hom::of(s.at(i, j), s.weight(i, j));
    for (int r = 1; r <= s.nv; ++r)
      for (int j = 0; j + r <= s.nv; ++j) row[j] = row[j] * sv + row[j + 1] * v;
    col[i] = row[0];
  }
  for (int r = 1; r <= s.nu; ++r)
    for (int i = 0; i + r <= s.nu; ++i) col[i] = col[i] * su + col[i + 1] * u;
  return col[0].point();
}

Vec3 evaluate_bernstein(const BezierPatch& s, double u, double v) {
  Vec3 num;
  double den = 0;
  for (int i = 0; i <= s.nu; ++i)
    for (int j = 0; j <= s.nv; ++j) {
      const double b = bernstein(s.nu, i, u) * bernstein(s.nv, j, v) * s.weight(i, j);
      num += s.at(i, j) * b;
      den += b;
    }
  return num / den;
}

PatchDerivs evaluate_derivs(const BezierPatch& s, double u, double v) {
  const HomDerivs r = hom_derivs(s, u, v);
  const Hom &h = r.h, &hu = r.hu, &hv = r.hv, &huu = r.huu, &huv = r.huv, &hvv = r.hvv;
  // Quotient rule for S = X / w (X = w S): X' = w' S + w S', and so on.
  PatchDerivs d;
  const double w = h.w;
  d.p = h.p / w;
  d.su = (hu.p - d.p * hu.w) / w;
  d.sv = (hv.p - d.p * hv.w) / w;
  d.suu = (huu.p - d.su * (2 * hu.w) - d.p * huu.w) / w;
  d.suv = (huv.p - d.su * hv.w - d.sv * hu.w - d.p * huv.w) / w;
  d.svv = (hvv.p - d.sv * (2 * hv.w) - d.p * hvv.w) / w;
  return d;
}

namespace {
// Homogeneous coefficients of the iso-curve (along `dir` at `at`) and of the
// derivative across it, as polynomials in the curve's parameter.
std::pair<Poly<Hom>, Poly<Hom>> iso_hom(const BezierPatch& s, char dir, double at) {
  const Grid<Hom> g = hom_grid(s);
  if (dir == 'u') {
    Poly<Hom> x(s.nu + 1), xc(s.nu + 1);
    for (int i = 0; i <= s.nu; ++i) {
      const Poly<Hom> r = g.row(i);
      x[i] = detail::bern_eval(r, at);
      xc[i] = detail::bern_eval(detail::bern_derivative(r), at);
    }
    return {x, xc};
  }
  Poly<Hom> x(s.nv + 1), xc(s.nv + 1);
  for (int j = 0; j <= s.nv; ++j) {
    const Poly<Hom> c = g.col(j);
    x[j] = detail::bern_eval(c, at);
    xc[j] = detail::bern_eval(detail::bern_derivative(c), at);
  }
  return {x, xc};
}
}  // namespace

Bezier iso_curve(const BezierPatch& s, char dir, double at) {
  return detail::from_homogeneous(iso_hom(s, dir, at).first, s.rational());
}

Bezier iso_normal(const BezierPatch& s, char dir, double at) {
  const auto [x, xc] = iso_hom(s, dir, at);
  const bool rat = s.rational();
  const Poly<Vec3> tangent = quotient_numerator(x, detail::bern_derivative(x), rat);
  const Poly<Vec3> across = quotient_numerator(x, xc, rat);
  // n = Su x Sv: along u the tangent is Su, along v it is Sv.
  return detail::from_vectors(dir == 'u' ? detail::bern_cross(tangent, across) : detail::bern_cross(across, tangent));
}

BezierPatch subpatch(const BezierPatch& s, double u0, double u1, double v0, double v1) {
  const Grid<Hom> g = hom_grid(s);
  Grid<Hom> a(s.nu, s.nv);
  for (int i = 0; i <= s.nu; ++i) {
    const Poly<Hom> r = detail::bern_restrict(g.row(i), v0, v1);
    for (int j = 0; j <= s.nv; ++j) a.at(i, j) = r[j];
  }
  for (int j = 0; j <= s.nv; ++j) {
    const Poly<Hom> c = detail::bern_restrict(a.col(j), u0, u1);
    for (int i = 0; i <= s.nu; ++i) a.at(i, j) = c[i];
  }
  return from_hom_grid(a, s.rational());
}

Box3 control_bounds(const BezierPatch& s) {
  Box3 b;
  for (const auto& p : s.points) b.add(p);
  return b;
}

namespace {
// The corners are on the patch; the net's box contains it. Split until the
// net's box exceeds the box found so far by at most eps in every axis.
void tight_bounds(const BezierPatch& s, Box3& box, double eps, int depth) {
  const Box3 hull = control_bounds(s);
  const bool inside = box.contains(hull, eps);
  if (inside || depth > 24) {
    if (!inside) box.add(hull);
    return;
  }
  const BezierPatch parts[4] = {subpatch(s, 0, 0.5, 0, 0.5), subpatch(s, 0.5, 1, 0, 0.5), subpatch(s, 0, 0.5, 0.5, 1),
                                subpatch(s, 0.5, 1, 0.5, 1)};
  for (const auto& p : parts) {
    box.add(p.at(0, 0));
    box.add(p.at(p.nu, p.nv));
  }
  for (const auto& p : parts) tight_bounds(p, box, eps, depth + 1);
}
}  // namespace

Box3 bounds(const BezierPatch& s) {
  Box3 box;
  for (const auto& p : {s.at(0, 0), s.at(s.nu, 0), s.at(0, s.nv), s.at(s.nu, s.nv)}) box.add(p);
  const Box3 hull = control_bounds(s);
  double size = 0;
  for (int k = 0; k < 3; ++k) size = std::max(size, hull.hi[k] - hull.lo[k]);
  tight_bounds(s, box, 1e-9 * size, 0);
  return box;
}

BezierPatch normal_patch(const BezierPatch& s) {
  auto cross_mul = [](const Vec3& a, const Vec3& b) { return cross(a, b); };
  Grid<Vec3> n;
  if (!s.rational()) {
    const Grid<Vec3> x = vec_grid(s);
    n = detail::grid_product(detail::grid_derivative(x, 'u'), detail::grid_derivative(x, 'v'), cross_mul);
  } else {
    // G_u = X_u w - X w_u, G_v = X_v w - X w_v (numerators of Su, Sv).
    const Grid<Hom> h = hom_grid(s);
    Grid<Vec3> x(s.nu, s.nv);
    Grid<double> w(s.nu, s.nv);
    for (size_t k = 0; k < h.c.size(); ++k) x.c[k] = h.c[k].p, w.c[k] = h.c[k].w;
    auto mul = [](const Vec3& a, double b) { return a * b; };
    auto numer = [&](char d) {
      Grid<Vec3> a = detail::grid_product(detail::grid_derivative(x, d), w, mul);
      const Grid<Vec3> b = detail::grid_product(x, detail::grid_derivative(w, d), mul);
      for (size_t k = 0; k < a.c.size(); ++k) a.c[k] -= b.c[k];
      return a;
    };
    n = detail::grid_product(numer('u'), numer('v'), cross_mul);
  }
  BezierPatch r;
  r.nu = n.nu;
  r.nv = n.nv;
  r.points = std::move(n.c);
  return r;
}

namespace {
// B(n,i)(u(w)) in homogeneous form, i = 0..n: C(n,i) U^i (W - U)^(n-i)
// where u = U / W; each of degree n d.
std::vector<Poly<double>> composed_basis(int n, const Poly<double>& U, const Poly<double>& W) {
  Poly<double> R(U.size());
  for (size_t k = 0; k < U.size(); ++k) R[k] = W[k] - U[k];
  std::vector<Poly<double>> up(n + 1), rp(n + 1);
  up[0] = rp[0] = {1.0};
  auto mul = [](double a, double b) { return a * b; };
  for (int i = 1; i <= n; ++i) {
    up[i] = detail::bern_product(up[i - 1], U, mul);
    rp[i] = detail::bern_product(rp[i - 1], R, mul);
  }
  std::vector<Poly<double>> basis(n + 1);
  for (int i = 0; i <= n; ++i) {
    basis[i] = detail::bern_product(up[i], rp[n - i], mul);
    for (double& c : basis[i]) c *= binomial(n, i);
  }
  return basis;
}

// sum_i sum_j q(i,j) Bu_i(w) Bv_j(w), without division: a polynomial of
// degree (nu + nv) d in w.
template <class T>
Poly<T> compose_grid(const Grid<T>& q, const Bezier& uv) {
  const int d = uv.degree();
  Poly<double> U(d + 1), V(d + 1), W(d + 1);
  for (int k = 0; k <= d; ++k) {
    W[k] = uv.weight(k);
    U[k] = uv.points[k].x * W[k];
    V[k] = uv.points[k].y * W[k];
  }
  const auto bu = composed_basis(q.nu, U, W), bv = composed_basis(q.nv, V, W);
  Poly<T> out;
  for (int j = 0; j <= q.nv; ++j) {
    Poly<T> inner(bu[0].size(), q.c[0] * 0.0);
    for (int i = 0; i <= q.nu; ++i)
      for (size_t k = 0; k < inner.size(); ++k) inner[k] += q.at(i, j) * bu[i][k];
    const Poly<T> term = detail::bern_scale(inner, bv[j]);
    if (out.empty()) {
      out = term;
    } else {
      for (size_t k = 0; k < out.size(); ++k) out[k] += term[k];
    }
  }
  return out;
}
}  // namespace

Bezier compose(const BezierPatch& s, const Bezier& uv) {
  const Poly<Hom> r = compose_grid(hom_grid(s), uv);
  return detail::from_homogeneous(r, s.rational() || uv.rational());
}

Bezier compose_direction(const BezierPatch& field, const Bezier& uv) {
  return detail::from_vectors(compose_grid(vec_grid(field), uv));
}

std::pair<size_t, double> locate_span(const std::vector<double>& breaks, double t) {
  const size_t n = breaks.size() - 1;
  size_t k = static_cast<size_t>(std::upper_bound(breaks.begin(), breaks.end(), t) - breaks.begin());
  k = k == 0 ? 0 : k - 1;
  if (k >= n) k = n - 1;
  const double a = breaks[k], b = breaks[k + 1];
  return {k, std::clamp((t - a) / (b - a), 0.0, 1.0)};
}

PatchDerivs evaluate_derivs(const PatchGrid& g, double u, double v) {
  const auto [a, lu] = locate_span(g.ubreaks, u);
  const auto [b, lv] = locate_span(g.vbreaks, v);
  PatchDerivs d = evaluate_derivs(g.cell(a, b), lu, lv);
  // Chain rule: local = (global - start) / span.
  const double ku = 1 / (g.ubreaks[a + 1] - g.ubreaks[a]), kv = 1 / (g.vbreaks[b + 1] - g.vbreaks[b]);
  d.su *= ku;
  d.sv *= kv;
  d.suu *= ku * ku;
  d.suv *= ku * kv;
  d.svv *= kv * kv;
  return d;
}

}  // namespace bezcam
