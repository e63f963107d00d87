#include "bezcam/flatten/arc_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "flatten/search.hpp"

// Why the bound holds (the notation of arc_fit.hpp).
//
// Let C be the true span from S = C(t0) to E = C(t1), and D the drawn path:
// centre c', start S', end E', sweep W <= pi - 0.02 in the arc's direction,
// D(theta) at radius rho(theta) moving linearly from r_s = |S'-c'| to
// r_e = |E'-c'|. Write rmin, rmax for min/max(r_s, r_e), and for a point p
//   d(p) = max(|p-c'| - rmin, rmax - |p-c'|)   if p lies in the sector of D
//   d(p) = min(|p-S'|, |p-E'|)                  otherwise.
// Both are upper bounds of dist(p, D): in the sector, D has a point at the
// angle of p at a radius in [rmin, rmax]; outside, S' and E' are points of D.
// Let U = sup over the span of d(C(t)). Then:
//  (a) every curve point is within U of D (by the definition of d);
//  (b) every point of D is within
//        B = max(U, |S-S'|, |E-E'|) + |r_e - r_s| * max(sS, sE)
//      of the curve, where sS, sE are the fractions of the sweep between
//      S' and the angle of S (resp. the angle of E and E') when those lie
//      inside the sweep. Proof: the curve stays within U < rmin/2 of D, a
//      region of angular extent below 2 pi that avoids c' (W < pi, and the
//      end discs of radius rmin/2 subtend 30 degrees each), so the angle of
//      C(t) around c' is a continuous single-valued function running from
//      the angle of S to that of E. By the intermediate value theorem every
//      angle of D between them is taken by a curve point p in the sector,
//      and |p - D(angle)| = ||p-c'| - rho| <= d(p) <= U. The angles of D
//      before the angle of S (a sliver next to S') are within
//      max(|S'-S|, ||S-c'| - r_s|) + |rho - r_s| of S: on a circle of
//      radius r_s the distance to S grows with the angle from S, and
//      ||S-c'| - r_s| <= max(U, |S-S'|) (triangle inequality when S is
//      outside the sector). The same holds at the end.
// U itself is bounded by branch and bound on the convex hulls of
// sub-curves (every piece, rational or not, lies in the hull of its
// control points): |p-c'| <= max |Q_i - c'| and |p-c'| >= min (Q_i-c').u
// for a unit u; when all Q_i are in the sector (a convex cone, W < pi) the
// hull is too and only the radial term applies, otherwise the end-distance
// term max |Q_i - S'| (or E') is added. Splitting tightens both terms
// quadratically (radial) or linearly (near the ends), and the curve's own
// points give the lower bound that ends the search.
// Finally the drawn path lies at the printed z' while a planar piece lies at
// z: the 3D distance is hypot(B, |z - z'|).
//
// The band (ArcFitOptions::band). On a piece that gets no arcs (its z
// varies, or its rounded z leaves no budget in the plane) the lines' inner
// ends are shifted off the curve towards its convex side by kBandShare of
// what rounding leaves, as the flattener's band vertices are, and each line
// is proven by band_deviation() (flatten_curve.hpp) between its printed
// ends: a parametric distance, which bounds both directions, rounding
// included since the ends are the printed points. The piece's ends stay on
// the curve (the last line ends at t = 1, where no shift is made), so the
// planar pieces around it and their arcs are as without the band.
// Arc ends stay on the curve, for a measured reason. The proof above would
// take an off-curve start S' as it is (nothing in (a), the angular argument
// or the sliver bound needs S' near S beyond the |S-S'| that B counts), but
// the arcs would not get longer: a circle's three parameters absorb a
// span's curvature up to its linear change, so the error along a span of
// length L grows like p(s) = a + (b - a) s / L + k s (s - L) (s - m), a and
// b the offsets at its ends. With a = b shared by consecutive spans, the
// best is a = 0 (on the curve); the minimax arc with a free end (errors of
// opposite signs at its ends, longer alone) leaves the next span starting
// at the wrong sign, and takes more blocks in all (bench/output_modes_bench
// --corpus). So do band lines between the arcs of planar pieces: an arc
// after a shifted line starts off the curve, where it is shorter.
//
// Helical arcs (ArcFitOptions::helical; G17 in the plane's coordinates,
// the axis h of D running linearly with the angle from h_s = S'.h to
// h_e = E'.h). Distances are 3D. In the sector, D has the point D(angle of
// p), whose in-plane distance to p is ||p-c'| - rho| and axial distance
// |p.h - h(angle)|, so
//   d(p) = hypot(max(|p-c'| - rmin, rmax - |p-c'|), |p.h - h(angle of p)|),
// and outside it d(p) = min(|p-S'|, |p-E'|) in 3D; both bound dist(p, D).
// (b) carries over: d bounds the in-plane distance too, so the curve's
// angle is continuous as before and every angle of D between those of S
// and E is taken by a curve point within U. Near S', a point D(angle) of
// the sliver is within |rho - r_s| + |h - h_s| <= (|r_e - r_s| + |h_e -
// h_s|) sS of the point Q at that angle on the circle of radius r_s at
// height h_s, and Q is no farther from S than S' is (same height, smaller
// angle to S): B = max(U, |S-S'|, |E-E'|) + (|r_e - r_s| + |h_e - h_s|)
// max(sS, sE). Over a hull that keeps away from the centre (Rmin > 0:
// it lies in a half-plane beyond c'), the angles of its points lie between
// the least and greatest angle of its control points (the cone they span
// is convex), so for its points in the sector h(angle) lies between its
// values at those angles clamped to the sweep, while p.h lies between the
// control points' least and greatest h: the axial term is bounded by the
// larger gap. That bound shrinks only linearly with the node; when every
// control point lies in the sector, the second-order bound of
// axial_taylor() (its Hessian is k times the angle's, of norm 1/r^2) is
// used where smaller. The end-distance term is taken in 3D.

namespace bezcam {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Largest sweep of an emitted arc: the sector must stay a convex cone.
constexpr double kMaxSweep = kPi - 0.02;
// Largest radius per unit of chord (sweep >= 0.001 rad): flatter spans are
// lines, and huge I/J words help no controller.
constexpr double kMaxRadiusPerChord = 1000;
// The same for a tangent chain's arcs: a flatter arc keeps the chain
// tangent where a line (its chord) would turn by up to 1 / (2 x this).
constexpr double kMaxTangentRadiusPerChord = 100000;
// A chain starts again where a free arc would be this many times longer.
constexpr double kChainRestart = 4;
// The largest turn a line inside a tangent chain may take (rad): what
// LinuxCNC 2.9 takes as tangent between arcs at F6000 on 1000 mm/s^2 and a
// 1 ms period (docs/motion.md).
constexpr double kMaxLineTurn = 5e-4;
// An arc of a chain ends along the curve within this many times the budget
// over its chord (ends_along_curve()).
constexpr double kChainAlign = 2.5;
// Curve samples used to choose the centre (the proof does not rely on them).
constexpr int kFitSamples = 16;
// The band: a line's inner end is shifted off the curve by this share of
// what the tolerance leaves after rounding (the flattener's share).
constexpr double kBandShare = 0.96;

double cross2(const Vec3& a, const Vec3& b) { return a.x * b.y - a.y * b.x; }
double dot2(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y; }
double norm2(const Vec3& v) { return std::hypot(v.x, v.y); }

// Angle from direction a to v, positive in the arc's direction, in (-pi, pi].
double directed_angle(const Vec3& a, const Vec3& v, bool ccw) {
  const double ang = std::atan2(cross2(a, v), dot2(a, v));
  return ccw ? ang : -ang;
}

Vec3 point_at(const Bezier& b, double t) {
  if (t <= 0) return b.front();
  if (t >= 1) return b.back();
  return evaluate(b, t);
}

// The sector test and the point distance d(p) of the proof.
struct ArcGeometry {
  const PrintedArc& arc;
  Vec3 a, b;  // S' - c', E' - c'
  double rmin, rmax;
  bool helical;
  double W = 0;  // helical: the sweep
  ArcGeometry(const PrintedArc& pa, bool hel) : arc(pa), a(pa.from - pa.center), b(pa.to - pa.center), helical(hel) {
    rmin = std::min(norm2(a), norm2(b));
    rmax = std::max(norm2(a), norm2(b));
    if (helical) W = pa.sweep();
  }
  bool in_sector(const Vec3& v) const {
    const double c1 = cross2(a, v), c2 = cross2(v, b);
    return arc.ccw ? (c1 >= 0 && c2 >= 0) : (c1 <= 0 && c2 <= 0);
  }
  double dist_end(const Vec3& p, const Vec3& e) const { return helical ? dist(p, e) : dist_xy(p, e); }
  // Helical: the height of D at the angle of v (in the sector), from S'.
  double h_at(const Vec3& v) const {
    const double th = std::clamp(directed_angle(a, v, arc.ccw), 0.0, W);
    return arc.from.z + (arc.to.z - arc.from.z) * (th / W);
  }
  double d(const Vec3& p) const {
    const Vec3 v = p - arc.center;
    if (in_sector(v)) {
      const double r = norm2(v);
      const double radial = std::max(r - rmin, rmax - r);
      return helical ? std::hypot(radial, p.z - h_at(v)) : radial;
    }
    return std::min(dist_end(p, arc.from), dist_end(p, arc.to));
  }
  // Helical: bound of |p.h - h(angle of p)| over the hull (see the top).
  double axial_bound(const Bezier& node, bool all_in, double Rmin) const {
    double zlo = kInf, zhi = -kInf, hlo = std::min(arc.from.z, arc.to.z), hhi = std::max(arc.from.z, arc.to.z);
    double thlo = kInf, thhi = -kInf;
    for (const auto& q : node.points) {
      zlo = std::min(zlo, q.z);
      zhi = std::max(zhi, q.z);
      const double th = directed_angle(a, q - arc.center, arc.ccw);
      thlo = std::min(thlo, th);
      thhi = std::max(thhi, th);
    }
    // Rmin > 0: the hull lies in a half-plane away from the centre, inside
    // the cone of its extreme control points (angles within pi of each
    // other, no wrap-around), so its points in the sector have angles in
    // [thlo, thhi] clamped to the sweep.
    if (Rmin > 0 && thhi - thlo < kPi) {
      const double t0 = std::clamp(thlo, 0.0, W), t1 = std::clamp(thhi, 0.0, W);
      const double h0 = arc.from.z + (arc.to.z - arc.from.z) * (t0 / W);
      const double h1 = arc.from.z + (arc.to.z - arc.from.z) * (t1 / W);
      hlo = std::min(h0, h1);
      hhi = std::max(h0, h1);
    }
    double bound = std::max({zhi - hlo, hhi - zlo, 0.0});
    if (all_in && Rmin > 0) bound = std::min(bound, axial_taylor(node, Rmin));
    return bound;
  }
  // Helical, all control points in the sector, the hull at least Rmin from
  // the centre: phi(p) = p.h - h(angle of p) is smooth on the hull, its
  // Hessian is k times the angle's, of norm 1/r^2 (k = (h_e - h_s) / W), so
  // around the node's first point q (a curve point)
  //   |phi(p)| <= |phi(q) + grad phi(q).(p - q)| + |k| |p - q|^2 / (2 Rmin^2)
  // with |p - q| in the plane; the linear part is largest at a control point.
  double axial_taylor(const Bezier& node, double Rmin) const {
    const double k = (arc.to.z - arc.from.z) / W;
    const Vec3 q = node.points.front(), v = q - arc.center;
    const double r2 = v.x * v.x + v.y * v.y;
    if (!(r2 > 0)) return kInf;
    const double sgn = arc.ccw ? 1 : -1;  // the angle grows in the arc's direction
    const double phi = q.z - h_at(v);
    // grad angle = sgn (-v.y, v.x) / r^2; grad phi = e_h - k grad angle.
    const double gx = k * sgn * v.y / r2, gy = -k * sgn * v.x / r2;
    double lin = 0, far2 = 0;
    for (const auto& p : node.points) {
      const Vec3 d = p - q;
      lin = std::max(lin, std::abs(phi + d.z + gx * d.x + gy * d.y));
      far2 = std::max(far2, d.x * d.x + d.y * d.y);
    }
    return lin + std::abs(k) * far2 / (2 * Rmin * Rmin);
  }
  // Upper bound of d over the convex hull of the node's control points.
  double hull_bound(const Bezier& node) const {
    double Rmax = 0, toS = 0, toE = 0;
    Vec3 sum;
    bool all_in = true;
    for (const auto& q : node.points) {
      const Vec3 v = q - arc.center;
      Rmax = std::max(Rmax, norm2(v));
      sum += v;
      all_in = all_in && in_sector(v);
      toS = std::max(toS, dist_end(q, arc.from));
      toE = std::max(toE, dist_end(q, arc.to));
    }
    double Rmin = 0;
    const double ls = norm2(sum);
    if (ls > 0) {
      const Vec3 u = sum / ls;
      Rmin = kInf;
      for (const auto& q : node.points) Rmin = std::min(Rmin, dot2(q - arc.center, u));
      Rmin = std::max(Rmin, 0.0);
    }
    double radial = std::max(Rmax - rmin, rmax - Rmin);
    if (helical) radial = std::hypot(radial, axial_bound(node, all_in, Rmin));
    return all_in ? radial : std::max(radial, std::min(toS, toE));
  }
};

// sup over the sub-curve of d(C(t)), by branch and bound (see the top).
// Early exits when budget >= 0: a result <= budget is a proven upper bound;
// a result above it is at least a proven lower bound of the same supremum.
// Otherwise the upper bound is refined to `resolution` (or 0.1 %).
double sup_d(const ArcGeometry& g, const Bezier& sub, double budget, double resolution) {
  const double lb = std::max(g.d(sub.front()), g.d(sub.back()));
  return flatten_detail::sup_branch_and_bound(
      sub, lb, {budget, 1e-3, resolution, 4000}, [&](const Bezier& b) { return g.hull_bound(b); },
      [&](const Bezier& b, Bezier& l, Bezier& r) {
        std::tie(l, r) = split(b, 0.5);
        return g.d(l.back());
      });
}

// A candidate arc for the span, and its certified XY bound.
struct ArcCandidate {
  PrintedArc arc;
  Vec3 ij;
  double bound_xy = kInf;
};

struct Span {
  const Bezier& b;
  double t0, t1;
  Vec3 S, E;    // true ends
  Vec3 Sr, Er;  // printed ends
};

// The unit vector at t towards the curve's convex side: minus the part of
// M'' across the tangent, normalised; zero where the tangent vanishes or
// the curve hardly bends (that part below 1e-12 of |M''|).
Vec3 convex_side(const Bezier& b, double t) {
  const Vec3 d1 = derivative(b, t), d2 = second_derivative(b, t);
  const double s2 = dot(d1, d1);
  if (!(s2 > 0)) return {};
  const Vec3 across = d2 - d1 * (dot(d1, d2) / s2);
  const double l = norm(across);
  if (!(l > 1e-12 * norm(d2)) || !std::isfinite(l)) return {};
  return across * (-1 / l);
}

// Fits one arc to the span: centre on the perpendicular bisector of S E,
// bulge chosen minimax over samples (golden section from the three-point
// circle), then the printed centre among the grid points around it, then
// certification. Returns nothing when no arc fits `budget_xy`.
double span_deviation(const Bezier& piece, double t0, double t1, const PrintedArc& arc, double budget,
                      double resolution, bool helical);

// The printed arcs from S' to E' round the grid points next to the centre
// c (the rounded centre alone when nothing is rounded) that keep their
// radius within `rtol`, their sweep within the limit and `keep`, tried
// best estimate (over the samples P and the ends) first: the first of at
// most three whose certified deviation is within `budget_xy`.
template <class Keep>
std::optional<ArcCandidate> certify_near(const Span& sp, const Vec3& c, bool ccw,
                                         const std::array<Vec3, kFitSamples - 1>& P, double q, int decimals,
                                         double rtol, bool helical, double budget_xy, Keep&& keep) {
  struct Option {
    PrintedArc arc;
    Vec3 ij;
    double estimate;
  };
  std::vector<Option> opts;
  const Vec3 ij0{quantize(c.x - sp.Sr.x, decimals), quantize(c.y - sp.Sr.y, decimals), 0};
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj) {
      if (q == 0 && (di || dj)) continue;
      const Vec3 ij{quantize(ij0.x + di * q, decimals), quantize(ij0.y + dj * q, decimals), 0};
      PrintedArc a;
      a.from = sp.Sr;
      a.to = sp.Er;
      a.center = {sp.Sr.x + ij.x, sp.Sr.y + ij.y, sp.Sr.z};
      a.ccw = ccw;
      if (std::abs(a.r_start() - a.r_end()) > rtol || a.sweep() > kMaxSweep || !keep(a)) continue;
      const ArcGeometry g(a, helical);
      double est = std::max(g.dist_end(sp.S, sp.Sr), g.dist_end(sp.E, sp.Er));
      for (const auto& p : P) est = std::max(est, g.d(p));
      opts.push_back({a, ij, est});
    }
  std::sort(opts.begin(), opts.end(), [](const Option& x, const Option& y) { return x.estimate < y.estimate; });
  for (size_t i = 0; i < opts.size() && i < 3; ++i) {
    if (opts[i].estimate > budget_xy) break;
    const double B = span_deviation(sp.b, sp.t0, sp.t1, opts[i].arc, budget_xy, 0, helical);
    if (B <= budget_xy) return ArcCandidate{opts[i].arc, opts[i].ij, B};
  }
  return std::nullopt;
}

std::optional<ArcCandidate> try_arc(const Span& sp, const ArcFitOptions& opt, double budget_xy, double rtol) {
  const Vec3 chord{sp.E.x - sp.S.x, sp.E.y - sp.S.y, 0};
  const double L = norm2(chord);
  const double q = opt.decimals >= 0 ? std::pow(10.0, -opt.decimals) : 0.0;
  // Printed ends that coincide would mean a full circle.
  if (!(L > 0) || dist_xy(sp.Er, sp.Sr) < std::max(1.5 * q, 1e-12 * L)) return std::nullopt;
  const Vec3 u = chord / L, n{-u.y, u.x, 0};
  const Vec3 M = (sp.S + sp.E) * 0.5;
  std::array<Vec3, kFitSamples - 1> P;
  for (int j = 1; j < kFitSamples; ++j) P[j - 1] = point_at(sp.b, sp.t0 + (sp.t1 - sp.t0) * j / kFitSamples);
  // Three-point circle through S, the middle sample and E: its bulge.
  const Vec3 pm = P[kFitSamples / 2 - 1] - M;
  const double xm = dot2(pm, u), ym = dot2(pm, n);
  if (std::abs(ym) <= 1e-9 * L) return std::nullopt;
  const double k3 = (xm * xm + ym * ym - L * L / 4) / (2 * ym);
  const double r3 = std::sqrt(L * L / 4 + k3 * k3);
  const double b3 = ym > 0 ? k3 + r3 : k3 - r3;
  // Bulge b: arc midpoint M + n b; centre M + n k, k = (b^2 - L^2/4) / 2b.
  const double bmax = L / 2 * std::tan(kMaxSweep / 4);
  const double bmin = L / (8 * kMaxRadiusPerChord);
  auto centre_of = [&](double bb) { return M + n * ((bb * bb - L * L / 4) / (2 * bb)); };
  auto misfit = [&](double bb) {
    const Vec3 c = centre_of(bb);
    const double r = dist_xy(sp.S, c);
    double m = 0;
    for (const auto& p : P) m = std::max(m, std::abs(dist_xy(p, c) - r));
    return m;
  };
  const double sgn = b3 > 0 ? 1 : -1;
  double lo = std::clamp(0.6 * std::abs(b3), bmin, bmax), hi = std::clamp(1.4 * std::abs(b3), bmin, bmax);
  if (!(hi > lo)) return std::nullopt;
  {
    const auto g = flatten_detail::golden_section(
        lo, hi, [&](double x) { return misfit(sgn * x); }, 40, 1e-12 * L);
    lo = g.a;
    hi = g.b;
  }
  const double bb = sgn * 0.5 * (lo + hi);
  if (misfit(bb) > budget_xy) return std::nullopt;  // hopeless even before rounding
  const Vec3 c = centre_of(bb);
  const bool ccw = bb < 0;  // bulge to the left of S->E means clockwise travel

  // Printed centres: the rounded one and its grid neighbours, best first.
  return certify_near(sp, c, ccw, P, q, opt.decimals, rtol, opt.helical, budget_xy,
                      [](const PrintedArc&) { return true; });
}

// An arc found for a span ending at t1 (curve point E).
struct Found {
  std::optional<ArcCandidate> arc;
  double t1 = 0;
  Vec3 E;
};

}  // namespace

bool tangent_joint(const Bezier& a, const Bezier& b) {
  const Vec3 u = derivative(a, 1), v = derivative(b, 0);
  const double nu = norm2(u), nv = norm2(v);
  if (!(nu > 0) || !(nv > 0)) return false;
  return std::abs(cross2(u, v)) <= 1e-9 * nu * nv && dot2(u, v) > 0;
}

Vec3 move_tangent(const Vec3& from, const FitMove& m, bool at_start) {
  if (m.kind == FitKind::line) {
    const Vec3 d{m.to.x - from.x, m.to.y - from.y, 0};
    const double l = norm2(d);
    return l > 0 ? d / l : Vec3{};
  }
  const Vec3 r = (at_start ? from : m.to) - m.center;
  const double l = norm2(r);
  if (!(l > 0)) return {};
  return m.kind == FitKind::arc_ccw ? Vec3{-r.y / l, r.x / l, 0} : Vec3{r.y / l, -r.x / l, 0};
}

namespace {

// How far (radians) a printed start tangent may turn from the chain's for
// an arc of radius r (or a line of length r) whose words are rounded to
// q: the rounding of its centre (or end) moves the direction by up to
// about q / r.
double tangent_slack(double q, double r) { return r > 0 ? q / r + 1e-9 : 0.0; }

// How far a line of length L in a chain may turn from the chain's
// direction: its printed ends' rounding (q / L), but never more than
// kMaxLineTurn. A short line's rounding would pass nearly any turn, where
// a tangent arc over the same span, its slack the rounding over its
// radius, stays tangent.
double line_slack(double q, double L) { return L > 0 ? std::min(q / L, kMaxLineTurn) + 1e-9 : 0.0; }

// Tangent-continuous chains (ArcFitOptions::tangent): the arc from the
// printed start S' that leaves it in direction `tin` and ends at the
// printed E' (its centre on the normal to `tin` at S', equidistant from
// S' and E'), then the printed centre among the grid points around it
// whose start tangent stays within the rounding's slack, then
// certification as for any arc.
std::optional<ArcCandidate> try_tangent_arc(const Span& sp, const ArcFitOptions& opt, double budget_xy, double rtol,
                                            const Vec3& tin) {
  const double q = opt.decimals >= 0 ? std::pow(10.0, -opt.decimals) : 0.0;
  const Vec3 d{sp.Er.x - sp.Sr.x, sp.Er.y - sp.Sr.y, 0};
  const double L = norm2(d);
  if (!(L > 0) || L < std::max(1.5 * q, 1e-12)) return std::nullopt;
  const Vec3 n{-tin.y, tin.x, 0};
  const double dn = dot2(d, n);
  if (std::abs(dn) <= 1e-12 * L) return std::nullopt;  // straight on: a line's
  const double k = L * L / (2 * dn);                   // signed radius: > 0 to the left
  if (std::abs(k) > kMaxTangentRadiusPerChord * L) return std::nullopt;
  const Vec3 c = sp.Sr + n * k;
  const bool ccw = k > 0;
  std::array<Vec3, kFitSamples - 1> P;
  for (int j = 1; j < kFitSamples; ++j) P[j - 1] = point_at(sp.b, sp.t0 + (sp.t1 - sp.t0) * j / kFitSamples);
  // Printed centres whose start tangent stays within the rounding's slack.
  return certify_near(sp, c, ccw, P, q, opt.decimals, rtol, false, budget_xy, [&](const PrintedArc& a) {
    FitMove m;
    m.kind = ccw ? FitKind::arc_ccw : FitKind::arc_cw;
    m.to = a.to;
    m.center = a.center;
    return std::abs(directed_angle(tin, move_tangent(a.from, m, true), true)) <= tangent_slack(q, a.r_start());
  });
}

// Whether arc c of a tangent chain, over span sp, leaves its end in the
// curve's direction closely enough for the next arc. The next arc starts
// in this arc's end direction: started at an angle d off the curve, an arc
// through the curve's points a chord L apart strays by about d L / 4 from
// it, so a chain whose arcs end as far off as they may drifts, and its
// arcs grow short until it must start again at a kink. Allowed: kChainAlign
// x budget / L (the next arc, as long as this one, spending 5/8 of its
// budget on it), plus the angle the printed centre's rounding may give.
bool ends_along_curve(const Span& sp, const ArcCandidate& c, double budget_xy, double q) {
  FitMove m;
  m.kind = c.arc.ccw ? FitKind::arc_ccw : FitKind::arc_cw;
  m.to = c.arc.to;
  m.center = c.arc.center;
  const Vec3 out = move_tangent(sp.Sr, m, false), along = derivative(sp.b, sp.t1);
  const double off = std::abs(std::atan2(cross2(out, along), dot2(out, along)));
  const double chord = norm2(Vec3{sp.Er.x - sp.Sr.x, sp.Er.y - sp.Sr.y, 0});
  return off <= kChainAlign * budget_xy / chord + tangent_slack(q, c.arc.r_end());
}

// The arcs from parameter t0 of piece b (printed start Sr, chain direction
// tin) that fit_arcs() chooses from.
struct ArcSearch {
  const Bezier& b;
  double t0;
  Vec3 S, Sr, tin;
  const ArcFitOptions& opt;
  double budget_xy, rtol, q;
  bool tangent;
  // Unrounded (the path an offset is made from), the chain goes on into the
  // next piece at a tangent joint: the piece's last arc ends along it too.
  // (Not for printed fits, whose last arcs would then grow tighter: a
  // controller's compensation refuses an arc tighter than its tool.)
  bool goes_on;

  // The arc over [t0, t1] (tangent to the chain or free), if one fits; in
  // a chain only one that ends along the curve (at the piece's end too
  // when `goes_on`).
  Found at(bool chain, double t1) const {
    const Vec3 E = point_at(b, t1);
    const Span sp{.b = b, .t0 = t0, .t1 = t1, .S = S, .E = E, .Sr = Sr, .Er = quantize(E, opt.decimals)};
    auto c = chain ? try_tangent_arc(sp, opt, budget_xy, rtol, tin) : try_arc(sp, opt, budget_xy, rtol);
    if (c && tangent && (t1 < 1 || goes_on) && !ends_along_curve(sp, *c, budget_xy, q)) c.reset();
    return c ? Found{c, t1, E} : Found{};
  }

  // The longest span an arc fits from alo on, searched from adt.
  Found longest(bool chain, double alo, double adt) const {
    Found f;
    double ahi = kInf;
    for (int iter = 0; iter < 60 && adt > alo * 1.0001; ++iter) {
      const double t1 = adt >= 1 - t0 ? 1.0 : t0 + adt;
      if (Found c = at(chain, t1); c.arc) {
        f = std::move(c);
        alo = adt;
        if (t1 >= 1) break;
        adt = ahi == kInf ? std::min(adt * 2, 1 - t0) : 0.5 * (alo + ahi);
      } else {
        ahi = adt;
        adt = 0.5 * (alo + ahi);
      }
      if (ahi != kInf && ahi - alo <= 0.02 * alo) break;
    }
    // Unrounded, the fit is a path another is made from (an offset, which
    // is printed): a stub it leaves at a piece's end would be printed as a
    // move too short to turn along the curve (its chord's direction off by
    // the rounding over its length). Where the stub is under a tenth of
    // the arc, two arcs share the piece's rest.
    if (tangent && f.arc && f.t1 < 1 && !(q > 0)) {
      const double stub = dist_xy(b.back(), f.arc->arc.to), chord = dist_xy(f.arc->arc.to, Sr);
      if (stub < 0.1 * chord)
        if (Found half = at(chain, 0.5 * (t0 + 1)); half.arc) return half;
    }
    return f;
  }
};

}  // namespace

bool planar_xy(const Bezier& piece) {
  for (const auto& p : piece.points)
    if (p.z != piece.points.front().z) return false;
  return true;
}

namespace {

// arc_span_deviation() (helical false) and helix_span_deviation() (true).
double span_deviation(const Bezier& piece, double t0, double t1, const PrintedArc& arc, double budget,
                      double resolution, bool helical) {
  const double W = arc.sweep();
  if (!(W > 0) || W > kMaxSweep) return kInf;
  const ArcGeometry g(arc, helical);
  if (!(g.rmin > 0)) return kInf;
  const Bezier sub = subcurve(piece, t0, t1);
  const Vec3 S = sub.front(), E = sub.back();
  // Slivers of D outside the curve's angular range, as sweep fractions.
  const double aS = directed_angle(g.a, S - arc.center, arc.ccw);
  const double aE = directed_angle(g.b, E - arc.center, arc.ccw);
  const double sS = aS > 0 ? std::min(aS / W, 1.0) : 0.0;
  const double sE = aE < 0 ? std::min(-aE / W, 1.0) : 0.0;
  const double rise = helical ? std::abs(arc.to.z - arc.from.z) : 0.0;
  const double spiral = (std::abs(arc.r_end() - arc.r_start()) + rise) * std::max(sS, sE);
  const double U = sup_d(g, sub, budget < 0 ? budget : std::max(budget - spiral, 0.0), resolution);
  const double B = std::max({U, g.dist_end(S, arc.from), g.dist_end(E, arc.to)}) + spiral;
  // The covering argument needs the curve to stay well away from the centre.
  if (!(B < 0.5 * g.rmin)) return kInf;
  return B;
}

}  // namespace

double arc_span_deviation(const Bezier& piece, double t0, double t1, const PrintedArc& arc, double budget,
                          double resolution) {
  return span_deviation(piece, t0, t1, arc, budget, resolution, false);
}

double helix_span_deviation(const Bezier& piece, double t0, double t1, const PrintedArc& arc, double budget,
                            double resolution) {
  return span_deviation(piece, t0, t1, arc, budget, resolution, true);
}

std::vector<Vec3> sample_arc(const PrintedArc& arc, double sagitta) {
  const double rho = std::max(arc.r_start(), arc.r_end());
  const double W = arc.sweep();
  double step = W;
  if (rho > 0 && sagitta < rho) step = 2 * std::acos(1 - sagitta / rho) * 0.9;
  const size_t n = std::max<size_t>(1, static_cast<size_t>(std::ceil(W / step)));
  std::vector<Vec3> out;
  out.reserve(n + 1);
  const ArcPoints pts(arc);
  for (size_t i = 0; i <= n; ++i) out.push_back(pts.at(static_cast<double>(i) / static_cast<double>(n)));
  return out;
}

double fit_arcs(std::span<const Bezier> pieces, const ArcFitOptions& opt,
                const std::function<void(const FitMove&)>& emit) {
  if (pieces.empty()) return 0;
  const double tol = opt.tolerance;
  const double scale = control_magnitude(pieces);
  const ToleranceBudget tb = check_tolerance(tol, opt.decimals, pieces.front().dim, scale);
  const double budget = tb.budget;
  // The band (not for helical fits): see the top.
  const bool band = opt.band && !opt.helical;
  // The controller compares radii computed from the same printed numbers;
  // keep a floating-point margin below its limit.
  const double rtol = opt.radius_tolerance - 64 * std::numeric_limits<double>::epsilon() * std::max(scale, 1.0);

  double bound = 0;
  Vec3 Sr = quantize(pieces.front().front(), opt.decimals);
  double line_hint = -1, arc_hint = -1;
  // Tangent chains: the direction the last move ends in (zero: no chain).
  const bool tangent = opt.tangent && !opt.helical;
  const double q = opt.decimals >= 0 ? std::pow(10.0, -opt.decimals) : 0.0;
  Vec3 tin;
  if (tangent && norm2(opt.start_direction) > 0)
    tin = Vec3{opt.start_direction.x, opt.start_direction.y, 0} / norm2(opt.start_direction);
  for (size_t pi = 0; pi < pieces.size(); ++pi) {
    const Bezier& b = pieces[pi];
    // Helical arcs take any piece; their bound is 3D (dz = 0 below).
    const bool planar = opt.helical || planar_xy(b);
    const double dz = planar && !opt.helical ? std::abs(b.front().z - quantize(b.front().z, opt.decimals)) : 0.0;
    const double budget_xy = dz < budget ? std::sqrt(budget * budget - dz * dz) : -1.0;
    // How far a line's inner end is shifted off the curve: the flattener's
    // share of what the tolerance leaves after rounding.
    const double line_shift = kBandShare * (budget - tb.rounding);
    // The band on pieces that get no arcs (see the top).
    const bool line_band = band && !(planar && budget_xy > 0);
    // A chain goes on across a joint where the curve is tangent.
    if (!(planar && budget_xy > 0) || (pi > 0 && !tangent_joint(pieces[pi - 1], b))) tin = {};
    double t0 = 0;
    Vec3 S = b.front();
    while (t0 < 1) {
      // Longest chord: the flattener's bound (exact deviation + rounding).
      // In the band (a piece without arcs): the chord from the printed
      // point to the end shifted towards the convex side (or, when that
      // fails, on the curve), proven by band_deviation() between the
      // printed points themselves.
      auto line_ok = [&](double t1, Vec3& E, Vec3& Er, double& dev) {
        E = point_at(b, t1);
        if (line_band) {
          const Vec3 side = t1 < 1 ? convex_side(b, t1) : Vec3{};
          if (side.x != 0 || side.y != 0 || side.z != 0) {
            Er = quantize(E + side * line_shift, opt.decimals);
            dev = band_deviation(b, t0, t1, Sr, Er, budget);
            if (dev <= budget) return true;
          }
          Er = quantize(E, opt.decimals);
          dev = band_deviation(b, t0, t1, Sr, Er, budget);
          return dev <= budget;
        }
        Er = quantize(E, opt.decimals);
        const double disp = std::max(dist(Sr, S), dist(Er, E));
        dev = chord_deviation(b, t0, t1, budget - disp) + disp;
        return dev <= budget;
      };
      double lo = 0, hi = kInf, dt = line_hint > 0 ? std::min(line_hint, 1 - t0) : 1 - t0;
      FitMove best;
      Vec3 bestE;
      for (int iter = 0; iter < 200; ++iter) {
        const double t1 = dt >= 1 - t0 ? 1.0 : t0 + dt;
        Vec3 E, Er;
        double dev;
        if (line_ok(t1, E, Er, dev)) {
          lo = dt;
          best = {FitKind::line, Er, {}, {}, pi, t1, dev};
          bestE = E;
          if (t1 >= 1) break;
          dt = hi == kInf ? dt * 2 : 0.5 * (lo + hi);
        } else {
          hi = dt;
          dt = lo > 0 ? 0.5 * (lo + hi) : dt * 0.25;
        }
        if (lo > 0 && hi != kInf && hi - lo <= 0.02 * lo) break;
      }
      if (!(lo > 0)) throw std::logic_error("arc fit: no chord fits (internal error)");
      line_hint = lo;
      // In a chain, a line must leave in the chain's direction; else arcs
      // of any length are tried, the line kept only when none fits.
      const bool chained = tangent && (tin.x != 0 || tin.y != 0);
      const bool line_tangent = !chained || std::abs(directed_angle(tin, move_tangent(Sr, best, true), true)) <=
                                                line_slack(q, dist_xy(best.to, Sr));
      // Longest arc, only worth it beyond the chord.
      if (planar && budget_xy > 0 && (best.t < 1 || !line_tangent)) {
        const bool goes_on = !(q > 0) && pi + 1 < pieces.size() && tangent_joint(b, pieces[pi + 1]);
        const ArcSearch search{b, t0, S, Sr, tin, opt, budget_xy, rtol, q, tangent, goes_on};
        const double free_from = std::min(std::max(2 * lo, arc_hint), 1 - t0);
        Found fd = chained
                       ? search.longest(true, line_tangent ? lo : 0, line_tangent ? free_from : std::min(lo, 1 - t0))
                       : search.longest(false, lo, free_from);
        // A chain that can go on only in much shorter spans than a free
        // arc takes starts again (one joint at a small angle).
        if (chained) {
          const Found fr = search.longest(false, lo, free_from);
          if (fr.arc && (!fd.arc || kChainRestart * (fd.t1 - t0) < fr.t1 - t0)) fd = fr;
        }
        const std::optional<ArcCandidate>& found = fd.arc;
        const double found_t1 = fd.t1;
        if (found) {
          arc_hint = found_t1 - t0;
          // Report a tight bound, not merely the accepted one.
          const double tight = span_deviation(b, t0, found_t1, found->arc, -1, 1e-4 * tol, opt.helical);
          const double B = std::hypot(std::min(found->bound_xy, tight), dz);
          best = {found->arc.ccw ? FitKind::arc_ccw : FitKind::arc_cw,
                  found->arc.to,
                  found->arc.center,
                  found->ij,
                  pi,
                  found_t1,
                  B};
          best.center.z = opt.helical ? Sr.z : best.to.z;
          bestE = fd.E;
        }
      }
      bound = std::max(bound, best.bound);
      emit(best);
      if (tangent) tin = planar && budget_xy > 0 ? move_tangent(Sr, best, false) : Vec3{};
      t0 = best.t;
      S = bestE;
      Sr = best.to;
    }
  }
  return bound;
}

ArcFitResult fit_arcs(std::span<const Bezier> pieces, const ArcFitOptions& opt) {
  ArcFitResult r;
  if (!pieces.empty()) r.start = quantize(pieces.front().front(), opt.decimals);
  r.bound = fit_arcs(pieces, opt, [&](const FitMove& m) { r.moves.push_back(m); });
  return r;
}

Plane least_climb_plane(std::span<const Bezier> pieces) {
  Box3 box;
  for (const Bezier& b : pieces)
    for (const Vec3& p : b.points) box.add(p);
  int axis = 2;
  for (int k = 0; k < 2; ++k)
    if (box.hi[k] - box.lo[k] < box.hi[axis] - box.lo[axis]) axis = k;
  return axis == 2 ? Plane::xy : axis == 1 ? Plane::zx : Plane::yz;
}

ArcFitResult fit_helical_arcs(std::span<const Bezier> pieces, const ArcFitOptions& opt, Plane pl) {
  ArcFitOptions ho = opt;
  ho.helical = true;
  if (pl == Plane::xy) {
    ArcFitResult r = fit_arcs(pieces, ho);
    r.plane = pl;
    return r;
  }
  std::vector<Bezier> local(pieces.begin(), pieces.end());
  for (Bezier& b : local)
    for (Vec3& p : b.points) p = to_plane(p, pl);
  ArcFitResult r = fit_arcs(local, ho);
  r.plane = pl;
  r.start = from_plane(r.start, pl);
  for (FitMove& m : r.moves) {
    m.to = from_plane(m.to, pl);
    m.center = from_plane(m.center, pl);
  }
  return r;
}

}  // namespace bezcam
