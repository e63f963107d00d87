#pragma once
// Bounds on how far a piece of curve lies from a chord: the closed forms
// for cubics (the chord through two points of the curve, and the band's
// chord with shifted ends, band_cubic_planar()), the hull bounds for other
// pieces, and a piece prepared for repeated chord tests (Prepared).
// Part of the flattener's translation unit (included by flatten_curve.cpp
// alone, so that its kernels inline into the loops that call them).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bezcam/flatten/degree_reduce.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/roots.hpp"
#include "flatten/search.hpp"

namespace bezcam {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A chord is accepted once its deviation uses this share of the budget:
// deviation grows like the square of the chord, so the chord is then at
// least sqrt(0.94) = 97 % of the longest allowed one.
constexpr double kAcceptShare = 0.94;
// Share of the budget aimed at when predicting the next step.
constexpr double kAimShare = 0.97;

// Max over s in [0,1] of |f(s)|, f the cubic with Bernstein coefficients
// (0, d1, d2, 0): f = 3 s (1-s) (d1 (1-s) + d2 s). Exact: the extremes are
// at the roots of f' = 3 [d1 + 2 (k - d1) s - 3 k s^2] with k = d2 - d1.
double bump_max(double d1, double d2) {
  if (d1 == 0 && d2 == 0) return 0;
  const double k = d2 - d1;
  double r[2];
  const int n = quadratic_roots01(d1, 2 * (k - d1), -3 * k, r);
  double m = 0;
  for (int i = 0; i < n; ++i) {
    const double s = r[i];
    m = std::max(m, std::abs(3 * s * (1 - s) * (d1 * (1 - s) + d2 * s)));
  }
  return m;
}

// Cubic with Bernstein coefficients (0, a1, a2, L): how far it leaves [0, L].
double overshoot(double a1, double a2, double L) {
  if (a1 >= 0 && a1 <= L && a2 >= 0 && a2 <= L) return 0;  // convex hull
  auto f = [&](double s) {
    const double u = 1 - s;
    return 3 * a1 * s * u * u + 3 * a2 * s * s * u + L * s * s * s;
  };
  // f' / 3 in Bernstein form (a1, a2 - a1, L - a2) -> power form.
  const double b0 = a1, b1 = a2 - a1, b2 = L - a2;
  double r[2];
  const int n = quadratic_roots01(b0, 2 * (b1 - b0), b0 - 2 * b1 + b2, r);
  double o = 0;
  for (int i = 0; i < n; ++i) {
    const double v = f(r[i]);
    o = std::max({o, -v, v - L});
  }
  return o;
}

// Returned by the closed forms when the curve leaves the chord's slab past
// an end: the distance there is to an end point, not to the line, and the
// caller switches to the hull bound below (rare: only near turnarounds).
constexpr double kOvershoot = -1;

// Exact distance of the cubic A, Q1, Q2, B to the segment [A, B] when it
// stays within the chord's slab (kOvershoot otherwise).
double cubic_chord_deviation(const Vec3& A, const Vec3& Q1, const Vec3& Q2, const Vec3& B) {
  const Vec3 ab = B - A;
  const double L = norm(ab);
  const Vec3 e1 = Q1 - A, e2 = Q2 - A;
  if (!(L > 1e-300)) {
    // Chord of zero length: the sub-curve lies in the hull of its points.
    return std::max(norm(e1), norm(e2));
  }
  const Vec3 u = ab / L;
  const double a1 = dot(e1, u), a2 = dot(e2, u);
  const Vec3 p1 = e1 - u * a1, p2 = e2 - u * a2;
  // Perpendicular part on two orthonormal axes across the chord; the first
  // is in the plane of the piece when the piece is planar, making the bound
  // exact there (always in 2D).
  Vec3 n1 = p1 + p2;
  if (norm(n1) < 1e-3 * std::max(norm(p1), norm(p2))) n1 = norm(p1) >= norm(p2) ? p1 : p2;
  double perp = 0;
  const double ln1 = norm(n1);
  if (ln1 > 0) {
    n1 = n1 / ln1;
    const Vec3 n2 = cross(u, n1);
    const double m1 = bump_max(dot(p1, n1), dot(p2, n1));
    const double m2 = bump_max(dot(p1, n2), dot(p2, n2));
    perp = std::sqrt(m1 * m1 + m2 * m2);
  }
  if (overshoot(a1, a2, L) > 0) return kOvershoot;
  return perp;
}

// The same in the plane, without building a frame (the common case).
double cubic_chord_deviation_2d(const Vec3& A, const Vec3& Q1, const Vec3& Q2, const Vec3& B) {
  const double abx = B.x - A.x, aby = B.y - A.y;
  const double e1x = Q1.x - A.x, e1y = Q1.y - A.y, e2x = Q2.x - A.x, e2y = Q2.y - A.y;
  const double L2 = abx * abx + aby * aby;
  if (!(L2 > 1e-300)) return std::max(std::hypot(e1x, e1y), std::hypot(e2x, e2y));
  const double L = std::sqrt(L2), inv = 1 / L;
  if (overshoot((abx * e1x + aby * e1y) * inv, (abx * e2x + aby * e2y) * inv, L) > 0) return kOvershoot;
  return bump_max((abx * e1y - aby * e1x) * inv, (abx * e2y - aby * e2x) * inv);
}

// Rigorous bound for any (rational) piece by branch and bound on the convex
// hull: dist(., [A,B]) is convex, so on a sub-curve it is at most its value
// at the control points, and splitting tightens that quadratically.
// `budget` allows an early exit once the answer (accept/reject) is certain.
double hull_chord_deviation(const Bezier& sub, const Vec3& A, const Vec3& B, double budget) {
  auto ub_of = [&](const Bezier& b) {
    double m = 0;
    for (const auto& p : b.points) m = std::max(m, dist_to_segment(p, A, B));
    return m;
  };
  // Known to 0.2 % at most 400 splits in: the flattener only needs to
  // accept or reject, which the budget usually decides much sooner.
  const flatten_detail::SupStop stop{budget, 2e-3, 0, 400};
  return flatten_detail::sup_branch_and_bound(sub, 0.0, stop, ub_of, [&](const Bezier& b, Bezier& l, Bezier& r) {
    std::tie(l, r) = split(b, 0.5);
    return dist_to_segment(l.back(), A, B);
  });
}

// sup_t |D(t)| for the polynomial cubic D with control points d, decided
// against `budget`: D(t) is a convex combination of the d_k, so |D| <=
// max |d_k| (split at 1/2 until that is within the budget). Returns that
// proven bound when it is <= budget, infinity when a value of D is over
// the budget or `depth` splits do not decide.
double cubic_within(const std::array<Vec3, 4>& d, double budget, int depth) {
  const double ub = std::max({norm(d[0]), norm(d[1]), norm(d[2]), norm(d[3])});
  if (ub <= budget) return ub;
  if (norm(d[0]) > budget || norm(d[3]) > budget || depth == 0) return kInf;
  const Vec3 a = (d[0] + d[1]) * 0.5, b = (d[1] + d[2]) * 0.5, c = (d[2] + d[3]) * 0.5;
  const Vec3 ab = (a + b) * 0.5, bc = (b + c) * 0.5, m = (ab + bc) * 0.5;
  if (norm(m) > budget) return kInf;
  const double l = cubic_within({d[0], a, ab, m}, budget, depth - 1);
  if (!(l <= budget)) return kInf;
  return std::max(l, cubic_within({m, bc, c, d[3]}, budget, depth - 1));
}

// sup |D|^2 |AB|^2 for the planar cubic sub-curve S against the segment
// [A, B] when S's projection on the line AB leaves the segment, decided
// against b2 (|AB|^2 budget^2). L(s) = A + u clamp(p(s)), p(s) the
// projection of the cubic with control points A, S1, S2, B (u along AB),
// runs continuously from A to B on the segment, so sup |S - L| bounds the
// Hausdorff distance both ways (as in band_bound()). Multiplied by |AB|,
// the cross part of D = S - L is the cubic with Bernstein coefficients c;
// the along part is a0 (1 - s)^3 + a3 s^3 (the ends' offsets along AB)
// plus e(p(s)) = p(s) - clamp(p(s), 0, l2), p's Bernstein coefficients
// (0, l1, l2p, l2), all multiplied by |AB|. On an interval of s each term
// lies between its values at the interval's ends and at its extremes
// inside (the roots of a quadratic; e is monotone in p), which bounds
// |D|^2 there; intervals are halved (at most 40 times) until the bound is
// within b2 (the largest such bound is returned) or a value of |D|^2 at a
// midpoint is over it (returned: over the budget); infinity when 40
// halvings do not decide.
__attribute__((noinline, cold)) double pointwise_within(const std::array<double, 4>& c, double a0, double a3, double l1,
                                                        double l2p, double l2, double b2) {
  auto cubic = [](double b0, double b1, double b2_, double b3, double s) {
    const double u = 1 - s;
    return u * u * (b0 * u + 3 * b1 * s) + s * s * (3 * b2_ * u + b3 * s);
  };
  auto cross_at = [&](double s) { return cubic(c[0], c[1], c[2], c[3], s); };
  auto p_at = [&](double s) { return cubic(0, l1, l2p, l2, s); };
  auto along_at = [&](double s) {
    const double u = 1 - s;
    return a0 * u * u * u + a3 * s * s * s;
  };
  auto excess = [&](double v) { return v < 0 ? v : v > l2 ? v - l2 : 0.0; };
  // The extremes inside [0, 1]: of the cross part, of p, of the along
  // part (a0 (1 - s)^2 = a3 s^2, where a0 and a3 have one sign).
  double rc[2], rp[2], ra = -1;
  const int nc = quadratic_roots01(c[1] - c[0], 2 * (c[2] - 2 * c[1] + c[0]), c[3] - 3 * c[2] + 3 * c[1] - c[0], rc);
  const int np = quadratic_roots01(l1, 2 * (l2p - 2 * l1), 3 * l1 - 3 * l2p + l2, rp);
  if (a0 * a3 > 0) ra = 1 / (1 + std::sqrt(a3 / a0));
  auto value = [&](double s) {
    const double cv = cross_at(s), av = along_at(s) + excess(p_at(s));
    return cv * cv + av * av;
  };
  auto interval_bound = [&](double s0, double s1) {
    double cl = std::min(cross_at(s0), cross_at(s1)), ch = std::max(cross_at(s0), cross_at(s1));
    double pl = std::min(p_at(s0), p_at(s1)), ph = std::max(p_at(s0), p_at(s1));
    double al = std::min(along_at(s0), along_at(s1)), ah = std::max(along_at(s0), along_at(s1));
    for (int i = 0; i < nc; ++i)
      if (rc[i] > s0 && rc[i] < s1) cl = std::min(cl, cross_at(rc[i])), ch = std::max(ch, cross_at(rc[i]));
    for (int i = 0; i < np; ++i)
      if (rp[i] > s0 && rp[i] < s1) pl = std::min(pl, p_at(rp[i])), ph = std::max(ph, p_at(rp[i]));
    if (ra > s0 && ra < s1) al = std::min(al, along_at(ra)), ah = std::max(ah, along_at(ra));
    const double lo = al + excess(pl), hi = ah + excess(ph);
    return std::max(cl * cl, ch * ch) + std::max(lo * lo, hi * hi);
  };
  struct Span {
    double s0, s1;
    int depth;
  };
  Span stack[48];
  int top = 0;
  stack[top++] = {0, 1, 0};
  double most = 0;
  while (top > 0) {
    const Span sp = stack[--top];
    const double ub = interval_bound(sp.s0, sp.s1);
    if (ub <= b2) {
      most = std::max(most, ub);
      continue;
    }
    const double mid = 0.5 * (sp.s0 + sp.s1), vm = value(mid);
    if (vm > b2) return vm;
    if (sp.depth >= 40) return kInf;
    stack[top++] = {mid, sp.s1, sp.depth + 1};
    stack[top++] = {sp.s0, mid, sp.depth + 1};
  }
  return most;
}

// The parametric distance of band_bound() for a planar polynomial cubic
// sub-curve S (control points S[0..3]) against the segment [A, B], in
// closed form. D = S - L has control points d0 = S0 - A, d1, d2, d3 = S3 - B;
// when the inner points of S project inside the segment (no clamping), d1
// and d2 are across the chord, so along the chord D has the Bernstein
// coefficients (a0, 0, 0, a3) and across it (p0, p1, p2, p3). The cross
// part's largest magnitude P is exact (its extremes are at the ends or at
// the roots of a quadratic); the along part is at most max(|a0|, |a3|) = T.
// So sup |D| <= sqrt(P^2 + T^2), and sup |D| >= P. Both are exact to within
// a relative T^2 / (2 P^2), which is about an eighth of the square of the
// angle the chord turns by (the ends are shifted across the curve, nearly
// across the chord). When the budget falls between them, or the inner
// points project outside the segment, the difference cubic is subdivided
// (cubic_within()). `bulge`, when not null, receives the largest signed
// distance of S from the line AB on the side of its inner control points:
// how far the sub-curve bulges past the chord, which steers the search.
// Squared quantities are kept multiplied by |AB|^2 to spare divisions.
// `inner`, when not null, receives the largest magnitude of the cross part
// at its interior extremes (0 when it has none), whatever the sides: for
// chords across an inflection, which have no bulge, it steers the search.
// Whether a planar curve has a convex side where its derivatives are
// M' = (d1x, d1y) and M'' = (d2x, d2y), given cr = M' x M'' and
// s2 = |M'|^2: its curvature is above 1e-12 of the turning M'' could give
// (not a straight stretch, an inflection or a stationary point).
constexpr double kSideFloor = 1e-24;  // (1e-12 squared)
inline bool planar_side(double cr, double s2, double d2x, double d2y) {
  return cr * cr > kSideFloor * (d2x * d2x + d2y * d2y) * s2 && std::isfinite(cr * cr * s2);
}

// A point of the plane, for the band's search on planar cubics (which
// needs no z); as_vec3() gives either kind of point as a Vec3.
struct XY {
  double x, y;
};
inline Vec3 as_vec3(const Vec3& p) { return p; }
inline Vec3 as_vec3(const XY& p) { return {p.x, p.y}; }

template <class Pt>
inline __attribute__((always_inline)) double band_cubic_planar(const Pt* S, const Pt& A, const Pt& B, double budget,
                                                               double* bulge, double* inner = nullptr) {
  const double abx = B.x - A.x, aby = B.y - A.y;
  const double l2 = abx * abx + aby * aby;
  auto cross_ab = [&](double x, double y) { return abx * y - aby * x; };
  auto dot_ab = [&](double x, double y) { return abx * x + aby * y; };
  const double w1x = S[1].x - A.x, w1y = S[1].y - A.y, w2x = S[2].x - A.x, w2y = S[2].y - A.y;
  const double d0x = S[0].x - A.x, d0y = S[0].y - A.y, d3x = S[3].x - B.x, d3y = S[3].y - B.y;
  const double c0 = cross_ab(d0x, d0y), c1 = cross_ab(w1x, w1y), c2 = cross_ab(w2x, w2y), c3 = cross_ab(d3x, d3y);
  const double l1 = dot_ab(w1x, w1y), l2p = dot_ab(w2x, w2y);
  // (one test of all five: these rarely hold, and branches on each cost more)
  const bool outside = !(l2 > 1e-300) | (l1 < 0) | (l1 > l2) | (l2p < 0) | (l2p > l2);
  // With inner points projecting outside the segment, the projection of S
  // on the line may still stay within it (a curve that doubles back along
  // the chord): L is then that projection unclamped, as when they project
  // inside (overshoot() reads the projection's Bernstein coefficients, all
  // multiplied by |AB|).
  const bool clamped = outside && (!(l2 > 1e-300) || overshoot(l1, l2p, l2) > 0);
  const double sg = c1 + c2 >= 0 ? 1 : -1;
  if (!clamped) {
    // A sufficient test first, without roots: the cross part split at
    // s = 1/2 (de Casteljau) lies within the hull of its 7 control values,
    // which is exact for a symmetric bump and within a few per cent of the
    // largest value for the chords the search tries. When that bound with
    // the along part's fits the budget, it is the answer (and the values
    // past the ends steer the search, a little on the safe side).
    const double a = 0.5 * (c0 + c1), b = 0.5 * (c1 + c2), c = 0.5 * (c2 + c3);
    const double ab = 0.5 * (a + b), bc = 0.5 * (b + c), m = 0.5 * (ab + bc);
    const double hin =
        std::max(std::max(std::max(std::abs(a), std::abs(ab)), std::max(std::abs(m), std::abs(bc))), std::abs(c));
    const double hb = std::max(hin, std::max(std::abs(c0), std::abs(c3)));
    const double a0 = dot_ab(d0x, d0y), a3 = dot_ab(d3x, d3y);
    const double U2 = hb * hb + std::max(a0 * a0, a3 * a3);
    if (U2 <= budget * budget * l2) {
      if (!bulge && !inner) return std::sqrt(U2 / l2);  // (one root fewer)
      const double inv = 1 / std::sqrt(l2);
      if (bulge && sg * c0 <= 0 && sg * c3 <= 0) {
        // The peak of the parabola through the values at 1/4, 1/2 and 3/4
        // (a near-symmetric bump's top, for steering only), at most the hull's.
        const double w1 = sg * (27 * (c0 + c1) + 9 * c2 + c3) / 64, w2 = sg * m,
                     w3 = sg * (c0 + 9 * c1 + 27 * (c2 + c3)) / 64;
        const double den = 2 * w2 - w1 - w3,
                     top = std::max(std::max(sg * a, sg * ab), std::max(std::max(w2, sg * bc), sg * c));
        *bulge = (den > 0 ? std::min(top, w2 + (w3 - w1) * (w3 - w1) / (8 * den)) : top) * inv;
      }
      if (inner) *inner = hin * inv;
      return std::sqrt(U2) * inv;
    }
  }
  // Extremes of the cross part: the ends and the roots of its derivative,
  // 3 B2(c1 - c0, c2 - c1, c3 - c2), in power form.
  const double e0 = c1 - c0, e1 = c2 - c1, e2 = c3 - c2;
  double r[2];
  const int n = quadratic_roots01(e0, 2 * (e1 - e0), e0 - 2 * e1 + e2, r);
  double lo = std::min(c0, c3), hi = std::max(c0, c3);
  // The bulge: on the side sg of the inner points, the largest interior
  // extreme, when both ends lie on the other side (a shape the search's
  // model fits; otherwise the bulge is left unknown).
  double in = -kInf, mag = 0, rv[2] = {0, 0};
  for (int i = 0; i < n; ++i) {
    const double s = r[i], u = 1 - s;
    const double v = u * u * (c0 * u + 3 * c1 * s) + s * s * (3 * c2 * u + c3 * s);
    rv[i] = v;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    in = std::max(in, sg * v);
    mag = std::max(mag, std::abs(v));
  }
  const double P2 = std::max(lo * lo, hi * hi);
  const double inv = l2 > 0 ? 1 / std::sqrt(l2) : 0;
  if (bulge && l2 > 0 && sg * c0 <= 0 && sg * c3 <= 0 && in > -kInf) *bulge = in * inv;
  if (inner) *inner = l2 > 0 ? mag * inv : -1;
  const double b2 = budget * budget * l2;
  if (!clamped) {
    const double a0 = dot_ab(d0x, d0y), a3 = dot_ab(d3x, d3y);
    const double U2 = P2 + std::max(a0 * a0, a3 * a3);
    if (U2 <= b2) return std::sqrt(U2) * inv;
    // Finer, before subdividing: |D|^2 l2 is cross^2 + along^2, with
    // along(s) = a0 (1 - s)^3 + a3 s^3 large only near the ends, where the
    // cross part is small. On each quarter of [0, 1] the cross part's
    // largest magnitude is at an end of it or at an extreme found above,
    // and |along|'s at an end (it is convex or monotone): their squares'
    // sum bounds |D|^2 l2 there.
    if (P2 <= b2) {
      double U2f = 0, cp = c0 * c0, ap = a0 * a0;
      for (int k = 1; k <= 4; ++k) {
        const double s = 0.25 * k, u = 1 - s;
        const double cv = u * u * (c0 * u + 3 * c1 * s) + s * s * (3 * c2 * u + c3 * s);
        const double av = a0 * u * u * u + a3 * s * s * s;
        double cm = std::max(cp, cv * cv);
        for (int i = 0; i < n; ++i)
          if (r[i] >= s - 0.25 && r[i] <= s) cm = std::max(cm, rv[i] * rv[i]);
        U2f = std::max(U2f, cm + std::max(ap, av * av));
        cp = cv * cv, ap = av * av;
      }
      if (U2f <= b2) return std::sqrt(U2f) * inv;
    }
  }
  // The cross part alone exceeds the budget somewhere: so does |D|.
  if (P2 > b2 && l2 > 0) return std::sqrt(P2) * inv;
  const Vec3 Av = as_vec3(A), Bv = as_vec3(B);
  std::array<Vec3, 4> d;
  d[0] = as_vec3(S[0]) - Av;
  d[3] = as_vec3(S[3]) - Bv;
  const Vec3 ab = Bv - Av;
  // (L's inner points clamped to the segment only where its projection
  // leaves it: otherwise L is the projection itself, as above)
  for (int k = 1; k < 3; ++k) {
    const Vec3 Sk = as_vec3(S[k]);
    const double f = l2 > 0 ? dot(Sk - Av, ab) / l2 : 0.0;
    d[k] = Sk - (Av + ab * (clamped ? std::clamp(f, 0.0, 1.0) : f));
  }
  const double sub = cubic_within(d, budget, 40);
  if (sub <= budget || !clamped || !(l2 > 1e-300)) return sub;
  // The projection of S on the line leaves the segment (the curve passes
  // an end of the chord, as over a tip), and L with its inner points
  // clamped does not prove the chord: L(s) = A + u clamp(p(s)) also runs
  // from A to B on the segment, and is often nearer (pointwise_within()).
  const double U2 = pointwise_within({c0, c1, c2, c3}, dot_ab(d0x, d0y), dot_ab(d3x, d3y), l1, l2p, l2, b2);
  return U2 <= b2 ? std::sqrt(U2) * inv : sub;
}

// band_deviation() on a sub-curve already cut out: L has the sub-curve's
// degree and weights, its ends A and B, its inner points the projections
// of the sub-curve's on the line AB clamped to the segment. L lies on the
// segment (convex hull) and runs from A to B, so it covers the segment:
// sup |sub - L| bounds both directions of the Hausdorff distance.
double band_bound(const Bezier& sub, const Vec3& A, const Vec3& B, double budget) {
  Bezier L = sub;
  const Vec3 ab = B - A;
  const double l2 = dot(ab, ab);
  for (auto& p : L.points) p = A + ab * (l2 > 0 ? std::clamp(dot(p - A, ab) / l2, 0.0, 1.0) : 0.0);
  L.points.front() = A;
  L.points.back() = B;
  return parametric_distance(sub, L, budget);
}

// The largest square of a second difference of the control points (Wang's
// formula's m, squared).
double second_difference_sq(const Bezier& b) {
  const auto& P = b.points;
  double m2 = 0;
  for (size_t i = 0; i + 2 < P.size(); ++i) {
    const Vec3 d = P[i] - P[i + 1] * 2 + P[i + 2];
    m2 = std::max(m2, dot(d, d));
  }
  return m2;
}

// Uniform step that Wang's formula proves safe for a polynomial piece.
double wang_step(const Bezier& b, double tol) {
  const int n = b.degree();
  if (n < 2) return 1;
  const double m = std::sqrt(second_difference_sq(b));  // (the largest square, one root: the same value)
  const double k = std::sqrt(n * (n - 1) * m / (8 * tol));
  return k <= 1 ? 1.0 : 1.0 / std::ceil(k);
}

// One piece, prepared for fast repeated chord tests: a polynomial of
// degree <= 3 by its power form (c0..c3, zero for other pieces).
struct Prepared : CubicPowerForm {
  const Bezier* b = nullptr;
  bool cubic = false;   // polynomial of degree <= 3 (elevated to 3)
  bool planar = false;  // 2D

  explicit Prepared(const Bezier& piece) : b(&piece) {
    if (piece.rational() || piece.degree() > 3) return;
    cubic = true;
    planar = piece.dim == 2;
    static_cast<CubicPowerForm&>(*this) = CubicPowerForm::of(piece);
  }
  Vec3 point(double t) const {
    if (t <= 0) return b->front();
    if (t >= 1) return b->back();
    if (cubic) return ((c3 * t + c2) * t + c1) * t + c0;
    return evaluate(*b, t);
  }
  Vec3 tangent(double t) const { return (c3 * (3 * t) + c2 * 2) * t + c1; }
  // |M''| across the tangent: a chord of parameter length dt deviates by
  // about dt^2 / 8 times this (the local parabola). Used to predict steps.
  double bend(double t) const {
    if (!cubic) return 0;
    const Vec3 d1 = tangent(t), d2 = c3 * (6 * t) + c2 * 2;
    if (planar) {
      const double s2 = d1.x * d1.x + d1.y * d1.y;
      return s2 > 0 ? std::abs(d1.x * d2.y - d1.y * d2.x) / std::sqrt(s2) : std::sqrt(d2.x * d2.x + d2.y * d2.y);
    }
    const double n = norm(d1);
    return n > 0 ? norm(cross(d1, d2)) / n : norm(d2);
  }

  double deviation(double t0, double t1, const Vec3& A, const Vec3& B, double budget) const {
    if (cubic) {
      const double h = (t1 - t0) / 3;
      const Vec3 Q1 = A + tangent(t0) * h, Q2 = B - tangent(t1) * h;
      const double d = planar ? cubic_chord_deviation_2d(A, Q1, Q2, B) : cubic_chord_deviation(A, Q1, Q2, B);
      if (d != kOvershoot) return d;
      Bezier sub;
      sub.dim = b->dim;
      sub.points = {A, Q1, Q2, B};
      return hull_chord_deviation(sub, A, B, budget);
    }
    return hull_chord_deviation(subcurve(*b, t0, t1), A, B, budget);
  }

  // The piece on [t0, t1] as a Bézier curve of its own (the cubic from its
  // power form: end points and end tangents).
  Bezier sub(double t0, double t1) const {
    if (!cubic) return subcurve(*b, t0, t1);
    const double h = (t1 - t0) / 3;
    const Vec3 A = point(t0), B = point(t1);
    Bezier s;
    s.dim = b->dim;
    s.points = {A, A + tangent(t0) * h, B - tangent(t1) * h, B};
    return s;
  }

  // Unit vector at t across the curve towards its convex side (away from
  // the centre of curvature); zero where there is none (a straight stretch,
  // an inflection, a stationary point). For the general search (pieces in
  // space, rational or of degree over 3); band_planar_piece() finds it for
  // planar cubics on its own, without a second square root.
  Vec3 convex_side(double t) const {
    Vec3 d1, d2;
    if (cubic) {
      d1 = tangent(t);
      d2 = c3 * (6 * t) + c2 * 2;
    } else {
      d1 = derivative(*b, t);
      d2 = second_derivative(*b, t);
    }
    const double s2 = dot(d1, d1);
    if (!(s2 > 0)) return {};
    const Vec3 n = d2 - d1 * (dot(d1, d2) / s2);
    const double ln = norm(n);
    // Curvature |n| / |M'|^2 below 1e-12 of the turning the piece can
    // make: no side to speak of.
    if (!(ln > 1e-12 * norm(d2)) || !std::isfinite(ln)) return {};
    return n / -ln;
  }

  // The cubic sub-curve on [t0, t1] from the power form (end points and
  // end tangents), without building a Bézier.
  void sub_points(double t0, double t1, Vec3* S) const {
    const double h = (t1 - t0) / 3;
    S[0] = point(t0);
    S[3] = point(t1);
    S[1] = S[0] + tangent(t0) * h;
    S[2] = S[3] - tangent(t1) * h;
  }

  // band_deviation() of the piece on [t0, t1]; for cubics with a budget,
  // decided on the difference cubic directly: in closed form in the plane
  // (band_cubic_planar(), which also reports the bulge), else by
  // subdivision (cubic_within()).
  double band(double t0, double t1, const Vec3& A, const Vec3& B, double budget, double* bulge = nullptr) const {
    if (!cubic || budget < 0) return band_bound(sub(t0, t1), A, B, budget);
    Vec3 S[4];
    sub_points(t0, t1, S);
    if (planar) return band_cubic_planar(S, A, B, budget, bulge);
    const Vec3 ab = B - A;
    const double l2 = dot(ab, ab);
    std::array<Vec3, 4> d;
    for (int k = 0; k < 4; ++k) {
      const Vec3 L = k == 0 ? A : k == 3 ? B : A + ab * (l2 > 0 ? std::clamp(dot(S[k] - A, ab) / l2, 0.0, 1.0) : 0.0);
      d[k] = S[k] - L;
    }
    return cubic_within(d, budget, 40);
  }

  // First guess for a piece: from the local parabola at the start, refined
  // once at the middle of the guessed chord; Wang's uniform step otherwise.
  double first_step(double budget) const {
    if (cubic) {
      double k = bend(0);
      if (!(k > 0)) return 1;
      double dt = std::sqrt(8 * kAimShare * budget / k);
      k = bend(std::min(1.0, dt / 2));
      if (k > 0) dt = std::sqrt(8 * kAimShare * budget / k);
      return std::min(1.0, dt);
    }
    return std::min(1.0, 1.5 * wang_step(*b, budget));
  }
};

}  // namespace

}  // namespace bezcam
