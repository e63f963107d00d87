#pragma once
// Internal to the kernel (and its tests): arithmetic on polynomials in
// Bernstein form over [0,1], for the exact constructions of the surface
// code (iso-curves, normals, Coons cells, curves on a surface).
//
// A polynomial of degree n is the vector of its n + 1 Bernstein
// coefficients. Coefficients are double, Vec3 or Hom (a homogeneous point
// (w P, w) of a rational construction). Every operation here is exact in
// exact arithmetic; in floating point each is a short sum of products with
// non-negative factors, so errors stay a small multiple of eps times the
// coefficients' magnitude (Farouki & Rajan, "Algorithms for polynomials in
// Bernstein form", 1988: products, elevation, subdivision).
#include <algorithm>
#include <cassert>
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam::detail {

/// Homogeneous point: p = w * P (the weighted point) and the weight w.
struct Hom {
  Vec3 p;
  double w = 0;
  Hom() = default;
  Hom(const Vec3& p_, double w_) : p(p_), w(w_) {}
  /// The homogeneous form of point P with weight w.
  static Hom of(const Vec3& P, double w) { return {P * w, w}; }
  Vec3 point() const { return p / w; }
  Hom operator+(const Hom& o) const { return {p + o.p, w + o.w}; }
  Hom operator-(const Hom& o) const { return {p - o.p, w - o.w}; }
  Hom operator*(double s) const { return {p * s, w * s}; }
  Hom& operator+=(const Hom& o) {
    p += o.p;
    w += o.w;
    return *this;
  }
};

template <class T>
using Poly = std::vector<T>;

template <class T>
int degree_of(const Poly<T>& c) {
  return static_cast<int>(c.size()) - 1;
}

/// Value at t by de Casteljau's cascade.
template <class T>
T bern_eval(Poly<T> c, double t) {
  const double s = 1 - t;
  for (size_t r = 1; r < c.size(); ++r)
    for (size_t i = 0; i + r < c.size(); ++i) c[i] = c[i] * s + c[i + 1] * t;
  return c[0];
}

/// Derivative: degree n - 1 with coefficients n (c_{i+1} - c_i); the
/// derivative of a constant is the zero constant.
template <class T>
Poly<T> bern_derivative(const Poly<T>& c) {
  const int n = degree_of(c);
  if (n <= 0) return {c[0] * 0.0};
  Poly<T> d(n);
  for (int i = 0; i < n; ++i) d[i] = (c[i + 1] - c[i]) * double(n);
  return d;
}

/// The same polynomial written with degree `to` >= its degree (repeated
/// degree elevation: c'_i = i/(n+1) c_{i-1} + (1 - i/(n+1)) c_i).
template <class T>
Poly<T> bern_elevate(Poly<T> c, int to) {
  assert(to >= degree_of(c));
  while (degree_of(c) < to) {
    const int n = degree_of(c);
    Poly<T> e(n + 2);
    e[0] = c[0];
    e[n + 1] = c[n];
    for (int i = 1; i <= n; ++i) {
      const double a = double(i) / (n + 1);
      e[i] = c[i - 1] * a + c[i] * (1 - a);
    }
    c = std::move(e);
  }
  return c;
}

/// Splits at t; returns the coefficients of the part on [0, t] (left) or
/// [t, 1] (right), each reparametrised on [0, 1].
template <class T>
Poly<T> bern_split(const Poly<T>& c, double t, bool left) {
  Poly<T> q = c, out(c.size());
  const size_t n = c.size() - 1;
  const double s = 1 - t;
  if (left)
    out[0] = q[0];
  else
    out[n] = q[n];
  for (size_t r = 1; r <= n; ++r) {
    for (size_t i = 0; i + r <= n; ++i) q[i] = q[i] * s + q[i + 1] * t;
    if (left)
      out[r] = q[0];
    else
      out[n - r] = q[n - r];
  }
  return out;
}

/// The polynomial restricted to [t0, t1], reparametrised on [0, 1].
template <class T>
Poly<T> bern_restrict(const Poly<T>& c, double t0, double t1) {
  if (t0 == 0 && t1 == 1) return c;
  if (t0 == 0) return bern_split(c, t1, true);
  Poly<T> right = bern_split(c, t0, false);
  if (t1 == 1) return right;
  return bern_split(right, (t1 - t0) / (1 - t0), true);
}

/// Weight of coefficient pair (i, k - i) in the product of degrees m and n:
/// C(m,i) C(n,k-i) / C(m+n,k).
inline double product_weight(int m, int n, int i, int k) {
  return binomial(m, i) * binomial(n, k - i) / binomial(m + n, k);
}

/// Product of two polynomials given a coefficient product `mul(a_i, b_j)`;
/// the degree is the sum of the degrees.
template <class A, class B, class F>
auto bern_product(const Poly<A>& a, const Poly<B>& b, F mul) -> Poly<decltype(mul(a[0], b[0]))> {
  using R = decltype(mul(a[0], b[0]));
  const int m = degree_of(a), n = degree_of(b);
  Poly<R> c(m + n + 1);
  for (int k = 0; k <= m + n; ++k) {
    R s = mul(a[0], b[0]) * 0.0;
    for (int i = std::max(0, k - n); i <= std::min(m, k); ++i) s += mul(a[i], b[k - i]) * product_weight(m, n, i, k);
    c[k] = s;
  }
  return c;
}

/// Product with a scalar polynomial.
template <class T>
Poly<T> bern_scale(const Poly<T>& a, const Poly<double>& s) {
  return bern_product(a, s, [](const T& x, double y) { return x * y; });
}

/// Sum of polynomials of possibly different degrees.
template <class T>
Poly<T> bern_add(const Poly<T>& a, const Poly<T>& b) {
  const int d = std::max(degree_of(a), degree_of(b));
  Poly<T> x = bern_elevate(a, d), y = bern_elevate(b, d);
  for (size_t i = 0; i < x.size(); ++i) x[i] += y[i];
  return x;
}

/// Cross product of two vector polynomials.
inline Poly<Vec3> bern_cross(const Poly<Vec3>& a, const Poly<Vec3>& b) {
  return bern_product(a, b, [](const Vec3& x, const Vec3& y) { return cross(x, y); });
}

/// Homogeneous coefficients of a Bézier curve (weights 1 when polynomial).
inline Poly<Hom> homogeneous(const Bezier& b) {
  Poly<Hom> h(b.points.size());
  for (size_t i = 0; i < h.size(); ++i) h[i] = Hom::of(b.points[i], b.weight(static_cast<int>(i)));
  return h;
}

/// The weights of homogeneous coefficients.
inline Poly<double> weights_of(const Poly<Hom>& h) {
  Poly<double> r(h.size());
  for (size_t i = 0; i < h.size(); ++i) r[i] = h[i].w;
  return r;
}

/// The curve of homogeneous coefficients; `rational` false keeps only the
/// points (their weights are 1 up to rounding). Weights are normalised so
/// the first is 1. Does not validate (degrees may exceed kMaxBezierDegree).
inline Bezier from_homogeneous(const Poly<Hom>& h, bool rational, int dim = 3) {
  Bezier b;
  b.dim = dim;
  b.points.resize(h.size());
  if (!rational) {
    for (size_t i = 0; i < h.size(); ++i) b.points[i] = h[i].p;
    return b;
  }
  b.weights.resize(h.size());
  const double w0 = h.front().w;
  for (size_t i = 0; i < h.size(); ++i) {
    b.points[i] = h[i].p / h[i].w;
    b.weights[i] = h[i].w / w0;
  }
  return b;
}

/// A polynomial curve of vector coefficients as a Bézier (at least 2 points).
inline Bezier from_vectors(Poly<Vec3> c, int dim = 3) {
  if (c.size() == 1) c.push_back(c[0]);
  Bezier b;
  b.dim = dim;
  b.points = std::move(c);
  return b;
}

/// A tensor-product polynomial in Bernstein form: c[i * (nv + 1) + j] is
/// the coefficient of B(nu,i)(u) B(nv,j)(v).
template <class T>
struct Grid {
  int nu = 0, nv = 0;
  std::vector<T> c;
  Grid() = default;
  Grid(int nu_, int nv_) : nu(nu_), nv(nv_), c(size_t(nu_ + 1) * (nv_ + 1)) {}
  T& at(int i, int j) { return c[size_t(i) * (nv + 1) + j]; }
  const T& at(int i, int j) const { return c[size_t(i) * (nv + 1) + j]; }
  Poly<T> row(int i) const { return Poly<T>(c.begin() + size_t(i) * (nv + 1), c.begin() + size_t(i + 1) * (nv + 1)); }
  Poly<T> col(int j) const {
    Poly<T> r(nu + 1);
    for (int i = 0; i <= nu; ++i) r[i] = at(i, j);
    return r;
  }
};

/// Tensor product a(u) b(v).
template <class A, class B, class F>
auto grid_tensor(const Poly<A>& a, const Poly<B>& b, F mul) -> Grid<decltype(mul(a[0], b[0]))> {
  Grid<decltype(mul(a[0], b[0]))> g(degree_of(a), degree_of(b));
  for (int i = 0; i <= g.nu; ++i)
    for (int j = 0; j <= g.nv; ++j) g.at(i, j) = mul(a[i], b[j]);
  return g;
}

/// Elevates to degrees (du, dv).
template <class T>
Grid<T> grid_elevate(const Grid<T>& g, int du, int dv) {
  Grid<T> a(g.nu, dv);
  for (int i = 0; i <= g.nu; ++i) {
    const Poly<T> r = bern_elevate(g.row(i), dv);
    for (int j = 0; j <= dv; ++j) a.at(i, j) = r[j];
  }
  Grid<T> b(du, dv);
  for (int j = 0; j <= dv; ++j) {
    const Poly<T> col = bern_elevate(a.col(j), du);
    for (int i = 0; i <= du; ++i) b.at(i, j) = col[i];
  }
  return b;
}

/// Partial derivative in u ('u') or v ('v').
template <class T>
Grid<T> grid_derivative(const Grid<T>& g, char dir) {
  if (dir == 'u') {
    Grid<T> d(std::max(g.nu - 1, 0), g.nv);
    for (int j = 0; j <= g.nv; ++j) {
      const Poly<T> col = bern_derivative(g.col(j));
      for (int i = 0; i <= d.nu; ++i) d.at(i, j) = col[i];
    }
    return d;
  }
  Grid<T> d(g.nu, std::max(g.nv - 1, 0));
  for (int i = 0; i <= g.nu; ++i) {
    const Poly<T> r = bern_derivative(g.row(i));
    for (int j = 0; j <= d.nv; ++j) d.at(i, j) = r[j];
  }
  return d;
}

/// Product of two tensor-product polynomials (degrees add in each variable).
template <class A, class B, class F>
auto grid_product(const Grid<A>& a, const Grid<B>& b, F mul) -> Grid<decltype(mul(a.c[0], b.c[0]))> {
  using R = decltype(mul(a.c[0], b.c[0]));
  Grid<R> g(a.nu + b.nu, a.nv + b.nv);
  for (auto& x : g.c) x = mul(a.c[0], b.c[0]) * 0.0;
  for (int i1 = 0; i1 <= a.nu; ++i1)
    for (int j1 = 0; j1 <= a.nv; ++j1)
      for (int i2 = 0; i2 <= b.nu; ++i2)
        for (int j2 = 0; j2 <= b.nv; ++j2) {
          const double k = product_weight(a.nu, b.nu, i1, i1 + i2) * product_weight(a.nv, b.nv, j1, j1 + j2);
          g.at(i1 + i2, j1 + j2) += mul(a.at(i1, j1), b.at(i2, j2)) * k;
        }
  return g;
}

/// The polynomial in the other variable at u = t ('u': a polynomial in v)
/// or v = t ('v': a polynomial in u).
template <class T>
Poly<T> grid_at(const Grid<T>& g, char fixed, double t) {
  if (fixed == 'u') {
    Poly<T> r(g.nv + 1);
    for (int j = 0; j <= g.nv; ++j) r[j] = bern_eval(g.col(j), t);
    return r;
  }
  Poly<T> r(g.nu + 1);
  for (int i = 0; i <= g.nu; ++i) r[i] = bern_eval(g.row(i), t);
  return r;
}

}  // namespace bezcam::detail
