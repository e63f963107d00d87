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

// Squared distance from p to the segment [a, b]: the arithmetic of
// dist_to_segment(), whose value is the square root of this one. Scans
// compare squares and take one root at the end (the same nearest distance).
inline double dist2_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const Vec3 q = len2 == 0 ? a : a + ab * std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  const Vec3 d = p - q;
  return dot(d, d);
}

// The nearest of the segments [a, b) of pts to x: (squared distance, index).
std::pair<double, size_t> scan2(const Vec3& x, std::span<const Vec3> pts, size_t a, size_t b) {
  double best = std::numeric_limits<double>::infinity();
  size_t arg = a;
  for (size_t i = a; i < b; ++i) {
    const double d = dist2_to_segment(x, pts[i], pts[i + 1]);
    if (d < best) best = d, arg = i;
  }
  return {best, arg};
}

// Nearest distance from x to the polyline pts, searching a window around
// *hint first and the whole polyline when the window's answer is large.
double dist_to_polyline(const Vec3& x, std::span<const Vec3> pts, size_t& hint, size_t window, double large,
                        size_t* seg_out = nullptr) {
  const size_t nseg = pts.size() > 1 ? pts.size() - 1 : 0;
  if (nseg == 0) return dist(x, pts[0]);
  const size_t a = hint > window ? hint - window : 0;
  const size_t b = std::min(nseg, hint + window + 1);
  auto [d2, arg] = scan2(x, pts, a, b);
  double d = std::sqrt(d2);
  if (d > large) std::tie(d2, arg) = scan2(x, pts, 0, nseg), d = std::sqrt(d2);
  hint = arg;
  if (seg_out) *seg_out = arg;
  return d;
}

// A quick reading of the distance from x to the polyline pts, an upper
// bound of it: from segment *hint, step to the next (or previous) segment
// while it is nearer; *hint is left at the segment found. Where the
// reading is above `large`, the whole polyline is searched (a reading above
// it is a true distance). A window centred on the segment found contains
// it: a windowed reading from there is never above this one.
double descend(const Vec3& x, std::span<const Vec3> pts, size_t& hint, double large) {
  const size_t nseg = pts.size() > 1 ? pts.size() - 1 : 0;
  if (nseg == 0) return dist(x, pts[0]);
  size_t i = std::min(hint, nseg - 1);
  double best = dist2_to_segment(x, pts[i], pts[i + 1]);
  const size_t from = i;
  while (i + 1 < nseg) {
    const double d = dist2_to_segment(x, pts[i + 1], pts[i + 2]);
    if (!(d < best)) break;
    best = d, ++i;
  }
  if (i == from)
    while (i > 0) {
      const double d = dist2_to_segment(x, pts[i - 1], pts[i]);
      if (!(d < best)) break;
      best = d, --i;
    }
  double dd = std::sqrt(best);
  if (dd > large) {
    const auto [d2, arg] = scan2(x, pts, 0, nseg);
    dd = std::sqrt(d2), i = arg;
  }
  hint = i;
  return dd;
}

// Nearest distance from x near *hint: a descent to the nearest segment
// along the chain from *hint (however closely the points crowd), then a
// window of w segments either side of the one found.
double near_distance(const Vec3& x, std::span<const Vec3> pts, size_t& hint, size_t w, double large,
                     size_t* seg_out = nullptr) {
  descend(x, pts, hint, large);
  return dist_to_polyline(x, pts, hint, w, large, seg_out);
}

// The exact nearest segment of a chain of points, searched by runs of
// consecutive segments: each run has a box, and a run whose box is not
// nearer than the best segment found so far is not read. No window: the
// reading is the true distance to the chain, wherever the chain comes
// back near itself (a curve doubling back along its chord, a loop).
class ChainIndex {
 public:
  void build(std::span<const Vec3> pts) {
    pts_ = pts;
    const size_t nseg = pts.size() > 1 ? pts.size() - 1 : 0;
    run_ = std::max<size_t>(8, static_cast<size_t>(std::sqrt(double(nseg))));
    boxes_.clear();
    for (size_t a = 0; a < nseg; a += run_) {
      Box3 b;
      for (size_t i = a; i <= std::min(a + run_, nseg); ++i) b.add(pts[i]);
      boxes_.push_back(b);
    }
  }
  // Distance from x to the chain; *seg receives the nearest segment. The
  // run of *seg is read first (the caller's guess).
  double nearest(const Vec3& x, size_t& seg) const {
    const size_t nseg = pts_.size() > 1 ? pts_.size() - 1 : 0;
    if (nseg == 0) return dist(x, pts_[0]);
    double best = std::numeric_limits<double>::infinity();
    size_t arg = 0;
    auto read_run = [&](size_t r) {
      const size_t a = r * run_, b = std::min(a + run_, nseg);
      const auto [d, i] = scan2(x, pts_, a, b);
      if (d < best) best = d, arg = i;
    };
    const size_t first = std::min(seg, nseg - 1) / run_;
    read_run(first);
    for (size_t r = 0; r < boxes_.size(); ++r)
      if (r != first && box_dist2(x, boxes_[r]) < best) read_run(r);
    seg = arg;
    return std::sqrt(best);
  }

 private:
  static double box_dist2(const Vec3& x, const Box3& b) {
    double d = 0;
    for (int k = 0; k < 3; ++k) {
      const double e = std::max({b.lo[k] - x[k], 0.0, x[k] - b.hi[k]});
      d += e * e;
    }
    return d;
  }
  std::span<const Vec3> pts_;
  std::vector<Box3> boxes_;
  size_t run_ = 8;
};

// A quick reading near *hint (near_distance()) checked against what the
// distance can be: a distance to a set moves no faster than the point, so
// at x it is at most `known` (the exact distance at x0) plus |x - x0|. A
// quick reading above that stopped at the wrong part of a chain that comes
// back near x: x is then read exactly with `index`.
double checked_distance(const Vec3& x, std::span<const Vec3> pts, const ChainIndex& index, size_t& hint, double large,
                        const Vec3& x0, double known) {
  const double d = near_distance(x, pts, hint, 2, large);
  return d > known + dist(x, x0) + 1e-9 * large ? index.nearest(x, hint) : d;
}

// A reading of a distance at one sample: the sample (index k, or segment k
// at fraction s), its reading d and the nearest segment found.
struct Cand {
  double d;
  size_t k;
  double s;
  size_t near;  // nearest segment found
  int steps;    // samples on its segment (the refinement spans the gap to the next)
};

// The eight largest exact readings of the samples in `cand`, largest
// first, from their quick readings (upper bounds of the exact ones, see
// descend()): candidates are read again with `reread` (which updates d and
// near) in decreasing order of their quick reading, until no quick reading
// can beat the eighth largest exact one: the same eight as reading every
// sample exactly, at a fraction of the cost. `cand` is
// consumed; the result is left in `top`.
template <class Reread>
void largest_readings(std::vector<Cand>& cand, std::vector<Cand>& top, Reread&& reread) {
  constexpr size_t kTop = 8;
  top.clear();
  // Largest quick readings popped from a heap: usually a handful are read
  // again before the stop.
  auto first_less = [](const Cand& x, const Cand& y) { return x.d < y.d; };  // max-heap on d
  std::make_heap(cand.begin(), cand.end(), first_less);
  auto by_d = [](const Cand& x, const Cand& y) { return x.d > y.d; };  // min-heap on d
  for (auto end = cand.end(); end != cand.begin(); --end) {
    std::pop_heap(cand.begin(), end, first_less);
    const Cand& c = *(end - 1);
    if (top.size() == kTop && c.d <= top.front().d) break;
    Cand w = c;
    reread(w);
    if (top.size() < kTop) {
      top.push_back(w);
      std::push_heap(top.begin(), top.end(), by_d);
    } else if (w.d > top.front().d) {
      std::pop_heap(top.begin(), top.end(), by_d);
      top.back() = w;
      std::push_heap(top.begin(), top.end(), by_d);
    }
  }
  std::sort(top.begin(), top.end(), by_d);
}

// The largest interior value seen by golden-section steps on [a, b], to
// 1e-5 of the interval (a distance read there is off by about the square
// of that times the second derivative along it: on the short intervals
// refined here, below 1e-12 of a millimetre).
// Returns the point of that value: the refinements read it again exactly.
struct GoldenMax {
  double value, at;
};
GoldenMax golden_max(double a, double b, const auto& f) {
  const auto g = flatten_detail::golden_section(a, b, f, 60, std::max(1e-15, 1e-5 * (b - a)), true);
  const double k = 0.3819660112501051;  // golden_section's interior points
  return g.f1 >= g.f2 ? GoldenMax{g.f1, g.a + k * (g.b - g.a)} : GoldenMax{g.f2, g.b - k * (g.b - g.a)};
}

// A piece with, when it is polynomial of degree <= 3, its power form
// (M(t) = sum c_j t^j, evaluated by Horner: a few multiply-adds per point,
// within a few units in the last place of the control points' magnitude
// for these degrees). Other pieces are evaluated by de Casteljau.
struct Piece {
  const Bezier* b = nullptr;
  int n = -1;  // degree of the power form; -1: none
  Vec3 c[4];

  explicit Piece(const Bezier& bz) : b(&bz) {
    if (bz.rational() || bz.degree() > 3) return;
    n = bz.degree();
    const auto& P = bz.points;
    c[0] = P[0];
    if (n == 1) c[1] = P[1] - P[0];
    if (n == 2) c[1] = (P[1] - P[0]) * 2.0, c[2] = P[2] - P[1] * 2.0 + P[0];
    if (n == 3) {
      c[1] = (P[1] - P[0]) * 3.0;
      c[2] = (P[2] - P[1] * 2.0 + P[0]) * 3.0;
      c[3] = P[3] - P[2] * 3.0 + P[1] * 3.0 - P[0];
    }
  }
  Vec3 at(double t) const {
    if (n < 0) return evaluate(*b, t);
    Vec3 r = c[n];
    for (int j = n; j-- > 0;) r = r * t + c[j];
    return r;
  }
  // The point and the first derivative at t.
  void point_and_derivative(double t, Vec3& p, Vec3& d) const;
};

// The point and the first derivative of `b` at t, from one de Casteljau
// cascade (homogeneous, on the stack for the usual degrees): the last two
// points of the cascade give both.
void cascade_point_and_derivative(const Bezier& b, double t, Vec3& p, Vec3& d) {
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

void Piece::point_and_derivative(double t, Vec3& p, Vec3& d) const {
  if (n < 0) return cascade_point_and_derivative(*b, t, p, d);
  p = at(t);
  d = Vec3{};
  for (int j = n; j >= 1; --j) d = d * t + c[j] * double(j);
}

// Uniform steps in t over a piece with a power form, as many as keep every
// arc between two steps within eps of its chord: a polynomial of degree n
// departs from its chord over a step h by at most h^2 / 8 max |C''|, and
// |C''| <= n (n - 1) max |P[i+2] - 2 P[i+1] + P[i]|. Returns false (nothing
// sampled) when the piece has no power form or would take too many steps.
bool sample_uniform(const Piece& pc, size_t piece, double eps, std::vector<Sample>& out) {
  if (pc.n < 0) return false;
  const auto& P = pc.b->points;
  const int n = pc.n;
  double m2 = 0;
  for (int i = 0; i + 2 <= n; ++i) m2 = std::max(m2, norm(P[i + 2] - P[i + 1] * 2.0 + P[i]));
  const double steps = std::ceil(std::sqrt(n * (n - 1) * m2 / (8 * eps)));
  constexpr double kMostSteps = 1 << 22;
  if (!(steps <= kMostSteps)) return false;
  const size_t N = std::max<size_t>(1, static_cast<size_t>(steps));
  const double h = 1.0 / double(N);
  for (size_t i = 1; i < N; ++i) {
    const double t = double(i) * h;
    out.push_back({pc.at(t), piece, t});
  }
  out.push_back({P.back(), piece, 1.0});
  return true;
}

// Distance from x to the arc of a piece over [t0, t1], an arc between two
// neighbouring dense samples (so within `resolution` of its chord, and
// the distance along it has a single minimum): at an end, or where
// (C(t) - x) . C'(t) changes sign, found by bracketed regula falsi
// (Illinois), to a billionth of the interval.
double nearest_on_arc(const Piece& b, double t0, double t1, const Vec3& x) {
  Vec3 p0, d0, p1, d1;
  b.point_and_derivative(t0, p0, d0);
  b.point_and_derivative(t1, p1, d1);
  double g0 = dot(p0 - x, d0), g1 = dot(p1 - x, d1);
  double best = std::min(dist(p0, x), dist(p1, x));
  if (!(g0 < 0 && g1 > 0)) return best;  // no interior minimum
  double a = t0, c = t1;
  int side = 0;
  for (int it = 0; it < 60 && c - a > 1e-9 * (t1 - t0); ++it) {
    const double t = (a * g1 - c * g0) / (g1 - g0);
    Vec3 p, dp;
    b.point_and_derivative(t, p, dp);
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

// Scratch vectors kept by each measuring thread: no allocation per sample,
// and none per entity once the first has grown them. Capacity beyond
// kKeep elements is given back after each measurement.
struct Scratch {
  std::vector<Sample> D;
  std::vector<Vec3> dpts;
  std::vector<Piece> pieces;
  std::vector<char> uniform;
  std::vector<Cand> cand, top;
  ChainIndex index;
  static constexpr size_t kKeep = size_t{1} << 20;
  void trim() {
    auto fit = [](auto& v) {
      if (v.capacity() > kKeep) std::decay_t<decltype(v)>().swap(v);
    };
    fit(D), fit(dpts), fit(pieces), fit(uniform), fit(cand), fit(top);
  }
};

}  // namespace

Deviation measure_deviation(std::span<const Bezier> pieces, std::span<const Vec3> polyline, double tolerance) {
  Deviation dev;
  if (pieces.empty() || polyline.empty()) return dev;
  const double resolution = std::max(tolerance * kMeasureResolution, control_magnitude(pieces) * 1e-13);
  thread_local Scratch scratch;
  struct Trim {
    Scratch& s;
    ~Trim() { s.trim(); }
  } trim{scratch};
  auto& D = scratch.D;
  auto& P = scratch.pieces;
  auto& uniform = scratch.uniform;  // per piece: sampled in uniform steps (each arc within `resolution` of its chord)
  D.clear(), P.clear(), uniform.clear();
  for (const Bezier& b : pieces) P.emplace_back(b);
  D.push_back({pieces[0].front(), 0, 0});
  for (size_t i = 0; i < pieces.size(); ++i) {
    uniform.push_back(sample_uniform(P[i], i, resolution, D));
    if (!uniform.back()) sample_any(pieces[i], i, resolution, D);
  }
  auto& dpts = scratch.dpts;
  dpts.resize(D.size());
  for (size_t i = 0; i < D.size(); ++i) dpts[i] = D[i].p;

  // Quick readings and refinements search near the nearest segment found
  // before (the two sequences advance together along the curve); a reading
  // above `large` is replaced by a search of everything.
  const double large = tolerance;
  auto& cand = scratch.cand;
  auto& top = scratch.top;
  // Curve -> polyline, at the on-curve samples (a quick reading each, the
  // largest read again exactly), then refined between them.
  {
    cand.clear();
    size_t hint = 0;
    for (size_t i = 0; i < D.size(); ++i) {
      const double d = descend(D[i].p, polyline, hint, large);
      cand.push_back({d, i, 0, hint, 0});
    }
    scratch.index.build(polyline);
    largest_readings(cand, top, [&](Cand& c) { c.d = scratch.index.nearest(D[c.k].p, c.near); });
    for (const Cand& c : top) {
      dev.curve_to_path = std::max(dev.curve_to_path, c.d);
      const size_t i = c.k;
      // Refine on the true curve between the neighbouring samples of the same piece.
      for (size_t j : {i > 0 ? i - 1 : i, i}) {
        if (j + 1 >= D.size()) continue;
        const Piece& b = P[D[j + 1].piece];
        const double t0 = D[j].piece == D[j + 1].piece ? D[j].t : 0.0;
        // Around the sample's nearest segment (found exactly), not the
        // whole polyline: the refinement cost does not grow with the
        // program's length.
        // The search's quick readings may read high where the path comes
        // back near itself: its best point is read again exactly, and that
        // reading is the one kept.
        size_t h = c.near;
        const GoldenMax m = golden_max(t0, D[j + 1].t, [&](double t) {
          return checked_distance(b.at(t), polyline, scratch.index, h, large, D[c.k].p, c.d);
        });
        dev.curve_to_path = std::max(dev.curve_to_path, scratch.index.nearest(b.at(m.at), h));
      }
    }
  }
  // Polyline -> curve: 64 samples per segment against the dense on-curve
  // chain (itself within `resolution` of the curve), then the worst samples
  // are refined along their segment and projected exactly on the true curve.
  {
    constexpr int kSteps = 64;
    cand.clear();
    size_t hint = 0;
    auto point_at = [&](size_t k, double s) {
      return k + 1 < polyline.size() ? lerp(polyline[k], polyline[k + 1], s) : polyline[k];
    };
    // A quick reading first (the nearest dense segment moves along with the
    // sample), then the largest read again exactly: see largest_readings().
    for (size_t k = 0; k < polyline.size(); ++k) {
      const int steps = k + 1 < polyline.size() ? kSteps : 1;
      for (int i = 0; i < steps; ++i) {
        const double s = double(i) / steps;
        const double d = descend(point_at(k, s), dpts, hint, large);
        cand.push_back({d, k, s, hint, steps});
      }
    }
    scratch.index.build(dpts);
    largest_readings(cand, top, [&](Cand& c) { c.d = scratch.index.nearest(point_at(c.k, c.s), c.near); });
    // Exact distance from x to the true curve near its nearest dense
    // segment: found by descent from the candidate's (exact) nearest one,
    // which the refinement's points stay close to, and searched exactly
    // when the descent's reading is more than the distance can be there (a
    // part of the curve coming back close). A whole-chain scan per
    // evaluation made long programs quadratic.
    // With `exact`, the nearest dense segment is searched exactly.
    auto to_curve = [&](const Vec3& x, size_t& h, const Cand& c, bool exact) {
      size_t seg = 0;
      double d = exact ? scratch.index.nearest(x, h)
                       : checked_distance(x, dpts, scratch.index, h, large, point_at(c.k, c.s), c.d);
      seg = h;
      const size_t lo = seg > 0 ? seg - 1 : 0, hi = std::min(seg + 2, D.size() - 1);
      for (size_t j = lo; j < hi; ++j) {
        if (D[j].piece == D[j + 1].piece && D[j + 1].t <= D[j].t) continue;
        // An arc within `resolution` of its chord is no nearer than the
        // chord's distance less that: such an arc cannot lower d.
        if (uniform[D[j + 1].piece] && std::sqrt(dist2_to_segment(x, dpts[j], dpts[j + 1])) - resolution >= d)
          continue;
        const Piece& b = P[D[j + 1].piece];
        const double t0 = D[j].piece == D[j + 1].piece ? D[j].t : 0.0;
        d = std::min(d, nearest_on_arc(b, t0, D[j + 1].t, x));
      }
      return d;
    };
    // Kept: exact readings at the candidate and at the search's best point
    // (its quick readings guide it, and may read high).
    for (const Cand& cd : top) {
      size_t h = cd.near;  // moves with the refinement's points
      dev.path_to_curve = std::max(dev.path_to_curve, to_curve(point_at(cd.k, cd.s), h, cd, true));
      if (cd.k + 1 >= polyline.size()) continue;
      const double a = std::max(0.0, cd.s - 1.0 / cd.steps), b = std::min(1.0, cd.s + 1.0 / cd.steps);
      const GoldenMax m = golden_max(a, b, [&](double s) { return to_curve(point_at(cd.k, s), h, cd, false); });
      dev.path_to_curve = std::max(dev.path_to_curve, to_curve(point_at(cd.k, m.at), h, cd, true));
    }
  }
  return dev;
}

}  // namespace bezcam
