#include "floors.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace bezcam::stock_detail {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kEps = std::numeric_limits<double>::epsilon();

}  // namespace

// ---- the profile ----------------------------------------------------------

Profile::Profile(const ToolShape& t) : kind(t.kind()), R(t.radius()), R2(t.radius() * t.radius()) {
  if (kind == ToolShapeKind::bull || kind == ToolShapeKind::ball) {
    rc = t.corner_radius();
    rc2 = rc * rc;
    a0 = R - rc;
  }
  k = t.cone_slope();
}

double Profile::H(double D) const {
  D = std::clamp(D, 0.0, R2);
  switch (kind) {
    case ToolShapeKind::flat: return 0;
    case ToolShapeKind::ball: return R - std::sqrt(R2 - D);
    case ToolShapeKind::bull: {
      const double x = std::sqrt(D) - a0;
      return x <= 0 ? 0 : rc - std::sqrt((rc - x) * (rc + x));
    }
    case ToolShapeKind::vee:
    case ToolShapeKind::drill: return k * std::sqrt(D);
  }
  return 0;
}

double Profile::H1(double D) const {
  D = std::clamp(D, 0.0, R2);
  switch (kind) {
    case ToolShapeKind::flat: return 0;
    case ToolShapeKind::ball: return D >= R2 ? kInf : 0.5 / std::sqrt(R2 - D);
    case ToolShapeKind::bull: {
      const double d = std::sqrt(D), x = d - a0;
      if (x <= 0) return 0;
      const double q = (rc - x) * (rc + x);
      return q <= 0 ? kInf : x / (std::sqrt(q) * 2 * d);
    }
    case ToolShapeKind::vee:
    case ToolShapeKind::drill: return D <= 0 ? kInf : k / (2 * std::sqrt(D));
  }
  return 0;
}

double Profile::H2(double D) const {
  D = std::clamp(D, 0.0, R2);
  switch (kind) {
    case ToolShapeKind::flat: return 0;
    case ToolShapeKind::ball: {
      const double q = R2 - D;
      return q <= 0 ? kInf : 0.25 / (q * std::sqrt(q));
    }
    case ToolShapeKind::bull: {
      const double d = std::sqrt(D), x = d - a0;
      if (x <= 0) return 0;
      const double q = (rc - x) * (rc + x);
      if (q <= 0) return kInf;
      const double s = std::sqrt(q);
      const double hb1 = x / s, hb2 = rc2 / (q * s);
      return (hb2 * d - hb1) / (4 * d * d * d);
    }
    case ToolShapeKind::vee:
    case ToolShapeKind::drill: return D <= 0 ? -kInf : -k / (4 * D * std::sqrt(D));
  }
  return 0;
}

// ---- lines ------------------------------------------------------------------

LinePrep prepare_line(const Vec3& a, const Vec3& b) {
  LinePrep l;
  l.ax = a.x, l.ay = a.y, l.az = a.z, l.bx = b.x, l.by = b.y, l.bz = b.z;
  l.vx = b.x - a.x, l.vy = b.y - a.y, l.dz = b.z - a.z;
  l.L2 = l.vx * l.vx + l.vy * l.vy;
  l.L = std::sqrt(l.L2);
  l.zmin = std::min(a.z, b.z);
  l.horizontal = l.dz == 0;
  l.m = l.L > 0 ? l.dz / l.L : 0;
  l.plunge = !(l.L > 0) || !std::isfinite(l.m) || !std::isfinite(1 / l.L2);
  if (!l.plunge) {
    l.invL2 = 1 / l.L2;
    l.nx = l.vx / l.L;
    l.ny = l.vy / l.L;
  }
  return l;
}

namespace {

// Bull tool along a sloped line: the minimiser of the convex
// g(s) = m s + H(e2 + s^2) on [slo, shi] (s along the line from the foot of
// the column's perpendicular), by Newton's method safeguarded by bisection
// on g', to machine precision.
double bull_line_min(const Profile& p, double m, double e2, double slo, double shi) {
  auto g1 = [&](double s) {
    const double D = e2 + s * s;
    if (D >= p.R2) return s > 0 ? kInf : -kInf;
    const double h1 = p.H1(D);
    return h1 == 0 ? m : m + 2 * s * h1;
  };
  const double flo = g1(slo), fhi = g1(shi);
  if (flo >= 0) return slo;
  if (fhi <= 0) return shi;
  double lo = slo, hi = shi, s = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double D = e2 + s * s;
    const double f = g1(s);
    if (f == 0) return s;
    if (f < 0)
      lo = s;
    else
      hi = s;
    const double h1 = p.H1(D), h2 = p.H2(D);
    const double fp = 2 * h1 + 4 * s * s * h2;
    double next = (std::isfinite(fp) && fp > 0) ? s - f / fp : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4 * kEps * std::max(std::abs(lo), std::abs(hi)) || next == s) return s;
    s = next;
  }
  return s;
}

}  // namespace

double line_floor(const LinePrep& l, const Profile& p, double px, double py) {
  const double ux = px - l.ax, uy = py - l.ay;
  if (l.plunge) {
    const double D = ux * ux + uy * uy;
    return D <= p.R2 ? l.zmin + p.H(D) : kInf;
  }
  const double along = ux * l.nx + uy * l.ny;
  const double e = std::abs(ux * l.ny - uy * l.nx);
  if (e > p.R) return kInf;
  const double w = std::sqrt((p.R - e) * (p.R + e));
  const double slo = std::max(-along, -w), shi = std::min(l.L - along, w);
  if (slo > shi) return kInf;
  const double m = l.m;
  double s = 0;
  switch (p.kind) {
    case ToolShapeKind::flat: s = m > 0 ? -kInf : (m < 0 ? kInf : 0); break;
    case ToolShapeKind::ball: s = -(m / std::hypot(1.0, m)) * w; break;
    case ToolShapeKind::vee:
    case ToolShapeKind::drill: {
      const double am = std::abs(m);
      if (am < p.k)
        s = -std::copysign(am * e / std::sqrt((p.k - am) * (p.k + am)), m);
      else
        s = m > 0 ? -kInf : kInf;
      break;
    }
    case ToolShapeKind::bull: s = m == 0 ? 0 : bull_line_min(p, m, e * e, slo, shi); break;
  }
  s = std::clamp(s, slo, shi);
  const double t = std::clamp((along + s) / l.L, 0.0, 1.0);
  const double z = std::lerp(l.az, l.bz, t);
  const double qx = px - std::lerp(l.ax, l.bx, t), qy = py - std::lerp(l.ay, l.by, t);
  const double D = std::min(qx * qx + qy * qy, p.R2);
  return z + p.H(D);
}

bool line_row_range(const LinePrep& l, double R, double y, double& xlo, double& xhi) {
  // The row's intersection with the capsule (the discs at both ends and the
  // band between them): the hull of the three pieces (the capsule is convex).
  double lo = kInf, hi = -kInf;
  auto disc = [&](double cx, double cy) {
    const double dy = y - cy;
    if (std::abs(dy) > R) return;
    const double hw = std::sqrt((R - std::abs(dy)) * (R + std::abs(dy)));
    lo = std::min(lo, cx - hw);
    hi = std::max(hi, cx + hw);
  };
  disc(l.ax, l.ay);
  disc(l.bx, l.by);
  if (!l.plunge) {
    // 0 <= (x - ax) vx + (y - ay) vy <= L2 and |(x - ax) vy - (y - ay) vx| <= R L.
    double blo = -kInf, bhi = kInf;
    const double dy = y - l.ay;
    auto clip = [&](double coef, double off, double vmin, double vmax) {  // vmin <= coef x + off <= vmax
      if (coef == 0) {
        if (off < vmin || off > vmax) {
          blo = kInf;
          bhi = -kInf;
        }
        return;
      }
      double a = (vmin - off) / coef, b = (vmax - off) / coef;
      if (a > b) std::swap(a, b);
      blo = std::max(blo, a);
      bhi = std::min(bhi, b);
    };
    clip(l.vx, -l.ax * l.vx + dy * l.vy, 0, l.L2);
    clip(l.vy, -l.ax * l.vy - dy * l.vx, -R * l.L, R * l.L);
    if (blo <= bhi) {
      lo = std::min(lo, blo);
      hi = std::max(hi, bhi);
    }
  }
  if (!(lo <= hi)) return false;
  const double margin = 1e-9 * (1 + std::abs(lo) + std::abs(hi) + R);
  xlo = lo - margin;
  xhi = hi + margin;
  return true;
}

namespace {

// Horizontal lines (and plunges): the floor is z + H(the squared distance to
// the segment), one projection and one or two square roots per column. (A
// branch-free form that GCC vectorises with SSE2 measured 15 % slower.)
template <ToolShapeKind K>
void flat_row(const LinePrep& l, const Profile& p, double z, double y, double x0, double C, int i0, int i1,
              double* floors) {
  const double ax = l.ax, uy = y - l.ay, vx = l.vx, vy = l.vy, inv = l.plunge ? 0.0 : l.invL2, R2 = p.R2, R = p.R;
  const double a0 = p.a0, rc = p.rc, k = p.k;
  for (int i = i0; i <= i1; ++i) {
    const double x = x0 + (i + 0.5) * C;
    const double ux = x - ax;
    const double t = std::min(std::max((ux * vx + uy * vy) * inv, 0.0), 1.0);
    const double dx = ux - t * vx, dy = uy - t * vy;
    const double D = dx * dx + dy * dy;
    double f;
    if constexpr (K == ToolShapeKind::flat) {
      f = z;
    } else if constexpr (K == ToolShapeKind::ball) {
      f = z + (R - std::sqrt(std::max(R2 - D, 0.0)));
    } else if constexpr (K == ToolShapeKind::bull) {
      const double xx = std::max(std::sqrt(D) - a0, 0.0);
      f = z + (rc - std::sqrt(std::max((rc - xx) * (rc + xx), 0.0)));
    } else {
      f = z + k * std::sqrt(D);
    }
    const double old = floors[i];
    floors[i] = (D <= R2 && f < old) ? f : old;
  }
}

}  // namespace

void line_row(const LinePrep& l, const Profile& p, double y, double x0, double C, int i0, int i1, double* floors,
              FloorStats& st) {
  if (i0 > i1) return;
  st.columns += static_cast<std::uint64_t>(i1 - i0 + 1);
  if (l.horizontal || l.plunge) {
    const double z = l.zmin;
    switch (p.kind) {
      case ToolShapeKind::flat: flat_row<ToolShapeKind::flat>(l, p, z, y, x0, C, i0, i1, floors); break;
      case ToolShapeKind::ball: flat_row<ToolShapeKind::ball>(l, p, z, y, x0, C, i0, i1, floors); break;
      case ToolShapeKind::bull: flat_row<ToolShapeKind::bull>(l, p, z, y, x0, C, i0, i1, floors); break;
      case ToolShapeKind::vee:
      case ToolShapeKind::drill: flat_row<ToolShapeKind::vee>(l, p, z, y, x0, C, i0, i1, floors); break;
    }
    return;
  }
  const double zmin = l.zmin;
  for (int i = i0; i <= i1; ++i) {
    if (floors[i] <= zmin) continue;  // already at or below anything this move reaches
    const double f = line_floor(l, p, x0 + (i + 0.5) * C, y);
    if (f < floors[i]) floors[i] = f;
  }
}

// ---- arcs: preparation --------------------------------------------------------

ArcPrep prepare_arc(const Arc& a) {
  ArcPrep r;
  r.arc = a;
  for (int k = 0; k < 3; ++k) {
    const int w = world_axis(a.plane, k);
    if (w == 0) r.ix = k;
    if (w == 1) r.iy = k;
    if (w == 2) r.iz = k;
  }
  const Vec3 c = to_plane(a.center, a.plane), f = to_plane(a.from, a.plane), t = to_plane(a.to, a.plane);
  r.ca = c.x;
  r.cb = c.y;
  r.th0 = a.start_angle();
  r.dir = a.ccw ? 1 : -1;
  r.T = a.sweep();
  r.r0 = a.r_start();
  r.r1 = a.r_end();
  r.eps = (r.r1 - r.r0) / r.T;
  r.h0 = f.z;
  r.h1 = t.z;
  r.kappa = (r.h1 - r.h0) / r.T;
  r.circle = a.plane == Plane::xy && r.r0 == r.r1;
  r.rmin = std::min(r.r0, r.r1);
  r.rmax = std::max(r.r0, r.r1);
  // The box of the path: arc_extent() holds the ends and the axis crossings;
  // the spiral's radius lies between the ends' radii.
  const Box3 b = arc_extent(a);
  const double dr = r.rmax - r.rmin;
  r.xlo = b.lo.x, r.xhi = b.hi.x, r.ylo = b.lo.y, r.yhi = b.hi.y, r.zmin = b.lo.z;
  if (r.ix != 2) {
    r.xlo -= dr;
    r.xhi += dr;
  }
  if (r.iy != 2) {
    r.ylo -= dr;
    r.yhi += dr;
  }
  if (r.iz != 2) r.zmin -= dr;
  return r;
}

bool arc_row_range(const ArcPrep& a, double R, double y, double& xlo, double& xhi) {
  if (y < a.ylo - R || y > a.yhi + R) return false;
  double lo = a.xlo - R, hi = a.xhi + R;
  if (a.arc.plane == Plane::xy) {
    const double dy = std::abs(y - a.cb), outer = a.rmax + R;
    if (dy > outer) return false;
    const double hw = std::sqrt((outer - dy) * (outer + dy));
    lo = std::max(lo, a.ca - hw);
    hi = std::min(hi, a.ca + hw);
  }
  if (!(lo <= hi)) return false;
  const double margin = 1e-9 * (1 + std::abs(lo) + std::abs(hi) + R);
  xlo = lo - margin;
  xhi = hi + margin;
  return true;
}

namespace {

// The tool's position on the arc at tau in [0, T] (the ends exactly).
struct ArcPoint {
  double x, y, z;
};

ArcPoint arc_point(const ArcPrep& a, double tau, double c, double s) {
  if (tau <= 0) return {a.arc.from.x, a.arc.from.y, a.arc.from.z};
  if (tau >= a.T) return {a.arc.to.x, a.arc.to.y, a.arc.to.z};
  const double r = std::lerp(a.r0, a.r1, tau / a.T);
  const double P[3] = {a.ca + r * c, a.cb + r * s, std::lerp(a.h0, a.h1, tau / a.T)};
  return {P[a.ix], P[a.iy], P[a.iz]};
}

// Quadratic a c^2 + b c + k = 0: its real roots (a double root once; a
// slightly negative discriminant from rounding counts as zero).
int quadratic(double a, double b, double k, double out[2]) {
  if (a == 0) {
    if (b == 0) return 0;
    out[0] = -k / b;
    return 1;
  }
  double disc = b * b - 4 * a * k;
  if (disc < 0) {
    if (disc < -1e-12 * (b * b + std::abs(4 * a * k))) return 0;
    disc = 0;
  }
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0) {
    out[0] = 0;
    return 1;
  }
  out[0] = q / a;
  out[1] = k / q;
  return 2;
}

}  // namespace

double arc_floor_closed(const ArcPrep& a, const Profile& p, double px, double py, double best) {
  // G17 circle of radius r, z = h0 + kappa tau. With q the column relative to
  // the centre (rho, phi) and psi = theta - phi, D = rho^2 + r^2 - 2 rho r cos psi.
  // The lowest point over the column is at an end of the sweep, at the edge
  // of the tool's reach (D = R^2), where the path passes closest or farthest
  // (psi = 0, pi: the cone's apex), or where g' = kappa + H'(D) D' vanishes;
  // squared, that condition is a quadratic in cos psi for the ball and the
  // cone. Every candidate is a position on the path, so the minimum over
  // them is the floor.
  const double r = a.r0;
  const double qx = px - a.ca, qy = py - a.cb;
  const double rho = std::hypot(qx, qy);
  const double R = p.R;
  if (rho - r > R || r - rho > R) return best;
  auto eval = [&](double tau, bool boundary) {
    const double th = a.th0 + a.dir * tau;
    const ArcPoint P = arc_point(a, tau, std::cos(th), std::sin(th));
    const double dx = px - P.x, dy = py - P.y;
    double D = dx * dx + dy * dy;
    if (D > p.R2) {
      if (!boundary) return;
      D = p.R2;
    }
    const double g = P.z + p.H(D);
    if (g < best) best = g;
  };
  eval(0, false);
  eval(a.T, false);
  if (rho == 0) return best;
  const double phi = std::atan2(qy, qx);
  auto at_psi = [&](double psi, bool boundary) {
    // every tau in [0, T] with th0 + dir tau = phi + psi (mod 2 pi)
    const double base = a.dir * (phi + psi - a.th0);
    const double j0 = std::ceil(-base / kTwoPi), j1 = std::floor((a.T - base) / kTwoPi);
    for (double j = j0; j <= j1; ++j) eval(base + kTwoPi * j, boundary);
  };
  at_psi(0, false);
  at_psi(kPi, false);
  // The edge of reach: tan(psi/2) = sqrt(R^2 - (rho - r)^2) / sqrt((rho + r)^2 - R^2).
  {
    const double u = (R - (rho - r)) * (R + (rho - r)), v = (rho + r - R) * (rho + r + R);
    if (u >= 0 && v > 0) {
      const double psi = 2 * std::atan2(std::sqrt(u), std::sqrt(v));
      at_psi(psi, true);
      at_psi(-psi, true);
    }
  }
  const double kap2 = a.kappa * a.kappa, rr = rho * r;
  double roots[2];
  int n = 0;
  if (p.kind == ToolShapeKind::ball) {
    // rho^2 r^2 sin^2 psi = kappa^2 (R^2 - D)
    n = quadratic(rr, 2 * kap2, (kap2 * (p.R2 - rho * rho - r * r) - rr * rr) / rr, roots);
  } else if (p.cone()) {
    // k^2 rho^2 r^2 sin^2 psi = kappa^2 D
    n = quadratic(p.k * p.k * rr, -2 * kap2, (kap2 * (rho * rho + r * r) - p.k * p.k * rr * rr) / rr, roots);
  }
  for (int i = 0; i < n; ++i) {
    if (!(roots[i] >= -1 - 1e-12 && roots[i] <= 1 + 1e-12)) continue;
    const double psi = std::acos(std::clamp(roots[i], -1.0, 1.0));
    at_psi(psi, false);
    at_psi(-psi, false);
  }
  return best;
}

// ---- arcs: the certified search -----------------------------------------------

namespace {

struct Iv {
  double lo, hi;
};
inline Iv operator+(Iv a, Iv b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Iv operator+(Iv a, double b) { return {a.lo + b, a.hi + b}; }
inline Iv mul(Iv a, Iv b) {
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  if (std::isnan(p1) || std::isnan(p2) || std::isnan(p3) || std::isnan(p4)) {
    // 0 x inf: the operands' signs still bound the product
    const bool nonneg = (a.lo >= 0 && b.lo >= 0) || (a.hi <= 0 && b.hi <= 0);
    const bool nonpos = (a.lo >= 0 && b.hi <= 0) || (a.hi <= 0 && b.lo >= 0);
    return {nonneg ? 0 : -kInf, nonpos ? 0 : kInf};
  }
  return {std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4})};
}
inline Iv scale(Iv a, double s) {
  if (s == 0) return {0, 0};
  return s > 0 ? Iv{a.lo * s, a.hi * s} : Iv{a.hi * s, a.lo * s};
}
inline Iv sqr(Iv a) {
  if (a.lo >= 0) return {a.lo * a.lo, a.hi * a.hi};
  if (a.hi <= 0) return {a.hi * a.hi, a.lo * a.lo};
  return {0, std::max(a.lo * a.lo, a.hi * a.hi)};
}
// Outward by a relative margin of the magnitude `mag` of the terms that made
// the interval: covers the rounding of the few operations before.
inline Iv widen(Iv a, double mag) {
  const double m = 64 * kEps * mag;
  return {a.lo - m, a.hi + m};
}
inline double mag(Iv a) { return std::max(std::abs(a.lo), std::abs(a.hi)); }

// cos over [lo, hi] given its values at the ends.
Iv cos_range(double lo, double hi, double clo, double chi) {
  if (hi - lo >= kTwoPi) return {-1, 1};
  Iv r{std::min(clo, chi), std::max(clo, chi)};
  if (kTwoPi * std::ceil(lo / kTwoPi) <= hi) r.hi = 1;
  if (kPi + kTwoPi * std::ceil((lo - kPi) / kTwoPi) <= hi) r.lo = -1;
  return r;
}
Iv sin_range(double lo, double hi, double slo, double shi) {
  if (hi - lo >= kTwoPi) return {-1, 1};
  Iv r{std::min(slo, shi), std::max(slo, shi)};
  if (kPi / 2 + kTwoPi * std::ceil((lo - kPi / 2) / kTwoPi) <= hi) r.hi = 1;
  if (-kPi / 2 + kTwoPi * std::ceil((lo + kPi / 2) / kTwoPi) <= hi) r.lo = -1;
  return r;
}

struct Pt {
  double tau = 0, th = 0, c = 0, s = 0;
  double D = 0, D1 = 0, D2 = 0, Z = 0, Z1 = 0, Z2 = 0;
  double g = kInf, g1 = 0;  // g and g' when feasible
  bool feasible = false;
};

class Search {
 public:
  Search(const ArcPrep& a, const Profile& p, double px, double py, FloorStats& st)
      : a_(a), p_(p), px_(px), py_(py), st_(st) {}

  double run(double best) {
    best_ = best;
    // Improvements below a few ulps of the heights are not worth an interval.
    tol_ = 8 * kEps * (std::abs(a_.zmin) + std::abs(a_.h0) + std::abs(a_.h1) + a_.rmax + p_.R);
    const int n = std::max(1, static_cast<int>(std::ceil(a_.T / (kPi / 4))));
    Pt prev = point(0);
    consider(prev);
    for (int i = 1; i <= n; ++i) {
      const Pt next = point(i == n ? a_.T : a_.T * i / n);
      consider(next);
      node(prev, next, 0, false);
      prev = next;
    }
    return best_;
  }

 private:
  static constexpr int kMaxDepth = 60;
  // Intervals one column may take; a search that would need more closes
  // the rest at their midpoints (counted with the depth-limited ones).
  static constexpr long kMaxNodes = 20000;

  Pt point(double tau) const {
    Pt q;
    q.tau = tau;
    q.th = a_.th0 + a_.dir * tau;
    q.c = std::cos(q.th);
    q.s = std::sin(q.th);
    const double r = std::lerp(a_.r0, a_.r1, tau / a_.T), e = a_.eps, d = a_.dir;
    const double P1[3] = {e * q.c - d * r * q.s, e * q.s + d * r * q.c, a_.kappa};
    const double P2[3] = {-2 * d * e * q.s - r * q.c, 2 * d * e * q.c - r * q.s, 0};
    const ArcPoint P = arc_point(a_, tau, q.c, q.s);  // the ends exactly
    const double X = P.x - px_, Y = P.y - py_;
    const double X1 = P1[a_.ix], Y1 = P1[a_.iy], X2 = P2[a_.ix], Y2 = P2[a_.iy];
    q.D = X * X + Y * Y;
    q.D1 = 2 * (X * X1 + Y * Y1);
    q.D2 = 2 * (X1 * X1 + X * X2 + Y1 * Y1 + Y * Y2);
    q.Z = P.z;
    q.Z1 = P1[a_.iz];
    q.Z2 = P2[a_.iz];
    // g and g' also just outside the reach (D clamped): a point of a node
    // known to lie within reach may round to just outside it.
    q.feasible = q.D <= p_.R2;
    q.g = q.Z + p_.H(q.D);
    const double h1 = p_.H1(q.D);
    q.g1 = q.Z1 + (q.D1 == 0 ? 0 : h1 * q.D1);
    return q;
  }

  void consider(const Pt& q) {
    if (q.feasible && q.g < best_) best_ = q.g;
  }

  // A point of the edge of reach inside [a, b] (D monotone there, one end
  // inside, the other outside): the last feasible point before the edge.
  Pt edge(const Pt& a, const Pt& b) const {
    Pt in = a.feasible ? a : b, out = a.feasible ? b : a;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (in.tau + out.tau);
      if (mid == in.tau || mid == out.tau) break;
      // secant on D - R^2, safeguarded to the middle half
      double t = in.tau + (p_.R2 - in.D) * (out.tau - in.tau) / (out.D - in.D);
      const double q1 = std::min(in.tau, out.tau), q2 = std::max(in.tau, out.tau), w = q2 - q1;
      if (!(t > q1 + 0.125 * w && t < q2 - 0.125 * w)) t = mid;
      const Pt m = point(t);
      (m.feasible ? in : out) = m;
    }
    return in;
  }

  // The minimiser of a function convex on [a, b] from its derivative
  // (increasing): f(a) < 0 < f(b). Newton's method safeguarded by bisection.
  template <class F1, class F2>
  double convex_root(double lo, double hi, F1 f1, F2 f2) const {
    double t = 0.5 * (lo + hi);
    for (int it = 0; it < 200; ++it) {
      const double f = f1(t);
      if (f == 0) return t;
      if (f < 0)
        lo = t;
      else
        hi = t;
      const double d = f2(t);
      double next = (std::isfinite(d) && d > 0 && std::isfinite(f)) ? t - f / d : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (next == t || next == lo || next == hi) return t;
      t = next;
    }
    return t;
  }

  struct Encl {
    Iv D, D1, D2, Z, Z1, Z2;
  };

  Encl enclose(const Pt& a, const Pt& b) const {
    const double thlo = std::min(a.th, b.th), thhi = std::max(a.th, b.th);
    const bool a_low = a.th <= b.th;
    const Iv C = cos_range(thlo, thhi, a_low ? a.c : b.c, a_low ? b.c : a.c);
    const Iv S = sin_range(thlo, thhi, a_low ? a.s : b.s, a_low ? b.s : a.s);
    const double ra = std::lerp(a_.r0, a_.r1, a.tau / a_.T), rb = std::lerp(a_.r0, a_.r1, b.tau / a_.T);
    const Iv r{std::min(ra, rb), std::max(ra, rb)};
    const double e = a_.eps, d = a_.dir;
    const Iv rC = mul(r, C), rS = mul(r, S);
    const double ha = std::lerp(a_.h0, a_.h1, a.tau / a_.T), hb = std::lerp(a_.h0, a_.h1, b.tau / a_.T);
    const Iv P0[3] = {rC + a_.ca, rS + a_.cb, Iv{std::min(ha, hb), std::max(ha, hb)}};
    const Iv P1[3] = {scale(C, e) + scale(rS, -d), scale(S, e) + scale(rC, d), Iv{a_.kappa, a_.kappa}};
    const Iv P2[3] = {scale(S, -2 * d * e) + scale(rC, -1), scale(C, 2 * d * e) + scale(rS, -1), Iv{0, 0}};
    const double scale_xy =
        std::abs(a_.ca) + std::abs(a_.cb) + a_.rmax + std::abs(px_) + std::abs(py_) + std::abs(a_.h0) + std::abs(a_.h1);
    const Iv X = widen(P0[a_.ix] + (-px_), scale_xy), Y = widen(P0[a_.iy] + (-py_), scale_xy);
    const Iv X1 = P1[a_.ix], Y1 = P1[a_.iy], X2 = P2[a_.ix], Y2 = P2[a_.iy];
    Encl E;
    E.D = sqr(X) + sqr(Y);
    E.D.lo = std::max(E.D.lo, 0.0);
    const Iv D1 = scale(mul(X, X1) + mul(Y, Y1), 2);
    const Iv D2 = scale(sqr(X1) + mul(X, X2) + sqr(Y1) + mul(Y, Y2), 2);
    E.D1 = widen(D1, 2 * (mag(X) * mag(X1) + mag(Y) * mag(Y1)));
    E.D2 = widen(D2, 2 * (mag(X1) * mag(X1) + mag(X) * mag(X2) + mag(Y1) * mag(Y1) + mag(Y) * mag(Y2)));
    E.Z = widen(P0[a_.iz], scale_xy);
    E.Z1 = widen(P1[a_.iz], mag(P1[a_.iz]));
    E.Z2 = widen(P2[a_.iz], mag(P2[a_.iz]));
    return E;
  }

  // H', H'' over a range of D within [0, R^2].
  Iv h1_range(Iv D) const {
    switch (p_.kind) {
      case ToolShapeKind::flat: return {0, 0};
      case ToolShapeKind::ball:
      case ToolShapeKind::bull: return {p_.H1(D.lo), p_.H1(D.hi)};
      case ToolShapeKind::vee:
      case ToolShapeKind::drill: return {p_.H1(D.hi), p_.H1(D.lo)};
    }
    return {0, 0};
  }
  Iv h2_range(Iv D) const {
    switch (p_.kind) {
      case ToolShapeKind::flat: return {0, 0};
      case ToolShapeKind::ball:
      case ToolShapeKind::vee:
      case ToolShapeKind::drill: return {p_.H2(D.lo), p_.H2(D.hi)};
      case ToolShapeKind::bull: {
        // H'' = (hb''(d) d - hb'(d)) / (4 d^3) lies in [0, hb''(dhi) / (4 dlo^2)]
        // on the torus (hb' <= hb'' (d - a0), both increasing), 0 on the flat.
        const double dlo = std::max(std::sqrt(D.lo), p_.a0), dhi = std::sqrt(D.hi);
        if (dhi <= p_.a0) return {0, 0};
        const double x = dhi - p_.a0, q = (p_.rc - x) * (p_.rc + x);
        if (q <= 0 || dlo <= 0) return {0, kInf};
        return {0, p_.rc2 / (q * std::sqrt(q)) / (4 * dlo * dlo) * (1 + 1e-12)};
      }
    }
    return {0, 0};
  }

  void node(const Pt& a, const Pt& b, int depth, bool feasible) {
    ++st_.generic_nodes;
    const Encl E = enclose(a, b);
    if (E.D.lo > p_.R2) return;  // out of reach
    Iv Dc{std::min(E.D.lo, p_.R2), std::min(E.D.hi, p_.R2)};
    if (E.Z.lo + p_.H(Dc.lo) >= best_ - tol_) return;  // cannot go below the best
    if (!feasible && E.D.hi <= p_.R2) feasible = true;
    if (!feasible) {
      if (E.D1.lo > 0 || E.D1.hi < 0) {  // D monotone on [a, b]
        if (a.feasible && b.feasible) return node(a, b, depth, true);
        if (!a.feasible && !b.feasible) return;
        const Pt e = edge(a, b);
        consider(e);
        if (a.feasible) return node(a, e, depth + 1, true);
        return node(e, b, depth + 1, true);
      }
      if (E.D2.lo > 0) {  // D convex: split at its minimum into monotone parts
        if (!(a.D1 < 0 && b.D1 > 0)) return split(a, b, depth);
        const double t = convex_root(
            a.tau, b.tau, [&](double u) { return point(u).D1; }, [&](double u) { return point(u).D2; });
        const Pt m = point(t);
        consider(m);
        if (!m.feasible) return;  // the closest approach is out of reach
        node(a, m, depth + 1, false);
        node(m, b, depth + 1, false);
        return;
      }
      return split(a, b, depth);
    }
    // Feasible on [a, b]: the ends are candidates already.
    const Iv h1 = h1_range(Dc);
    const Iv G1 = widen(E.Z1 + mul(h1, E.D1), mag(E.Z1) + mag(h1) * mag(E.D1));
    if (G1.lo >= 0 || G1.hi <= 0) return;  // monotone: the minimum is at an end
    const Iv h2 = h2_range(Dc);
    const Iv G2 = widen(E.Z2 + mul(h2, sqr(E.D1)) + mul(h1, E.D2),
                        mag(E.Z2) + mag(h2) * mag(E.D1) * mag(E.D1) + mag(h1) * mag(E.D2));
    if (G2.lo >= 0) {  // convex: the minimum is at an end or where g' = 0
      if (!(a.g1 < 0 && b.g1 > 0)) return;
      const double t = convex_root(
          a.tau, b.tau, [&](double u) { return point(u).g1; },
          [&](double u) {
            const Pt q = point(u);
            return q.Z2 + p_.H2(q.D) * q.D1 * q.D1 + p_.H1(q.D) * q.D2;
          });
      consider(point(t));
      return;
    }
    if (G2.hi <= 0) return;  // concave: the minimum is at an end
    // Two lines through the ends with the extreme slopes bound g from below.
    if (std::isfinite(G1.lo) && std::isfinite(G1.hi)) {
      const double t = std::clamp((b.g - a.g + G1.lo * a.tau - G1.hi * b.tau) / (G1.lo - G1.hi), a.tau, b.tau);
      if (a.g + G1.lo * (t - a.tau) >= best_ - tol_) return;
    }
    split(a, b, depth, true);
  }

  void split(const Pt& a, const Pt& b, int depth, bool feasible = false) {
    const double t = 0.5 * (a.tau + b.tau);
    const Pt m = point(t);
    consider(m);
    if (depth >= kMaxDepth || t == a.tau || t == b.tau || --budget_ <= 0) {
      ++st_.depth_limited;
      return;
    }
    // the lower half first: a lower best prunes more of the other
    if (std::min(a.g, m.g) <= std::min(m.g, b.g)) {
      node(a, m, depth + 1, feasible);
      node(m, b, depth + 1, feasible);
    } else {
      node(m, b, depth + 1, feasible);
      node(a, m, depth + 1, feasible);
    }
  }

  const ArcPrep& a_;
  const Profile& p_;
  double px_, py_;
  FloorStats& st_;
  double best_ = kInf, tol_ = 0;
  long budget_ = kMaxNodes;
};

}  // namespace

double arc_floor_search(const ArcPrep& a, const Profile& p, double px, double py, double best, FloorStats& st) {
  ++st.generic_columns;
  return Search(a, p, px, py, st).run(best);
}

double arc_floor(const ArcPrep& a, const Profile& p, double px, double py, double best, FloorStats& st) {
  ++st.columns;
  // Nothing of the move reaches below `best` over this column: the column's
  // distance to the path is at least the distance to the path's box (and,
  // in G17, to the annulus between the radii).
  double dx = std::max({a.xlo - px, px - a.xhi, 0.0}), dy = std::max({a.ylo - py, py - a.yhi, 0.0});
  double D = dx * dx + dy * dy;
  if (a.arc.plane == Plane::xy) {
    const double rho = std::hypot(px - a.ca, py - a.cb);
    const double dr = std::max({a.rmin - rho, rho - a.rmax, 0.0});
    D = std::max(D, dr * dr);
  }
  if (D > p.R2 * (1 + 1e-12)) return best;
  if (a.zmin + p.H(D) >= best) return best;
  if (a.circle && p.kind != ToolShapeKind::bull) return arc_floor_closed(a, p, px, py, best);
  return arc_floor_search(a, p, px, py, best, st);
}

void arc_row(const ArcPrep& a, const Profile& p, double y, double x0, double C, int i0, int i1, double* floors,
             FloorStats& st) {
  for (int i = i0; i <= i1; ++i) floors[i] = arc_floor(a, p, x0 + (i + 0.5) * C, y, floors[i], st);
}

}  // namespace bezcam::stock_detail
