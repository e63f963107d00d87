// A pass's polyline as arcs and lines within a distance of it (pocket_plan.hpp
// polyline_arcs()), each block's bound proven in closed form.
//
// The proof for an arc. The printed arc runs from S about c' (S plus the
// rounded I, J) to E, both vertices of the polyline; a controller draws the
// spiral whose radius moves from r_s = |S - c'| to r_e = |E - c'| with the
// angle, so every drawn point lies at a radius in [r_lo, r_hi] = [min, max]
// of the two. Every vertex of the polyline between S and E lies in the arc's
// sector (its angle about c' between S's and E's, in the direction of travel),
// a convex set for a sweep below pi, so every point of the polyline does.
// Then (1) a polyline point q at angle a is within | |q - c'| - r(a) | of the
// drawn point at a, and (2) since the polyline runs continuously from S's
// angle to E's, every drawn point has a polyline point at its angle, within
// the same distance. |q - c'| along a segment is convex: its largest value is
// at an end, its smallest the distance from c' to the segment; so the
// segment's points are within max(max(d_a, d_b) - r_lo, r_hi - d_min) of the
// drawn arc, both ways.
//
// The proof for a line from S to E: every vertex between lies within the
// bound of the segment [S, E], hence every point of the polyline (the
// distance to a segment is convex); the polyline's projection onto the
// segment covers it, so every point of the segment is within the bound of
// the polyline point that projects onto it.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "pocket_grid.hpp"
#include "pocket_plan.hpp"

namespace bezcam::detail {

namespace {

// The arcs' limits: a sweep short of a half turn (the centre words stay
// well conditioned), a radius a controller prints without trouble (and at
// least 100 units of the last printed digit).
constexpr double kMaxSweep = std::numbers::pi - 0.02;
constexpr double kMaxRadius = 1e4;
// Tangent chains: a line goes on from the move before when its direction
// is within this angle of that move's end (radians; LinuxCNC takes a joint
// as tangent below 4.95e-4 at F6000 on the linuxcnc profile); the chain
// starts again, free, where the free move reaches more than this many
// times as far.
constexpr double kChainLine = 4e-4;
constexpr double kChainRestart = 2;

struct Span {
  FitMove move;
  size_t end = 0;  ///< the polyline vertex it ends at
  bool ok = false;
};

class Fitter {
 public:
  Fitter(const std::vector<Vec3>& pts, double tol, int decimals, double radius_tol)
      : p_(pts), tol_(tol), dec_(decimals), rtol_(radius_tol) {}

  Span line(size_t i, size_t j) const {
    Span s;
    double worst = 0;
    for (size_t k = i + 1; k < j && worst <= tol_; ++k) worst = std::max(worst, point_segment(p_[k], p_[i], p_[j]));
    s.ok = worst <= tol_;
    s.end = j;
    s.move.kind = FitKind::line;
    s.move.to = p_[j];
    s.move.bound = worst;
    return s;
  }

  // The line from vertex i to j, when it leaves in direction u (unit).
  Span tangent_line(size_t i, size_t j, const Vec3& u) const {
    const Vec3 d{p_[j].x - p_[i].x, p_[j].y - p_[i].y, 0};
    const double l = std::hypot(d.x, d.y);
    if (!(l > 0) || std::atan2(std::abs(u.x * d.y - u.y * d.x), u.x * d.x + u.y * d.y) > kChainLine) return {};
    return line(i, j);
  }

  // The arc from vertex i leaving in direction u (unit) to vertex j: its
  // centre on the normal there (then rounded as any arc's).
  Span tangent_arc(size_t i, size_t j, const Vec3& u) const {
    const Vec3 S = p_[i], E = p_[j];
    const Vec3 n{-u.y, u.x, 0}, w{E.x - S.x, E.y - S.y, 0};
    const double wn = w.x * n.x + w.y * n.y, ww = w.x * w.x + w.y * w.y;
    if (!(std::abs(wn) > 1e-12 * std::sqrt(ww)) || !(w.x * u.x + w.y * u.y > 0)) return {};
    const double r = ww / (2 * wn);  // signed: the centre on u's left when > 0
    const double R = std::abs(r);
    if (!(R < kMaxRadius) || R < 100 * std::pow(10.0, -dec_)) return {};
    return certify(i, j, Vec3{S.x + n.x * r, S.y + n.y * r, 0}, r > 0);
  }

  // The arc from vertex i to vertex j arriving in direction d (unit): the
  // tangent arc from j leaving in -d, run the other way.
  Span tangent_arc_into(size_t i, size_t j, const Vec3& d) const {
    const Vec3 S = p_[i], E = p_[j];
    const Vec3 n{d.y, -d.x, 0}, w{S.x - E.x, S.y - E.y, 0};
    const double wn = w.x * n.x + w.y * n.y, ww = w.x * w.x + w.y * w.y;
    if (!(std::abs(wn) > 1e-12 * std::sqrt(ww)) || !(w.x * d.x + w.y * d.y < 0)) return {};
    const double r = ww / (2 * wn);
    const double R = std::abs(r);
    if (!(R < kMaxRadius) || R < 100 * std::pow(10.0, -dec_)) return {};
    return certify(i, j, Vec3{E.x + n.x * r, E.y + n.y * r, 0}, r < 0);
  }

  // The same fitter within a distance t instead.
  Fitter within(double t) const { return Fitter(p_, t, dec_, rtol_); }

  // The arc about c (its centre when printed from vertex i) to vertex j.
  Span arc_about(size_t i, size_t j, const Vec3& c, bool ccw) const { return certify(i, j, c, ccw); }

  Span arc(size_t i, size_t j) const {
    Span s;
    const Vec3 S = p_[i], E = p_[j];
    const double h = dist_xy(S, E) / 2;
    if (!(h > 0) || j < i + 2) return s;
    const Vec3 M{(S.x + E.x) / 2, (S.y + E.y) / 2, 0};
    const Vec3 n{-(E.y - S.y) / (2 * h), (E.x - S.x) / (2 * h), 0};  // left of S -> E
    // The signed sagitta (the arc's middle point is M + sigma n) of the
    // circle through S, E and the middle vertex, then the one that makes the
    // polyline's radial spread least (golden-section steps about it).
    const Vec3& q = p_[(i + j) / 2];
    const double along = ((q.x - M.x) * (E.x - S.x) + (q.y - M.y) * (E.y - S.y)) / (2 * h);
    const double off = (q.x - M.x) * n.x + (q.y - M.y) * n.y;
    if (std::abs(along) >= h || std::abs(off) < 1e-12) return s;
    const double t0 = (along * along + off * off - h * h) / (2 * off);  // centre M + t0 n
    const double sig0 = off > 0 ? t0 + std::hypot(h, t0) : t0 - std::hypot(h, t0);
    auto centre = [&](double sig, double& R) {
      R = (h * h + sig * sig) / (2 * std::abs(sig));
      const double t = sig - (sig > 0 ? R : -R);
      return Vec3{M.x + n.x * t, M.y + n.y * t, 0};
    };
    auto spread = [&](double sig) {
      double R = 0;
      const Vec3 c = centre(sig, R);
      double lo = 0, hi = 0;
      for (size_t k = i; k < j; ++k) {
        lo = std::min(lo, point_segment(c, p_[k], p_[k + 1]) - R);
        hi = std::max(hi, dist_xy(p_[k + 1], c) - R);
      }
      return std::max(-lo, hi);
    };
    double a = sig0 - 2 * tol_, b = sig0 + 2 * tol_;
    if ((a > 0) != (sig0 > 0)) a = sig0 > 0 ? sig0 / 4 : a;
    if ((b > 0) != (sig0 > 0)) b = sig0 < 0 ? sig0 / 4 : b;
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = spread(x1), f2 = spread(x2);
    for (int it = 0; it < 24; ++it) {
      if (f1 <= f2)
        b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = spread(x1);
      else
        a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = spread(x2);
    }
    const double sig = f1 <= f2 ? x1 : x2;
    if (std::abs(sig) >= h) return s;  // half a turn or more
    double R = 0;
    const Vec3 c = centre(sig, R);
    // A radius a few printed digits long would be refused (LinuxCNC's
    // "zero-radius arc") or drawn with a large relative error: lines there.
    if (!(R < kMaxRadius) || R < 100 * std::pow(10.0, -dec_)) return s;
    return certify(i, j, c, sig < 0);
  }

 private:
  // The printed arc about c (rounded through I, J) from p_[i] to p_[j] and
  // its proven distance from the polyline between (above: why).
  Span certify(size_t i, size_t j, const Vec3& c, bool ccw) const {
    Span s;
    const Vec3 S = p_[i], E = p_[j];
    const Vec3 ij = quantize(Vec3{c.x - S.x, c.y - S.y, 0}, dec_);
    const Vec3 cc{S.x + ij.x, S.y + ij.y, 0};
    const double rs = dist_xy(S, cc), re = dist_xy(E, cc);
    if (std::abs(rs - re) > rtol_) return s;
    const double lo = std::min(rs, re), hi = std::max(rs, re);
    const double turn = ccw ? 1 : -1;
    auto angle = [&](const Vec3& v) {  // from S about cc in the direction of travel, in [0, 2 pi)
      const double ux = S.x - cc.x, uy = S.y - cc.y, vx = v.x - cc.x, vy = v.y - cc.y;
      double t = std::atan2(turn * (ux * vy - uy * vx), ux * vx + uy * vy);
      if (t < 0) t += 2 * std::numbers::pi;
      return t;
    };
    const double sweep = angle(E);
    if (!(sweep > 0) || sweep > kMaxSweep) return s;
    double worst = 0;
    for (size_t k = i; k < j; ++k) {
      if (k > i && angle(p_[k]) > sweep) return s;
      const double da = dist_xy(p_[k], cc), db = dist_xy(p_[k + 1], cc), dm = point_segment(cc, p_[k], p_[k + 1]);
      worst = std::max({worst, std::max(da, db) - lo, hi - dm});
      if (worst > tol_) return s;
    }
    // Rounding of the arithmetic: a few ulps of the coordinates' size.
    worst += 1e-12 * (hi + std::abs(S.x) + std::abs(S.y));
    if (worst > tol_) return s;
    s.ok = true;
    s.end = j;
    s.move.kind = ccw ? FitKind::arc_ccw : FitKind::arc_cw;
    s.move.to = E;
    s.move.center = cc;
    s.move.ij = ij;
    s.move.bound = worst;
    return s;
  }

  const std::vector<Vec3>& p_;
  double tol_;
  int dec_;
  double rtol_;
};

// The farthest end j > i for which `fits` holds, searched by doubling and
// bisection from i + first (taken to hold when nothing farther does).
template <class F>
Span farthest(size_t i, size_t first, size_t n, F fits) {
  Span best;
  size_t good = 0, step = 1, j = i + first;
  if (j >= n) return best;
  Span s = fits(j);
  if (!s.ok) return best;
  best = s, good = j;
  size_t bad = n;
  while (good + step < n) {
    s = fits(good + step);
    if (!s.ok) {
      bad = good + step;
      break;
    }
    best = s, good += step, step *= 2;
  }
  if (bad == n && good + 1 < n) {
    s = fits(n - 1);
    if (s.ok) return s;
    bad = n - 1;
  }
  while (bad - good > 1) {
    const size_t mid = good + (bad - good) / 2;
    s = fits(mid);
    if (s.ok)
      best = s, good = mid;
    else
      bad = mid;
  }
  return best;
}

// Where a joint would turn, the move before it may end elsewhere so that a
// tangent one goes on from there: a few vertices sooner (a polyline's
// straight run taken a vertex into the round that follows, within the
// distance yet turning there, leaves no tangent arc from its end), or at
// the point where the two moves' supports touch (a line and the circle of
// the arc after it, two circles), put on the polyline as a vertex of its
// own when it falls between two.
constexpr size_t kRetreat = 4;

struct Taken {
  Span span;
  size_t from = 0;
  Vec3 tin;  ///< the direction it had to leave in (zero: free)
};

// The move from t.from ending at vertex e instead, on the same terms (a
// tangent one tangent again, a free one free), when one fits.
Span refit(const Fitter& fit, const Taken& t, size_t e) {
  const bool chained = t.tin.x != 0 || t.tin.y != 0;
  Span s = t.span.move.kind == FitKind::line ? (chained ? fit.tangent_line(t.from, e, t.tin) : fit.line(t.from, e))
                                             : (chained ? fit.tangent_arc(t.from, e, t.tin) : fit.arc(t.from, e));
  if (s.ok && s.move.kind != t.span.move.kind) s.ok = false;
  return s;
}

// The points where the support of `prev` (a line from a, or a circle) and
// that of `next` touch or would, nearest the joint j first.
std::vector<Vec3> touch_points(const Vec3& a, const FitMove& prev, const FitMove& next, const Vec3& j) {
  std::vector<Vec3> q;
  auto unit = [](double x, double y) {
    const double l = std::hypot(x, y);
    return l > 0 ? Vec3{x / l, y / l, 0} : Vec3{};
  };
  const bool pl = prev.kind == FitKind::line, nl = next.kind == FitKind::line;
  if (pl && !nl) {
    const Vec3 d = unit(prev.to.x - a.x, prev.to.y - a.y), c = next.center;
    const double s = (c.x - a.x) * d.x + (c.y - a.y) * d.y;
    q.push_back({a.x + d.x * s, a.y + d.y * s, 0});
  } else if (!pl) {
    const Vec3 c = prev.center;
    const double R = dist_xy(prev.to, c);
    const Vec3 w = nl ? unit(-(next.to.y - j.y), next.to.x - j.x) : unit(next.center.x - c.x, next.center.y - c.y);
    if (w.x == 0 && w.y == 0) return q;
    q.push_back({c.x + w.x * R, c.y + w.y * R, 0});
    q.push_back({c.x - w.x * R, c.y - w.y * R, 0});
  }
  std::sort(q.begin(), q.end(), [&](const Vec3& u, const Vec3& v) { return dist_xy(u, j) < dist_xy(v, j); });
  return q;
}

// The polyline's point nearest q on its segments from vertex lo to hi:
// the segment's first vertex k and the point.
std::pair<size_t, Vec3> nearest_on(const std::vector<Vec3>& p, size_t lo, size_t hi, const Vec3& q) {
  size_t best = lo;
  Vec3 at = p[lo];
  double d = dist_xy(q, at);
  for (size_t k = lo; k < hi && k + 1 < p.size(); ++k) {
    const Vec3 m = segment_point(q, p[k], p[k + 1]);
    if (dist_xy(q, m) < d) d = dist_xy(q, m), best = k, at = m;
  }
  return {best, at};
}

// The tangent move from vertex i leaving in direction u that reaches
// farthest. A line's direction is judged by its chord, surer the longer:
// the farthest line first (`free_line`, when the caller has it), then the
// farthest whose chord is tangent.
Span chain_from(const Fitter& fit, size_t n, size_t i, const Vec3& u, const Span* free_line = nullptr) {
  Span tl = free_line ? *free_line : farthest(i, 1, n, [&](size_t j) { return fit.line(i, j); });
  if (tl.ok) tl = fit.tangent_line(i, tl.end, u);
  if (!tl.ok) tl = farthest(i, 1, n, [&](size_t j) { return fit.tangent_line(i, j, u); });
  const Span ta = farthest(i, 1, n, [&](size_t j) { return fit.tangent_arc(i, j, u); });
  return ta.ok && (!tl.ok || ta.end > tl.end) ? ta : tl;
}

// Where a joint may be put near point c: a vertex of p from lo to hi
// (index k, eps 0), or c rounded (q) between vertices k and k + 1, with
// its distance eps from that segment. Made a vertex there, it leaves the
// polyline within eps of what it was, both ways, when it projects inside
// the segment (each side of the projection is within eps of the
// triangle's side through q: distance to a segment is convex).
struct JointSpot {
  size_t k = 0;
  Vec3 q;
  double eps = 0;
  bool vertex = true;
};

std::optional<JointSpot> place_near(const std::vector<Vec3>& p, size_t lo, size_t hi, const Vec3& c, int decimals) {
  const auto [k, at] = nearest_on(p, lo, hi, c);
  JointSpot pl{k, quantize(Vec3{c.x, c.y, 0}, decimals), 0, true};
  if (dist_xy(pl.q, p[k]) == 0) return pl;
  if (k + 1 < p.size() && dist_xy(pl.q, p[k + 1]) == 0) return pl.k = k + 1, pl;
  if (k + 1 >= p.size()) return std::nullopt;
  const Vec3 &u = p[k], &v = p[k + 1];
  const double ex = v.x - u.x, ey = v.y - u.y, ll = ex * ex + ey * ey;
  const double t = ll > 0 ? ((pl.q.x - u.x) * ex + (pl.q.y - u.y) * ey) / ll : -1;
  if (!(t > 0 && t < 1)) return std::nullopt;
  pl.eps = point_segment(pl.q, u, v);
  pl.vertex = false;
  return pl;
}

// A joint near c (place_near(), between vertices lo and hi), made a vertex
// of p when it falls between two, offered to fits(qi, inserted, f2, eps):
// qi its vertex, f2 the fitter within tol less its distance eps from the
// polyline (moves f2 fits are within tol of the polyline as it was, once
// eps is added to their bounds). The vertex stays when fits takes it.
template <class F>
bool try_joint(const Fitter& fit, std::vector<Vec3>& p, size_t lo, size_t hi, const Vec3& c, double tol, int decimals,
               F&& fits) {
  const std::optional<JointSpot> pl = place_near(p, lo, hi, c, decimals);
  if (!pl || !(pl->eps <= tol / 2)) return false;
  const size_t qi = pl->vertex ? pl->k : pl->k + 1;
  if (!pl->vertex) p.insert(p.begin() + static_cast<std::ptrdiff_t>(qi), pl->q);
  if (fits(qi, !pl->vertex, fit.within(tol - pl->eps), pl->eps)) return true;
  if (!pl->vertex) p.erase(p.begin() + static_cast<std::ptrdiff_t>(qi));
  return false;
}

// At a joint at vertex i that would turn: the move before ended where its
// support and the free move's touch, and a tangent move from there that
// reaches past i. The joint is the touch point itself (rounded) when it
// lies within half the distance of the polyline, else the polyline's point
// nearest it (try_joint()). On success prev and take are the two moves and
// i the joint's vertex as p now numbers it.
bool touch(const Fitter& fit, std::vector<Vec3>& p, Taken& prev, Taken& take, size_t& i, double tol, int decimals) {
  const size_t lo = std::max(prev.from, i >= kRetreat ? i - kRetreat : 0);
  const size_t hi = std::min(take.span.end, i + kRetreat);
  auto fits = [&](size_t qi, bool inserted, const Fitter& f2, double eps) {
    const size_t ii = inserted && qi <= i ? i + 1 : i, end = inserted ? take.span.end + 1 : take.span.end;
    if (qi <= prev.from || qi == ii) return false;
    const FitMove& m = prev.span.move;
    const Vec3& q = p[qi];
    Span before;
    if (m.kind != FitKind::line && take.span.move.kind == FitKind::line && prev.tin.x == 0 && prev.tin.y == 0) {
      const Vec3& e = p[end];
      const double l = dist_xy(e, q);
      if (l > 0) before = f2.tangent_arc_into(prev.from, qi, Vec3{(e.x - q.x) / l, (e.y - q.y) / l, 0});
    }
    if (!before.ok && m.kind != FitKind::line)
      before = f2.arc_about(prev.from, qi, m.center, m.kind == FitKind::arc_ccw);
    if (!before.ok) before = refit(f2, prev, qi);
    if (!before.ok) return false;
    const Vec3 u = move_tangent(p[prev.from], before.move, false);
    Span chain = chain_from(f2, p.size(), qi, u);
    if (!(chain.ok && chain.end > ii && kChainRestart * double(chain.end - qi) >= double(end - qi) &&
          before.move.bound + eps <= tol && chain.move.bound + eps <= tol))
      return false;
    before.move.bound += eps, chain.move.bound += eps;
    prev.span = before;
    take = {chain, qi, u};
    i = ii;
    return true;
  };
  for (const Vec3& t : touch_points(p[prev.from], prev.span.move, take.span.move, p[i])) {
    const Vec3 at = nearest_on(p, lo, hi, t).second;
    if (!(dist_xy(at, t) <= tol)) continue;
    for (const Vec3& c : {t, at})
      if (try_joint(fit, p, lo, hi, c, tol, decimals, fits)) return true;
  }
  return false;
}

// A ring (closed) whose first free move is an arc: it starts on the
// straight run the ring closes with, a little before the round, where no
// arc from the start is tangent to what follows. The ring then starts with
// a line along the run to where the arc's circle touches the run (the foot
// of its centre, placed as touch() places a joint), and a tangent move
// from there. On success the line is in out and take the move after it.
bool lead_line(const Fitter& fit, std::vector<Vec3>& p, Taken& take, std::vector<Taken>& out, double tol,
               int decimals) {
  const size_t n = p.size();
  if (n < 4 || dist_xy(p.front(), p.back()) > 0 || take.span.move.kind == FitKind::line) return false;
  const Vec3 &a = p[n - 2], s = p[0];
  const double l = dist_xy(a, s);
  if (!(l > 0)) return false;
  const Vec3 u{(s.x - a.x) / l, (s.y - a.y) / l, 0}, c = take.span.move.center;
  const double along = (c.x - s.x) * u.x + (c.y - s.y) * u.y;
  if (!(along > 0)) return false;
  const Vec3 t{s.x + u.x * along, s.y + u.y * along, 0};
  const size_t hi = std::min(take.span.end, kRetreat);
  const Vec3 at = nearest_on(p, 0, hi, t).second;
  if (!(dist_xy(at, t) <= tol)) return false;
  auto fits = [&](size_t qi, bool inserted, const Fitter& f2, double eps) {
    if (qi == 0) return false;
    const size_t end = inserted ? take.span.end + 1 : take.span.end;
    Span ln = f2.line(0, qi);
    if (!ln.ok) return false;
    const Vec3 d = move_tangent(p[0], ln.move, false);
    Span chain = chain_from(f2, p.size(), qi, d);
    if (!(chain.ok && chain.end > qi && kChainRestart * double(chain.end - qi) >= double(end - qi) &&
          ln.move.bound + eps <= tol && chain.move.bound + eps <= tol))
      return false;
    ln.move.bound += eps, chain.move.bound += eps;
    out.push_back({ln, 0, Vec3{}});
    take = {chain, qi, d};
    return true;
  };
  for (const Vec3& cand : {t, at})
    if (try_joint(fit, p, 0, hi, cand, tol, decimals, fits)) return true;
  return false;
}

}  // namespace

std::vector<FitMove> polyline_arcs(const std::vector<Vec3>& polyline, double tol, int decimals, double radius_tol) {
  std::vector<Vec3> p;
  for (const Vec3& v : polyline)
    if (p.empty() || dist_xy(p.back(), v) > 0) p.push_back({v.x, v.y, 0});
  std::vector<Taken> out;
  const Fitter fit(p, tol, decimals, radius_tol);
  Vec3 tin;  // the direction the last move ends in (zero: none)
  for (size_t i = 0; i + 1 < p.size();) {
    const Span ln = farthest(i, 1, p.size(), [&](size_t j) { return fit.line(i, j); });
    const Span ar = farthest(i, 2, p.size(), [&](size_t j) { return fit.arc(i, j); });
    Taken take{ar.ok && ar.end > ln.end ? ar : ln, i, Vec3{}};
    // In a tangent chain: each move leaves in the direction the one
    // before ends in, so that a controller's planner runs through the
    // joint, unless a free move reaches much farther (one joint at an
    // angle).
    bool tangent = false;
    if (tin.x != 0 || tin.y != 0) {
      const Span chain = chain_from(fit, p.size(), i, tin, &ln);
      if (chain.ok && kChainRestart * double(chain.end - i) >= double(take.span.end - i))
        take = {chain, i, tin}, tangent = true;
    }
    // Else the move before, ended sooner, and a tangent move from there.
    for (size_t e = i - 1; !tangent && !out.empty() && e > out.back().from && i - e <= kRetreat; --e) {
      const Span before = refit(fit, out.back(), e);
      if (!before.ok) continue;
      const Vec3 u = move_tangent(p[out.back().from], before.move, false);
      const Span chain = chain_from(fit, p.size(), e, u);
      if (!chain.ok || chain.end <= i || kChainRestart * double(chain.end - e) < double(take.span.end - e)) continue;
      out.back().span = before;
      take = {chain, e, u}, tangent = true;
    }
    if (!tangent && !out.empty() && (tin.x != 0 || tin.y != 0))
      tangent = touch(fit, p, out.back(), take, i, tol, decimals);
    if (!tangent && out.empty()) lead_line(fit, p, take, out, tol, decimals);
    tin = move_tangent(p[take.from], take.span.move, false);
    out.push_back(take);
    i = take.span.end;
  }
  std::vector<FitMove> moves;
  moves.reserve(out.size());
  for (const Taken& t : out) moves.push_back(t.span.move);
  return moves;
}

}  // namespace bezcam::detail
