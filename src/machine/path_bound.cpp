#include "bezcam/machine/path_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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
// of a piece and the most rounds.
constexpr double kLoss = 0.003;
constexpr int kMaxDepth = 16;
constexpr int kRounds = 16;

struct Iv {
  double lo = 0, hi = 0;
};
Iv operator-(Iv a, Iv b) { return {a.lo - b.hi, a.hi - b.lo}; }
Iv operator*(Iv a, Iv b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
Iv operator*(double s, Iv a) { return s >= 0 ? Iv{s * a.lo, s * a.hi} : Iv{s * a.hi, s * a.lo}; }
// Division by an interval of positive numbers.
Iv operator/(Iv a, Iv w) { return a * Iv{1 / w.hi, 1 / w.lo}; }
double mag_lo(Iv a) { return a.lo > 0 ? a.lo : a.hi < 0 ? -a.hi : 0; }
double mag_hi(Iv a) { return std::max(std::abs(a.lo), std::abs(a.hi)); }

using Box = std::array<Iv, 3>;
Box point_box(const Vec3& p) { return {Iv{p.x, p.x}, Iv{p.y, p.y}, Iv{p.z, p.z}}; }
Box hull(const std::vector<Vec3>& pts) {
  Box b = point_box(pts.front());
  for (const Vec3& p : pts)
    for (int i = 0; i < 3; ++i) {
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

// Differences of a coefficient sequence times `f` (a hodograph's points).
std::vector<Vec3> diffs(const std::vector<Vec3>& c, double f) {
  std::vector<Vec3> d;
  for (size_t i = 0; i + 1 < c.size(); ++i) d.push_back((c[i + 1] - c[i]) * f);
  if (d.empty()) d.push_back({});
  return d;
}

// Boxes of C' and C'' over a (sub)curve, in its own parameter on [0, 1].
void enclose(const Bezier& b, Box& D, Box& E) {
  const int n = b.degree();
  const double dn = n;
  if (!b.rational()) {
    const std::vector<Vec3> d1 = diffs(b.points, dn);
    D = hull(d1);
    E = n >= 2 ? hull(diffs(d1, dn - 1)) : point_box({});
    return;
  }
  std::vector<Vec3> A, W;  // W as Vec3 (x) to reuse diffs()
  for (int i = 0; i <= n; ++i) {
    A.push_back(b.points[static_cast<size_t>(i)] * b.weight(i));
    W.push_back({b.weight(i), 0, 0});
  }
  const std::vector<Vec3> A1 = diffs(A, dn), W1 = diffs(W, dn);
  const Box C = hull(b.points), a1 = hull(A1);
  const Iv w = hull(W)[0], w1 = hull(W1)[0];
  Box a2 = point_box({});
  Iv w2{0, 0};
  if (n >= 2) {
    a2 = hull(diffs(A1, dn - 1));
    w2 = hull(diffs(W1, dn - 1))[0];
  }
  for (size_t i = 0; i < 3; ++i) D[i] = (a1[i] - w1 * C[i]) / w;
  for (size_t i = 0; i < 3; ++i) E[i] = (a2[i] - 2.0 * (w1 * D[i]) - w2 * C[i]) / w;
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
struct Stretch {
  const Bezier* piece;
  double t0, t1;
  int depth;
  double length, ucap, acc, umid, amid;
};

// Arc length of piece b on [t0, t1]: 8-point Gauss-Legendre.
double stretch_length(const Bezier& b, double t0, double t1) {
  static constexpr double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double m = 0.5 * (t0 + t1), h = 0.5 * (t1 - t0);
  double s = 0;
  for (int k = 0; k < 4; ++k) s += w[k] * (norm(derivative(b, m - h * x[k])) + norm(derivative(b, m + h * x[k])));
  return s * h;
}

Stretch make_stretch(const Bezier& piece, double t0, double t1, int depth, const Limits& L) {
  Stretch s{&piece, t0, t1, depth, 0, 0, 0, 0, 0};
  Box D, E;
  enclose(subcurve(piece, t0, t1), D, E);
  caps(D, E, L, s.ucap, s.acc);
  const double h = t1 - t0, tm = 0.5 * (t0 + t1);
  caps(point_box(derivative(piece, tm) * h), point_box(second_derivative(piece, tm) * (h * h)), L, s.umid, s.amid);
  s.length = std::clamp(stretch_length(piece, t0, t1), dist_lo(D), dist_hi(D));
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
  // A stretch per piece to start with; then, round by round, a
  // stretch is halved where its enclosure loses more time (against its
  // midpoint's figures) than its share of a budget of kLoss of the total.
  std::vector<Stretch> st;
  for (const Bezier& b : pieces) st.push_back(make_stretch(b, 0, 1, 0, L));
  double total_length = 0;
  for (const Stretch& s : st) total_length += s.length;
  double t = 0;
  for (int round = 0;; ++round) {
    const std::vector<double> u = node_speeds(st, from_rest);
    t = 0;
    std::vector<double> lost(st.size());
    for (size_t k = 0; k < st.size(); ++k) {
      const Stretch& s = st[k];
      const double here = stretch_time(s.length, u[k], u[k + 1], s.ucap, s.acc);
      t += here;
      const double c = std::min(s.umid, s.ucap);
      lost[k] = stretch_time(s.length, std::min(u[k], c), std::min(u[k + 1], c), c, std::min(s.amid, s.acc)) - here;
    }
    if (round == kRounds || !(total_length > 0)) break;
    std::vector<Stretch> next;
    next.reserve(st.size() * 2);
    bool split = false;
    for (size_t k = 0; k < st.size(); ++k) {
      const Stretch& s = st[k];
      if (s.depth < kMaxDepth && lost[k] > kLoss * t * s.length / total_length) {
        const double tm = 0.5 * (s.t0 + s.t1);
        next.push_back(make_stretch(*s.piece, s.t0, tm, s.depth + 1, L));
        next.push_back(make_stretch(*s.piece, tm, s.t1, s.depth + 1, L));
        split = true;
      } else {
        next.push_back(s);
      }
    }
    if (!split) break;
    st = std::move(next);
  }
  return t * (1 - 1e-9);
}

}  // namespace bezcam
