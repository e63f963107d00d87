#include "bezcam/flatten/tip_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/minimize.hpp"
#include "bezcam/limits.hpp"
#include "flatten/search.hpp"
#include "kernel/bernstein_ops.hpp"

namespace bezcam {

namespace {

const Vec3 kZ{0, 0, 1};

[[noreturn]] void normal_undefined(const SurfaceCurve& c, double t) {
  const auto [u, v] = uv_at(c, t);
  throw InputError(errc::surface_normal_undefined, Place{},
                   "the surface normal vanishes near u = " + fmt_num(u) + ", v = " + fmt_num(v) +
                       " (a collapsed edge or a cusp), so a ball-end tool cannot follow it there; "
                       "use tool_radius 0 or a patch without degenerate points");
}

// Largest norm among the control points of the k-th hodograph of a
// polynomial piece, times n (n-1) ... : a bound of |b^(k)| on [0,1].
double derivative_bound(const Bezier& b, int k) {
  const int n = b.degree();
  if (k > n) return 0;
  std::vector<Vec3> d = b.points;
  double f = 1;
  for (int j = 0; j < k; ++j) {
    for (size_t i = 0; i + 1 < d.size(); ++i) d[i] = d[i + 1] - d[i];
    d.pop_back();
    f *= n - j;
  }
  double m = 0;
  for (const auto& p : d) m = std::max(m, norm(p));
  return f * m;
}

// Bound of |P''| on [0,1] for a polynomial or rational piece (module comment).
double second_derivative_bound(const Bezier& b) {
  if (!b.rational()) return derivative_bound(b, 2);
  const int n = b.degree();
  const Vec3 c = evaluate(b, 0.5);
  double R = 0, wmin = HUGE_VAL;
  Bezier h;  // H = w (P - c), as a polynomial curve
  Bezier w;  // w as a polynomial curve in x
  h.dim = w.dim = 3;
  for (int i = 0; i <= n; ++i) {
    R = std::max(R, dist(b.points[i], c));
    wmin = std::min(wmin, b.weights[i]);
    h.points.push_back((b.points[i] - c) * b.weights[i]);
    w.points.push_back({b.weights[i], 0, 0});
  }
  const double h1 = derivative_bound(h, 1), h2 = derivative_bound(h, 2);
  const double w1 = derivative_bound(w, 1), w2 = derivative_bound(w, 2);
  const double p1 = (h1 + w1 * R) / wmin;
  return (h2 + w2 * R + 2 * w1 * p1) / wmin;
}

// Lower bound of |n| on [0,1]: the least projection of the control points
// on the direction of n(1/2) (convex hull); 0 when not provably positive.
double min_norm_bound(const Bezier& n) {
  const Vec3 m = evaluate(n, 0.5);
  const double l = norm(m);
  if (!(l > 0)) return 0;
  const Vec3 d = m / l;
  double lo = HUGE_VAL;
  for (const auto& p : n.points) lo = std::min(lo, dot(p, d));
  return std::max(lo, 0.0);
}

double magnitude(const SurfaceCurve& c) {
  double m = 0;
  for (const auto& b : c.points)
    for (const auto& p : b.points) m = std::max(m, max_abs(p));
  return m;
}

// Tip of piece k at local parameter x.
Vec3 tip_local(const SurfaceCurve& c, double radius, size_t k, double x, double global_t) {
  const Vec3 p = evaluate(c.points[k], x);
  if (radius == 0 || c.normals.empty()) return p;
  const Vec3 n = evaluate(c.normals[k], x);
  const double l = norm(n);
  if (!(l > 0)) normal_undefined(c, global_t);
  return p + (n / l - kZ) * radius;
}

double global_of(const SurfaceCurve& c, size_t k, double x) {
  return c.breaks[k] + x * (c.breaks[k + 1] - c.breaks[k]);
}

}  // namespace

Vec3 tip_point(const SurfaceCurve& c, double radius, double t) {
  const auto [k, x] = locate(c, t);
  return tip_local(c, radius, k, x, t);
}

double tip_chord_bound(const Bezier& point, const Bezier* normal, double radius, double t0, double t1) {
  const Bezier p = subcurve(point, t0, t1);
  double m2 = second_derivative_bound(p);
  if (radius > 0 && normal) {
    const Bezier n = subcurve(*normal, t0, t1);
    const double s = min_norm_bound(n);
    if (!(s > 0)) return HUGE_VAL;
    const double n1 = derivative_bound(n, 1) / s, n2 = derivative_bound(n, 2) / s;
    m2 += radius * std::hypot(n2 + 2 * n1 * n1, n1 * n1);
  }
  return m2 / 8;
}

TipPolyline flatten_tip(const SurfaceCurve& c, double radius, const FlattenOptions& opt) {
  TipPolyline out;
  if (radius == 0 || c.normals.empty()) {
    // Exact pieces: the curve flattener's proven bound, vertices on the
    // curve (their parameters are kept).
    FlattenOptions on = opt;
    on.on_curve = true;
    out.bound = flatten_pieces(c.points, on, [&](const FlatVertex& v) {
      out.points.push_back(v.point);
      out.params.push_back(global_of(c, v.piece, v.t));
    });
    return out;
  }
  const double tol = opt.tolerance;
  // Evaluation of the tip adds a unit normal times r to the point.
  const double margin = check_tolerance(tol, opt.decimals, 3, magnitude(c) + radius).margin;
  Vec3 Ar = quantize(tip_local(c, radius, 0, 0, 0), opt.decimals);
  out.points.push_back(Ar);
  out.params.push_back(0);
  for (size_t k = 0; k < c.points.size(); ++k) {
    const Bezier& P = c.points[k];
    const Bezier* N = &c.normals[k];
    Vec3 A = tip_local(c, radius, k, 0, c.breaks[k]);
    double dispA = dist(Ar, A);  // includes the float gap at a joint
    double t0 = 0, dt = 0.25;
    while (t0 < 1) {
      // Longest step whose bound fits: the bound shrinks like dt^2.
      double lo = 0, hi = HUGE_VAL, best_t1 = t0, best_dev = 0, best_disp = 0;
      Vec3 bestB, bestBr;
      bool found = false;
      for (int iter = 0; iter < 200; ++iter) {
        const bool last = dt >= 1 - t0;
        if (last) dt = 1 - t0;
        const double t1 = last ? 1.0 : t0 + dt;
        const double dev = tip_chord_bound(P, N, radius, t0, t1);
        double budget = -1, dispB = 0;
        Vec3 B, Br;
        if (std::isfinite(dev)) {
          B = tip_local(c, radius, k, t1, global_of(c, k, t1));
          Br = quantize(B, opt.decimals);
          dispB = dist(Br, B);
          budget = tol - margin - std::max(dispA, dispB);
        }
        if (budget > 0 && dev <= budget) {
          found = true;
          lo = dt, best_t1 = t1, best_dev = dev, best_disp = std::max(dispA, dispB), bestB = B, bestBr = Br;
          const double ratio = dev / budget;
          if (last || ratio >= 0.9 || lo >= 0.97 * hi) break;
          double nd = dt * std::min(ratio > 1e-12 ? std::sqrt(0.95 / ratio) : 4.0, 4.0);
          if (nd >= hi) nd = 0.5 * (lo + hi);
          dt = nd;
        } else {
          hi = dt;
          if (found && lo >= 0.97 * hi) break;
          const double g = budget > 0 && std::isfinite(dev) ? std::sqrt(0.95 * budget / dev) : 0.5;
          double nd = dt * std::clamp(g, 0.05, 0.9);
          if (nd <= lo) nd = 0.5 * (lo + hi);
          dt = nd;
        }
        if (!found && dt < 1e-13) normal_undefined(c, global_of(c, k, t0));
      }
      if (!found) normal_undefined(c, global_of(c, k, t0));
      out.bound = std::max(out.bound, best_dev + best_disp);
      out.points.push_back(bestBr);
      out.params.push_back(global_of(c, k, best_t1));
      t0 = best_t1;
      A = bestB;
      Ar = bestBr;
      dispA = dist(Ar, A);
      dt = std::min(2 * lo, 1.0);
    }
  }
  out.params.back() = 1;
  return out;
}

namespace {

using detail::Hom;
using detail::Poly;

// One tip piece on [0,1] of a point piece P and its normal direction n:
// the rational piece A = P + r (n / w - z) and its proven distance to the
// tip (tip_curve.hpp); nothing when w is not provably positive.
std::optional<std::pair<Bezier, double>> tip_piece(const Bezier& P, const Bezier& n, double radius) {
  const double f0 = norm(evaluate(n, 0)), fm = norm(evaluate(n, 0.5)), f1 = norm(evaluate(n, 1));
  const Poly<double> w{f0, 0.5 * (4 * fm - f0 - f1), f1};
  const double wmin = std::min({w[0], w[1], w[2]});
  if (!(wmin > 0)) return std::nullopt;
  auto dbl = [](double a, double b) { return a * b; };
  const Poly<Vec3> nv(n.points.begin(), n.points.end());
  Poly<double> nn = detail::bern_product(nv, nv, [](const Vec3& a, const Vec3& b) { return dot(a, b); });
  Poly<double> ww = detail::bern_product(w, w, dbl);
  const int dd = std::max(detail::degree_of(nn), detail::degree_of(ww));
  nn = detail::bern_elevate(nn, dd);
  ww = detail::bern_elevate(ww, dd);
  double dmax = 0, scale = 0;
  for (size_t i = 0; i < nn.size(); ++i) {
    dmax = std::max(dmax, std::abs(nn[i] - ww[i]));
    scale = std::max(scale, std::abs(nn[i]));
  }
  // Floating-point error of the few products and sums above: a small
  // multiple of eps times the coefficients' size.
  const double bound = radius * (dmax + 64 * 2.2e-16 * scale) / (wmin * wmin);
  // Numerator w H + r n h - r z w h over weight w h, H = h P.
  const Poly<Hom> ph = detail::homogeneous(P);
  Poly<Vec3> H(ph.size());
  Poly<double> h(ph.size());
  for (size_t i = 0; i < ph.size(); ++i) H[i] = ph[i].p, h[i] = ph[i].w;
  const Poly<double> wh = detail::bern_product(w, h, dbl);
  Poly<Vec3> a = detail::bern_scale(H, w), b = detail::bern_scale(nv, h);
  const int d = std::max({detail::degree_of(a), detail::degree_of(b), detail::degree_of(wh)});
  a = detail::bern_elevate(a, d);
  b = detail::bern_elevate(b, d);
  const Poly<double> den = detail::bern_elevate(wh, d);
  Poly<Hom> hom(static_cast<size_t>(d) + 1);
  for (size_t i = 0; i < hom.size(); ++i) {
    if (!(den[i] > 0)) return std::nullopt;
    hom[i] = Hom(a[i] + b[i] * radius - Vec3{0, 0, radius * den[i]}, den[i]);
  }
  return std::make_pair(detail::from_homogeneous(hom, true, 3), bound);
}

void approximate_on(const SurfaceCurve& c, size_t k, double radius, double budget, double x0, double x1, int depth,
                    TipApprox& out, bool& ok) {
  if (!ok) return;
  const Bezier P = subcurve(c.points[k], x0, x1), n = subcurve(c.normals[k], x0, x1);
  const auto got = tip_piece(P, n, radius);
  if (got && got->second <= budget) {
    out.pieces.push_back(got->first);
    out.breaks.push_back(global_of(c, k, x1));
    out.bound = std::max(out.bound, got->second);
    return;
  }
  if (depth >= 12) {
    ok = false;
    return;
  }
  const double xm = 0.5 * (x0 + x1);
  approximate_on(c, k, radius, budget, x0, xm, depth + 1, out, ok);
  approximate_on(c, k, radius, budget, xm, x1, depth + 1, out, ok);
}

}  // namespace

std::optional<TipApprox> approximate_tip(const SurfaceCurve& c, double radius, double budget) {
  TipApprox out;
  if (radius == 0 || c.normals.empty()) {
    out.pieces = c.points;
    for (auto& b : out.pieces) b.dim = 3;
    out.breaks = c.breaks;
    return out;
  }
  out.breaks.push_back(c.breaks.front());
  bool ok = true;
  for (size_t k = 0; k < c.points.size() && ok; ++k) approximate_on(c, k, radius, budget, 0, 1, 0, out, ok);
  if (!ok) return std::nullopt;
  out.breaks.back() = c.breaks.back();
  return out;
}

namespace {

// The smallest distance from x to point(t) for t in [lo, hi]: Brent's
// method on the squared distance, smooth even where the distance reaches 0
// (the distance itself grows linearly off such a minimum, which only
// bisection-like steps pin down), located to 1e-10 of the window; and the
// window's ends themselves, which Brent's method only approaches (a
// nearest point at an end would read high by the speed times that step).
template <class P>
double nearest_distance(double lo, double hi, const Vec3& x, P point) {
  const auto d2 = [&](double t) {
    const Vec3 d = point(t) - x;
    return dot(d, d);
  };
  const auto m = brent_min(lo, hi, d2, 1e-10 * (hi - lo));
  return std::sqrt(std::min({m.f, d2(lo), d2(hi)}));
}

// The largest value of f on [a, b] (bracketing a sampled peak), located to
// 1e-7 of the window.
template <class F>
double peak_value(double a, double b, F f) {
  return -brent_min(
              a, b, [&](double s) { return -f(s); }, 1e-7 * (b - a))
              .f;
}

}  // namespace

Deviation measure_tip(const SurfaceCurve& c, double radius, const TipPolyline& p) {
  Deviation d;
  const auto& V = p.points;
  const auto& T = p.params;
  if (V.size() < 2) return d;
  auto tip = [&](double t) { return tip_point(c, radius, std::clamp(t, 0.0, 1.0)); };
  auto dist_poly = [&](const Vec3& x, size_t i) {  // to segments i-1 .. i+1
    double m = HUGE_VAL;
    for (size_t j = i > 0 ? i - 1 : 0; j <= i + 1 && j + 1 < V.size(); ++j)
      m = std::min(m, dist_to_segment(x, V[j], V[j + 1]));
    return m;
  };
  constexpr int kSamples = 8;
  for (size_t i = 0; i + 1 < V.size(); ++i) {
    const double a = T[i], b = T[i + 1];
    // Curve -> polyline: the curve between the vertices, worst refined.
    double best = -1, bt = a;
    for (int s = 0; s <= kSamples; ++s) {
      const double t = a + (b - a) * s / kSamples;
      const double e = dist_poly(tip(t), i);
      if (e > best) best = e, bt = t;
    }
    const double h = (b - a) / kSamples;
    best = std::max(
        best, peak_value(std::max(a, bt - h), std::min(b, bt + h), [&](double t) { return dist_poly(tip(t), i); }));
    d.curve_to_path = std::max(d.curve_to_path, best);
    // Polyline -> curve: chord points to their nearest curve point, searched
    // over the vertices' parameter range widened by half a segment each side.
    const double lo = std::max(0.0, a - 0.5 * (b - a)), hi = std::min(1.0, b + 0.5 * (b - a));
    for (int s = 1; s < kSamples; ++s) {
      const Vec3 x = lerp(V[i], V[i + 1], double(s) / kSamples);
      const double e = nearest_distance(lo, hi, x, tip);
      d.path_to_curve = std::max(d.path_to_curve, e);
    }
    d.path_to_curve = std::max(d.path_to_curve, dist(V[i], tip(a)));
  }
  d.path_to_curve = std::max(d.path_to_curve, dist(V.back(), tip(1)));
  return d;
}

namespace {

// The measurement of measure_tip_pieces() and measure_tip_moves(): printed
// move j at local s is printed(j, s); `in_step` says it follows the curve in
// the same parameter (nearest points searched in a window of a sixteenth of
// the move around the same parameter) or not (searched over the whole move,
// and the curve over the move's interval widened by a quarter either side).
Deviation measure_tip_core(const SurfaceCurve& c, double radius, size_t n,
                           const std::function<Vec3(size_t, double)>& printed, std::span<const double> breaks,
                           bool in_step) {
  Deviation d;
  auto tip = [&](double t) { return tip_point(c, radius, std::clamp(t, 0.0, 1.0)); };
  constexpr int kSamples = 32;
  for (size_t j = 0; j < n; ++j) {
    const double a = breaks[j], b = breaks[j + 1], w = b - a;
    // Distance from a printed point at local s to the tip curve near it,
    // and from the tip at local s to the printed move near it.
    auto to_curve = [&](double s) {
      const Vec3 x = printed(j, s);
      const double t = a + s * w, h = w / 16;
      const double lo = in_step ? t - h : a - w / 4, hi = in_step ? t + h : b + w / 4;
      return nearest_distance(std::max(0.0, lo), std::min(1.0, hi), x, tip);
    };
    auto to_piece = [&](double s) {
      const Vec3 x = tip(a + s * w);
      const double lo = in_step ? s - 1.0 / 16 : 0.0, hi = in_step ? s + 1.0 / 16 : 1.0;
      return nearest_distance(std::max(0.0, lo), std::min(1.0, hi), x, [&](double u) { return printed(j, u); });
    };
    auto worst_of = [&](const auto& f) {
      std::vector<double> v(kSamples + 1);
      for (int i = 0; i <= kSamples; ++i) v[i] = f(double(i) / kSamples);
      double m = *std::max_element(v.begin(), v.end());
      for (int i = 0; i <= kSamples; ++i) {
        const bool peak = (i == 0 || v[i] >= v[i - 1]) && (i == kSamples || v[i] >= v[i + 1]);
        if (!peak) continue;
        const double s0 = std::max(0.0, double(i - 1) / kSamples), s1 = std::min(1.0, double(i + 1) / kSamples);
        m = std::max(m, peak_value(s0, s1, f));
      }
      return m;
    };
    d.path_to_curve = std::max(d.path_to_curve, worst_of(to_curve));
    d.curve_to_path = std::max(d.curve_to_path, worst_of(to_piece));
  }
  return d;
}

}  // namespace

Deviation measure_tip_pieces(const SurfaceCurve& c, double radius, std::span<const Bezier> pieces,
                             std::span<const double> breaks) {
  return measure_tip_core(
      c, radius, pieces.size(), [&](size_t j, double s) { return evaluate(pieces[j], s); }, breaks, true);
}

Deviation measure_tip_moves(const SurfaceCurve& c, double radius, size_t n,
                            const std::function<Vec3(size_t, double)>& printed, std::span<const double> breaks) {
  return measure_tip_core(c, radius, n, printed, breaks, false);
}

}  // namespace bezcam
