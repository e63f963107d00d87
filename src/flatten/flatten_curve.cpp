#include "bezcam/flatten/flatten_curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <tuple>
#include <type_traits>
#include <stdexcept>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/flatten/degree_reduce.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/roots.hpp"
#include "flatten/search.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
__attribute__((noinline, cold)) double pointwise_within(const std::array<double, 4>& c, double a0, double a3, double l1, double l2p, double l2,
                        double b2) {
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
    const double hin = std::max(std::max(std::max(std::abs(a), std::abs(ab)), std::max(std::abs(m), std::abs(bc))), std::abs(c));
    const double hb = std::max(hin, std::max(std::abs(c0), std::abs(c3)));
    const double a0 = dot_ab(d0x, d0y), a3 = dot_ab(d3x, d3y);
    const double U2 = hb * hb + std::max(a0 * a0, a3 * a3);
    if (U2 <= budget * budget * l2) {
      if (!bulge && !inner) return std::sqrt(U2 / l2);  // (one root fewer)
      const double inv = 1 / std::sqrt(l2);
      if (bulge && sg * c0 <= 0 && sg * c3 <= 0) {
        // The peak of the parabola through the values at 1/4, 1/2 and 3/4
        // (a near-symmetric bump's top, for steering only), at most the hull's.
        const double w1 = sg * (27 * (c0 + c1) + 9 * c2 + c3) / 64, w2 = sg * m, w3 = sg * (c0 + 9 * c1 + 27 * (c2 + c3)) / 64;
        const double den = 2 * w2 - w1 - w3, top = std::max(std::max(sg * a, sg * ab), std::max(std::max(w2, sg * bc), sg * c));
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
  bool cubic = false;         // polynomial of degree <= 3 (elevated to 3)
  bool planar = false;        // 2D

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

double chord_deviation(const Bezier& piece, double t0, double t1, double budget) {
  const Prepared p(piece);
  return p.deviation(t0, t1, p.point(t0), p.point(t1), budget);
}

double band_deviation(const Bezier& piece, double t0, double t1, const Vec3& A, const Vec3& B, double budget) {
  return Prepared(piece).band(t0, t1, A, B, budget);
}

double estimate_segments(std::span<const Bezier> pieces, double tolerance) {
  // Gauss-Legendre nodes would do no better on the kinks of a wild piece;
  // midpoints avoid the ends, where a cusp makes the integrand singular.
  constexpr int kSamples = 16;
  double total = 0;
  for (const auto& b : pieces) {
    double n = 0;
    if (b.degree() >= 2) {
      for (int i = 0; i < kSamples; ++i) {
        const double t = (i + 0.5) / kSamples;
        const Vec3 d1 = derivative(b, t), d2 = second_derivative(b, t);
        const double speed = norm(d1);
        // sqrt(k / (8 tol)) |M'| with k = |M' x M''| / |M'|^3.
        if (speed > 0) n += std::sqrt(norm(cross(d1, d2)) / (8 * tolerance * speed)) / kSamples;
      }
    }
    total += std::isfinite(n) ? std::max(1.0, std::ceil(n)) : kInf;
  }
  return total;
}

namespace {

// A vertex is moved off the curve by this share of what the tolerance
// leaves after the margin and the worst rounding (pieces ends stay on it).
constexpr double kBandShare = 0.96;
// A band chord is accepted once its parameter step is within this share of
// one known not to fit.
constexpr double kBandClose = 0.97;
// ... or once its sagitta is this share of the longest chord's: its step is
// then at least sqrt(0.7) = 84 % of the longest. Most chords are settled by
// their first try, aimed at kBandAim of the longest chord's sagitta; a
// lower share accepts more first tries (fewer tries per chord) for a few
// more chords.
constexpr double kBandAccept = 0.70;
constexpr double kBandAim = 0.97;
// Without a bulge to steer by (rational or higher-degree pieces, 3D
// cubics): first step of the search from the predicted chord; 1 / 1.03 >
// 0.97, so a good prediction is settled by two tries.
constexpr double kBandStep = 0.03;

// The band (docs/flattening.md): from vertex A (at parameter t0 of the
// piece, maybe off the curve), the vertex B across from the largest t1 whose
// chord band_deviation() proves within the budget; B = M(t1) + delta n(t1),
// n towards the convex side, delta = kBandShare of tol - margin - rounding,
// or delta = 0 when that chord fails (inflections) and at the piece's end.
// `Ar` is the rounded first vertex, already emitted.
//
// The search is steered by the bulge (planar cubics): with the ends shifted
// by dA and dB across the curve, a chord's bulge past the segment is about
// H - (dA + dB) / 2, H the sub-curve's bulge past its own chord, which grows
// like the square of the step. So fill = (bulge + (dA + dB) / 2) / (budget +
// (dA + dB) / 2) is the share of the longest chord's H that this one uses,
// and a chord is settled once its fill reaches kAcceptShare (its step is
// within 3 % of the longest) or its step is within kBandClose of one that
// failed. The next chord's first step is the last one's, scaled by the fill
// and by the change of bending, so most chords are settled by their first try.
// The search's model of a chord whose ends lie dA and dB off the curve on
// its convex side, for a sub-curve of sagitta H (its bulge past its own
// chord, growing like the square of the step): near the top the sub-curve
// is a parabola, and its bulge past the chord is H - (dA + dB) / 2 +
// (dB - dA)^2 / (16 H). sagitta() inverts that for a measured bulge,
// longest_sagitta() gives the H whose bulge is the budget.
double sagitta(double bulge, double dA, double dB) {
  const double m = bulge + 0.5 * (dA + dB), q = 0.25 * (dB - dA) * (dB - dA);
  if (q == 0) return m;
  return m * m > q ? 0.5 * (m + std::sqrt(m * m - q)) : 0.5 * m;
}
double longest_sagitta(double budget, double dA, double dB) { return sagitta(budget, dA, dB); }

// A chord across an inflection has no bulge: its ends lie on opposite
// sides, and what limits it is the cross part's interior extreme, which
// grows about like the cube of the step (the gap of a chord across an
// inflection is |M^(3)| l^3 / (72 sqrt 3)). Such a chord is settled once that
// extreme reaches kCrossAccept of the budget (its step is then within
// cbrt(0.85) = 95 % of the longest under that model) or its step is within
// kCrossClose of one that failed.
constexpr double kCrossAccept = 0.85;
constexpr double kCrossClose = 0.93;
// The search for such a chord: a root of f(dt) = cbrt(extreme) -
// cbrt(kBandAim budget) (the cube law makes it about linear), by regula
// falsi with the Illinois modification (an end kept twice in a row has its
// value halved, so that both ends move). With one end known, by a power law
// from it: the cube, or the exponent the last two tries on that side show
// (the extreme near an end shifted off the curve hardly changes with the
// step, and a cube law would then creep).
struct CrossSearch {
  double f_lo = kInf, f_hi = kInf;  // f at lo and hi; infinity: not known
  int last = 0;                     // which end moved last: -1 lo, +1 hi
  double dt_last = 0, in_last = -1, dt_prev = 0, in_prev = -1;  // the last two tries on the side `last`
  double aim_budget = -1, aim_cbrt = 0;  // cbrt(kBandAim budget) for the last budget seen (the same for every try without rounding)
  // Records a try of step dt whose extreme is `inner` (fitting or not).
  void record(bool ok, double dt, double inner, double budget) {
    if (budget != aim_budget) aim_budget = budget, aim_cbrt = std::cbrt(kBandAim * budget);
    const double f = std::cbrt(inner) - aim_cbrt;
    const int side = ok ? -1 : 1;
    if (side == last) {
      (ok ? f_hi : f_lo) *= 0.5;  // infinity stays infinity
      dt_prev = dt_last, in_prev = in_last;
    } else {
      in_prev = -1;
    }
    (ok ? f_lo : f_hi) = f;
    last = side, dt_last = dt, in_last = inner;
  }
  // The next step in the bracket [lo, hi] (hi infinite: none yet).
  double next(double lo, double hi, double budget) const {
    if (std::isfinite(f_lo) && std::isfinite(f_hi) && std::isfinite(hi) && lo > 0) {
      const double nd = f_hi > f_lo ? lo + (hi - lo) * -f_lo / (f_hi - f_lo) : 0.5 * (lo + hi);
      return std::clamp(nd, lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo));
    }
    const bool grow = std::isfinite(f_lo) && !std::isfinite(hi), shrink = std::isfinite(f_hi) && lo <= 0;
    if (grow || shrink) {
      const double dt = grow ? lo : hi, in = in_last;
      double p = 3;
      if (in_prev > 0 && in > 0 && dt_prev > 0 && dt_prev != dt)
        p = std::clamp(std::log(in / in_prev) / std::log(dt / dt_prev), 0.5, 3.0);
      const double g = in > 0 ? std::pow(kBandAim * budget / in, 1 / p) : 2.0;
      return grow ? lo * std::clamp(g, 1.03, 2.0) : hi * std::clamp(g, 0.3, 0.95);
    }
    // One end known without an extreme: halve the bracket.
    return std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * lo;
  }
};

#ifdef BEZCAM_FLATTEN_COUNTERS
// For measurement only (bench/flatten_tries.sh builds the benchmark with
// it): the planned pieces (band_planar_spread()) with their tries and the
// chords shortened; the searches (band_planar_piece() and the general
// loop) and their tries, by kind (steered by the bulge; across an
// inflection, where some try had none; the piece's last chord), with how
// many searches took 1, 2, ..., 8 or more tries; printed to stderr at exit.
struct Counters {
  long searches[3] = {}, tries[3] = {}, hist[3][8] = {};
  long spread_pieces = 0, spread_tries = 0, spread_shrinks = 0;
  ~Counters() {
    std::fprintf(stderr, "planned    pieces %ld tries %ld shortened %ld\n", spread_pieces, spread_tries, spread_shrinks);
    const char* names[3] = {"steered", "inflection", "last"};
    for (int k = 0; k < 3; ++k) {
      std::fprintf(stderr, "%-10s searches %ld tries %ld (%.2f)", names[k], searches[k], tries[k], searches[k] ? double(tries[k]) / searches[k] : 0.0);
      for (int i = 0; i < 8; ++i) std::fprintf(stderr, " %ld", hist[k][i]);
      std::fprintf(stderr, "\n");
    }
  }
} g_counters;
#endif

// The next step after a chord that did not fit, when no sagitta steers the
// search: shrunk as if the deviation grew like the square of the step (by
// 1 / (1 + step) at least, half at most), or by 1 / (1 + step) without a
// deviation to go by.
inline double shrink_unsteered(double dt, double dev, double budget, double step) {
  return dev > budget && budget > 0 ? dt * std::clamp(std::sqrt(kBandAim * budget / dev), 0.5, 1 / (1 + step))
                                    : dt / (1 + step);
}

#ifdef BEZCAM_FLATTEN_COUNTERS
inline void count_search(int kind, int n_tries) {
  ++g_counters.searches[kind];
  g_counters.tries[kind] += n_tries;
  ++g_counters.hist[kind][std::min(n_tries, 8) - 1];
}
#endif

// The band's search on one planar polynomial cubic piece (the common case),
// steered by the bulge as described above. It works on plain x and y values
// held in locals (no z; the curve's point and tangent at t0 carried from the
// chord that ended there; the largest sagittas computed once per search when
// there is no rounding), for speed: it gives the same vertices as the
// general search (flatten_bench --only hash-all). bound_band() calls it for
// such pieces and searches every other one itself. `A`, `Ar` (the last
// vertex, exact and rounded) and `dispA` come in for the piece's start;
// `Ar` leaves as the piece's last vertex; `bound` and `emitted` accumulate.
template <class Emit>
void band_planar_piece(const Bezier& piece, const Prepared& P, bool final_piece, const FlattenOptions& opt,
                       double tol, double margin, double shift, size_t pi, const Vec3& A, Vec3& Ar, double dispA,
                       double& bound, size_t& emitted, Emit& emit, double t_start = 0, double offA_start = 0,
                       double dt_start = 0) {
  const double c0x = P.c0.x, c0y = P.c0.y, c1x = P.c1.x, c1y = P.c1.y;
  const double c2x = P.c2.x, c2y = P.c2.y, c3x = P.c3.x, c3y = P.c3.y;
  const double endx = piece.back().x, endy = piece.back().y;
  const int decimals = opt.decimals;
  // One try's chord: its end B (exact, rounded), its bound and budget, the
  // sub-curve's sagitta H (sagitta(); -infinity: not known), bend() at t1,
  // the cross part's largest interior extreme (-1: not known), the curve's
  // point M and tangent dM at t1, and whether B is on the curve.
  struct Chord2 {
    double t1 = 0, dev = 0, disp = 0, H = -kInf, budget = 0;
    double Bx = 0, By = 0, Brx = 0, Bry = 0, bend = 0, inner = -1;
    double Mx = 0, My = 0, dMx = 0, dMy = 0;
    bool on = false;
  };
  double offA = offA_start;
  double bend0 = P.bend(t_start);
  double t0 = t_start;
  double dt = dt_start > 0 ? dt_start : P.first_step(longest_sagitta(tol - margin - dispA, 0, shift));
  double ax = A.x, ay = A.y;
  const Vec3 T0v = P.tangent(t_start), S0v = P.point(t_start);
  double S0x = S0v.x, S0y = S0v.y, T0x = T0v.x, T0y = T0v.y;  // M(t0), M'(t0)
  // Two slots, the best chord so far and the one being tried, swapped by
  // index rather than copied, kept across the piece's searches.
  Chord2 slot[2];
  while (t0 < 1) {
    double lo = 0, hi = kInf;  // largest dt known to fit, smallest known not to
    // Without a bulge (chords across an inflection), the cross part's
    // interior extreme at lo and hi steers the search.
    CrossSearch cross;
    bool found = false;
    for (Chord2& c : slot) c.dev = 0, c.budget = 0, c.H = -kInf, c.on = false;
    int cur = 0;
    double step = kBandStep;
    // Without rounding every try of this search has the same budget, and
    // so the same largest sagittas.
    const double budget0 = tol - margin - dispA;
    // (the one for B on the curve only when asked: it takes a square root).
    const double ls_shift = longest_sagitta(budget0, offA, shift);
    double ls_on_ = -1;
    auto ls_on = [&] { return ls_on_ >= 0 ? ls_on_ : (ls_on_ = longest_sagitta(budget0, offA, 0)); };
#ifdef BEZCAM_FLATTEN_COUNTERS
    int n_tries = 0;
    bool unsteered = false;
#endif
    for (int iter = 0; iter < 200; ++iter) {
      const bool last = dt >= 1 - t0;
      if (last) dt = 1 - t0;
      Chord2& c = slot[cur];
      const double t1 = last ? 1.0 : t0 + dt;
      const bool zero = !found || slot[cur ^ 1].on;
      // One try: B shifted across the curve, then (when allowed and of
      // use) B on the curve.
      bool ok = false;
      {
        double onx, ony, d1x, d1y, sx = 0, sy = 0, bend1 = 0;
        if (t1 < 1) {
          const double t = t1, t3 = 3 * t, t6 = 6 * t;
          onx = ((c3x * t + c2x) * t + c1x) * t + c0x;
          ony = ((c3y * t + c2y) * t + c1y) * t + c0y;
          d1x = (c3x * t3 + c2x * 2) * t + c1x;
          d1y = (c3y * t3 + c2y * 2) * t + c1y;
          const double d2x = c3x * t6 + c2x * 2, d2y = c3y * t6 + c2y * 2;
          const double s2 = d1x * d1x + d1y * d1y, cr = d1x * d2y - d1y * d2x;
          if (planar_side(cr, s2, d2x, d2y)) {
            const double k = std::copysign(1.0, -cr) / std::sqrt(s2);  // (-1 where cr > 0, without a branch)
            bend1 = std::abs(cr * k);
            sx = -d1y * k, sy = d1x * k;
          }
        } else {
          onx = endx, ony = endy;
          d1x = (c3x * (3 * t1) + c2x * 2) * t1 + c1x;
          d1y = (c3y * (3 * t1) + c2y * 2) * t1 + c1y;
        }
        const double h = (t1 - t0) / 3;
        const XY S[4] = {{S0x, S0y}, {S0x + T0x * h, S0y + T0y * h}, {onx - d1x * h, ony - d1y * h}, {onx, ony}};
        const bool has_side = sx != 0 || sy != 0;
        double H = -kInf;
        for (int pass = 0; pass < 2; ++pass) {
          const double delta = pass == 0 ? shift : 0.0;
          if (pass == 0 ? !has_side : !zero) continue;
          const double Bx = pass == 0 ? onx + sx * delta : onx, By = pass == 0 ? ony + sy * delta : ony;
          double Brx = Bx, Bry = By, disp = dispA, budget = budget0;
          if (decimals >= 0) {
            const Vec3 Br = quantize(Vec3{Bx, By}, decimals);
            Brx = Br.x, Bry = Br.y;
            disp = std::max(dispA, dist(Br, Vec3{Bx, By}));
            budget = tol - margin - disp;
          }
          if (!(budget > 0)) continue;
          if (pass == 1 && H > (decimals >= 0 ? longest_sagitta(budget, offA, 0) : ls_on())) break;
          double bulge = -kInf, inner = -1;
          const double dev = band_cubic_planar(S, XY{ax, ay}, XY{Bx, By}, budget, &bulge, &inner);
          H = bulge > -kInf ? sagitta(bulge, offA, delta) : -kInf;
          c.t1 = t1, c.dev = dev, c.disp = disp, c.H = H, c.budget = budget;
          c.Bx = Bx, c.By = By, c.Brx = Brx, c.Bry = Bry, c.on = pass == 1, c.bend = bend1, c.inner = inner;
          c.Mx = onx, c.My = ony, c.dMx = d1x, c.dMy = d1y;
          if (dev <= budget) {
            ok = true;
            break;
          }
        }
        if (!ok) c.H = H;
      }
      const bool shifted = !(ok && c.on);
      const double ls = decimals >= 0 || c.budget != budget0 ? longest_sagitta(c.budget, offA, shifted ? shift : 0)
                        : shifted                           ? ls_shift
                                                            : ls_on();
      const double fill = c.H / ls;
#ifdef BEZCAM_FLATTEN_COUNTERS
      ++n_tries;
      if (!std::isfinite(fill)) unsteered = true;
#endif
      if (ok) {
        found = true;
        lo = dt;
        cur ^= 1;
        if (last || lo >= kBandClose * hi || fill >= kBandAccept) break;
        if (!std::isfinite(fill) && c.inner >= 0) {
          cross.record(true, dt, c.inner, c.budget);
          if (lo >= kCrossClose * hi || c.inner >= kCrossAccept * c.budget) break;
          dt = cross.next(lo, hi, c.budget);
          step = std::min(2 * step, 1.0);
          continue;
        }
        double nd = !std::isfinite(fill) ? dt * (1 + step) : fill > 0 ? dt * std::min(4.0, std::sqrt(kBandAim / fill)) : 2 * dt;
        if (nd >= hi) nd = 0.5 * (lo + hi);
        dt = nd;
      } else {
        hi = dt;
        if (found && lo >= kBandClose * hi) break;
        if (!std::isfinite(fill) && c.inner >= 0) {
          cross.record(false, dt, c.inner, c.budget);
          if (found && lo >= kCrossClose * hi) break;
          dt = cross.next(lo, hi, c.budget);
          step = std::min(2 * step, 1.0);
          continue;
        }
        double nd = std::isfinite(fill) && fill > 1 ? dt * std::clamp(std::sqrt(kBandAim / fill), 0.05, 0.99)
                    : std::isfinite(fill)           ? 0.7 * dt
                                                    : shrink_unsteered(dt, c.dev, c.budget, step);
        if (found && nd <= lo) nd = 0.5 * (lo + hi);
        dt = nd;
      }
      step = std::min(2 * step, 1.0);
    }
    if (!found) throw std::logic_error("flatten: no band chord fits (internal error)");
    const Chord2& best = slot[cur ^ 1];
#ifdef BEZCAM_FLATTEN_COUNTERS
    count_search(best.t1 >= 1 ? 2 : unsteered ? 1 : 0, n_tries);
#endif
    bound = std::max(bound, best.dev + best.disp);
    const Vec3 Br{best.Brx, best.Bry};
    const bool final_vertex = final_piece && best.t1 >= 1;
    if (!(Br == Ar) || (final_vertex && emitted == 0)) {
      emit({Br, pi, best.t1});
      ++emitted;
    }
    if (best.t1 < 1) {
      double g2 = 1;
      const double b0 = 0.5 * (bend0 + best.bend);
      const double b1 = std::max(best.bend + 0.5 * (best.bend - bend0), 0.25 * best.bend);
      bend0 = best.bend;
      if (b0 > 0 && b1 > 0) g2 = b0 / b1;
      if (best.H > 0) g2 *= kBandAim * longest_sagitta(best.budget, best.on ? 0 : shift, shift) / best.H;
      dt = lo * std::sqrt(std::clamp(g2, 1.0 / 16, 16.0));
    }
    t0 = best.t1;
    ax = best.Bx, ay = best.By;
    Ar = Br;
    dispA = best.Brx == best.Bx && best.Bry == best.By ? 0.0 : std::sqrt((best.Brx - best.Bx) * (best.Brx - best.Bx) + (best.Bry - best.By) * (best.Bry - best.By));
    S0x = best.Mx, S0y = best.My, T0x = best.dMx, T0y = best.dMy;
    offA = best.on ? 0.0 : shift;
  }
}

// The band's fast path on one planar polynomial cubic piece: the chords
// planned all at once, then each one proven. Band chords that all use the
// same share of their room are close to the fewest (the error spread
// evenly is the asymptotic optimum), and planning them needs no search: a
// chord of parameter step h where the density
//   f(t) = sqrt(|M'(t) x M''(t)| / |M'(t)|)
// holds has a sagitta of about f^2 h^2 / 8, so the piece needs about
//   integral of f / sqrt(8 H) dt
// chords of sagitta H, and they end where the running integral reaches
// equal shares of the whole. H is kSpreadAim of the longest sagitta the
// band allows with both ends shifted (longest_sagitta()) under the worst
// rounding; a chord with an end on the curve (the piece's first and last)
// has less room and is planned shorter. Near an inflection, where f
// vanishes and a chord's gap grows like the cube of its step, the cubic
// term's density takes over. The integral is taken by the trapezoid rule,
// on 16 or kSpreadSamples intervals (more for pieces that need more chords).
// Every chord is then proven like any other (band_cubic_planar(), with its
// ends' real rounding), two at a time where the plan gives two inner
// vertices ahead. One that does not fit is shortened, as if its sagitta
// grew like the square of its step, and the rest of the piece is planned
// again from its end. A piece the plan cannot serve (a density undefined
// even beside its sample, as on a piece of one point, or more than
// kSpreadMax chords) goes to band_planar_piece(), and so does the rest of
// one whose chord will not fit after kSpreadShrinks tries.
constexpr int kSpreadSamples = 32;
constexpr double kSpreadRefine = 1.0;
constexpr double kSpreadAim = 0.95;
constexpr double kSpreadMax = 1 << 16;
constexpr int kSpreadShrinks = 32;
// Cube root for planning only (a guess refined by two Newton steps: about
// 1e-5 relative), for x > 0: far cheaper than std::cbrt.
inline double cbrt_estimate(double x) {
  std::uint64_t i;
  std::memcpy(&i, &x, sizeof i);
  i = i / 3 + 0x2A9F7893782DA1CEull;
  double y;
  std::memcpy(&y, &i, sizeof y);
  y = (2 * y + x / (y * y)) * (1.0 / 3);
  return (2 * y + x / (y * y)) * (1.0 / 3);
}

#if defined(__SSE2__)
using v2d = double __attribute__((vector_size(16)));
inline v2d vabs(v2d x) { return v2d(_mm_andnot_pd(_mm_set1_pd(-0.0), __m128d(x))); }
inline v2d vmax(v2d a, v2d b) { return v2d(_mm_max_pd(__m128d(a), __m128d(b))); }
inline v2d vsqrt(v2d x) { return v2d(_mm_sqrt_pd(__m128d(x))); }
// band_cubic_planar()'s sufficient test (the one without roots) on two
// chords at once, lane by lane the same arithmetic: ok[i] when it settles
// chord i (it fits, of bound dev[i]); otherwise band_cubic_planar() decides.
inline __attribute__((always_inline)) void band_sufficient2(const v2d* Sx, const v2d* Sy, v2d Ax, v2d Ay, v2d Bx, v2d By, v2d budget, bool ok[2],
                             double dev[2]) {
  const v2d abx = Bx - Ax, aby = By - Ay;
  const v2d l2 = abx * abx + aby * aby;
  auto cross_ab = [&](v2d x, v2d y) { return abx * y - aby * x; };
  auto dot_ab = [&](v2d x, v2d y) { return abx * x + aby * y; };
  const v2d w1x = Sx[1] - Ax, w1y = Sy[1] - Ay, w2x = Sx[2] - Ax, w2y = Sy[2] - Ay;
  const v2d d0x = Sx[0] - Ax, d0y = Sy[0] - Ay, d3x = Sx[3] - Bx, d3y = Sy[3] - By;
  const v2d c0 = cross_ab(d0x, d0y), c1 = cross_ab(w1x, w1y), c2 = cross_ab(w2x, w2y), c3 = cross_ab(d3x, d3y);
  const v2d l1 = dot_ab(w1x, w1y), l2p = dot_ab(w2x, w2y);
  const v2d a = 0.5 * (c0 + c1), b = 0.5 * (c1 + c2), c = 0.5 * (c2 + c3);
  const v2d ab = 0.5 * (a + b), bc = 0.5 * (b + c), m = 0.5 * (ab + bc);
  const v2d hin = vmax(vmax(vmax(vabs(a), vabs(ab)), vmax(vabs(m), vabs(bc))), vabs(c));
  const v2d hb = vmax(hin, vmax(vabs(c0), vabs(c3)));
  const v2d a0 = dot_ab(d0x, d0y), a3 = dot_ab(d3x, d3y);
  const v2d U2 = hb * hb + vmax(a0 * a0, a3 * a3);
  const auto fit = (l2 > 1e-300) & (l1 >= 0) & (l1 <= l2) & (l2p >= 0) & (l2p <= l2) & (U2 <= budget * budget * l2);
  const v2d dv = vsqrt(U2 / l2);
  ok[0] = fit[0] != 0, ok[1] = fit[1] != 0;
  dev[0] = dv[0], dev[1] = dv[1];
}
#endif

// Where a planar polynomial cubic turns back on itself: the parameters in
// (0, 1) where its speed |M'| has a local minimum (a root of M' . M'', a
// cubic in t, where it changes from negative to positive) and its radius of
// curvature there, |M'|^2 / |M''| (M'' is across M' there), is at most
// `radius`. That includes a cusp (M' = 0) and where a collinear cubic
// reverses along its line (its extreme points, vertices of the shortest
// polyline). Returns how many (at most 2, ascending).
int planar_tips(const Prepared& P, double radius, double out[2]) {
  auto d2 = [](const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y; };
  const Vec3 &c1 = P.c1, &c2 = P.c2, &c3 = P.c3;
  const double g0 = 2 * d2(c1, c2), g1 = 6 * d2(c1, c3) + 4 * d2(c2, c2), g2 = 18 * d2(c2, c3), g3 = 18 * d2(c3, c3);
  auto g = [&](double t) { return ((g3 * t + g2) * t + g1) * t + g0; };
  auto dg = [&](double t) { return (3 * g3 * t + 2 * g2) * t + g1; };
  const double noise = 1e-12 * (std::abs(g0) + std::abs(g1) + std::abs(g2) + std::abs(g3));
  // g is monotone between the roots of g'.
  double b[4] = {0, 0, 0, 1};
  int nb = 1 + quadratic_roots01(g1, 2 * g2, 3 * g3, b + 1);
  if (nb == 3 && b[1] > b[2]) std::swap(b[1], b[2]);
  b[nb] = 1;
  int n = 0;
  // Speed squared, and |M''| squared, at t.
  auto speed2 = [&](double t, double& a2) {
    const Vec3 d1 = P.tangent(t), dd = c3 * (6 * t) + c2 * 2;
    a2 = dd.x * dd.x + dd.y * dd.y;
    return d1.x * d1.x + d1.y * d1.y;
  };
  for (int i = 0; i < nb; ++i) {
    double lo = b[i], hi = b[i + 1];
    double glo = g(lo), ghi = g(hi);
    // (a change of sign within rounding noise is none: the speed vanishing
    // at an end, where the last control points coincide, is not a tip)
    if (!(glo < -noise && ghi > noise)) continue;
    // g rises through the bracket [lo, hi], so the speed squared, whose
    // derivative is 2 g, is at least s2(lo) + 2 g(lo) (hi - lo) and
    // s2(hi) - 2 g(hi) (hi - lo) there; |M''| is largest at an end. When
    // that rules a tip out the search stops; otherwise Newton's method,
    // kept within the bracket (bisection where it leaves it), from the
    // secant's root, narrows it.
    double alo, ahi;
    double slo = speed2(lo, alo), shi = speed2(hi, ahi);
    double t = lo - glo * (hi - lo) / (ghi - glo);
    bool tip = true;
    for (int it = 0; it < 60; ++it) {
      const double w = hi - lo, least = std::max(slo + 2 * glo * w, shi - 2 * ghi * w);
      if (least > 0 && least * least > radius * radius * std::max(alo, ahi)) {
        tip = false;
        break;
      }
      double a2;
      const double v = g(t), d = dg(t), s2 = speed2(t, a2);
      if (v == 0) break;
      if (v < 0) lo = t, glo = v, slo = s2, alo = a2;
      else hi = t, ghi = v, shi = s2, ahi = a2;
      double nt = d > 0 ? t - v / d : 0.5 * (lo + hi);
      if (!(nt > lo && nt < hi)) nt = 0.5 * (lo + hi);
      const bool last = std::abs(nt - t) < 1e-14;
      t = nt;
      if (last) break;
    }
    if (!tip || !(t > 0 && t < 1)) continue;
    // (where M' . M'' = 0, |M' x M''| = |M'| |M''|: the radius is |M'|^2 / |M''|)
    double a2;
    const double s2 = speed2(t, a2);
    if (s2 * s2 <= radius * radius * a2) out[n++] = t;
  }
  return n;
}
// A tip is one where the radius of curvature is at most this share of the
// plan's budget; an inflection within kTipAbsorb chords of the plan from a
// tip is left to the tip's vertex; kTipShare, kTipPlan and kTipEager in
// band_planar_spread().
constexpr double kTipRadius = 1.0;
constexpr double kTipAbsorb = 0.5;
constexpr double kTipShare = 1.0;
constexpr double kTipPlan = 8.0;
constexpr double kTipEager = 3.0;

template <class Emit>
void band_planar_spread(const Bezier& piece, const Prepared& P, bool final_piece, const FlattenOptions& opt,
                        double tol, double margin, double rounding, double shift, size_t pi, const Vec3& A, Vec3& Ar,
                        double dispA, double& bound, size_t& emitted, Emit& emit) {
  const double c0x = P.c0.x, c0y = P.c0.y, c1x = P.c1.x, c1y = P.c1.y;
  const double c2x = P.c2.x, c2y = P.c2.y, c3x = P.c3.x, c3y = P.c3.y;
  const double plan_budget = tol - margin - std::max(rounding, dispA);
  if (!(plan_budget > 0))
    return band_planar_piece(piece, P, final_piece, opt, tol, margin, shift, pi, A, Ar, dispA, bound, emitted, emit);
  const double H2 = longest_sagitta(plan_budget, shift, shift);
  const double inv8H = 1 / std::sqrt(8 * kSpreadAim * H2);
  // The cubic term: across an inflection a chord's gap is about
  // |M' x M'''| / |M'| h^3 / (72 sqrt 3), with M''' = 6 c3.
  const double k3 = 6 / (72 * std::sqrt(3.0) * kSpreadAim * plan_budget);
  // Densities on a grid of kSpreadSamples intervals, sampled every other
  // one, then at all of them when the piece needs more than kSpreadRefine
  // chords per interval. (Starting from every 4th would make the plan
  // coarser and save no time.)
  double D[kSpreadSamples + 1];
  // The two densities at t: the sagitta's (d) and the cubic term's cube (g).
  auto one = [&](double t, double& d, double& g) {
    const double d1x = (c3x * (3 * t) + c2x * 2) * t + c1x, d1y = (c3y * (3 * t) + c2y * 2) * t + c1y;
    const double d2x = c3x * (6 * t) + c2x * 2, d2y = c3y * (6 * t) + c2y * 2;
    const double is = 1 / std::sqrt(d1x * d1x + d1y * d1y);
    d = std::sqrt(std::abs(d1x * d2y - d1y * d2x) * is) * inv8H;
    g = std::abs(d1x * c3y - d1y * c3x) * is * k3;
  };
  // Where the last control points coincide, M'(1) = 0, but c1 + 2 c2 +
  // 3 c3 cancels to rounding noise, which the density would read as a
  // sharp turn. (M'(0) = c1 is exact.)
  const bool end_stationary = piece.points.back() == piece.points[piece.points.size() - 2];
  // N samples, from index `from` by `step`, two at a time with SSE2 (the
  // same arithmetic as one()); the cubic term's root, rarely needed, after.
  auto densities = [&]<int N>(std::integral_constant<int, N>, int from, int step) {
    double d[N], g[N];
#if defined(__SSE2__)
    for (int k = 0; k < N; k += 2) {
      const v2d t = v2d{double(from + k * step), double(from + (k + 1) * step)} * (1.0 / kSpreadSamples);
      const v2d d1x = (c3x * (3 * t) + c2x * 2) * t + c1x, d1y = (c3y * (3 * t) + c2y * 2) * t + c1y;
      const v2d d2x = c3x * (6 * t) + c2x * 2, d2y = c3y * (6 * t) + c2y * 2;
      const v2d is = 1 / vsqrt(d1x * d1x + d1y * d1y);
      const v2d dk = vsqrt(vabs(d1x * d2y - d1y * d2x) * is) * inv8H;
      const v2d gk = vabs(d1x * c3y - d1y * c3x) * is * k3;
      d[k] = dk[0], d[k + 1] = dk[1], g[k] = gk[0], g[k + 1] = gk[1];
    }
#else
    for (int k = 0; k < N; ++k) one(double(from + k * step) * (1.0 / kSpreadSamples), d[k], g[k]);
#endif
    for (int k = 0; k < N; ++k) {
      const int idx = from + k * step;
      if (idx > kSpreadSamples) break;
      // A stationary point at the sample (M' = 0, as where the first or
      // the last control points coincide): the density's limit, from close
      // by.
      if (!(d[k] >= 0 && g[k] >= 0)) {
        const double t = double(idx) * (1.0 / kSpreadSamples);
        one(t < 0.5 ? t + 1e-6 : t - 1e-6, d[k], g[k]);
      }
      D[idx] = g[k] > d[k] * d[k] * d[k] ? cbrt_estimate(g[k]) : d[k];
    }
  };
  // The running integral (trapezoid rule) on the grid of M intervals, and
  // the intervals' inverse widths (divisions here, two at a time, off the
  // chords' path).
  double C[kSpreadSamples + 1];
  double W[kSpreadSamples];
  auto prefix = [&]<int M>(std::integral_constant<int, M>) {
    constexpr int stride = kSpreadSamples / M;
    constexpr double inv_m = 1.0 / M;  // (a power of 2: multiplying by it divides exactly)
    C[0] = 0;
    for (int j = 1; j <= M; ++j) C[j] = C[j - 1] + 0.5 * (D[(j - 1) * stride] + D[j * stride]) * inv_m;
  };
  static_assert(kSpreadSamples == 32, "the grid is refined once, from 16 intervals to 32");
  int m = 16;
  densities(std::integral_constant<int, 18>{}, 0, 2);  // (the 18th is past the end, unused)
  if (end_stationary) {
    double d1, g1;
    one(1 - 1e-6, d1, g1);
    D[kSpreadSamples] = g1 > d1 * d1 * d1 ? cbrt_estimate(g1) : d1;
  }
  prefix(std::integral_constant<int, 16>{});
  if (16 * kSpreadRefine < C[16]) {
    densities(std::integral_constant<int, 16>{}, 1, 2);
    m = 32;
    prefix(std::integral_constant<int, 32>{});
  }
  double total = C[m];
  // (a density undefined even beside its sample gives infinity or NaN here)
  if (!(total < kSpreadMax))
    return band_planar_piece(piece, P, final_piece, opt, tol, margin, shift, pi, A, Ar, dispA, bound, emitted, emit);
#if defined(__SSE2__)
  for (int j = 0; j < m; j += 2) {
    const v2d lo = {C[j], C[j + 1]}, hi = {C[j + 1], C[j + 2]};
    const v2d w = 1 / (hi - lo);
    W[j] = hi[0] > lo[0] ? w[0] : 0.0;
    W[j + 1] = hi[1] > lo[1] ? w[1] : 0.0;
  }
#else
  for (int j = 0; j < m; ++j) W[j] = C[j + 1] > C[j] ? 1 / (C[j + 1] - C[j]) : 0.0;
#endif
  const double inv_m = 1.0 / m;
  // The plan from a vertex: the rest of the integral shared among as few
  // chords as fit, the last one (and the first, from a vertex on the curve)
  // counting for e of the units (both ends on the curve: e1).
  const double e = std::sqrt(longest_sagitta(plan_budget, 0, shift) / H2), e1 = std::sqrt(plan_budget / H2);
  int j = 0;         // the grid interval of `level`
  double level = 0;  // the integral at the planned end
  double unit = 0;   // the integral an inner chord covers
  int left = 0;      // chords left in the plan, the planned one included
  auto at_level = [&](double lv) __attribute__((always_inline)) {
    while (j < m - 1 && C[j + 1] < lv) ++j;
    return (j + std::clamp((lv - C[j]) * W[j], 0.0, 1.0)) * inv_m;
  };
  // The piece's inflections (CubicPowerForm::inflections()), those not
  // within 5 % of an end, ascending: the plan puts a vertex on the curve at
  // each and plans the stretches between them apart (seg_end: the end of
  // the stretch planned). A chord across an inflection
  // has its ends shifted to opposite sides, so the curve crosses it and it
  // fits only when very short: such planned chords often fail. Split
  // there, the planned chords fail less often, for a few more chords (the
  // vertex on the curve, and each stretch's count rounded up on its own).
  double infl[2];
  int n_infl = 0;
  {
    double r[2];
    const int n = P.inflections(r);
    for (int i = 0; i < n; ++i)
      if (r[i] > 0.05 && r[i] < 0.95) infl[n_infl++] = r[i];
  }
  // The running integral at t (linear within its grid interval, which
  // goes to jj).
  auto integral_at = [&](double t, int& jj) {
    jj = std::min(int(t * m), m - 1);
    return C[jj] + (t * m - jj) * (C[jj + 1] - C[jj]);
  };
  // The plan's breaks, where it puts a vertex on the curve and plans the
  // stretches on either side apart: the inflections, and the piece's tips
  // (planar_tips(), where it turns back on itself: a chord across a tip
  // has the curve poke past its end). The tips are looked for on pieces
  // that need at most kTipPlan chords (beyond, a vertex more or less at a
  // tip matters little): at once on those that need at most kTipEager (to
  // pass over them from the start, below), else once a chord does not fit
  // (where a tip costs). add_tips() returns whether there is one after
  // `from`.
  double brk[4];
  bool brk_tip[4];  // whether the break is a tip
  int n_brk = n_infl, n_tip = 0;
  for (int i = 0; i < n_infl; ++i) brk_tip[i] = false, brk[i] = infl[i];
  bool tips_known = !(total <= kTipPlan);
  auto add_tips = [&](double from) {
    tips_known = true;
    double tip[2];
    n_tip = planar_tips(P, kTipRadius * plan_budget, tip);
    if (n_tip == 0) return false;
    int jj;
    double ctip[2];
    for (int i = 0; i < n_tip; ++i) ctip[i] = integral_at(tip[i], jj);
    // An inflection within kTipAbsorb chords of a tip is left to it.
    n_brk = 0;
    for (int i = 0; i < n_infl; ++i) {
      const double ci = integral_at(infl[i], jj);
      bool keep = true;
      for (int k = 0; k < n_tip; ++k) keep = keep && std::abs(ci - ctip[k]) >= kTipAbsorb;
      if (keep) brk_tip[n_brk] = false, brk[n_brk++] = infl[i];
    }
    for (int i = 0; i < n_tip; ++i) brk_tip[n_brk] = true, brk[n_brk++] = tip[i];
    for (int i = 1; i < n_brk; ++i)
      for (int k = i; k > 0 && brk[k - 1] > brk[k]; --k) std::swap(brk[k - 1], brk[k]), std::swap(brk_tip[k - 1], brk_tip[k]);
    return tip[n_tip - 1] > from + 1e-9;
  };
  if (total <= kTipEager) add_tips(0);
  double seg_end = 1.0;  // the end of the stretch planned
  // The breaks after the plan's start: the first (k_next) and the one the
  // stretch planned ends at (k_end; n_brk: the piece's end); whether the
  // plan's start is on the curve; whether the chord planned is one tried
  // before the plan proper (it falls back to that when the chord does not
  // fit, in shrink()).
  int k_next = 0, k_end = 0;
  bool plan_on_curve = true, trial = false;
  auto brk_at = [&](int k) { return k < n_brk ? brk[k] : 1.0; };
  // A break is passed over while the stretch beyond it still needs only
  // one chord by the plan (a curve that doubles back along its chord within
  // it, or a short one across an inflection), not counting the share of
  // the integral a tip itself takes (at most kTipShare: the density's
  // integral over a turn of radius r is about pi sqrt(r / (8 H)) chords);
  // and beside a tip, where the density's model of a chord (a small turn)
  // does not hold, a stretch that would take two chords by the plan tries
  // one first. From `from` (the integral c there), the stretch to break
  // k_next (cend there) being short enough for either: sets k_end,
  // seg_end and trial, returns the integral at seg_end.
  auto plan_trial = [&](double from, double c, double room, double cend, int k_cap) __attribute__((noinline)) {
    int je;
    double allowance = room;
    while (k_end < std::min(n_brk, k_cap)) {
      allowance += brk_tip[k_end] ? kTipShare : 0.0;
      const double beyond = k_end + 1 < n_brk ? integral_at(brk[k_end + 1], je) : total;
      if (!(beyond - c <= allowance)) break;
      ++k_end;
      cend = beyond;
    }
    seg_end = brk_at(k_end);
    const double rest = cend - c;
    const bool at_tip = n_tip > 0 && ((k_next > 0 && brk_tip[k_next - 1] && !(brk[k_next - 1] < from - 1e-9)) ||
                                      (k_end < n_brk && brk_tip[k_end]));
    trial = k_end > k_next || (at_tip && rest > room && rest <= room + kTipShare);
    return cend;
  };
  // The plan from `from`, passing over no break after k_cap, and trying a
  // single chord first only when `try_one`.
  auto plan_from = [&](double from, bool from_curve, int k_cap = 4, bool try_one = true) {
    const double c = integral_at(from, j);
    const double room = from_curve ? e1 : e;
    plan_on_curve = from_curve;
    k_next = 0;
    while (k_next < n_brk && !(brk[k_next] > from + 1e-9)) ++k_next;
    k_end = k_next;
    seg_end = brk_at(k_next);
    int je;
    double cend = seg_end < 1 ? integral_at(seg_end, je) : total;
    trial = false;
    if (try_one && n_tip > 0 && cend - c <= room + n_tip * kTipShare) cend = plan_trial(from, c, room, cend, k_cap);
    const double rest = cend - c;
    if (trial || !(rest > room)) {
      left = 1;
      return seg_end;
    }
    const double first = from_curve ? e : 1.0;
    const double inner = std::max(0.0, std::ceil(rest - first - e - 1e-9));
    unit = rest / (first + inner + e);
    left = int(inner) + 2;
    level = c + first * unit;
    return std::max(from, at_level(level));
  };
  double ax = A.x, ay = A.y, dA = dispA;
  double t0 = 0, S0x = piece.front().x, S0y = piece.front().y, T0x = c1x, T0y = c1y;
  const double endx = piece.back().x, endy = piece.back().y;
  const int decimals = opt.decimals;
  int shrinks = 0;
  bool drop = false;     // the next try's end on the curve (repeated failures that shortening does not cure)
  double prev_dev = kInf;
  bool as_planned = true;  // the chord tried ends where the plan put it
  double t1 = plan_from(0, true);
  // One vertex: the curve's point and tangent at t, B shifted towards the
  // convex side (none at an inflection, a straight stretch or the end),
  // its rounding and how far that moved it.
  struct Vtx {
    double t, onx, ony, d1x, d1y, Bx, By, disp;
    Vec3 Br;
    bool side;
  };
  auto finish = [&](Vtx& v, double sx, double sy) __attribute__((always_inline)) {
    v.Bx = v.onx + sx, v.By = v.ony + sy, v.side = sx != 0 || sy != 0;
    v.Br = Vec3{v.Bx, v.By};
    v.disp = 0;
    if (decimals >= 0) {
      v.Br = quantize(v.Br, decimals);
      v.disp = std::sqrt((v.Br.x - v.Bx) * (v.Br.x - v.Bx) + (v.Br.y - v.By) * (v.Br.y - v.By));
    }
  };
  auto vertex = [&](double t, Vtx& v) __attribute__((always_inline)) {
    v.t = t;
    double sx = 0, sy = 0;
    if (t < 1) {
      const double t3 = 3 * t, t6 = 6 * t;
      v.onx = ((c3x * t + c2x) * t + c1x) * t + c0x;
      v.ony = ((c3y * t + c2y) * t + c1y) * t + c0y;
      v.d1x = (c3x * t3 + c2x * 2) * t + c1x;
      v.d1y = (c3y * t3 + c2y * 2) * t + c1y;
      const double d2x = c3x * t6 + c2x * 2, d2y = c3y * t6 + c2y * 2;
      const double s2 = v.d1x * v.d1x + v.d1y * v.d1y, cr = v.d1x * d2y - v.d1y * d2x;
      // (none at an inflection the plan stops at)
      if (t < seg_end && planar_side(cr, s2, d2x, d2y)) {
        const double k = std::copysign(shift, -cr) / std::sqrt(s2);  // (-shift where cr > 0, without a branch)
        sx = -v.d1y * k, sy = v.d1x * k;
      }
    } else {
      v.onx = endx, v.ony = endy;
      v.d1x = c3x * 3 + c2x * 2 + c1x;
      v.d1y = c3y * 3 + c2y * 2 + c1y;
    }
    finish(v, sx, sy);
  };
  // The chord from the current vertex to v: its bound (infinity: it cannot
  // fit) and budget.
  auto chord = [&](const Vtx& v, double& budget) __attribute__((always_inline)) {
    budget = tol - margin - std::max(dA, v.disp);
    const double h = (v.t - t0) * (1.0 / 3);
    const XY S[4] = {{S0x, S0y}, {S0x + T0x * h, S0y + T0y * h}, {v.onx - v.d1x * h, v.ony - v.d1y * h}, {v.onx, v.ony}};
#ifdef BEZCAM_FLATTEN_COUNTERS
    ++g_counters.spread_tries;
#endif
    return budget > 0 ? band_cubic_planar(S, XY{ax, ay}, XY{v.Bx, v.By}, budget, nullptr) : kInf;
  };
  // v becomes the current vertex (its chord proven, of bound dev).
  auto accept = [&](const Vtx& v, double dev) __attribute__((always_inline)) {
    shrinks = 0;
    drop = false;
    prev_dev = kInf;
    bound = std::max(bound, dev + std::max(dA, v.disp));
    // A vertex that rounds onto the one before it is left out (a path keeps
    // at least one segment), as in the search.
    const bool final_vertex = final_piece && v.t >= 1;
    if (!(v.Br == Ar) || (final_vertex && emitted == 0)) {
      emit({v.Br, pi, v.t});
      ++emitted;
    }
    Ar = v.Br;
    t0 = v.t;
    ax = v.Bx, ay = v.By, dA = v.disp;
    S0x = v.onx, S0y = v.ony, T0x = v.d1x, T0y = v.d1y;
  };
  // The next end after an accepted vertex v.
  auto next = [&](const Vtx& v) __attribute__((always_inline)) {
    if (as_planned && --left > 1) {
      level += unit;
      return std::max(t0, at_level(level));
    }
    if (as_planned && left == 1 && v.side) return seg_end;
    return plan_from(t0, !v.side);
  };
#if defined(__SSE2__)
  // vertex() at two parameters below 1 at once (the same arithmetic).
  auto vertex2 = [&](double ta, double tb, Vtx& va, Vtx& vb) __attribute__((always_inline)) {
    const v2d t = {ta, tb}, t3 = 3 * t, t6 = 6 * t;
    const v2d onx = ((c3x * t + c2x) * t + c1x) * t + c0x, ony = ((c3y * t + c2y) * t + c1y) * t + c0y;
    const v2d d1x = (c3x * t3 + c2x * 2) * t + c1x, d1y = (c3y * t3 + c2y * 2) * t + c1y;
    const v2d d2x = c3x * t6 + c2x * 2, d2y = c3y * t6 + c2y * 2;
    const v2d s2 = d1x * d1x + d1y * d1y, cr = d1x * d2y - d1y * d2x;
    // (-shift where cr > 0, shift where cr < 0, without a branch: the sign
    // of -cr on shift; where cr is 0 or not finite there is no side)
    const v2d k = v2d(_mm_or_pd(_mm_andnot_pd(__m128d(cr), _mm_set1_pd(-0.0)), _mm_set1_pd(shift))) / vsqrt(s2);
    // (planar_side() on both lanes)
    const v2d q = kSideFloor * (d2x * d2x + d2y * d2y) * s2, cr2 = cr * cr;
    Vtx* out[2] = {&va, &vb};
    for (int i = 0; i < 2; ++i) {
      Vtx& v = *out[i];
      v.t = t[i], v.onx = onx[i], v.ony = ony[i], v.d1x = d1x[i], v.d1y = d1y[i];
      const bool side = cr2[i] > q[i] && std::isfinite(cr2[i] * s2[i]);
      finish(v, side ? -d1y[i] * k[i] : 0.0, side ? d1x[i] * k[i] : 0.0);
    }
  };
  // chord() from the current vertex to va and from va to vb; the second
  // only matters when the first fits.
  auto chord2 = [&](const Vtx& va, const Vtx& vb, double& deva, double& ba, double& devb, double& bb) __attribute__((always_inline)) {
    ba = tol - margin - std::max(dA, va.disp);
    bb = tol - margin - std::max(va.disp, vb.disp);
    const v2d h = v2d{va.t - t0, vb.t - va.t} * (1.0 / 3);
    const v2d Sx0 = {S0x, va.onx}, Sy0 = {S0y, va.ony}, onx = {va.onx, vb.onx}, ony = {va.ony, vb.ony};
    const v2d Sx[4] = {Sx0, Sx0 + v2d{T0x, va.d1x} * h, onx - v2d{va.d1x, vb.d1x} * h, onx};
    const v2d Sy[4] = {Sy0, Sy0 + v2d{T0y, va.d1y} * h, ony - v2d{va.d1y, vb.d1y} * h, ony};
    bool ok[2];
    double dev[2];
    band_sufficient2(Sx, Sy, v2d{ax, va.Bx}, v2d{ay, va.By}, v2d{va.Bx, vb.Bx}, v2d{va.By, vb.By}, v2d{ba, bb}, ok,
                     dev);
#ifdef BEZCAM_FLATTEN_COUNTERS
    g_counters.spread_tries += 2;
#endif
    auto full = [&](int i, double budget) {
      if (!(budget > 0)) return kInf;
      const XY S[4] = {{Sx[0][i], Sy[0][i]}, {Sx[1][i], Sy[1][i]}, {Sx[2][i], Sy[2][i]}, {Sx[3][i], Sy[3][i]}};
      return i == 0 ? band_cubic_planar(S, XY{ax, ay}, XY{va.Bx, va.By}, budget, nullptr)
                    : band_cubic_planar(S, XY{va.Bx, va.By}, XY{vb.Bx, vb.By}, budget, nullptr);
    };
    deva = ok[0] && ba > 0 ? dev[0] : full(0, ba);
    devb = !(deva <= ba) ? kInf : ok[1] && bb > 0 ? dev[1] : full(1, bb);
  };
#endif
  // A chord to v that does not fit: the next try is shorter, as if the
  // sagitta grew like the square of the step; the search takes over the
  // rest of a piece where that runs on (false: it has).
  auto shrink = [&](const Vtx& v, double dev, double budget) {
    if (!tips_known && add_tips(t0)) {
      // (planned again, with the tips)
      t1 = plan_from(t0, ax == S0x && ay == S0y);
      as_planned = true;
      return true;
    }
    if (trial && v.t == seg_end) {
      // A single chord tried first that does not fit: across one break
      // fewer, or planned.
      t1 = k_end > k_next ? plan_from(t0, plan_on_curve, k_end - 1) : plan_from(t0, plan_on_curve, k_next, false);
      as_planned = true;
      return true;
    }
    if (++shrinks > kSpreadShrinks || !(v.t - t0 > 1e-9)) {
      band_planar_piece(piece, P, final_piece, opt, tol, margin, shift, pi, Vec3{ax, ay}, Ar, dA, bound, emitted, emit,
                        t0, ax == S0x && ay == S0y ? 0.0 : shift, v.t - t0);
      return false;
    }
    // Shortened once already, and the deviation (with the shift, what the
    // model says falls like the square of the step) fell by less than 5 %:
    // what fails is not the length but the end's side (near an inflection,
    // or a turn tighter than the band, the end shifted away from the
    // chord's bulge). The same end on the curve is tried before shortening
    // on, rather than creeping down 5 % a try.
    const bool stuck = dev < kInf && dev + shift > 0.95 * (prev_dev + shift);
    if (!drop && v.side && stuck) {
      drop = true;
      t1 = v.t;
      as_planned = false;
      return true;
    }
    prev_dev = dev;
    double g = dev < kInf ? std::sqrt(kSpreadAim * (budget + shift) / (dev + shift)) : 0.5;
    // Still stuck with the end on the curve: the start vertex is what fails
    // (shifted away from this chord's bulge), and only a much shorter chord
    // fits: shortened by 0.7 at least rather than creeping down 5 % a try.
    if (stuck && drop) g = std::min(g, 0.7);
    t1 = t0 + (v.t - t0) * std::clamp(g, 0.3, 0.95);
    as_planned = false;
#ifdef BEZCAM_FLATTEN_COUNTERS
    ++g_counters.spread_shrinks;
#endif
    return true;
  };
  Vtx v1, v2;
  for (;;) {
#if defined(__SSE2__)
    // Two planned inner vertices ahead: both evaluated, and both chords
    // tested, at once (one at a time without SSE2: the same chords).
    if (as_planned && left > 2) {
      const double t2 = std::max(t1, at_level(level + unit));
      if (t2 < seg_end) {
        vertex2(t1, t2, v1, v2);
        double b1, b2;
        double dev1, dev2;
        chord2(v1, v2, dev1, b1, dev2, b2);
        if (dev1 <= b1) {
          accept(v1, dev1);
          // (what next(v1) gives: the plan goes on, and its end is t2)
          --left;
          level += unit;
          t1 = t2;
          if (dev2 <= b2) {
            accept(v2, dev2);
            t1 = next(v2);
            continue;
          }
          if (!shrink(v2, dev2, b2)) return;
          continue;
        }
        if (!shrink(v1, dev1, b1)) return;
        continue;
      }
    }
#endif
    vertex(t1, v1);
    if (drop && v1.side) finish(v1, 0.0, 0.0);
    double budget;
    const double dev = chord(v1, budget);
    if (!(dev <= budget)) {
      if (!shrink(v1, dev, budget)) return;
      continue;
    }
    accept(v1, dev);
    if (v1.t >= 1) break;
    t1 = next(v1);
    as_planned = true;
  }
#ifdef BEZCAM_FLATTEN_COUNTERS
  ++g_counters.spread_pieces;
#endif
}

template <class Emit>
double bound_band(std::span<const Bezier> pieces, const FlattenOptions& opt, const ToleranceBudget& tb, Vec3 Ar,
                  Emit&& emit) {
  const double tol = opt.tolerance, margin = tb.margin;
  // Room for the offset: the next chord starts there, and whatever its
  // other end's rounding, a short enough chord from here fits.
  const double shift = kBandShare * (tol - margin - tb.rounding);
  double bound = 0;
  size_t emitted = 0;  // vertices after the first
  struct Chord {
    double t1 = 0, dev = 0, disp = 0, budget = 0;
    Vec3 B, Br;
    bool on = false;  // B on the curve
  };
  for (size_t pi = 0; pi < pieces.size(); ++pi) {
    const Prepared P(pieces[pi]);
    Vec3 A = pieces[pi].front();
    double dispA = dist(Ar, A);  // includes the tiny gap at a path joint
    // Planar cubics (a 2D piece keeps z = 0): the chords planned, then
    // proven (band_planar_spread()).
    if (P.cubic && P.planar) {
      band_planar_spread(pieces[pi], P, pi + 1 == pieces.size(), opt, tol, margin, tb.rounding, shift, pi, A, Ar, dispA,
                         bound, emitted, emit);
      continue;
    }
    // Every other piece (rational, of degree over 3, in space): no bulge to
    // steer by; the deviation over the budget tells how much to shrink, as
    // if it grew like the square of the step.
    double t0 = 0;
    double dt = 1.2 * P.first_step(tol - margin - dispA);
    // One try: B shifted across the curve, then (when allowed) B on it.
    auto try_chord = [&](double t1, Chord& c, bool zero) {
      const Vec3 on = P.point(t1);
      const Vec3 side = t1 < 1 ? P.convex_side(t1) : Vec3{};
      const bool has_side = side.x != 0 || side.y != 0 || side.z != 0;
      for (int pass = 0; pass < 2; ++pass) {
        if (pass == 0 ? !has_side : !zero) continue;
        const Vec3 B = pass == 0 ? on + side * shift : on;
        Vec3 Br = B;
        double disp = dispA;
        if (opt.decimals >= 0) {
          Br = quantize(B, opt.decimals);
          disp = std::max(dispA, dist(Br, B));
        }
        const double budget = tol - margin - disp;
        if (!(budget > 0)) continue;
        const double dev = P.band(t0, t1, A, B, budget);
        c.t1 = t1, c.dev = dev, c.disp = disp, c.budget = budget;
        c.B = B, c.Br = Br, c.on = pass == 1;
        if (dev <= budget) return true;
      }
      return false;
    };
    Chord slot[2];
    while (t0 < 1) {
      double lo = 0, hi = kInf;  // largest dt known to fit, smallest known not to
      bool found = false;
      for (Chord& c : slot) c.dev = 0, c.budget = 0, c.on = false;
      int cur = 0;
      double step = kBandStep;
#ifdef BEZCAM_FLATTEN_COUNTERS
      int n_tries = 0;
#endif
      for (int iter = 0; iter < 200; ++iter) {
        const bool last = dt >= 1 - t0;
        if (last) dt = 1 - t0;
        Chord& c = slot[cur];
        const bool ok = try_chord(last ? 1.0 : t0 + dt, c, !found || slot[cur ^ 1].on);
#ifdef BEZCAM_FLATTEN_COUNTERS
        ++n_tries;
#endif
        if (ok) {
          found = true;
          lo = dt;
          cur ^= 1;  // c is now the best
          if (last || lo >= kBandClose * hi) break;
          double nd = dt * (1 + step);
          if (nd >= hi) nd = 0.5 * (lo + hi);
          dt = nd;
        } else {
          hi = dt;
          if (found && lo >= kBandClose * hi) break;
          double nd = shrink_unsteered(dt, c.dev, c.budget, step);
          if (found && nd <= lo) nd = 0.5 * (lo + hi);
          dt = nd;
        }
        step = std::min(2 * step, 1.0);
      }
      if (!found) throw std::logic_error("flatten: no band chord fits (internal error)");
      const Chord& best = slot[cur ^ 1];
#ifdef BEZCAM_FLATTEN_COUNTERS
      count_search(best.t1 >= 1 ? 2 : 1, n_tries);
#endif
      bound = std::max(bound, best.dev + best.disp);
      // A vertex that rounds onto the one before it would print a move of
      // length zero: the printed polyline is the same without it (but a
      // path keeps at least one segment).
      const bool final_vertex = pi + 1 == pieces.size() && best.t1 >= 1;
      if (!(best.Br == Ar) || (final_vertex && emitted == 0)) {
        emit({best.Br, pi, best.t1});
        ++emitted;
      }
      if (best.t1 < 1) {
        // Next guess: the same step, scaled by the change of bending
        // between this chord's middle and the next one's.
        const double b0 = P.bend(best.t1 - 0.5 * lo), b1 = P.bend(std::min(1.0, best.t1 + 0.5 * lo));
        const double g2 = b0 > 0 && b1 > 0 ? b0 / b1 : 1.0;
        dt = lo * std::sqrt(std::clamp(g2, 1.0 / 16, 16.0));
      }
      t0 = best.t1;
      A = best.B;
      Ar = best.Br;
      dispA = Ar == A ? 0.0 : dist(Ar, A);
    }
  }
  return bound;
}

}  // namespace

namespace {

// flatten_pieces() for any sink of FlatVertex: flatten_into() passes one that
// appends the point to a vector, inlined with the rest (no call through a
// std::function per vertex).
template <class Sink>
double flatten_with(std::span<const Bezier> pieces, const FlattenOptions& opt, Sink&& emit) {
  if (pieces.empty()) return 0;
  const double tol = opt.tolerance;
  const ToleranceBudget tb = check_tolerance(tol, opt.decimals, pieces.front().dim, control_magnitude(pieces));
  const double rmax = tb.rounding, margin = tb.margin;

  // Stated limit (limits.hpp): a count that would exceed it is refused
  // before the work, or as soon as it is exceeded.
  auto too_many = [&](const std::string& found) {
    return InputError(errc::limit_segments, Place::at_json("tolerance"),
                      "flattening within tolerance " + fmt_num(tol) + " needs " + found + " segments, more than the " +
                          std::to_string(opt.max_vertices) +
                          " a program may hold (docs/limits.md); raise the tolerance or split the curve");
  };
  // Wang's formula bounds the uniform step count of each polynomial piece
  // from its control points alone (O(n), no allocation); only when that
  // bound could reach the limit is the sampled estimate worth its cost.
  // Cheaper still, and enough for most paths: each piece's count ceil(k),
  // k = sqrt(n (n - 1) m / (8 tol)), is at most k + 1, so the sum stays
  // within the limit when every k is within K = limit / pieces - 1, that
  // is when (n (n - 1))^2 m^2 <= (8 tol K^2)^2 with the largest n and m
  // (no root, no division per piece; K half a count short, for rounding).
  double m2max = 0;
  int nmax = 0;
  bool rational = false;
  for (const auto& pc : pieces) {
    rational = rational || pc.rational();
    nmax = std::max(nmax, pc.degree());
    m2max = std::max(m2max, second_difference_sq(pc));
  }
  const double K = static_cast<double>(opt.max_vertices) / static_cast<double>(pieces.size()) - 1.5;
  const double nn = double(nmax) * (nmax - 1), w = 8 * (tol - rmax) * K * K;
  if (rational || !(K > 0) || !(nn * nn * m2max <= w * w)) {
    double wang = 0;
    for (const auto& pc : pieces) {
      const double step = pc.rational() ? 0 : wang_step(pc, tol - rmax);
      wang += step > 0 ? 1 / step : kInf;
    }
    // The band's chords see a band twice as wide (estimate_segments()).
    const double estimate = wang <= static_cast<double>(opt.max_vertices)
                                ? wang
                                : estimate_segments(pieces, (opt.on_curve ? 1 : 2) * (tol - rmax));
    if (estimate > static_cast<double>(opt.max_vertices))
      throw too_many("about " + (std::isfinite(estimate) ? fmt_num(std::round(estimate)) : std::string("infinitely many")));
  }
  std::size_t emitted = 0;
  // (the refusal out of line: the sink stays inlined with the flattener)
  auto refuse = [&]() __attribute__((noinline, cold)) { throw too_many("at least " + std::to_string(emitted)); };
  auto emit_counted = [&](const FlatVertex& v) __attribute__((always_inline)) {
    if (++emitted > opt.max_vertices) [[unlikely]] refuse();
    emit(v);
  };

  double bound = 0;
  Vec3 Ar = quantize(pieces.front().front(), opt.decimals);
  emit_counted({Ar, 0, 0});
  if (!opt.on_curve) return bound_band(pieces, opt, tb, Ar, emit_counted);
  double dt_hint = -1;
  for (size_t pi = 0; pi < pieces.size(); ++pi) {
    const Prepared P(pieces[pi]);
    Vec3 A = pieces[pi].front();
    double dispA = dist(Ar, A);  // includes the tiny gap at a path joint
    double t0 = 0;
    double dt = dt_hint > 0 ? dt_hint : P.first_step(tol - margin - dispA);
    while (t0 < 1) {
      // Search the longest chord from t0 whose bound fits the budget.
      double lo = 0, hi = kInf;  // largest dt known to fit, smallest known not to
      double best_dev = 0, best_disp = 0, best_ratio = 0, best_t1 = t0;
      Vec3 bestB, bestBr;
      bool found = false;
      for (int iter = 0; iter < 200; ++iter) {
        const bool last = dt >= 1 - t0;
        const double t1 = last ? 1.0 : t0 + dt;
        if (last) dt = 1 - t0;
        const Vec3 B = P.point(t1);
        const Vec3 Br = opt.decimals < 0 ? B : quantize(B, opt.decimals);
        const double dispB = opt.decimals < 0 ? 0.0 : dist(Br, B);
        const double budget = tol - margin - std::max(dispA, dispB);
        const double dev = budget > 0 ? P.deviation(t0, t1, A, B, budget) : kInf;
        const bool ok = dev <= budget;
        if (ok) {
          found = true;
          lo = dt;
          best_t1 = t1;
          best_dev = dev;
          best_disp = std::max(dispA, dispB);
          best_ratio = dev / budget;
          bestB = B;
          bestBr = Br;
          if (last || best_ratio >= kAcceptShare || lo >= 0.985 * hi) break;
          double g = best_ratio > 1e-12 ? std::sqrt(kAimShare / best_ratio) : 4.0;
          double nd = dt * std::min(g, 4.0);
          if (nd >= hi) nd = 0.5 * (lo + hi);
          dt = nd;
        } else {
          hi = dt;
          if (found && lo >= 0.985 * hi) break;
          double g = std::isfinite(dev) && dev > 0 ? std::sqrt(kAimShare * budget / dev) : 0.5;
          double nd = dt * std::clamp(g, 0.05, 0.9);
          if (nd <= lo) nd = 0.5 * (lo + hi);
          dt = nd;
        }
      }
      if (!found) throw std::logic_error("flatten: no chord fits (internal error)");
      const double t1 = best_t1;
      bound = std::max(bound, best_dev + best_disp);
      emit_counted({bestBr, pi, t1});
      // Next guess: the same step scaled by the room this chord left and by
      // the change of bending between this chord's middle and the next's.
      if (t1 >= 1) {
        dt_hint = -1;
      } else {
        double g = std::sqrt(kAimShare / std::max(best_ratio, 1e-12));
        const double b0 = P.bend(t1 - 0.5 * lo), b1 = P.bend(std::min(1.0, t1 + 0.5 * lo));
        if (b0 > 0 && b1 > 0) g *= std::sqrt(b0 / b1);
        dt_hint = lo * std::clamp(g, 0.25, 2.0);
        dt = dt_hint;
      }
      t0 = t1;
      A = bestB;
      Ar = bestBr;
      dispA = dist(Ar, A);
    }
    dt_hint = -1;
  }
  return bound;
}

}  // namespace

double flatten_pieces(std::span<const Bezier> pieces, const FlattenOptions& opt,
                      const std::function<void(const FlatVertex&)>& emit) {
  return flatten_with(pieces, opt, emit);
}

double flatten_into(std::span<const Bezier> pieces, const FlattenOptions& opt, std::vector<Vec3>& out) {
  return flatten_with(pieces, opt, [&out](const FlatVertex& v) { out.push_back(v.point); });
}

FlattenResult flatten(std::span<const Bezier> pieces, const FlattenOptions& opt) {
  FlattenResult r;
  // (room for most curves at once: growing one vertex at a time from none
  // would allocate four or five times)
  r.points.reserve(32);
  r.bound = flatten_into(pieces, opt, r.points);
  return r;
}

}  // namespace bezcam
