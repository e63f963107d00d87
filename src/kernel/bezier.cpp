#include "bezcam/kernel/bezier.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/kernel/quadrature.hpp"
#include "bezcam/kernel/roots.hpp"

namespace bezcam {

namespace {

// Homogeneous point (w P, w) for rational de Casteljau.
struct H {
  Vec3 p;
  double w;
};

// Runs the de Casteljau cascade on homogeneous points; when `left`/`right`
// are given they receive the control points of the two halves.
H cascade(const Bezier& b, double t, std::vector<H>* left = nullptr, std::vector<H>* right = nullptr) {
  const int n = b.degree();
  // On the stack for the usual degrees (evaluation runs millions of times
  // in the measurement); the same arithmetic either way.
  constexpr int kStack = 16;
  H stack[kStack];
  std::vector<H> heap;
  if (n + 1 > kStack) heap.resize(n + 1);
  H* q = n + 1 > kStack ? heap.data() : stack;
  for (int i = 0; i <= n; ++i) {
    const double w = b.weight(i);
    q[i] = {b.points[i] * w, w};
  }
  if (left) {
    left->resize(n + 1);
    (*left)[0] = q[0];
  }
  if (right) {
    right->resize(n + 1);
    (*right)[n] = q[n];
  }
  const double s = 1 - t;
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) {
      q[i] = {q[i].p * s + q[i + 1].p * t, q[i].w * s + q[i + 1].w * t};
    }
    if (left) (*left)[r] = q[0];
    if (right) (*right)[n - r] = q[n - r];
  }
  return q[0];
}

Bezier from_homogeneous(const std::vector<H>& hs, const Bezier& like) {
  Bezier out;
  out.dim = like.dim;
  out.points.resize(hs.size());
  for (size_t i = 0; i < hs.size(); ++i) out.points[i] = hs[i].p / hs[i].w;
  if (like.rational()) {
    out.weights.resize(hs.size());
    // Normalise so the first weight is 1: same curve, tidier numbers.
    const double w0 = hs.front().w;
    for (size_t i = 0; i < hs.size(); ++i) out.weights[i] = hs[i].w / w0;
  }
  return out;
}

}  // namespace

void validate_control_points(std::span<const Vec3> pts, std::span<const double> w, int dim) {
  for (size_t i = 0; i < pts.size(); ++i) {
    if (!all_finite(pts[i]))
      throw InputError(errc::curve_not_finite, Place::at_json("points[" + std::to_string(i) + "]"),
                       "expected finite coordinates");
    if (dim == 2 && pts[i].z != 0)
      throw InputError(errc::curve_dimension, Place::at_json("points[" + std::to_string(i) + "]"),
                       "2D curve with a z coordinate");
  }
  if (w.empty()) return;
  if (w.size() != pts.size())
    throw InputError(errc::curve_weights_count, Place::at_json("weights"),
                     "expected one weight per control point (" + std::to_string(pts.size()) + "), found " +
                         std::to_string(w.size()));
  for (size_t i = 0; i < w.size(); ++i)
    if (!(w[i] > 0) || !std::isfinite(w[i]))
      throw InputError(errc::curve_weight, Place::at_json("weights[" + std::to_string(i) + "]"),
                       "expected a finite weight > 0, found " + fmt_num(w[i]));
}

double control_magnitude(std::span<const Bezier> pieces) {
  double scale = 0;
  for (const auto& pc : pieces)
    for (const auto& p : pc.points) scale = std::max(scale, max_abs(p));
  return scale;
}

Bezier Bezier::make(std::vector<Vec3> pts, std::vector<double> w, int d) {
  if (d != 2 && d != 3)
    throw InputError(errc::curve_dimension, Place{}, "expected dimension 2 or 3, found " + std::to_string(d));
  if (pts.size() < 2)
    throw InputError(errc::curve_too_few_points, Place::at_json("points"),
                     "expected at least 2 control points, found " + std::to_string(pts.size()));
  if (static_cast<int>(pts.size()) - 1 > kMaxBezierDegree)
    throw InputError(errc::curve_degree_too_high, Place::at_json("points"),
                     "expected at most " + std::to_string(kMaxBezierDegree + 1) + " control points (degree " +
                         std::to_string(kMaxBezierDegree) + "), found " + std::to_string(pts.size()));
  validate_control_points(pts, w, d);
  if (!w.empty()) {
    // All weights equal: the curve is polynomial; keep it so (faster, exact).
    bool all_equal = true;
    for (double x : w) all_equal = all_equal && x == w.front();
    if (all_equal) w.clear();
  }
  Bezier b;
  b.dim = d;
  b.points = std::move(pts);
  b.weights = std::move(w);
  return b;
}

Vec3 evaluate(const Bezier& b, double t) {
  const H h = cascade(b, t);
  return h.p / h.w;
}

Bezier hodograph(const Bezier& b) {
  assert(!b.rational());
  const int n = b.degree();
  Bezier h;
  h.dim = b.dim;
  if (n == 1) {
    h.points = {(b.points[1] - b.points[0]), (b.points[1] - b.points[0])};
    return h;  // a constant, kept with two points so it stays a valid curve
  }
  h.points.resize(n);
  for (int i = 0; i < n; ++i) h.points[i] = (b.points[i + 1] - b.points[i]) * n;
  return h;
}

Vec3 derivative_k(const Bezier& b, double t, int k) {
  if (k == 0) return evaluate(b, t);
  if (!b.rational()) {
    if (k > b.degree()) return {};
    Bezier h = b;
    for (int i = 0; i < k; ++i) {
      if (h.degree() == 1) {
        if (i == k - 1) return h.points[1] - h.points[0];
        return {};
      }
      h = hodograph(h);
    }
    return evaluate(h, t);
  }
  // Rational: A(t) = sum B w P, w(t) = sum B w; C = A / w. Leibniz:
  // C^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) C^(k-i)) / w.
  Bezier a;  // homogeneous numerator as a polynomial curve
  a.dim = b.dim;
  Bezier wc;
  wc.dim = 2;
  for (int i = 0; i <= b.degree(); ++i) {
    a.points.push_back(b.points[i] * b.weights[i]);
    wc.points.push_back({b.weights[i], 0});
  }
  std::vector<Vec3> c(k + 1);
  std::vector<double> wd(k + 1);
  for (int i = 0; i <= k; ++i) wd[i] = derivative_k(wc, t, i).x;
  for (int j = 0; j <= k; ++j) {
    Vec3 v = derivative_k(a, t, j);
    for (int i = 1; i <= j; ++i) v -= c[j - i] * (binomial(j, i) * wd[i]);
    c[j] = v / wd[0];
  }
  return c[k];
}

Vec3 derivative(const Bezier& b, double t) {
  if (!b.rational()) {
    // n times the difference of the last two points of the cascade.
    return derivative_from_cascade(b, t);
  }
  return derivative_k(b, t, 1);
}

Vec3 second_derivative(const Bezier& b, double t) { return derivative_k(b, t, 2); }

std::pair<Bezier, Bezier> split(const Bezier& b, double t) {
  std::vector<H> l, r;
  cascade(b, t, &l, &r);
  return {from_homogeneous(l, b), from_homogeneous(r, b)};
}

Bezier subcurve(const Bezier& b, double t0, double t1) {
  if (t0 == 0 && t1 == 1) return b;
  if (t0 == 0) return split(b, t1).first;
  // Right part at t0, then the left part of that at the rescaled t1.
  Bezier right = (t0 == 1) ? b : split(b, t0).second;
  if (t1 == 1 || t0 == 1) return right;
  const double u = (t1 - t0) / (1 - t0);
  return split(right, u).first;
}

Bezier elevate(const Bezier& b) {
  const int n = b.degree();
  std::vector<H> q(n + 2);
  auto hp = [&](int i) { return H{b.points[i] * b.weight(i), b.weight(i)}; };
  q[0] = hp(0);
  q[n + 1] = hp(n);
  for (int i = 1; i <= n; ++i) {
    const double a = double(i) / (n + 1);
    const H x = hp(i - 1), y = hp(i);
    q[i] = {x.p * a + y.p * (1 - a), x.w * a + y.w * (1 - a)};
  }
  return from_homogeneous(q, b);
}

Bezier reversed(const Bezier& b) {
  Bezier r = b;
  std::reverse(r.points.begin(), r.points.end());
  std::reverse(r.weights.begin(), r.weights.end());
  return r;
}

std::vector<Bezier> reversed(std::span<const Bezier> pieces) {
  std::vector<Bezier> out;
  out.reserve(pieces.size());
  for (auto it = pieces.rbegin(); it != pieces.rend(); ++it) out.push_back(reversed(*it));
  return out;
}

Box3 control_bounds(const Bezier& b) {
  Box3 box;
  for (const auto& p : b.points) box.add(p);
  return box;
}

namespace {
void tight_bounds(const Bezier& b, Box3& box, double eps, int depth) {
  // The curve's end points are on the curve; the control box contains it.
  const Box3 hull = control_bounds(b);
  const bool inside = box.contains(hull, eps);
  if (inside || depth > 40) {
    if (!inside) box.add(hull);
    return;
  }
  auto [l, r] = split(b, 0.5);
  box.add(l.back());
  tight_bounds(l, box, eps, depth + 1);
  tight_bounds(r, box, eps, depth + 1);
}
}  // namespace

Box3 bounds(const Bezier& b) {
  Box3 box;
  box.add(b.front());
  box.add(b.back());
  const Box3 hull = control_bounds(b);
  double size = 0;
  for (int k = 0; k < 3; ++k) size = std::max(size, hull.hi[k] - hull.lo[k]);
  tight_bounds(b, box, 1e-12 * size, 0);
  return box;
}

double length(const Bezier& b) {
  double poly = 0;
  for (int i = 1; i <= b.degree(); ++i) poly += dist(b.points[i], b.points[i - 1]);
  return integrate([&](double t) { return norm(derivative(b, t)); }, 0, 1, 1e-10 * std::max(poly, 1e-300));
}

namespace {

CubicPowerForm power_form(const std::vector<Vec3>& P) {
  CubicPowerForm f;
  f.c0 = P[0];
  f.c1 = (P[1] - P[0]) * 3;
  f.c2 = (P[0] - P[1] * 2 + P[2]) * 3;
  f.c3 = P[3] - P[0] + (P[1] - P[2]) * 3;
  return f;
}

}  // namespace

CubicPowerForm CubicPowerForm::of(const Bezier& b) {
  assert(!b.rational() && b.degree() <= 3);
  if (b.degree() == 3) return power_form(b.points);  // the common case: no copy
  Bezier e = b;
  while (e.degree() < 3) e = elevate(e);
  return power_form(e.points);
}

int CubicPowerForm::inflections(double out[2]) const {
  const int n = quadratic_roots01(2 * cross(c1, c2).z, 6 * cross(c1, c3).z, 6 * cross(c2, c3).z, out);
  if (n == 2 && out[0] > out[1]) std::swap(out[0], out[1]);
  return n;
}

std::vector<double> inflections(const Bezier& b) {
  double r[2];
  const int n = CubicPowerForm::of(b).inflections(r);
  return {r, r + n};
}

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  k = std::min(k, n - k);
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

double bernstein(int n, int k, double t) { return binomial(n, k) * std::pow(t, k) * std::pow(1 - t, n - k); }

Vec3 evaluate_bernstein(const Bezier& b, double t) {
  Vec3 num;
  double den = 0;
  for (int k = 0; k <= b.degree(); ++k) {
    const double c = bernstein(b.degree(), k, t) * b.weight(k);
    num += b.points[k] * c;
    den += c;
  }
  return num / den;
}

Vec3 derivative_from_cascade(const Bezier& b, double t) {
  assert(!b.rational());
  const int n = b.degree();
  std::vector<Vec3> q = b.points;
  const double s = 1 - t;
  for (int r = 1; r < n; ++r)
    for (int i = 0; i <= n - r; ++i) q[i] = q[i] * s + q[i + 1] * t;
  return (q[1] - q[0]) * n;
}

std::vector<Vec3> power_coefficients(const Bezier& b) {
  assert(!b.rational());
  // c_j = C(n,j) sum_{i<=j} (-1)^(j-i) C(j,i) P_i: the rows of the digest's
  // matrix, for any degree.
  const int n = b.degree();
  std::vector<Vec3> c(n + 1);
  for (int j = 0; j <= n; ++j) {
    Vec3 s;
    for (int i = 0; i <= j; ++i) s += b.points[i] * (((j - i) % 2 ? -1.0 : 1.0) * binomial(j, i));
    c[j] = s * binomial(n, j);
  }
  return c;
}

Vec3 evaluate_power(const std::vector<Vec3>& c, double t) {
  Vec3 r;
  for (size_t j = c.size(); j-- > 0;) r = r * t + c[j];  // Horner
  return r;
}

double durand_f(int n, int k, double t) {
  double s = 0;
  for (int j = k; j <= n; ++j) s += bernstein(n, j, t);
  return s;
}

Vec3 evaluate_durand(const Bezier& b, double t) {
  Vec3 m = b.points[0];
  for (int k = 1; k <= b.degree(); ++k) m += (b.points[k] - b.points[k - 1]) * durand_f(b.degree(), k, t);
  return m;
}

}  // namespace bezcam
