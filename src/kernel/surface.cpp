#include "bezcam/kernel/surface.hpp"

#include <cmath>

#include "bernstein_ops.hpp"

namespace bezcam {

using detail::Poly;

namespace {

double orientation_of(const PatchGrid& g) {
  // Sum of the unit normals' z over a grid: the sign makes N point up on
  // most of the patch (a 3-axis tool comes from +z).
  double sum = 0;
  constexpr int n = 16;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const PatchDerivs d = evaluate_derivs(g, double(i) / n, double(j) / n);
      const Vec3 c = cross(d.su, d.sv);
      const double l = norm(c);
      if (l > 0) sum += c.z / l;
    }
  return sum >= 0 ? 1.0 : -1.0;
}

Bezier line2(double u0, double v0, double u1, double v1) {
  Bezier b;
  b.dim = 2;
  b.points = {{u0, v0}, {u1, v1}};
  return b;
}

Bezier scaled(Bezier b, double k) {
  for (auto& p : b.points) p *= k;
  return b;
}

}  // namespace

std::shared_ptr<const SurfaceGeometry> SurfaceGeometry::make(BezierPatch p) {
  auto s = std::make_shared<SurfaceGeometry>();
  s->kind = "bezier_patch";
  s->grid.cells = {p};
  s->source = std::move(p);
  s->orientation = orientation_of(s->grid);
  return s;
}

std::shared_ptr<const SurfaceGeometry> SurfaceGeometry::make(CoonsPatch p) {
  auto s = std::make_shared<SurfaceGeometry>();
  s->kind = "coons_patch";
  s->grid = to_bezier_cells(p);
  s->source = std::move(p);
  s->orientation = orientation_of(s->grid);
  return s;
}

int SurfaceGeometry::degree_u() const {
  int d = 0;
  for (const auto& c : grid.cells) d = std::max(d, c.nu);
  return d;
}
int SurfaceGeometry::degree_v() const {
  int d = 0;
  for (const auto& c : grid.cells) d = std::max(d, c.nv);
  return d;
}
bool SurfaceGeometry::rational() const {
  for (const auto& c : grid.cells)
    if (c.rational()) return true;
  return false;
}

PatchDerivs evaluate_derivs(const SurfaceGeometry& s, double u, double v) { return evaluate_derivs(s.grid, u, v); }

Vec3 evaluate(const SurfaceGeometry& s, double u, double v) {
  const auto [a, lu] = locate_span(s.grid.ubreaks, u);
  const auto [b, lv] = locate_span(s.grid.vbreaks, v);
  return evaluate(s.grid.cell(a, b), lu, lv);
}

Vec3 unit_normal(const SurfaceGeometry& s, double u, double v) {
  const PatchDerivs d = evaluate_derivs(s, u, v);
  const Vec3 n = cross(d.su, d.sv) * s.orientation;
  const double l = norm(n);
  return l > 0 ? n / l : Vec3{};
}

Curvatures principal_curvatures(const SurfaceGeometry& s, double u, double v) {
  // Second fundamental form with the oriented normal (do Carmo §3.3), so a
  // valley (bending toward N) has positive curvature, written in an
  // orthonormal frame of the tangent plane: the shape operator is then a
  // symmetric 2 x 2 matrix whose eigenvalues (a+c)/2 +- sqrt(((a-c)/2)^2 +
  // b^2) stay accurate at umbilics, where the H +- sqrt(H^2 - K) form loses
  // half the digits.
  const PatchDerivs d = evaluate_derivs(s, u, v);
  Curvatures c;
  const Vec3 n = cross(d.su, d.sv) * s.orientation;
  const double ln = norm(n), alpha = norm(d.su);
  if (!(ln > 0) || !(alpha > 0)) return c;
  const Vec3 N = n / ln, e1 = d.su / alpha;
  const double beta = dot(d.sv, e1);
  const double gamma = norm(d.sv - e1 * beta);
  if (!(gamma > 1e-12 * norm(d.sv))) return c;
  const double L = dot(d.suu, N), M = dot(d.suv, N), Nn = dot(d.svv, N);
  // Su = alpha e1, Sv = beta e1 + gamma e2; J^-1 = [[p, q], [0, r]].
  const double p = 1 / alpha, q = -beta / (alpha * gamma), r = 1 / gamma;
  const double a = L * p * p, b = p * (L * q + M * r), cc = L * q * q + 2 * M * q * r + Nn * r * r;
  const double mid = 0.5 * (a + cc), rad = std::hypot(0.5 * (a - cc), b);
  c.k_max = mid + rad;
  c.k_min = mid - rad;
  c.defined = true;
  return c;
}

Box3 bounds(const SurfaceGeometry& s) {
  Box3 b;
  for (const auto& c : s.grid.cells) b.add(bounds(c));
  return b;
}

SurfaceCurve iso_curve(const SurfaceGeometry& s, char dir, double at, bool with_normals) {
  SurfaceCurve c;
  const PatchGrid& g = s.grid;
  if (dir == 'u') {
    const auto [b, lv] = locate_span(g.vbreaks, at);
    for (size_t a = 0; a < g.cells_u(); ++a) {
      c.points.push_back(iso_curve(g.cell(a, b), 'u', lv));
      if (with_normals) c.normals.push_back(scaled(iso_normal(g.cell(a, b), 'u', lv), s.orientation));
      c.uv.push_back(line2(g.ubreaks[a], at, g.ubreaks[a + 1], at));
    }
    c.breaks = g.ubreaks;
  } else {
    const auto [a, lu] = locate_span(g.ubreaks, at);
    for (size_t b = 0; b < g.cells_v(); ++b) {
      c.points.push_back(iso_curve(g.cell(a, b), 'v', lu));
      if (with_normals) c.normals.push_back(scaled(iso_normal(g.cell(a, b), 'v', lu), s.orientation));
      c.uv.push_back(line2(at, g.vbreaks[b], at, g.vbreaks[b + 1]));
    }
    c.breaks = g.vbreaks;
  }
  return c;
}

namespace {

// Roots in (0,1) of a polynomial in Bernstein form, by subdivision: no
// sign change among the coefficients means no root (convex hull).
void bern_roots(const Poly<double>& c, double a, double b, int depth, std::vector<double>& out) {
  bool pos = false, neg = false;
  for (double x : c) pos = pos || x > 0, neg = neg || x < 0;
  if (!(pos && neg)) return;
  if (b - a < 1e-13 || depth > 60) {
    out.push_back(0.5 * (a + b));
    return;
  }
  const double m = 0.5 * (a + b);
  bern_roots(detail::bern_split(c, 0.5, true), a, m, depth + 1, out);
  bern_roots(detail::bern_split(c, 0.5, false), m, b, depth + 1, out);
}

// Parameters where the 2D curve crosses u = break (axis 0) or v = break.
void crossings(const Bezier& uv, int axis, const std::vector<double>& breaks, std::vector<double>& out) {
  double mag = 0;
  for (const auto& p : uv.points) mag = std::max(mag, std::abs(p[axis]));
  for (size_t k = 1; k + 1 < breaks.size(); ++k) {
    Poly<double> c(uv.points.size());
    double big = 0;
    for (size_t i = 0; i < c.size(); ++i) {
      c[i] = (uv.points[i][axis] - breaks[k]) * uv.weight(static_cast<int>(i));
      big = std::max(big, std::abs(c[i]));
    }
    if (big <= 1e-14 * std::max(mag, 1.0)) continue;  // runs along the border: either cell holds it
    bern_roots(c, 0, 1, 0, out);
  }
}

bool inside_unit(const Bezier& b, double slack) {
  for (const auto& p : b.points)
    if (p.x < -slack || p.x > 1 + slack || p.y < -slack || p.y > 1 + slack) return false;
  return true;
}

struct Mapper {
  const SurfaceGeometry& s;
  bool with_normals;
  std::vector<BezierPatch> normal_cache;
  std::vector<bool> cached;
  SurfaceCurve out;

  const BezierPatch& normals_of(size_t cell) {
    if (!cached[cell]) normal_cache[cell] = normal_patch(s.grid.cells[cell]), cached[cell] = true;
    return normal_cache[cell];
  }

  // `piece`: part of the uv curve lying in one cell, over [t0, t1] of the
  // result's parameter.
  void add(const Bezier& piece, double t0, double t1, int depth) {
    const PatchGrid& g = s.grid;
    const Vec3 mid = evaluate(piece, 0.5);
    const size_t a = locate_span(g.ubreaks, mid.x).first, b = locate_span(g.vbreaks, mid.y).first;
    const double ua = g.ubreaks[a], du = g.ubreaks[a + 1] - ua, va = g.vbreaks[b], dv = g.vbreaks[b + 1] - va;
    Bezier local = piece;
    for (auto& p : local.points) p = {(p.x - ua) / du, (p.y - va) / dv};
    const BezierPatch& cell = g.cell(a, b);
    // A rational cell needs the control points in its square (then every
    // weight of the composition is positive); they converge to the curve,
    // which is inside, under subdivision. A polynomial composition is an
    // identity whatever the control points.
    if (cell.rational() && !inside_unit(local, 1e-9)) {
      if (depth < 30) {
        auto [l, r] = split(piece, 0.5);
        const double tm = 0.5 * (t0 + t1);
        add(l, t0, tm, depth + 1);
        add(r, tm, t1, depth + 1);
        return;
      }
    }
    if (cell.rational())
      for (auto& p : local.points) p = {std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0)};
    out.points.push_back(compose(cell, local));
    if (with_normals)
      out.normals.push_back(scaled(compose_direction(normals_of(a * g.cells_v() + b), local), s.orientation));
    out.uv.push_back(piece);
    out.breaks.push_back(t1);
  }
};

}  // namespace

SurfaceCurve map_curve(const SurfaceGeometry& s, const CurveGeometry& uv, bool with_normals) {
  Mapper m{s,
           with_normals,
           std::vector<BezierPatch>(s.grid.cells.size()),
           std::vector<bool>(s.grid.cells.size(), false),
           {}};
  m.out.breaks.push_back(0);
  const double K = static_cast<double>(uv.pieces.size());
  for (size_t k = 0; k < uv.pieces.size(); ++k) {
    const Bezier& piece = uv.pieces[k];
    std::vector<double> cuts;
    crossings(piece, 0, s.grid.ubreaks, cuts);
    crossings(piece, 1, s.grid.vbreaks, cuts);
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> ws{0};
    for (double w : cuts)
      if (w > 1e-12 && w < 1 - 1e-12 && w - ws.back() > 1e-12) ws.push_back(w);
    ws.push_back(1);
    for (size_t i = 0; i + 1 < ws.size(); ++i)
      m.add(subcurve(piece, ws[i], ws[i + 1]), (double(k) + ws[i]) / K, (double(k) + ws[i + 1]) / K, 0);
  }
  m.out.breaks.back() = 1;
  return std::move(m.out);
}

std::pair<size_t, double> locate(const SurfaceCurve& c, double t) { return locate_span(c.breaks, t); }

std::pair<double, double> uv_at(const SurfaceCurve& c, double t) {
  const auto [k, s] = locate(c, t);
  const Vec3 p = evaluate(c.uv[k], s);
  return {p.x, p.y};
}

SurfaceCurve restrict(const SurfaceCurve& c, double t0, double t1) {
  SurfaceCurve r;
  const double span = t1 - t0;
  r.breaks.push_back(0);
  for (size_t k = 0; k + 1 < c.breaks.size(); ++k) {
    const double a = c.breaks[k], b = c.breaks[k + 1];
    const double lo = std::max(a, t0), hi = std::min(b, t1);
    if (!(hi > lo)) continue;
    const double s0 = (lo - a) / (b - a), s1 = (hi - a) / (b - a);
    r.points.push_back(subcurve(c.points[k], s0, s1));
    if (!c.normals.empty()) r.normals.push_back(subcurve(c.normals[k], s0, s1));
    r.uv.push_back(subcurve(c.uv[k], s0, s1));
    r.breaks.push_back((hi - t0) / span);
  }
  r.breaks.back() = 1;
  return r;
}

SurfaceCurve reversed(const SurfaceCurve& c) {
  SurfaceCurve r;
  for (size_t k = c.points.size(); k-- > 0;) {
    r.points.push_back(reversed(c.points[k]));
    if (!c.normals.empty()) r.normals.push_back(reversed(c.normals[k]));
    r.uv.push_back(reversed(c.uv[k]));
  }
  for (size_t k = c.breaks.size(); k-- > 0;) r.breaks.push_back(1 - c.breaks[k]);
  r.breaks.front() = 0;
  r.breaks.back() = 1;
  return r;
}

}  // namespace bezcam
