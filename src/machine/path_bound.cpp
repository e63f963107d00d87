#include "bezcam/machine/path_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

// Why the result is a lower bound (docs/motion-bound.md has the argument
// in full).
//
// A motion along the curve is its arc length s(t); write u(s) = v^2 for
// the squared speed at s. The axes' velocity is v T and their acceleration
// a = s'' T + u K (T the unit tangent, K the curvature vector). Every
// admissible motion satisfies, at every s:
//   (1) u <= F^2, u T_i^2 <= V_i^2 and u (T . e)^2 <= h_V(T)^2 where
//       h_V(T) = sum V_i |T_i| (the box of velocities' support);
//   (2) u |K| <= h_A(N) (N = K/|K|: the normal part of a point of the
//       acceleration box is at most the box's support in N);
//   (3) |du/ds| = 2 |s''| <= min(h_A(T), min_i (A_i + u |K_i|) / |T_i|).
// Over a stretch of the curve, T and K lie in boxes enclosed by interval
// arithmetic on the stretch's Bézier form (the convex hull property gives
// boxes of the homogeneous numerator, its weight and their derivatives;
// C' = (A' - C W') / W and C'' = (A'' - 2 W' C' - W'' C) / W). Replacing
// each right-hand side by its largest value over the stretch (u's cap
// taken at the stretch's cap) gives a relaxed problem with a constant cap
// c_k and a constant slope limit 2 a_k per stretch. Every admissible motion
// is admissible for it, so its squared speed is at most the relaxed
// problem's pointwise largest solution u*, which is the forward-backward
// pass with u = 0 at both ends, and the time int ds / sqrt(u) is at least
// int ds / sqrt(u*), computed in closed form per stretch.
// Floating-point error: the enclosures and lengths are accurate to a few
// ulps of their values (the stretches' lengths to about 1e-12 relative by
// Gauss-Legendre quadrature, clamped into the enclosure's range); the
// result is scaled by (1 - 1e-9), far more than those errors move it.

namespace bezcam {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Refining (tightness, not validity): the share of the total time the
// enclosures may lose against the midpoints' figures, the deepest halving
// of a piece, the most rounds and the most stretches per piece.
constexpr double kLoss = 0.003;
constexpr int kMaxDepth = 20;
constexpr int kRounds = 40;
constexpr size_t kMostStretches = 256;

struct Iv {
  double lo = 0, hi = 0;
};
Iv operator-(Iv a, Iv b) { return {a.lo - b.hi, a.hi - b.lo}; }
Iv operator*(Iv a, Iv b) {
  const double p = a.lo * b.lo, q = a.lo * b.hi, r = a.hi * b.lo, t = a.hi * b.hi;
  return {std::min(std::min(p, q), std::min(r, t)), std::max(std::max(p, q), std::max(r, t))};
}
Iv operator*(double s, Iv a) { return s >= 0 ? Iv{s * a.lo, s * a.hi} : Iv{s * a.hi, s * a.lo}; }
// Division by an interval of positive numbers.
Iv operator/(Iv a, Iv w) { return a * Iv{1 / w.hi, 1 / w.lo}; }
double mag_lo(Iv a) { return a.lo > 0 ? a.lo : a.hi < 0 ? -a.hi : 0; }
double mag_hi(Iv a) { return std::max(std::abs(a.lo), std::abs(a.hi)); }

using Box = std::array<Iv, 3>;
Box point_box(const Vec3& p) { return {Iv{p.x, p.x}, Iv{p.y, p.y}, Iv{p.z, p.z}}; }
Box hull(const Vec3* pts, int count) {
  Box b = point_box(pts[0]);
  for (int k = 0; k < count; ++k)
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = pts[k];
      b[static_cast<size_t>(i)].lo = std::min(b[static_cast<size_t>(i)].lo, p[i]);
      b[static_cast<size_t>(i)].hi = std::max(b[static_cast<size_t>(i)].hi, p[i]);
    }
  return b;
}
Box cross(const Box& a, const Box& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// Least and largest distance from the origin of the box's points.
double dist_lo(const Box& b) { return std::hypot(mag_lo(b[0]), mag_lo(b[1]), mag_lo(b[2])); }
double dist_hi(const Box& b) { return std::hypot(mag_hi(b[0]), mag_hi(b[1]), mag_hi(b[2])); }

// A piece in homogeneous form (w P, w), coefficients on the stack: the
// stretches are cut from it without allocating.
constexpr int kMost = kMaxBezierDegree + 1;
struct Hom {
  double x, y, z, w;
  Hom operator-(const Hom& o) const { return {x - o.x, y - o.y, z - o.z, w - o.w}; }
  Hom operator*(double f) const { return {x * f, y * f, z * f, w * f}; }
  Hom operator+(const Hom& o) const { return {x + o.x, y + o.y, z + o.z, w + o.w}; }
};
struct Form {
  int n = 0;                 // degree
  std::array<Hom, kMost> c;  // the first n + 1 are set
};

Form form_of(const Bezier& b) {
  Form f;
  f.n = b.degree();
  for (int i = 0; i <= f.n; ++i) {
    const double w = b.weight(i);
    const Vec3& p = b.points[static_cast<size_t>(i)];
    f.c[static_cast<size_t>(i)] = {p.x * w, p.y * w, p.z * w, w};
  }
  return f;
}

// The form restricted to [t0, t1] (two de Casteljau subdivisions).
Form sub_form(const Form& f, double t0, double t1) {
  const int n = f.n;
  const auto at = [](int i) { return static_cast<size_t>(i); };
  // The right part at t0: the cascade's right edge, b_{n-r} at level r.
  Form right;
  right.n = n;
  std::array<Hom, kMost> tmp;
  std::copy_n(f.c.begin(), n + 1, tmp.begin());
  for (int r = 0; r <= n; ++r) {
    right.c[at(n - r)] = tmp[at(n - r)];
    for (int i = 0; i + r < n; ++i) tmp[at(i)] = tmp[at(i)] * (1 - t0) + tmp[at(i + 1)] * t0;
  }
  // Its left part at the parameter of t1: the left edge, b_0 at level r.
  const double s = t0 < 1 ? (t1 - t0) / (1 - t0) : 1;
  Form out;
  out.n = n;
  std::copy_n(right.c.begin(), n + 1, tmp.begin());
  for (int r = 0; r <= n; ++r) {
    out.c[at(r)] = tmp[0];
    for (int i = 0; i + r < n; ++i) tmp[at(i)] = tmp[at(i)] * (1 - s) + tmp[at(i + 1)] * s;
  }
  return out;
}

Vec3 xyz(const Hom& h) { return {h.x, h.y, h.z}; }

// Value and first two derivatives of the form at x (de Casteljau: at the
// start of step r the cascade holds level r - 1; the derivatives are the
// differences of levels n - 1 and n - 2).
void eval3(const Form& f, double x, Hom& v, Hom& d1, Hom& d2) {
  const int n = f.n;
  std::array<Hom, kMost> t;
  std::copy_n(f.c.begin(), n + 1, t.begin());
  d1 = d2 = {0, 0, 0, 0};
  for (int r = 1; r <= n; ++r) {
    if (r == n - 1 && n >= 2) d2 = (t[2] - t[1] * 2 + t[0]) * (static_cast<double>(n) * (n - 1));
    if (r == n) d1 = (t[1] - t[0]) * static_cast<double>(n);
    for (int i = 0; i + r <= n; ++i)
      t[static_cast<size_t>(i)] = t[static_cast<size_t>(i)] * (1 - x) + t[static_cast<size_t>(i) + 1] * x;
  }
  v = t[0];
}

// C' and C'' of the curve the form describes, at x.
void curve_derivatives(const Form& f, double x, Vec3& c1, Vec3& c2) {
  Hom v, d1, d2;
  eval3(f, x, v, d1, d2);
  const Vec3 C = xyz(v) / v.w;
  c1 = (xyz(d1) - C * d1.w) / v.w;
  c2 = (xyz(d2) - c1 * (2 * d1.w) - C * d2.w) / v.w;
}

// Boxes of C' and C'' over the form's curve on [0, 1].
void enclose(const Form& f, Box& D, Box& E) {
  const int n = f.n;
  const double dn = n;
  std::array<Vec3, kMost> pts, a1, a2;
  Iv w{kInf, -kInf}, w1{kInf, -kInf}, w2{0, 0};
  for (int i = 0; i <= n; ++i) {
    const Hom& h = f.c[static_cast<size_t>(i)];
    pts[static_cast<size_t>(i)] = xyz(h) / h.w;
    w = {std::min(w.lo, h.w), std::max(w.hi, h.w)};
  }
  for (int i = 0; i < n; ++i) {
    const Hom d = (f.c[static_cast<size_t>(i) + 1] - f.c[static_cast<size_t>(i)]) * dn;
    a1[static_cast<size_t>(i)] = xyz(d);
    w1 = {std::min(w1.lo, d.w), std::max(w1.hi, d.w)};
  }
  Box h1 = hull(a1.data(), n), h2 = point_box({});
  if (n >= 2) {
    w2 = {kInf, -kInf};
    for (int i = 0; i + 1 < n; ++i) {
      const Hom d =
          (f.c[static_cast<size_t>(i) + 2] - f.c[static_cast<size_t>(i) + 1] * 2 + f.c[static_cast<size_t>(i)]) *
          (dn * (dn - 1));
      a2[static_cast<size_t>(i)] = xyz(d);
      w2 = {std::min(w2.lo, d.w), std::max(w2.hi, d.w)};
    }
    h2 = hull(a2.data(), n - 1);
  }
  const Box C = hull(pts.data(), n + 1);
  for (size_t i = 0; i < 3; ++i) D[i] = (h1[i] - w1 * C[i]) / w;
  for (size_t i = 0; i < 3; ++i) E[i] = (h2[i] - 2.0 * (w1 * D[i]) - w2 * C[i]) / w;
}

struct Limits {
  Vec3 V, A;    // units/s, units/s^2 per axis
  double feed;  // units/s
};

// The relaxed problem's cap on u and limit on |s''| for C' in D, C'' in E.
void caps(const Box& D, const Box& E, const Limits& L, double& ucap, double& acc) {
  const double dlo = dist_lo(D), dhi = dist_hi(D);
  double v = L.feed;
  acc = kInf;
  ucap = v * v;
  if (!(dlo > 0)) return;  // the tangent is not enclosed: feed only
  // 1 / |T_i| <= r[i]: |C'_i| at its least, the other components at their most.
  std::array<double, 3> r{kInf, kInf, kInf};
  for (size_t i = 0; i < 3; ++i) {
    const double lo = mag_lo(D[i]);
    if (lo > 0) r[i] = std::hypot(lo, mag_hi(D[(i + 1) % 3]), mag_hi(D[(i + 2) % 3])) / lo;
  }
  double hV = 0, hA = 0;
  for (size_t i = 0; i < 3; ++i) {
    const double hi = mag_hi(D[i]);
    v = std::min(v, L.V[static_cast<int>(i)] * r[i]);
    hV += L.V[static_cast<int>(i)] * hi;
    hA += L.A[static_cast<int>(i)] * hi;
  }
  v = std::min(v, hV / dlo);
  ucap = v * v;
  const Box Nn = cross(cross(D, E), D);  // |C'|^4 K
  const double nlo = dist_lo(Nn);
  if (nlo > 0) {
    double hN = 0;
    for (size_t i = 0; i < 3; ++i) hN += L.A[static_cast<int>(i)] * mag_hi(Nn[i]);
    const double d2 = dhi * dhi;
    ucap = std::min(ucap, hN * d2 * d2 / (nlo * nlo));
  }
  acc = hA / dlo;
  const double d4 = dlo * dlo * dlo * dlo;
  for (size_t i = 0; i < 3; ++i)
    if (r[i] < kInf) acc = std::min(acc, (L.A[static_cast<int>(i)] + ucap * mag_hi(Nn[i]) / d4) * r[i]);
}

// A stretch of a piece, its length, the relaxed problem's cap and slope
// limit over it, and the same figures at its midpoint (estimates of the
// exact problem's, which say where refining tightens the bound).
// A stretch of a piece, its length, the relaxed problem's cap and slope
// limit over it, and the same figures at its midpoint (estimates of the
// exact problem's, which say where refining tightens the bound).
struct Stretch {
  const Form* piece;
  double t0, t1;
  int depth;
  double length, ucap, acc, umid, amid;
};

// Arc length of the form's curve on [0, 1]: 8-point Gauss-Legendre.
double form_length(const Form& f) {
  static constexpr double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double s = 0;
  Vec3 c1, c2;
  for (int k = 0; k < 4; ++k) {
    curve_derivatives(f, 0.5 - 0.5 * x[k], c1, c2);
    s += w[k] * norm(c1);
    curve_derivatives(f, 0.5 + 0.5 * x[k], c1, c2);
    s += w[k] * norm(c1);
  }
  return 0.5 * s;
}

Stretch make_stretch(const Form& piece, double t0, double t1, int depth, const Limits& L) {
  Stretch s{&piece, t0, t1, depth, 0, 0, 0, 0, 0};
  const Form sub = sub_form(piece, t0, t1);  // NRVO: no copy
  Box D, E;
  enclose(sub, D, E);
  caps(D, E, L, s.ucap, s.acc);
  Vec3 c1, c2;
  curve_derivatives(sub, 0.5, c1, c2);
  caps(point_box(c1), point_box(c2), L, s.umid, s.amid);
  s.length = std::clamp(form_length(sub), dist_lo(D), dist_hi(D));
  return s;
}

// Time over a stretch of length l with squared speeds u0, u1 at its ends,
// cap c and slope limit 2a: the largest profile min(c, u0 + 2ax, u1 + 2a(l-x)).
double stretch_time(double l, double u0, double u1, double c, double a) {
  if (!(l > 0)) return 0;
  if (!std::isfinite(a)) return l / std::sqrt(c);
  const double x1 = (c - u0) / (2 * a), x2 = l - (c - u1) / (2 * a);
  const double sc = std::sqrt(c);
  if (x1 <= x2) return (sc - std::sqrt(u0)) / a + (x2 - x1) / sc + (sc - std::sqrt(u1)) / a;
  const double up = std::min(c, 0.5 * (u0 + u1) + a * l);
  const double sp = std::sqrt(up);
  return (sp - std::sqrt(u0)) / a + (sp - std::sqrt(u1)) / a;
}

// The forward-backward pass: the largest squared speed at every node
// (node k starts stretch k; the last node ends the path), at rest at both
// ends or (`from_rest` false) at any speed the stretches there allow.
std::vector<double> node_speeds(const std::vector<Stretch>& st, bool from_rest) {
  const size_t m = st.size();
  std::vector<double> u(m + 1, kInf);
  u[0] = from_rest ? 0 : st[0].ucap;
  for (size_t k = 0; k < m; ++k)
    u[k + 1] = std::min({u[k] + 2 * st[k].acc * st[k].length, st[k].ucap, k + 1 < m ? st[k + 1].ucap : kInf});
  if (from_rest) u[m] = 0;
  for (size_t k = m; k-- > 0;) u[k] = std::min(u[k], u[k + 1] + 2 * st[k].acc * st[k].length);
  return u;
}

}  // namespace

double exact_path_time_bound(std::span<const Bezier> pieces, double feed, const MotionModel& model, Units units,
                             bool from_rest) {
  if (pieces.empty() || !(feed > 0)) return 0;
  const double scale = mm_per_unit(units);
  Limits L;
  for (int i = 0; i < 3; ++i) {
    L.V[i] = model.max_velocity_mm_min[static_cast<size_t>(i)] / 60 / scale;
    L.A[i] = model.max_acceleration_mm_s2[static_cast<size_t>(i)] / scale;
  }
  L.feed = feed / 60;
  // A stretch per piece to start with; then, round by round, while the
  // enclosures lose more than kLoss of the time against the midpoints'
  // figures, the stretches that lose most (half of the loss) are halved,
  // up to kMostStretches per piece (a cusp's neighbourhood could take any
  // number).
  std::vector<Form> forms;
  forms.reserve(pieces.size());
  for (const Bezier& b : pieces) forms.push_back(form_of(b));
  std::vector<Stretch> st;
  for (const Form& f : forms) st.push_back(make_stretch(f, 0, 1, 0, L));
  const size_t most = kMostStretches * pieces.size();
  double t = 0;
  std::vector<double> lost, order;
  for (int round = 0;; ++round) {
    const std::vector<double> u = node_speeds(st, from_rest);
    t = 0;
    double loss = 0;
    lost.assign(st.size(), 0);
    for (size_t k = 0; k < st.size(); ++k) {
      const Stretch& s = st[k];
      const double here = stretch_time(s.length, u[k], u[k + 1], s.ucap, s.acc);
      t += here;
      const double c = std::min(s.umid, s.ucap);
      if (s.depth < kMaxDepth)
        lost[k] = std::max(
            0.0, stretch_time(s.length, std::min(u[k], c), std::min(u[k + 1], c), c, std::min(s.amid, s.acc)) - here);
      loss += lost[k];
    }
    if (round == kRounds || !(loss > kLoss * t) || st.size() >= most) break;
    // The least loss split: the largest losses adding up to half of it.
    order = lost;
    std::sort(order.begin(), order.end(), std::greater<>());
    double cut = 0, sum = 0;
    for (size_t k = 0; k < order.size() && sum < 0.5 * loss && k < most - st.size(); ++k) sum += cut = order[k];
    std::vector<Stretch> next;
    next.reserve(st.size() * 2);
    for (size_t k = 0; k < st.size(); ++k) {
      const Stretch& s = st[k];
      if (lost[k] >= cut && lost[k] > 0) {
        const double tm = 0.5 * (s.t0 + s.t1);
        next.push_back(make_stretch(*s.piece, s.t0, tm, s.depth + 1, L));
        next.push_back(make_stretch(*s.piece, tm, s.t1, s.depth + 1, L));
      } else {
        next.push_back(s);
      }
    }
    st = std::move(next);
  }
  return t * (1 - 1e-9);
}

}  // namespace bezcam
