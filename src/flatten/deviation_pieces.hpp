#pragma once
// The pieces the deviation measures work on (private to deviation.cpp,
// which alone includes it): a chain of points indexed for its nearest
// segment (ChainIndex), a piece of curve with its evaluation and the sag
// bound every measurement rests on (Piece), and the closed forms for the
// largest value of a line plus a bump.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "bezcam/flatten/deviation.hpp"

namespace bezcam {

namespace {

// Squared distance from p to the segment [a, b]: the arithmetic of
// dist_to_segment(), whose value is the square root of this one.
inline double dist2_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const Vec3 q = len2 == 0 ? a : a + ab * std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  const Vec3 d = p - q;
  return dot(d, d);
}

// Segment k of a chain of points (a single point: a segment of length 0).
inline double seg_dist(const Vec3& x, std::span<const Vec3> pts, size_t k) {
  return std::sqrt(dist2_to_segment(x, pts[k], pts[std::min(k + 1, pts.size() - 1)]));
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
    if (nseg == 0) return seg = 0, dist(x, pts_[0]);
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

// Homogeneous point (w P, w) of a piece's general form.
struct H {
  Vec3 p;
  double w;
};
inline H lerp_h(const H& a, const H& b, double t) {
  const double s = 1 - t;
  return {a.p * s + b.p * t, a.w * s + b.w * t};
}

// Work space for a de Casteljau cascade of m homogeneous points: on the
// stack below kSmall points, on the heap only for the rare higher degrees.
constexpr int kSmall = 16;
class HWork {
 public:
  explicit HWork(int m) : p_(m > kSmall ? (heap_.resize(static_cast<size_t>(m)), heap_.data()) : stack_) {}
  H* get() { return p_; }
  H& operator[](int i) { return p_[i]; }

 private:
  H stack_[kSmall];
  std::vector<H> heap_;
  H* p_;
};

// A piece of the curve: evaluation and the bound every measurement below
// rests on, sag(): the arc over [t0, t1] and its chord lie within sag() of
// each other (each point of either within that distance of the other).
// Polynomial pieces up to degree 3 have a power form (Horner); the others
// (rational, or degree > 3) a general form: their homogeneous control
// points, evaluated and split by de Casteljau's cascade on the stack (no
// allocation below degree kSmall).
struct Piece {
  const Bezier* b = nullptr;
  int n = -1;  // degree of the power form; -1: none
  Vec3 c[4];
  int deg = 0;            // the general form's degree
  const H* hp = nullptr;  // its deg + 1 homogeneous control points (n < 0)
  double sag01 = -1;      // sag() over the whole piece (-1: not known yet)
  Vec3 e0, e1;            // its ends

  // `hom`: room for the general form's points (n < 0), filled here.
  Piece(const Bezier& bz, H* hom) : b(&bz), deg(bz.degree()) {
    if (bz.rational() || bz.degree() > 3) {
      for (int i = 0; i <= deg; ++i) {
        const double w = bz.weight(i);
        hom[i] = {bz.points[i] * w, w};
      }
      hp = hom;
    } else {
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
    e0 = at(0), e1 = at(1);
    sag01 = sag(0, 1, e0, e1);
  }
  // Room a piece's general form takes.
  static size_t room(const Bezier& bz) { return bz.rational() || bz.degree() > 3 ? bz.points.size() : 0; }

  Vec3 at(double t) const {
    if (n < 0) {
      HWork q(deg + 1);
      for (int i = 0; i <= deg; ++i) q[i] = hp[i];
      for (int r = 1; r <= deg; ++r)
        for (int i = 0; i <= deg - r; ++i) q[i] = lerp_h(q[i], q[i + 1], t);
      return q[0].p / q[0].w;
    }
    Vec3 r = c[n];
    for (int j = n; j-- > 0;) r = r * t + c[j];
    return r;
  }
  // C'(t), with a power form (n >= 0).
  Vec3 tangent(double t) const {
    Vec3 d{};
    for (int j = n; j >= 1; --j) d = d * t + c[j] * double(j);
    return d;
  }
  // The point and its first two derivatives at t.
  void derivatives(double t, Vec3& p, Vec3& d1, Vec3& d2) const {
    if (n < 0) return general_derivatives(t, p, d1, d2);
    p = at(t);
    d1 = n >= 1 ? c[1] : Vec3{};
    d2 = Vec3{};
    if (n >= 2) d1 += c[2] * (2 * t), d2 = c[2] * 2.0;
    if (n >= 3) d1 += c[3] * (3 * t * t), d2 += c[3] * (6 * t);
  }
  // The cascade down to its last three points gives the homogeneous
  // curve A (with weight) and its derivatives: A' = deg (S1 - S0) from
  // the last two, A'' = deg (deg - 1) (R2 - 2 R1 + R0) from the three;
  // then C = A / w, C' = (A' - w' C) / w, C'' = (A'' - 2 w' C' - w'' C) / w.
  void general_derivatives(double t, Vec3& p, Vec3& d1, Vec3& d2) const {
    HWork q(deg + 1);
    for (int i = 0; i <= deg; ++i) q[i] = hp[i];
    H a2{{}, 0};
    for (int r = 1; r <= deg - 2; ++r)
      for (int i = 0; i <= deg - r; ++i) q[i] = lerp_h(q[i], q[i + 1], t);
    if (deg >= 2) {
      const double k = double(deg) * double(deg - 1);
      a2 = {(q[2].p - q[1].p * 2.0 + q[0].p) * k, (q[2].w - 2 * q[1].w + q[0].w) * k};
      q[0] = lerp_h(q[0], q[1], t), q[1] = lerp_h(q[1], q[2], t);
    }
    const H a1{(q[1].p - q[0].p) * double(deg), (q[1].w - q[0].w) * double(deg)};
    const H a0 = lerp_h(q[0], q[1], t);
    p = a0.p / a0.w;
    d1 = (a1.p - p * a1.w) / a0.w;
    d2 = (a2.p - d1 * (2 * a1.w) - p * a2.w) / a0.w;
  }
  // |C''(t)| with a power form (-1 without: sag() does not use it).
  double acc(double t) const {
    if (n < 0) return -1;
    if (n <= 1) return 0;
    return n == 2 ? 2 * norm(c[2]) : norm(c[2] * 2.0 + c[3] * (6 * t));
  }
  // sag() from the ends' acc(), already known.
  double sag(double t0, double t1, double acc0, double acc1, const Vec3& p0, const Vec3& p1) const {
    if (n < 0) return sag(t0, t1, p0, p1);
    const double h = t1 - t0;
    return h * h * 0.125 * std::max(acc0, acc1);
  }
  // Polynomial of degree n <= 3: C(t) - the chord's point at the same
  // fraction is at most h^2 / 8 max |C''| over the interval (h = t1 - t0),
  // and |C''| (linear in t) is largest at an end. Otherwise the sub-curve
  // (general_sag()).
  double sag(double t0, double t1, const Vec3& p0, const Vec3& p1) const {
    const double h = t1 - t0;
    if (n >= 0) {
      if (n <= 1) return 0;
      const Vec3 a2 = c[2] * 2.0;
      if (n == 2) return h * h * 0.125 * norm(a2);
      return h * h * 0.125 * std::max(norm(a2 + c[3] * (6 * t0)), norm(a2 + c[3] * (6 * t1)));
    }
    if (t0 == 0 && t1 == 1 && sag01 >= 0 && p0 == e0 && p1 == e1) return sag01;
    return general_sag(t0, t1, p0, p1);
  }
  // The sub-curve over [t0, t1] (the cascade's right part at t0, then the
  // left part of that at the rescaled t1, as subcurve() does), its control
  // points' largest distance from the chord: with weights > 0 the arc lies
  // in their hull, so within that distance of the chord; and, joining the
  // chord's ends, it passes within that distance of every chord point. A
  // quadratic's arc is nearer: with weights normalised to 1, w, 1, its
  // distance to the chord's line is 2 u w d / (1 + 2 u (w - 1)) at
  // u = t (1 - t), d the middle point's, increasing in u, so at most
  // w d / (1 + w); when the middle point projects inside the chord the
  // whole hull does, and that is also the distance to the chord.
  double general_sag(double t0, double t1, const Vec3& p0, const Vec3& p1) const {
    HWork q(deg + 1);
    for (int i = 0; i <= deg; ++i) q[i] = hp[i];
    // Forward in place, q[k] is last written at row deg - k: its last
    // point, the right part's k-th. Backward in place, q[k] is last
    // written at row k: its first point, the left part's k-th.
    if (t0 > 0)
      for (int r = 1; r <= deg; ++r)
        for (int i = 0; i <= deg - r; ++i) q[i] = lerp_h(q[i], q[i + 1], t0);
    if (t1 < 1) {
      const double u = t0 > 0 ? (t1 - t0) / (1 - t0) : t1;
      for (int r = 1; r <= deg; ++r)
        for (int i = deg; i >= r; --i) q[i] = lerp_h(q[i - 1], q[i], u);
    }
    double s = 0;
    for (int i = 0; i <= deg; ++i) s = std::max(s, dist_to_segment(q[i].p / q[i].w, p0, p1));
    if (deg == 2) {
      const Vec3 e = p1 - p0, m = q[1].p / q[1].w - p0;
      const double len2 = dot(e, e), l = len2 > 0 ? dot(m, e) / len2 : -1;
      if (l >= 0 && l <= 1) {
        const double w = q[1].w / std::sqrt(q[0].w * q[2].w), d = norm(m - e * l);
        const double ends =
            std::max(dist_to_segment(q[0].p / q[0].w, p0, p1), dist_to_segment(q[2].p / q[2].w, p0, p1));
        s = std::min(s, std::max(w * d / (1 + w), ends));
      }
    }
    return s;
  }
};

// The largest value over l in [l0, l1] of c0 + l (c1 - c0) + 4 q l (1 - l)
// (q >= 0: a line plus a bump of height q at l = 1/2, concave).
// *at (optional) receives the place of that value.
double max_line_bump(double c0, double c1, double q, double l0 = 0, double l1 = 1, double* at = nullptr) {
  double l = q > 0 ? 0.5 + (c1 - c0) / (8 * q) : (c1 > c0 ? l1 : l0);
  l = std::clamp(l, l0, l1);
  if (at) *at = l;
  return c0 + l * (c1 - c0) + 4 * q * l * (1 - l);
}

// The largest value over l in [0, 1] of the lower of two lines (a0 to a1,
// b0 to b1) plus the bump of height q.
double max_of_min(double a0, double a1, double b0, double b1, double q = 0, double* at = nullptr) {
  const double e0 = a0 - b0, e1 = a1 - b1;
  if ((e0 < 0) != (e1 < 0) && e0 != e1) {
    const double l = e0 / (e0 - e1);
    if (l > 0 && l < 1) {
      // The lower line at 0 up to the crossing, the other after.
      double l1 = 0, l2 = 0;
      const double m1 = e0 < 0 ? max_line_bump(a0, a1, q, 0, l, &l1) : max_line_bump(b0, b1, q, 0, l, &l1);
      const double m2 = e0 < 0 ? max_line_bump(b0, b1, q, l, 1, &l2) : max_line_bump(a0, a1, q, l, 1, &l2);
      if (at) *at = m1 >= m2 ? l1 : l2;
      return std::max(m1, m2);
    }
  }
  return e0 + e1 <= 0 ? max_line_bump(a0, a1, q, 0, 1, at) : max_line_bump(b0, b1, q, 0, 1, at);
}

}  // namespace

}  // namespace bezcam
