#include "bezcam/kernel/coons_patch.hpp"

#include <cmath>
#include <string>

#include "bernstein_ops.hpp"
#include "bezcam/error.hpp"
#include "bezcam/limits.hpp"

namespace bezcam {

using detail::Grid;
using detail::Hom;
using detail::Poly;

const char* to_string(CoonsBlend b) {
  switch (b) {
    case CoonsBlend::linear: return "linear";
    case CoonsBlend::cubic: return "cubic";
    case CoonsBlend::quintic: return "quintic";
  }
  return "?";
}

int blend_degree(CoonsBlend b) { return b == CoonsBlend::linear ? 1 : (b == CoonsBlend::cubic ? 3 : 5); }

double blend_f0(CoonsBlend b, double t, int order) {
  const double t2 = t * t, t3 = t2 * t;
  switch (b) {
    case CoonsBlend::linear: return order == 0 ? 1 - t : (order == 1 ? -1 : 0);
    case CoonsBlend::cubic:  // 2t^3 - 3t^2 + 1
      return order == 0 ? 2 * t3 - 3 * t2 + 1 : (order == 1 ? 6 * t2 - 6 * t : 12 * t - 6);
    case CoonsBlend::quintic:  // -6t^5 + 15t^4 - 10t^3 + 1
      return order == 0 ? -6 * t3 * t2 + 15 * t2 * t2 - 10 * t3 + 1
                        : (order == 1 ? -30 * t2 * t2 + 60 * t3 - 30 * t2 : -120 * t3 + 180 * t2 - 60 * t);
  }
  return 0;
}

double blend_f1(CoonsBlend b, double t, int order) {
  // f1 = 1 - f0 for all three blends (digest: f0 + f1 = 1).
  return order == 0 ? 1 - blend_f0(b, t, 0) : -blend_f0(b, t, order);
}

namespace {

// Bernstein coefficients of f0 on [0,1]: f0 = B0 + ... + B(k) of degree
// 2k+1 (linear (1,0); cubic (1,1,0,0); quintic (1,1,1,0,0,0)).
Poly<double> f0_coefficients(CoonsBlend b) {
  const int n = blend_degree(b);
  Poly<double> c(n + 1, 0.0);
  for (int i = 0; i <= n / 2; ++i) c[i] = 1;
  return c;
}
Poly<double> f1_coefficients(CoonsBlend b) {
  Poly<double> c = f0_coefficients(b);
  for (double& x : c) x = 1 - x;
  return c;
}

double magnitude(const BoundaryCurve& c) {
  double m = 0;
  for (const auto& b : c.pieces)
    for (const auto& p : b.points) m = std::max(m, max_abs(p));
  return m;
}

}  // namespace

BoundaryCurve BoundaryCurve::make(std::vector<Bezier> pieces, std::vector<double> breaks) {
  if (pieces.empty()) throw InputError(errc::coons_boundary_empty, Place{}, "expected a curve with at least one piece");
  if (breaks.size() != pieces.size() + 1 || breaks.front() != 0 || breaks.back() != 1)
    throw InputError(errc::coons_boundary_partition, Place{},
                     "internal: expected " + std::to_string(pieces.size() + 1) + " breaks from 0 to 1, found " +
                         std::to_string(breaks.size()));
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
    if (!(breaks[k + 1] > breaks[k]))
      throw InputError(errc::coons_boundary_partition, Place{}, "internal: breaks are not strictly increasing");
  for (const auto& b : pieces)
    if (b.dim != 3)
      throw InputError(errc::coons_dimension, Place{}, "expected a 3D curve (points [x, y, z]), found a 2D one");
  BoundaryCurve c;
  c.pieces = std::move(pieces);
  c.breaks = std::move(breaks);
  return c;
}

BoundaryCurve BoundaryCurve::make(std::vector<Bezier> pieces) {
  std::vector<double> br(pieces.size() + 1);
  for (size_t k = 0; k < br.size(); ++k) br[k] = double(k) / double(pieces.size());
  br.back() = 1;
  return make(std::move(pieces), std::move(br));
}

Vec3 evaluate(const BoundaryCurve& c, double t, int order) {
  const auto [k, s] = locate_span(c.breaks, t);
  const double span = c.breaks[k + 1] - c.breaks[k];
  return derivative_k(c.pieces[k], s, order) / std::pow(span, order);
}

CoonsPatch CoonsPatch::make(BoundaryCurve v0, BoundaryCurve v1, BoundaryCurve u0, BoundaryCurve u1, CoonsBlend blend) {
  const double scale = std::max({magnitude(v0), magnitude(v1), magnitude(u0), magnitude(u1), 1.0});
  const double tol = 1e-9 * scale;
  // v0 and v1 fix the corners; u0 and u1 must run between them.
  struct Check {
    const char* name;  // the u-boundary checked
    const BoundaryCurve* c;
    bool at_end;  // which end of it
    const char* corner;
    const char* ref_name;  // the v-boundary that fixes the corner
    const BoundaryCurve* ref;
    bool ref_end;
  };
  const Check checks[4] = {{"u0", &u0, false, "S(0,0)", "v0", &v0, false},
                           {"u0", &u0, true, "S(0,1)", "v1", &v1, false},
                           {"u1", &u1, false, "S(1,0)", "v0", &v0, true},
                           {"u1", &u1, true, "S(1,1)", "v1", &v1, true}};
  for (const auto& ck : checks) {
    const Vec3 want = ck.ref_end ? ck.ref->back() : ck.ref->front();
    const Vec3 got = ck.at_end ? ck.c->back() : ck.c->front();
    const double gap = dist(want, got);
    if (gap <= tol) continue;
    std::string hint;
    const Vec3 other = ck.at_end ? ck.c->front() : ck.c->back();
    const Vec3 ref_other = ck.ref_end ? ck.ref->front() : ck.ref->back();
    if (dist(other, want) <= tol)
      hint = "; its other end is there: reverse the points of " + std::string(ck.name);
    else if (dist(ref_other, got) <= tol)
      hint = "; the other end of " + std::string(ck.ref_name) + " is there: reverse the points of " + ck.ref_name;
    throw InputError(errc::coons_corner, Place::at_json(std::string("boundaries.") + ck.name),
                     std::string("expected ") + ck.name + " to " + (ck.at_end ? "end" : "start") + " at corner " +
                         ck.corner + " = " + fmt_point(want) + ", where " + ck.ref_name + " " +
                         (ck.ref_end ? "ends" : "starts") + ", found " + fmt_point(got) + ", " + fmt_num(gap) +
                         " away" + hint);
  }
  CoonsPatch s;
  s.v0 = std::move(v0);
  s.v1 = std::move(v1);
  s.u0 = std::move(u0);
  s.u1 = std::move(u1);
  s.blend = blend;
  return s;
}

namespace {
// d^p/du^p d^q/dv^q of the Coons formula: every term is a product of a
// function of u and a function of v.
Vec3 coons_mixed(const CoonsPatch& s, double u, double v, int p, int q) {
  const CoonsBlend b = s.blend;
  const double f0u = blend_f0(b, u, p), f1u = blend_f1(b, u, p), f0v = blend_f0(b, v, q), f1v = blend_f1(b, v, q);
  Vec3 r =
      evaluate(s.v0, u, p) * f0v + evaluate(s.v1, u, p) * f1v + evaluate(s.u0, v, q) * f0u + evaluate(s.u1, v, q) * f1u;
  r -= s.corner(0, 0) * (f0u * f0v) + s.corner(0, 1) * (f0u * f1v) + s.corner(1, 0) * (f1u * f0v) +
       s.corner(1, 1) * (f1u * f1v);
  return r;
}
}  // namespace

Vec3 evaluate(const CoonsPatch& s, double u, double v) { return coons_mixed(s, u, v, 0, 0); }

PatchDerivs evaluate_derivs(const CoonsPatch& s, double u, double v) {
  PatchDerivs d;
  d.p = coons_mixed(s, u, v, 0, 0);
  d.su = coons_mixed(s, u, v, 1, 0);
  d.sv = coons_mixed(s, u, v, 0, 1);
  d.suu = coons_mixed(s, u, v, 2, 0);
  d.suv = coons_mixed(s, u, v, 1, 1);
  d.svv = coons_mixed(s, u, v, 0, 2);
  return d;
}

namespace {

// Union of two partitions of [0,1]; breaks closer than 1e-12 are merged.
std::vector<double> merge_breaks(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> all(a);
  all.insert(all.end(), b.begin(), b.end());
  std::sort(all.begin(), all.end());
  std::vector<double> out;
  for (double x : all)
    if (out.empty() || x - out.back() > 1e-12) out.push_back(x);
  out.back() = 1;
  return out;
}

// Homogeneous coefficients of the boundary restricted to [ta, tb], which
// lies in one piece (up to merged breaks: a sliver outside the piece is
// covered by extrapolating it, exact for the polynomial it is).
Poly<Hom> restrict_boundary(const BoundaryCurve& c, double ta, double tb) {
  const size_t k = locate_span(c.breaks, 0.5 * (ta + tb)).first;
  const double a = c.breaks[k], span = c.breaks[k + 1] - a;
  double s0 = (ta - a) / span, s1 = (tb - a) / span;
  if (std::abs(s0) < 1e-14) s0 = 0;
  if (std::abs(s1 - 1) < 1e-14) s1 = 1;
  return detail::bern_restrict(detail::homogeneous(c.pieces[k]), s0, s1);
}

Poly<Hom> corner_poly(const Vec3& P, const Poly<double>& s) {
  Poly<Hom> r(s.size());
  for (size_t k = 0; k < s.size(); ++k) r[k] = Hom(P * s[k], s[k]);
  return r;
}

}  // namespace

PatchGrid to_bezier_cells(const CoonsPatch& s) {
  PatchGrid g;
  g.ubreaks = merge_breaks(s.v0.breaks, s.v1.breaks);
  g.vbreaks = merge_breaks(s.u0.breaks, s.u1.breaks);
  // One exact cell per pair of spans across: refuse a grid too large to
  // hold or to cut before building it (limits.hpp).
  const size_t cells = (g.ubreaks.size() - 1) * (g.vbreaks.size() - 1);
  if (cells > kMaxPatchCells)
    throw InputError(errc::limit_patch_cells, Place::at_json("boundaries"),
                     "the boundaries' " + std::to_string(g.ubreaks.size() - 1) + " spans along u and " +
                         std::to_string(g.vbreaks.size() - 1) + " along v make " + std::to_string(cells) +
                         " exact Bézier cells, more than the limit of " + std::to_string(kMaxPatchCells) +
                         " (docs/limits.md); use boundary curves with fewer knot spans or split the patch");
  bool rational = false;
  for (const BoundaryCurve* c : {&s.v0, &s.v1, &s.u0, &s.u1})
    for (const auto& b : c->pieces) rational = rational || b.rational();
  const Poly<double> F0 = f0_coefficients(s.blend), F1 = f1_coefficients(s.blend);
  auto hom_dbl = [](const Hom& h, double x) { return h * x; };
  auto dbl_hom = [](double x, const Hom& h) { return h * x; };
  auto dbl = [](double x, double y) { return x * y; };
  for (size_t a = 0; a + 1 < g.ubreaks.size(); ++a) {
    const double ua = g.ubreaks[a], ub = g.ubreaks[a + 1];
    const Poly<Hom> A = restrict_boundary(s.v0, ua, ub), B = restrict_boundary(s.v1, ua, ub);
    const Poly<double> f0u = detail::bern_restrict(F0, ua, ub), f1u = detail::bern_restrict(F1, ua, ub);
    for (size_t b = 0; b + 1 < g.vbreaks.size(); ++b) {
      const double va = g.vbreaks[b], vb = g.vbreaks[b + 1];
      const Poly<Hom> C = restrict_boundary(s.u0, va, vb), D = restrict_boundary(s.u1, va, vb);
      const Poly<double> f0v = detail::bern_restrict(F0, va, vb), f1v = detail::bern_restrict(F1, va, vb);
      // Common denominator W = alpha beta (u) gamma delta (v); each term is
      // (its point times its blend) * W written as a tensor product.
      const Poly<double> al = rational ? detail::weights_of(A) : Poly<double>{1.0};
      const Poly<double> be = rational ? detail::weights_of(B) : Poly<double>{1.0};
      const Poly<double> ga = rational ? detail::weights_of(C) : Poly<double>{1.0};
      const Poly<double> de = rational ? detail::weights_of(D) : Poly<double>{1.0};
      const Poly<double> ab = detail::bern_product(al, be, dbl), gd = detail::bern_product(ga, de, dbl);
      const Poly<double> ab0 = detail::bern_product(ab, f0u, dbl), ab1 = detail::bern_product(ab, f1u, dbl);
      Poly<double> gd0 = detail::bern_product(gd, f0v, dbl), gd1 = detail::bern_product(gd, f1v, dbl);
      std::vector<Grid<Hom>> terms;
      terms.push_back(detail::grid_tensor(detail::bern_scale(A, be), gd0, hom_dbl));
      terms.push_back(detail::grid_tensor(detail::bern_scale(B, al), gd1, hom_dbl));
      terms.push_back(detail::grid_tensor(ab0, detail::bern_scale(C, de), dbl_hom));
      terms.push_back(detail::grid_tensor(ab1, detail::bern_scale(D, ga), dbl_hom));
      for (double& x : gd0) x = -x;
      for (double& x : gd1) x = -x;
      terms.push_back(detail::grid_tensor(corner_poly(s.corner(0, 0), ab0), gd0, hom_dbl));
      terms.push_back(detail::grid_tensor(corner_poly(s.corner(0, 1), ab0), gd1, hom_dbl));
      terms.push_back(detail::grid_tensor(corner_poly(s.corner(1, 0), ab1), gd0, hom_dbl));
      terms.push_back(detail::grid_tensor(corner_poly(s.corner(1, 1), ab1), gd1, hom_dbl));
      int du = 0, dv = 0;
      for (const auto& t : terms) du = std::max(du, t.nu), dv = std::max(dv, t.nv);
      Grid<Hom> sum(du, dv);
      for (const auto& t : terms) {
        const Grid<Hom> e = detail::grid_elevate(t, du, dv);
        for (size_t k = 0; k < sum.c.size(); ++k) sum.c[k] += e.c[k];
      }
      BezierPatch cell;
      cell.nu = du;
      cell.nv = dv;
      for (const auto& h : sum.c) {
        cell.points.push_back(rational ? h.point() : h.p);
        if (rational) cell.weights.push_back(h.w);
      }
      g.cells.push_back(std::move(cell));
    }
  }
  return g;
}

}  // namespace bezcam
