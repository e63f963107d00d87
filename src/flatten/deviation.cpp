// The deviation measures (deviation.hpp): curve to polyline and polyline
// to curve, by descent along the polyline and Newton steps on the curve,
// read again exactly where a reading could hide a larger distance.
#include "bezcam/flatten/deviation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "flatten/deviation_pieces.hpp"

namespace bezcam {

namespace {

// The B&B's refinement stops at this many halvings of an interval; what
// an interval still bounds then is taken into the result as it is.
constexpr int kMostDepth = 60;

// ---- Curve -> polyline --------------------------------------------------

// A point of the curve with its reading: d is the distance to segment k of
// the polyline (the nearest one found), so at least the distance to the
// polyline, and equal to it above `large`.
struct CurvePt {
  double t;
  double acc;  // Piece::acc(t)
  Vec3 p;
  size_t k;
  double d;
};

// From segment *hint, step to the next (or previous) segment while it is
// nearer; returns that distance (an upper bound of the distance to the
// polyline) and leaves *hint at the segment found. A reading above `large`
// is replaced by the exact one (`exact`, every segment).
template <class Exact>
double descend(const Vec3& x, std::span<const Vec3> pts, size_t& hint, double large, Exact&& exact) {
  const size_t nseg = pts.size() > 1 ? pts.size() - 1 : 0;
  if (nseg == 0) return hint = 0, dist(x, pts[0]);
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
  hint = i;
  const double d = std::sqrt(best);
  return d > large ? exact(x, hint) : d;
}

// ---- Polyline -> curve --------------------------------------------------

// A point of the polyline (segment k at fraction s) with its reading: d is
// the distance to the curve point of piece i at t (a foot found by Newton
// steps from a neighbour's), so at least the distance to the curve, and
// equal to it above `large`.
struct PathPt {
  double s;
  Vec3 x;
  size_t i;
  double t;
  double acc;  // Piece::acc(t) of piece i
  Vec3 f;      // the curve point
  double d;
};

// An arc of piece i over [t0, t1] in the exact nearest-point search.
struct SearchArc {
  size_t i;
  double t0, t1;
  Vec3 p0, p1;
  int depth;
};

// Scratch vectors kept by each measuring thread: no allocation per
// measurement once the first has grown them.
struct Scratch {
  std::vector<Piece> pieces;
  std::vector<H> hom;  // the pieces' general forms
  std::vector<CurvePt> cpts;
  std::vector<PathPt> ppts;
  std::vector<size_t> first;   // per piece: its first coarse point
  std::vector<CurvePt> workc;  // the B&B's stacks of points
  std::vector<PathPt> workp;
  std::vector<int> depth;  // halvings of each arc on the stack
  std::vector<SearchArc> arcs;
  ChainIndex index;
  static constexpr size_t kKeep = size_t{1} << 20;
  void trim() {
    auto fit = [](auto& v) {
      if (v.capacity() > kKeep) std::decay_t<decltype(v)>().swap(v);
    };
    fit(pieces), fit(hom), fit(cpts), fit(ppts), fit(first), fit(workc), fit(workp), fit(depth), fit(arcs);
  }
};

class Measure {
 public:
  Measure(Scratch& s, std::span<const Bezier> pieces, std::span<const Vec3> poly, double tolerance)
      : s_(s), poly_(poly), large_(tolerance) {
    size_t room = 0;
    for (const Bezier& b : pieces) room += Piece::room(b);
    s_.hom.resize(room);
    s_.pieces.clear();
    room = 0;
    for (const Bezier& b : pieces) s_.pieces.emplace_back(b, s_.hom.data() + room), room += Piece::room(b);
    gap_ = std::max({tolerance * kMeasureGap, control_magnitude(pieces) * 1e-14, 1e-300});
    planar_ = std::all_of(poly.begin(), poly.end(), [](const Vec3& p) { return p.z == 0; }) &&
              std::all_of(pieces.begin(), pieces.end(), [](const Bezier& b) {
                return std::all_of(b.points.begin(), b.points.end(), [](const Vec3& p) { return p.z == 0; });
              });
  }

  double curve_to_path();
  double path_to_curve();

 private:
  const std::vector<Piece>& P() const { return s_.pieces; }

  // Exact distance from x to the polyline.
  double exact_to_path(const Vec3& x, size_t& seg) {
    if (!indexed_) s_.index.build(poly_), indexed_ = true;
    return s_.index.nearest(x, seg);
  }
  void read_curve(CurvePt& q, size_t hint) {
    q.k = hint;
    q.d = descend(q.p, poly_, q.k, exact_above_, [&](const Vec3& x, size_t& k) { return exact_to_path(x, k); });
  }
  // Upper bound of the distance to the polyline over the arc between a and
  // b (of piece i): every arc point is within the sag of a chord point y,
  // and the distance from y to either segment found at the ends is convex
  // along the chord, so at most the segment's readings' interpolation.
  // With a power form the sag is the parameter's own: C(t) at fraction l
  // of the arc is within 4 s l (1 - l) of the chord's point at l, and the
  // bound is the interpolation plus that bump.
  // In the plane z = 0, with a power form, when both ends are read
  // against the same segment and the whole arc projects inside it (the
  // ends' projections, widened by the sag), the distance to that segment
  // is |n . (C(t) - A)|, a polynomial in t: its exact largest value over
  // the arc is the bound, and *split its place (a reading there settles
  // the arc unless another segment is nearer: it is split there).
  double bound(const Piece& pc, const CurvePt& a, const CurvePt& b, double* split) const {
    const double s = pc.sag(a.t, b.t, a.acc, b.acc, a.p, b.p);
    *split = 0.5 * (a.t + b.t);
    if (a.k == b.k && planar_ && pc.n >= 0 && poly_.size() > 1) {
      const Vec3 A = poly_[a.k], B = poly_[a.k + 1];
      const double L = norm(B - A);
      if (L > 0) {
        const Vec3 e = (B - A) / L, nv{-e.y, e.x, 0};
        const double ua = dot(a.p - A, e), ub = dot(b.p - A, e);
        if (std::min(ua, ub) >= s && std::max(ua, ub) + s <= L) {
          double f[4] = {dot(nv, pc.c[0] - A), 0, 0, 0};
          for (int j = 1; j <= pc.n; ++j) f[j] = dot(nv, pc.c[j]);
          auto F = [&](double t) { return std::abs(((f[3] * t + f[2]) * t + f[1]) * t + f[0]); };
          double best = std::max(a.d, b.d), arg = *split;
          auto at = [&](double t) {
            if (t > a.t && t < b.t) {
              const double v = F(t);
              if (v > best) best = v, arg = t;
            }
          };
          // f' = 3 f3 t^2 + 2 f2 t + f1.
          const double qa = 3 * f[3], qb = 2 * f[2], qc = f[1];
          if (qa == 0) {
            if (qb != 0) at(-qc / qb);
          } else {
            const double disc = qb * qb - 4 * qa * qc;
            if (disc >= 0) {
              const double r = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
              if (r != 0) at(qc / r);
              at(r / qa);
            }
          }
          *split = arg;
          return best;
        }
      }
    }
    // Split where the bound is largest, kept off the ends.
    const double q = pc.n >= 0 ? s : 0, add = pc.n >= 0 ? 0 : s;
    double l = 0.5;
    const double ub = a.k == b.k ? max_line_bump(a.d, b.d, q, 0, 1, &l)
                                 : max_of_min(a.d, seg_dist(b.p, poly_, a.k), seg_dist(a.p, poly_, b.k), b.d, q, &l);
    *split = a.t + std::clamp(l, 0.1, 0.9) * (b.t - a.t);
    return ub + add;
  }

  void foot(PathPt& q, size_t i, double t);
  double exact_to_curve(const Vec3& x, size_t& piece, double& t);
  void read_path(PathPt& q, size_t i, double t) {
    foot(q, i, t);
    if (q.d > exact_above_) {
      q.d = exact_to_curve(q.x, q.i, q.t);
      q.f = P()[q.i].at(q.t);
    }
    q.acc = P()[q.i].acc(q.t);
  }
  double bound(const PathPt& a, const PathPt& b, double* split, bool* apart) const;

  Scratch& s_;
  std::span<const Vec3> poly_;
  double large_, gap_;
  double exact_above_ = large_;  // readings above it are taken exactly
  double floor_ = 0;             // a true distance known beforehand
 public:
  // Whether an arc of bound ub is done, lb being the largest reading.
  bool done(double ub, double lb) const { return ub <= lb + gap_; }
  bool indexed_ = false;
  bool planar_ = false;  // curve and polyline in the plane z = 0
  CurvePt best_c_{};     // the largest reading of each direction
  PathPt best_p_{};
  double curve_to_path_once();
  double path_to_curve_once();
};

// The largest reading is read again exactly (every segment) unless it is
// exact already (above the tolerance): when that is lower (the descent
// stopped at a part of the polyline that is not the nearest, where it
// comes back near itself), the search runs again with that true distance
// as its floor and every reading above it taken exactly: its largest
// reading is then a true distance.
double Measure::curve_to_path() {
  const double d = curve_to_path_once();
  if (!(best_c_.d > gap_) || best_c_.d > exact_above_) return d;
  size_t k = best_c_.k;
  const double e = exact_to_path(best_c_.p, k);
  if (e >= best_c_.d - gap_) return d;
  exact_above_ = floor_ = e;
  const double r = curve_to_path_once();
  exact_above_ = large_, floor_ = 0;
  return r;
}

double Measure::curve_to_path_once() {
  auto& pts = s_.cpts;
  pts.clear();
  // A coarse grid per piece, each arc within twice the tolerance of its
  // chord (polynomial pieces; 8 steps otherwise: about as many arcs as the
  // polyline has segments), read from the segment found at the point before.
  size_t hint = 0;
  const double coarse = std::max(2 * large_, 1000 * gap_);
  std::vector<size_t>& first = s_.first;
  first.clear();
  for (size_t i = 0; i < P().size(); ++i) {
    const Piece& pc = P()[i];
    size_t N = 8;
    if (pc.n >= 0) {
      const double s = pc.sag(0, 1, pc.at(0), pc.at(1));
      N = s > coarse ? static_cast<size_t>(std::min<double>(std::ceil(std::sqrt(s / coarse)), 1 << 16)) : 1;
    }
    first.push_back(pts.size());
    for (size_t j = 0; j <= N; ++j) {
      CurvePt q;
      q.t = j == N ? 1.0 : double(j) / double(N);
      q.p = pc.at(q.t);
      q.acc = pc.acc(q.t);
      read_curve(q, hint);
      hint = q.k;
      pts.push_back(q);
    }
  }
  first.push_back(pts.size());
  double lb = 0;
  best_c_ = pts.front();
  for (const CurvePt& q : pts)
    if (q.d > best_c_.d) best_c_ = q;
  lb = std::max(best_c_.d, floor_);
  // Branch and bound: an arc whose bound is within eps of the largest
  // reading is done; others are halved.
  double open = 0;  // bounds of arcs left at the depth limit
  std::vector<CurvePt>& work = s_.workc;
  std::vector<int>& depth_ = s_.depth;
  for (size_t i = 0; i < P().size(); ++i) {
    const Piece& pc = P()[i];
    for (size_t j = first[i]; j + 1 < first[i + 1]; ++j) {
      work.clear();
      work.push_back(pts[j + 1]);
      work.push_back(pts[j]);
      depth_.assign(1, 0);
      // work holds a stack of points: the top two are the current arc.
      while (work.size() >= 2) {
        const CurvePt a = work[work.size() - 1], b = work[work.size() - 2];
        const int depth = depth_.back();
        double split = 0;
        const double ub = bound(pc, a, b, &split);
        if (done(ub, lb) || depth >= kMostDepth) {
          if (!done(ub, lb)) open = std::max(open, ub);
          work.pop_back();
          depth_.pop_back();
          continue;
        }
        CurvePt m;
        m.t = split;
        m.p = pc.at(m.t);
        m.acc = pc.acc(m.t);
        read_curve(m, a.k);
        if (m.d > lb) lb = m.d, best_c_ = m;
        // [a, m] on top, then [m, b].
        work.back() = m;
        work.push_back(a);
        depth_.back() = depth + 1;
        depth_.push_back(depth + 1);
      }
    }
  }
  return std::max(lb, open);
}

// A foot of x on the curve from (i, t): Newton steps on (C - x) . C' = 0,
// passing to the next or previous piece at an end when the distance still
// falls that way, along this piece or along the neighbour (at a corner the
// distance may rise along this piece's end and fall along the next one's
// start). Never back to the piece just left. Keeps the nearest curve point
// met: whatever the steps do, the reading is the distance to a point of
// the curve.
void Measure::foot(PathPt& q, size_t i, double t) {
  Vec3 p, d1, d2;
  double best = HUGE_VAL;
  size_t from = std::numeric_limits<size_t>::max();  // the piece just left
  // At an end shared with a neighbour where the distance falls along it:
  // over to it.
  auto cross = [&]() {
    if (t == 1 && i + 1 < P().size() && i + 1 != from) {
      P()[i + 1].derivatives(0, p, d1, d2);
      if (dot(p - q.x, d1) < 0) return from = i, ++i, t = 0, true;
    } else if (t == 0 && i > 0 && i - 1 != from) {
      P()[i - 1].derivatives(1, p, d1, d2);
      if (dot(p - q.x, d1) > 0) return from = i, --i, t = 1, true;
    }
    return false;
  };
  for (int it = 0; it < 16; ++it) {
    const Piece& pc = P()[i];
    pc.derivatives(t, p, d1, d2);
    const Vec3 r = p - q.x;
    const double r2 = dot(r, r);
    if (r2 < best) best = r2, q.i = i, q.t = t, q.f = p;
    const double g = dot(r, d1), v2 = dot(d1, d1);
    double gp = v2 + dot(r, d2);
    if (!(gp > 0)) gp = v2;
    if (!(gp > 0) || g == 0) {
      if (cross()) continue;
      break;
    }
    // The step would bring the distance down by about g^2 / (2 gp d): done
    // when that is below 1e-4 of the resolution; when below a tenth of it,
    // the step is the last (the step after would gain about its square).
    // (Compared squared: gain^2 = g^4 / (4 gp^2 r2).)
    const double g2 = g * g, lhs = g2 * g2, rhs = 4 * gp * gp * r2;
    if (!(lhs >= 0.01 * gap_ * gap_ * rhs)) {
      if (cross()) continue;
      break;
    }
    const bool last = lhs < 1e4 * gap_ * gap_ * rhs;
    double tn = t - g / gp;
    if (tn > 1) {
      if (t == 1 && i + 1 < P().size() && i + 1 != from) {
        from = i, ++i, t = 0;
        continue;
      }
      tn = 1;
    } else if (tn < 0) {
      if (t == 0 && i > 0 && i - 1 != from) {
        from = i, --i, t = 1;
        continue;
      }
      tn = 0;
    }
    if (tn == t) {
      if (cross()) continue;
      break;
    }
    const bool small = last || std::abs(tn - t) < 1e-12;
    t = tn;
    if (small) {
      const Vec3 pn = pc.at(t);
      const double rn = dot(pn - q.x, pn - q.x);
      if (rn < best) best = rn, q.i = i, q.t = t, q.f = pn;
      if (cross()) continue;
      break;
    }
  }
  q.d = std::sqrt(best);
}

// The exact distance from x to the curve: branch and bound over the arcs
// of every piece (an arc is no nearer than its chord's distance less its
// sag), arcs that could be nearer halved, the nearest point met polished by
// Newton steps. *piece and *t receive its foot.
// Whether the arc a of a power-form piece is certainly no nearer to x
// than `floor`, when |C(t) - x|^2 is convex over it: its second derivative
// 2 (|C'|^2 + (C - x) . C'') is positive where |C'| >= |C'(tm)| - h/2 max
// |C''| exceeds sqrt(max |C - x| max |C''|). Then Newton steps kept in the
// arc find its nearest point (noted in best, bi, bt when nearer), and the
// tangent there bounds the rest: r^2 >= r^2(t) - |(r^2)'(t)| h.
bool convex_min_at_least(const Piece& pc, const SearchArc& a, const Vec3& x, double floor, double& best, size_t& bi,
                         double& bt) {
  const double h = a.t1 - a.t0, tm = 0.5 * (a.t0 + a.t1);
  const double A = std::max(pc.acc(a.t0), pc.acc(a.t1));
  const double s = h * h * 0.125 * A;
  Vec3 p, d1, d2;
  pc.derivatives(tm, p, d1, d2);
  const double speed = norm(d1) - 0.5 * h * A;
  const double far = std::max(dist(x, a.p0), dist(x, a.p1)) + s;
  if (!(speed > 0 && speed * speed > far * A)) return false;
  double t = tm, r2 = 0, g = 0;
  for (int it = 0; it < 30; ++it) {
    pc.derivatives(t, p, d1, d2);
    const Vec3 r = p - x;
    r2 = dot(r, r), g = dot(r, d1);
    const double gp = dot(d1, d1) + dot(r, d2);
    const double tn = std::clamp(t - g / gp, a.t0, a.t1);
    if (tn == t) break;
    t = tn;
  }
  pc.derivatives(t, p, d1, d2);
  r2 = dot(p - x, p - x), g = dot(p - x, d1);
  if (std::sqrt(r2) < best) best = std::sqrt(r2), bi = a.i, bt = t;
  // Past an end where the slope pushes outwards, the bound holds on the arc.
  const double lb2 = r2 - 2 * std::abs(g) * std::max(t - a.t0, a.t1 - t);
  return floor <= 0 || (lb2 > 0 && lb2 >= floor * floor);
}

double Measure::exact_to_curve(const Vec3& x, size_t& piece, double& t) {
  PathPt q;
  q.x = x;
  foot(q, piece, t);
  double best = q.d;
  size_t bi = q.i;
  double bt = q.t;
  auto& stack = s_.arcs;
  stack.clear();
  for (size_t i = 0; i < P().size(); ++i) stack.push_back({i, 0, 1, P()[i].at(0), P()[i].at(1), 0});
  const double tiny = gap_;
  while (!stack.empty()) {
    const SearchArc a = stack.back();
    stack.pop_back();
    const Piece& pc = P()[a.i];
    const double sag = pc.sag(a.t0, a.t1, a.p0, a.p1);
    if (dist_to_segment(x, a.p0, a.p1) - sag >= best - tiny || a.depth >= kMostDepth) continue;
    const double tm = 0.5 * (a.t0 + a.t1);
    const Vec3 pm = pc.at(tm);
    const double d = dist(x, pm);
    if (d < best) {
      q.x = x;
      foot(q, a.i, tm);
      if (q.d < d)
        best = q.d, bi = q.i, bt = q.t;
      else
        best = d, bi = a.i, bt = tm;
    }
    // An arc this close to its chord is within 2 tiny of what it can give,
    // once read near the chord's point nearest to x (the midpoint need not
    // be: on a straight piece it may be no nearer than the best so far
    // while the foot lies elsewhere on it).
    if (sag <= tiny) {
      const Vec3 ch = a.p1 - a.p0;
      const double len2 = dot(ch, ch);
      const double l = len2 > 0 ? std::clamp(dot(x - a.p0, ch) / len2, 0.0, 1.0) : 0.5;
      q.x = x;
      foot(q, a.i, a.t0 + l * (a.t1 - a.t0));
      if (q.d < best) best = q.d, bi = q.i, bt = q.t;
      continue;
    }
    if (pc.n >= 2 && convex_min_at_least(pc, a, x, best - tiny, best, bi, bt)) continue;
    stack.push_back({a.i, a.t0, tm, a.p0, pm, a.depth + 1});
    stack.push_back({a.i, tm, a.t1, pm, a.p1, a.depth + 1});
  }
  piece = bi, t = bt;
  return best;
}

// Upper bound of the distance to the curve over the polyline between a
// and b: the distance to the curve is at most that to a chord of it plus
// the chord's sag, and the distance to a chord is convex along the
// segment. The chord joins the two feet (one per piece when they lie in
// neighbouring pieces); the distance moving no faster than the point gives
// the other bound.
double Measure::bound(const PathPt& a, const PathPt& b, double* split, bool* apart) const {
  *split = 0.5;
  *apart = false;
  // The bound from the distance moving no faster than the point (lip
  // below) is the one that shrinks with the stretch where the feet jump
  // (two parts of the curve equally near).
  if (a.i == b.i && P()[a.i].n >= 0) {
    // With a power form: x at fraction l of [a, b] against C at fraction l
    // of [a.t, b.t]: their difference is the interpolation of a's and b's
    // plus at most the bump 4 s l (1 - l).
    const Piece& pc = P()[a.i];
    double l = 0.5;
    const double ub =
        max_line_bump(a.d, b.d, pc.sag(std::min(a.t, b.t), std::max(a.t, b.t), a.acc, b.acc, a.f, b.f), 0, 1, &l);
    // Split where it is largest, kept off the ends.
    *split = std::clamp(l, 0.1, 0.9);
    if (ub <= std::max(a.d, b.d) + gap_) return ub;
    // Without the parameter: the arc between the feet lies within its
    // control polygon's distance s of its own chord [a.f, b.f] and, joining
    // its ends, passes within s of every point of it; the distance to that
    // chord is convex along the segment. So the stretch is within the ends'
    // distances to the chord, plus s, of the curve. This is what settles a
    // stretch near a fold of the curve (where it turns back along itself,
    // the foot of a point moves like the square root of its distance, and
    // the parametric bump halves only as the stretch does).
    const PathPt& lo = a.t <= b.t ? a : b;
    const PathPt& hi = a.t <= b.t ? b : a;
    const double h = (hi.t - lo.t) / 3;
    const Vec3 q1 = lo.f + pc.tangent(lo.t) * h, q2 = hi.f - pc.tangent(hi.t) * h;
    const double geo = std::max(dist_to_segment(a.x, lo.f, hi.f), dist_to_segment(b.x, lo.f, hi.f)) +
                       std::max(dist_to_segment(q1, lo.f, hi.f), dist_to_segment(q2, lo.f, hi.f));
    const double lip = 0.5 * (a.d + b.d + dist(a.x, b.x));
    // (neither bound from the curve between the feet helps: they lie on
    // parts of it that are apart, both near the segment)
    *apart = lip < std::min(ub, geo);
    return std::min({ub, geo, lip});
  }
  double ub = 0.5 * (a.d + b.d + dist(a.x, b.x));
  if (a.i == b.i) {
    const Piece& pc = P()[a.i];
    const bool fwd = a.t <= b.t;
    const PathPt& lo = fwd ? a : b;
    const PathPt& hi = fwd ? b : a;
    const double s = pc.sag(lo.t, hi.t, lo.f, hi.f);
    ub = std::min(ub, std::max(dist_to_segment(a.x, a.f, b.f), dist_to_segment(b.x, a.f, b.f)) + s);
  } else if (a.i + 1 == b.i || b.i + 1 == a.i) {
    // a's piece from a's foot to its end nearest b's piece, and b's the same way.
    const bool fwd = a.i < b.i;
    const Piece& pa = P()[a.i];
    const Piece& pb = P()[b.i];
    const double ea = fwd ? 1.0 : 0.0, eb = fwd ? 0.0 : 1.0;
    const Vec3 qa = pa.at(ea), qb = pb.at(eb);
    const double sa = fwd ? pa.sag(a.t, 1, a.f, qa) : pa.sag(0, a.t, qa, a.f);
    const double sb = fwd ? pb.sag(0, b.t, qb, b.f) : pb.sag(b.t, 1, b.f, qb);
    ub = std::min(ub, max_of_min(dist_to_segment(a.x, a.f, qa) + sa, dist_to_segment(b.x, a.f, qa) + sa,
                                 dist_to_segment(a.x, qb, b.f) + sb, dist_to_segment(b.x, qb, b.f) + sb));
  }
  return ub;
}

// The largest reading is read again exactly (over every piece) unless it
// is exact already: when that is lower (a foot that is not the nearest
// point), the search runs again as curve_to_path()'s does.
double Measure::path_to_curve() {
  const double d = path_to_curve_once();
  if (!(best_p_.d > gap_) || best_p_.d > exact_above_) return d;
  size_t i = best_p_.i;
  double t = best_p_.t;
  const double e = exact_to_curve(best_p_.x, i, t);
  if (e >= best_p_.d - gap_) return d;
  exact_above_ = floor_ = e;
  const double r = path_to_curve_once();
  exact_above_ = large_, floor_ = 0;
  return r;
}

double Measure::path_to_curve_once() {
  auto& pts = s_.ppts;
  pts.clear();
  // Two readings per segment and the end, the foot followed from the
  // vertex before; the first one's from the curve's start (by the exact
  // search unless it is there).
  constexpr int kCoarse = 2;
  size_t fi = 0;
  double ft = 0;
  {
    PathPt q;
    q.s = 0, q.x = poly_[0];
    foot(q, 0, 0);
    fi = q.i, ft = q.t;
    if (q.d > gap_) exact_to_curve(q.x, fi, ft);
  }
  const size_t nseg = poly_.size() > 1 ? poly_.size() - 1 : 0;
  for (size_t k = 0; k <= nseg; ++k) {
    const int steps = k < nseg ? kCoarse : 1;
    for (int j = 0; j < steps; ++j) {
      PathPt q;
      q.s = double(k) + double(j) / steps;
      q.x = k < nseg ? lerp(poly_[k], poly_[k + 1], double(j) / steps) : poly_[k];
      read_path(q, fi, ft);
      fi = q.i, ft = q.t;
      pts.push_back(q);
    }
  }
  double lb = 0;
  best_p_ = pts.front();
  for (const PathPt& q : pts)
    if (q.d > best_p_.d) best_p_ = q;
  lb = std::max(best_p_.d, floor_);
  double open = 0;
  auto& work = s_.workp;
  auto& depth = s_.depth;
  for (size_t j = 0; j + 1 < pts.size(); ++j) {
    work.clear();
    work.push_back(pts[j + 1]);
    work.push_back(pts[j]);
    depth.assign(1, 0);
    const size_t k = static_cast<size_t>(pts[j].s);
    while (work.size() >= 2) {
      const PathPt a = work[work.size() - 1], b = work[work.size() - 2];
      const int dep = depth.back();
      double split = 0.5;
      bool apart = false;
      const double ub = bound(a, b, &split, &apart);
      if (done(ub, lb) || dep >= kMostDepth) {
        if (!done(ub, lb)) open = std::max(open, ub);
        work.pop_back();
        depth.pop_back();
        continue;
      }
      PathPt m;
      m.s = a.s + split * (b.s - a.s);
      m.x = lerp(poly_[k], poly_[k + 1], m.s - double(k));
      // Start from the foot interpolated between the ends' when they share
      // a piece, unless they lie on parts of it that are apart (where the
      // curve turns back along itself, several parts may be near the
      // segment): then from a's, so that the feet change parts at one
      // place of the stretch, not at many.
      read_path(m, a.i, a.i == b.i && !apart ? a.t + split * (b.t - a.t) : a.t);
      if (m.d > lb) lb = m.d, best_p_ = m;
      work.back() = m;
      work.push_back(a);
      depth.back() = dep + 1;
      depth.push_back(dep + 1);
    }
  }
  return std::max(lb, open);
}

}  // namespace

Deviation measure_deviation(std::span<const Bezier> pieces, std::span<const Vec3> polyline, double tolerance) {
  Deviation dev;
  if (pieces.empty() || polyline.empty()) return dev;
  thread_local Scratch scratch;
  struct Trim {
    Scratch& s;
    ~Trim() { s.trim(); }
  } trim{scratch};
  Measure m(scratch, pieces, polyline, tolerance);
  dev.curve_to_path = m.curve_to_path();
  dev.path_to_curve = m.path_to_curve();
  return dev;
}

}  // namespace bezcam
