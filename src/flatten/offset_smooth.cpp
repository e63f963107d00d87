// An arc spline made tangent where its chains start again (offset_smooth.hpp).
#include "offset_smooth.hpp"

#include <cmath>
#include <optional>

#include "bezcam/flatten/arc_fit.hpp"

namespace bezcam::flatten_detail {

namespace {

// A joint of A turning by more than this (radians) keeps its turn: a
// biarc across it would bulge from the curve.
constexpr double kMaxSmoothTurn = 0.05;

double cross_xy(const Vec3& a, const Vec3& b) { return a.x * b.y - a.y * b.x; }
double dot_xy(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y; }

// The arc from p leaving in unit direction u through q (none where q lies
// on the line through p along u, or behind a half turn).
std::optional<Arc> arc_leaving(const Vec3& p, const Vec3& u, const Vec3& q) {
  const Vec3 n{-u.y, u.x, 0}, w = q - p;
  const double wn = dot_xy(w, n), ww = dot_xy(w, w);
  if (!(std::abs(wn) > 1e-9 * std::sqrt(ww)) || !(dot_xy(w, u) > 0)) return std::nullopt;
  const double s = ww / (2 * wn);  // signed radius: the centre on u's left when > 0
  return Arc{p, q, p + n * s, s > 0};
}

// The parameter in [lo, hi] of the curve's point nearest q (sampled, then
// golden section around the nearest sample).
double nearest_t(const Bezier& b, double lo, double hi, const Vec3& q) {
  constexpr int kSamples = 64;
  auto d2 = [&](double t) {
    const Vec3 m = evaluate(b, t);
    return (m.x - q.x) * (m.x - q.x) + (m.y - q.y) * (m.y - q.y);
  };
  int best = 0;
  double best_d = d2(lo);
  for (int i = 1; i <= kSamples; ++i)
    if (const double d = d2(lo + (hi - lo) * i / kSamples); d < best_d) best = i, best_d = d;
  double a = lo + (hi - lo) * std::max(0, best - 1) / kSamples,
         c = lo + (hi - lo) * std::min(kSamples, best + 1) / kSamples;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int i = 0; i < 60 && c - a > 1e-14; ++i) {
    const double x1 = c - g * (c - a), x2 = a + g * (c - a);
    if (d2(x1) < d2(x2))
      c = x2;
    else
      a = x1;
  }
  return 0.5 * (a + c);
}

ArcSeg to_seg(const Arc& a) {
  const double sweep = a.sweep();
  return ArcSeg::make_arc(a.from, a.to, a.center, a.ccw ? sweep : -sweep);
}

}  // namespace

double smooth_joint(std::vector<ArcSeg>& A, size_t k, const Vec3& next_dir, const Bezier& piece, double t_from,
                    double t_to, double budget) {
  if (k >= A.size() || !(t_from < t_to)) return -1;
  const ArcSeg& seg = A[k];
  const Vec3 p0 = seg.a, p1 = seg.b, u0 = seg.tangent(0), u1 = next_dir;
  const Vec3 end = seg.tangent(1);
  const double turn = std::atan2(std::abs(cross_xy(end, u1)), dot_xy(end, u1));
  if (!(turn > 1e-12) || turn > kMaxSmoothTurn) return -1;
  // The biarc whose two tangent legs are equally long (d): its arcs meet
  // at j, tangent to each other there.
  const Vec3 v = p1 - p0, t = u0 + u1;
  const double vt = dot_xy(v, t), vv = dot_xy(v, v), c = 2 * (1 - dot_xy(u0, u1));
  const double d = c > 1e-12 ? (-vt + std::sqrt(vt * vt + c * vv)) / c : vv / (4 * dot_xy(v, u1));
  if (!(d > 0) || !std::isfinite(d)) return -1;
  const Vec3 j = (p0 + u0 * d + p1 - u1 * d) * 0.5;
  const auto a1 = arc_leaving(p0, u0, j);
  // (the second arc, travelled back from p1 against u1)
  auto a2 = arc_leaving(p1, u1 * -1, j);
  if (!a1 || !a2) return -1;
  a2 = Arc{j, p1, a2->center, !a2->ccw};
  const double tj = nearest_t(piece, t_from, t_to, j);
  if (!(tj > t_from) || !(tj < t_to)) return -1;
  const double dev1 = arc_span_deviation(piece, t_from, tj, *a1, budget);
  if (!(dev1 <= budget)) return -1;
  const double dev2 = arc_span_deviation(piece, tj, t_to, *a2, budget);
  if (!(dev2 <= budget)) return -1;
  A[k] = to_seg(*a1);
  A.insert(A.begin() + static_cast<std::ptrdiff_t>(k) + 1, to_seg(*a2));
  A[k + 1].b = p1;
  return std::max(dev1, dev2);
}

}  // namespace bezcam::flatten_detail
