#include "bezcam/flatten/deviation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "flatten/search.hpp"

namespace bezcam {

namespace {

struct Sample {
  Vec3 p;
  size_t piece;
  double t;
};

// Subdivide until the control polygon is within eps of the chord; keeps
// on-curve end points with their parameters.
void sample_piece(const Bezier& b, size_t piece, double t0, double t1, double eps, int depth,
                  std::vector<Sample>& out) {
  double flat = 0;
  for (const auto& p : b.points) flat = std::max(flat, dist_to_segment(p, b.front(), b.back()));
  if (flat <= eps || depth >= 40) {
    out.push_back({b.back(), piece, t1});
    return;
  }
  const double tm = 0.5 * (t0 + t1);
  auto [l, r] = split(b, 0.5);
  sample_piece(l, piece, t0, tm, eps, depth + 1, out);
  sample_piece(r, piece, tm, t1, eps, depth + 1, out);
}

// The same subdivision on the stack, for degrees below 16: the same
// arithmetic as the kernel's split() (homogeneous cascade at 1/2, points
// divided back by their weights, weights normalised to a first weight of
// 1), so the same samples, without two allocations per split.
struct SmallBezier {
  int n = 0;
  bool rational = false;
  Vec3 p[16];
  double w[16];
};

void sample_small(const SmallBezier& b, size_t piece, double t0, double t1, double eps, int depth,
                  std::vector<Sample>& out) {
  double flat = 0;
  for (int i = 0; i <= b.n; ++i) flat = std::max(flat, dist_to_segment(b.p[i], b.p[0], b.p[b.n]));
  if (flat <= eps || depth >= 40) {
    out.push_back({b.p[b.n], piece, t1});
    return;
  }
  const int n = b.n;
  Vec3 qp[16];
  double qw[16];
  for (int i = 0; i <= n; ++i) {
    const double w = b.rational ? b.w[i] : 1.0;
    qp[i] = b.p[i] * w;
    qw[i] = w;
  }
  Vec3 lp[16], rp[16];
  double lw[16], rw[16];
  lp[0] = qp[0], lw[0] = qw[0];
  rp[n] = qp[n], rw[n] = qw[n];
  const double t = 0.5, s = 1 - t;
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) {
      qp[i] = qp[i] * s + qp[i + 1] * t;
      qw[i] = qw[i] * s + qw[i + 1] * t;
    }
    lp[r] = qp[0], lw[r] = qw[0];
    rp[n - r] = qp[n - r], rw[n - r] = qw[n - r];
  }
  SmallBezier L, R;
  L.n = R.n = n;
  L.rational = R.rational = b.rational;
  for (int i = 0; i <= n; ++i) {
    L.p[i] = lp[i] / lw[i];
    R.p[i] = rp[i] / rw[i];
    if (b.rational) L.w[i] = lw[i] / lw[0], R.w[i] = rw[i] / rw[0];
  }
  const double tm = 0.5 * (t0 + t1);
  sample_small(L, piece, t0, tm, eps, depth + 1, out);
  sample_small(R, piece, tm, t1, eps, depth + 1, out);
}

void sample_any(const Bezier& b, size_t piece, double eps, std::vector<Sample>& out) {
  if (b.degree() + 1 > 16) return sample_piece(b, piece, 0, 1, eps, 0, out);
  SmallBezier sb;
  sb.n = b.degree();
  sb.rational = b.rational();
  for (int i = 0; i <= sb.n; ++i) {
    sb.p[i] = b.points[i];
    sb.w[i] = b.weight(i);
  }
  sample_small(sb, piece, 0, 1, eps, 0, out);
}

// Nearest distance from x to the polyline pts, searching a window around
// *hint first and the whole polyline when the window's answer is large.
double dist_to_polyline(const Vec3& x, std::span<const Vec3> pts, size_t& hint, size_t window, double large,
                        size_t* seg_out = nullptr) {
  const size_t nseg = pts.size() > 1 ? pts.size() - 1 : 0;
  if (nseg == 0) return dist(x, pts[0]);
  auto scan = [&](size_t a, size_t b) {
    double best = std::numeric_limits<double>::infinity();
    size_t arg = a;
    for (size_t i = a; i < b; ++i) {
      const double d = dist_to_segment(x, pts[i], pts[i + 1]);
      if (d < best) best = d, arg = i;
    }
    return std::pair(best, arg);
  };
  const size_t a = hint > window ? hint - window : 0;
  const size_t b = std::min(nseg, hint + window + 1);
  auto [d, arg] = scan(a, b);
  if (d > large) std::tie(d, arg) = scan(0, nseg);
  hint = arg;
  if (seg_out) *seg_out = arg;
  return d;
}

// The largest interior value seen by golden-section steps on [a, b], to a
// billionth of the interval (a distance read there is off by the square of
// that times the curve's speed: far below floating-point noise).
double golden_max(double a, double b, const auto& f) {
  const auto g = flatten_detail::golden_section(a, b, f, 60, std::max(1e-15, 1e-9 * (b - a)), true);
  return std::max(g.f1, g.f2);
}

// The point and the first derivative of `b` at t, from one de Casteljau
// cascade (homogeneous, on the stack for the usual degrees): the last two
// points of the cascade give both.
void point_and_derivative(const Bezier& b, double t, Vec3& p, Vec3& d) {
  const int n = b.degree();
  struct H {
    Vec3 p;
    double w;
  };
  constexpr int kStack = 16;
  H stack[kStack];
  std::vector<H> heap;
  if (n + 1 > kStack) heap.resize(n + 1);
  H* q = n + 1 > kStack ? heap.data() : stack;
  for (int i = 0; i <= n; ++i) q[i] = {b.points[i] * b.weight(i), b.weight(i)};
  const double s = 1 - t;
  for (int r = 1; r < n; ++r)
    for (int i = 0; i <= n - r; ++i) q[i] = {q[i].p * s + q[i + 1].p * t, q[i].w * s + q[i + 1].w * t};
  const H a{q[0].p * s + q[1].p * t, q[0].w * s + q[1].w * t};
  p = a.p / a.w;
  // C = A / w: C' = (A' - C w') / w, with A' = n (A1 - A0), w' = n (w1 - w0).
  d = ((q[1].p - q[0].p) * double(n) - p * (double(n) * (q[1].w - q[0].w))) / a.w;
}

// Distance from x to the arc of `b` over [t0, t1], an arc between two
// neighbouring dense samples (so within `resolution` of its chord, and
// the distance along it has a single minimum): at an end, or where
// (C(t) - x) . C'(t) changes sign, found by bracketed regula falsi
// (Illinois), to a billionth of the interval.
double nearest_on_arc(const Bezier& b, double t0, double t1, const Vec3& x) {
  Vec3 p0, d0, p1, d1;
  point_and_derivative(b, t0, p0, d0);
  point_and_derivative(b, t1, p1, d1);
  double g0 = dot(p0 - x, d0), g1 = dot(p1 - x, d1);
  double best = std::min(dist(p0, x), dist(p1, x));
  if (!(g0 < 0 && g1 > 0)) return best;  // no interior minimum
  double a = t0, c = t1;
  int side = 0;
  for (int it = 0; it < 60 && c - a > 1e-9 * (t1 - t0); ++it) {
    const double t = (a * g1 - c * g0) / (g1 - g0);
    Vec3 p, dp;
    point_and_derivative(b, t, p, dp);
    best = std::min(best, dist(p, x));
    const double g = dot(p - x, dp);
    if (g == 0) break;
    if (g < 0) {
      a = t, g0 = g;
      if (side == -1) g1 *= 0.5;
      side = -1;
    } else {
      c = t, g1 = g;
      if (side == 1) g0 *= 0.5;
      side = 1;
    }
  }
  return best;
}

}  // namespace

Deviation measure_deviation(std::span<const Bezier> pieces, std::span<const Vec3> polyline, double tolerance) {
  Deviation dev;
  if (pieces.empty() || polyline.empty()) return dev;
  const double resolution = std::max(tolerance * kMeasureResolution, control_magnitude(pieces) * 1e-13);
  std::vector<Sample> D;
  D.push_back({pieces[0].front(), 0, 0});
  for (size_t i = 0; i < pieces.size(); ++i) sample_any(pieces[i], i, resolution, D);
  std::vector<Vec3> dpts(D.size());
  for (size_t i = 0; i < D.size(); ++i) dpts[i] = D[i].p;

  const double large = tolerance;
  // Windows: the two sequences advance together along the curve.
  const size_t wP = 8 + 2 * polyline.size() / D.size();
  // (Two polyline segments' worth of dense samples either side: consecutive
  // samples are 1/64 of a segment apart, but the dense samples crowd where
  // the curve bends; one segment's worth over-read on random curves. Any
  // window can only over-read a distance, never under-read it.)
  const size_t wD = 8 + 2 * D.size() / polyline.size();
  // Curve -> polyline, at the on-curve samples, then refined between them.
  {
    size_t hint = 0;
    std::vector<std::pair<double, size_t>> cand;
    std::vector<size_t> near(D.size());  // nearest polyline segment of each sample
    for (size_t i = 0; i < D.size(); ++i) {
      const double d = dist_to_polyline(D[i].p, polyline, hint, wP, large);
      near[i] = hint;
      cand.push_back({d, i});
    }
    std::partial_sort(cand.begin(), cand.begin() + std::min<size_t>(8, cand.size()), cand.end(),
                      [](auto& x, auto& y) { return x.first > y.first; });
    for (size_t c = 0; c < std::min<size_t>(8, cand.size()); ++c) {
      dev.curve_to_path = std::max(dev.curve_to_path, cand[c].first);
      const size_t i = cand[c].second;
      // Refine on the true curve between the neighbouring samples of the same piece.
      for (size_t j : {i > 0 ? i - 1 : i, i}) {
        if (j + 1 >= D.size()) continue;
        const Bezier& b = pieces[D[j + 1].piece];
        const double t0 = D[j].piece == D[j + 1].piece ? D[j].t : 0.0;
        // Around the sample's nearest segment, not the whole polyline: the
        // refinement cost no longer grows with the program's length.
        size_t h = near[j];
        const double m = golden_max(t0, D[j + 1].t, [&](double t) {
          return dist_to_polyline(evaluate(b, t), polyline, h, wP, large);
        });
        dev.curve_to_path = std::max(dev.curve_to_path, m);
      }
    }
  }
  // Polyline -> curve: 64 samples per segment against the dense on-curve
  // chain (itself within `resolution` of the curve), then the worst samples
  // are refined along their segment and projected exactly on the true curve.
  {
    constexpr int kSteps = 64;
    struct Cand {
      double d;
      size_t k;
      double s;
      size_t near;  // nearest dense segment found
      int steps;    // samples on its segment (the refinement spans the gap to the next)
    };
    std::vector<Cand> cand;
    size_t hint = 0;
    auto point_at = [&](size_t k, double s) {
      return k + 1 < polyline.size() ? lerp(polyline[k], polyline[k + 1], s) : polyline[k];
    };
    // A first reading with a narrow window (the nearest dense segment moves
    // along with the sample); a narrow window can only over-read, so each
    // reading is an upper bound of the wide-window one. The candidates are
    // then read again with the wide window in decreasing order of their
    // first reading, until no first reading can beat the eighth largest
    // wide reading: the same eight as reading every sample wide, at a
    // fraction of the cost.
    constexpr size_t kNarrow = 4;
    for (size_t k = 0; k < polyline.size(); ++k) {
      const int steps = k + 1 < polyline.size() ? kSteps : 1;
      for (int i = 0; i < steps; ++i) {
        const double s = double(i) / steps;
        const double d = dist_to_polyline(point_at(k, s), dpts, hint, kNarrow, large);
        cand.push_back({d, k, s, hint, steps});
      }
    }
    // Largest first readings popped from a heap: usually a handful are
    // read again before the stop.
    auto first_less = [](const Cand& x, const Cand& y) { return x.d < y.d; };  // max-heap on d
    std::make_heap(cand.begin(), cand.end(), first_less);
    std::vector<Cand> wide;
    auto by_d = [](const Cand& x, const Cand& y) { return x.d > y.d; };  // min-heap on d
    for (auto end = cand.end(); end != cand.begin(); --end) {
      std::pop_heap(cand.begin(), end, first_less);
      const Cand& c = *(end - 1);
      if (wide.size() == 8 && c.d <= wide.front().d) break;
      size_t h = c.near;
      Cand w = c;
      w.d = dist_to_polyline(point_at(c.k, c.s), dpts, h, wD, large);
      w.near = h;
      if (wide.size() < 8) {
        wide.push_back(w);
        std::push_heap(wide.begin(), wide.end(), by_d);
      } else if (w.d > wide.front().d) {
        std::pop_heap(wide.begin(), wide.end(), by_d);
        wide.back() = w;
        std::push_heap(wide.begin(), wide.end(), by_d);
      }
    }
    cand = std::move(wide);
    const size_t top = cand.size();
    std::sort(cand.begin(), cand.end(), [](const Cand& x, const Cand& y) { return x.d > y.d; });
    // Exact distance from x to the true curve near its nearest dense sample.
    // Searched around the candidate's nearest dense segment (a whole-chain
    // scan per evaluation made long programs quadratic).
    // (The candidate's nearest dense segment is known: a sample 1/64 of a
    // segment away has its nearest within a few dense segments of it.)
    auto to_curve = [&](const Vec3& x, size_t near) {
      size_t seg = 0, h = near;
      double d = dist_to_polyline(x, dpts, h, 8, large, &seg);
      const size_t lo = seg > 0 ? seg - 1 : 0, hi = std::min(seg + 2, D.size() - 1);
      for (size_t j = lo; j < hi; ++j) {
        if (D[j].piece == D[j + 1].piece && D[j + 1].t <= D[j].t) continue;
        const Bezier& b = pieces[D[j + 1].piece];
        const double t0 = D[j].piece == D[j + 1].piece ? D[j].t : 0.0;
        d = std::min(d, nearest_on_arc(b, t0, D[j + 1].t, x));
      }
      return d;
    };
    for (size_t c = 0; c < top; ++c) {
      const auto& cd = cand[c];
      if (cd.k + 1 >= polyline.size()) {
        dev.path_to_curve = std::max(dev.path_to_curve, to_curve(polyline[cd.k], cd.near));
        continue;
      }
      const double a = std::max(0.0, cd.s - 1.0 / cd.steps), b = std::min(1.0, cd.s + 1.0 / cd.steps);
      dev.path_to_curve =
          std::max(dev.path_to_curve, golden_max(a, b, [&](double s) { return to_curve(point_at(cd.k, s), cd.near); }));
    }
  }
  return dev;
}

}  // namespace bezcam
