#pragma once
// The band's plan: on a planar polynomial cubic piece, the chords planned
// all at once from the density of the sagitta, then each one proven
// (band_planar_spread()), with the piece's tips where the plan breaks.
// Part of the flattener's translation unit (included by flatten_curve.cpp
// alone, so that its kernels inline into the loops that call them).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "flatten/band_search.hpp"
#include "flatten/band_simd.hpp"

namespace bezcam {

namespace {

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
// rounding (aimed a little low: a chord planned closer to the limit often
// needs the exact proof, the hull test reading a few per cent high, or
// does not fit and is planned again, which costs more than the few more
// chords; docs/flattening.md); a chord with an end on the curve (the
// piece's first and last) has less room and is planned shorter. Near an inflection, where f
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
constexpr double kSpreadAim = 0.92;
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
      if (v < 0)
        lo = t, glo = v, slo = s2, alo = a2;
      else
        hi = t, ghi = v, shi = s2, ahi = a2;
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

// band_planar_spread() on one piece, stage by stage: the density's running
// integral on the grid (grid()), the piece's breaks (inflections(),
// add_tips()), the plan over the integral (plan_from()), and the chords
// tried, proven and accepted (run()).
template <class Emit>
struct BandSpread {
  // The piece and the flattening (band_planar_spread()'s parameters).
  const Bezier& piece;
  const Prepared& P;
  bool final_piece;
  const FlattenOptions& opt;
  double tol, margin, shift;
  size_t pi;
  Vec3& Ar;
  double& bound;
  size_t& emitted;
  Emit& emit;
  double plan_budget;

  BandSpread(const Bezier& piece_, const Prepared& P_, bool final_piece_, const FlattenOptions& opt_, double tol_,
             double margin_, double shift_, size_t pi_, Vec3& Ar_, double& bound_, size_t& emitted_, Emit& emit_,
             double plan_budget_)
      : piece(piece_),
        P(P_),
        final_piece(final_piece_),
        opt(opt_),
        tol(tol_),
        margin(margin_),
        shift(shift_),
        pi(pi_),
        Ar(Ar_),
        bound(bound_),
        emitted(emitted_),
        emit(emit_),
        plan_budget(plan_budget_) {}

  // The power form's coordinates.
  double c0x = P.c0.x, c0y = P.c0.y, c1x = P.c1.x, c1y = P.c1.y;
  double c2x = P.c2.x, c2y = P.c2.y, c3x = P.c3.x, c3y = P.c3.y;
  double H2 = longest_sagitta(plan_budget, shift, shift);
  double inv8H = 1 / std::sqrt(8 * kSpreadAim * H2);
  // The cubic term: across an inflection a chord's gap is about
  // |M' x M'''| / |M'| h^3 / (72 sqrt 3), with M''' = 6 c3.
  double k3 = 6 / (72 * std::sqrt(3.0) * kSpreadAim * plan_budget);

  // The grid: densities D on kSpreadSamples intervals, the running
  // integral C on m of them (and its total), the intervals' inverse
  // widths W.
  double D[kSpreadSamples + 1];
  double C[kSpreadSamples + 1];
  double W[kSpreadSamples];
  int m = 16;
  double total = 0, inv_m = 0;

  // The plan from a vertex: the rest of the integral shared among as few
  // chords as fit, the last one (and the first, from a vertex on the curve)
  // counting for e of the units (both ends on the curve: e1).
  double e = 0, e1 = 0;
  int j = 0;         // the grid interval of `level`
  double level = 0;  // the integral at the planned end
  double unit = 0;   // the integral an inner chord covers
  int left = 0;      // chords left in the plan, the planned one included

  // The plan's breaks (add_tips()).
  double infl[2];
  int n_infl = 0;
  double brk[4];
  bool brk_tip[4];  // whether the break is a tip
  int n_brk = 0, n_tip = 0;
  bool tips_known = false;
  double seg_end = 1.0;  // the end of the stretch planned
  // The breaks after the plan's start: the first (k_next) and the one the
  // stretch planned ends at (k_end; n_brk: the piece's end); whether the
  // plan's start is on the curve; whether the chord planned is one tried
  // before the plan proper (it falls back to that when the chord does not
  // fit, in shrink()).
  int k_next = 0, k_end = 0;
  bool plan_on_curve = true, trial = false;

  // The current vertex: off the curve at (ax, ay), its rounding moved it
  // by dA; on the curve at parameter t0, (S0x, S0y), tangent (T0x, T0y).
  double ax = 0, ay = 0, dA = 0;
  double t0 = 0, S0x = 0, S0y = 0, T0x = 0, T0y = 0;
  int shrinks = 0;
  bool drop = false;  // the next try's end on the curve (repeated failures that shortening does not cure)
  double prev_dev = kInf;
  bool as_planned = true;  // the chord tried ends where the plan put it
  double t1 = 0;           // the end tried next

  // One vertex: the curve's point and tangent at t, B shifted towards the
  // convex side (none at an inflection, a straight stretch or the end),
  // its rounding and how far that moved it.
  struct Vtx {
    double t, onx, ony, d1x, d1y, Bx, By, disp;
    Vec3 Br;
    bool side;
  };

  bool grid();
  void inflections();
  bool add_tips(double from);
  double plan_trial(double from, double c, double room, double cend, int k_cap) __attribute__((noinline));
  double plan_from(double from, bool from_curve, int k_cap = 4, bool try_one = true);
  void run(const Vec3& A, double dispA);

  // The two densities at t: the sagitta's (d) and the cubic term's cube (g).
  void one(double t, double& d, double& g) const {
    const double d1x = (c3x * (3 * t) + c2x * 2) * t + c1x, d1y = (c3y * (3 * t) + c2y * 2) * t + c1y;
    const double d2x = c3x * (6 * t) + c2x * 2, d2y = c3y * (6 * t) + c2y * 2;
    const double is = 1 / std::sqrt(d1x * d1x + d1y * d1y);
    d = std::sqrt(std::abs(d1x * d2y - d1y * d2x) * is) * inv8H;
    g = std::abs(d1x * c3y - d1y * c3x) * is * k3;
  }
  template <int N>
  void densities(int from, int step);
  template <int M>
  void prefix() {
    constexpr int stride = kSpreadSamples / M;
    constexpr double inv = 1.0 / M;  // (a power of 2: multiplying by it divides exactly)
    C[0] = 0;
    for (int i = 1; i <= M; ++i) C[i] = C[i - 1] + 0.5 * (D[(i - 1) * stride] + D[i * stride]) * inv;
  }
  inline __attribute__((always_inline)) double at_level(double lv) {
    while (j < m - 1 && C[j + 1] < lv) ++j;
    return (j + std::clamp((lv - C[j]) * W[j], 0.0, 1.0)) * inv_m;
  }
  // The running integral at t (linear within its grid interval, which
  // goes to jj).
  double integral_at(double t, int& jj) const {
    jj = std::min(int(t * m), m - 1);
    return C[jj] + (t * m - jj) * (C[jj + 1] - C[jj]);
  }
  double brk_at(int k) const { return k < n_brk ? brk[k] : 1.0; }

  inline __attribute__((always_inline)) void finish(Vtx& v, double sx, double sy) const {
    v.Bx = v.onx + sx, v.By = v.ony + sy, v.side = sx != 0 || sy != 0;
    v.Br = Vec3{v.Bx, v.By};
    v.disp = 0;
    if (opt.decimals >= 0) {
      v.Br = quantize(v.Br, opt.decimals);
      v.disp = std::sqrt((v.Br.x - v.Bx) * (v.Br.x - v.Bx) + (v.Br.y - v.By) * (v.Br.y - v.By));
    }
  }
  inline __attribute__((always_inline)) void vertex(double t, Vtx& v) const;
  inline __attribute__((always_inline)) double chord(const Vtx& v, double& budget) const;
  inline __attribute__((always_inline)) void accept(const Vtx& v, double dev);
  inline __attribute__((always_inline)) double next(const Vtx& v);
#if defined(__SSE2__)
  inline __attribute__((always_inline)) void vertex2(double ta, double tb, Vtx& va, Vtx& vb) const;
  inline __attribute__((always_inline)) void chord2(const Vtx& va, const Vtx& vb, double& deva, double& ba,
                                                    double& devb, double& bb) const;
#endif
  bool shrink(const Vtx& v, double dev, double budget);
};

// N samples, from index `from` by `step`, two at a time with SSE2 (the
// same arithmetic as one()); the cubic term's root, rarely needed, after.
template <class Emit>
template <int N>
void BandSpread<Emit>::densities(int from, int step) {
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
}

// Densities on a grid of kSpreadSamples intervals, sampled every other
// one, then at all of them when the piece needs more than kSpreadRefine
// chords per interval (starting from every 4th would make the plan coarser
// and save no time); their running integral (trapezoid rule) on the grid
// of m intervals, and the intervals' inverse widths (divisions here, two
// at a time, off the chords' path). False where the plan cannot serve.
template <class Emit>
bool BandSpread<Emit>::grid() {
  // Where the last control points coincide, M'(1) = 0, but c1 + 2 c2 +
  // 3 c3 cancels to rounding noise, which the density would read as a
  // sharp turn. (M'(0) = c1 is exact.)
  const bool end_stationary = piece.points.back() == piece.points[piece.points.size() - 2];
  static_assert(kSpreadSamples == 32, "the grid is refined once, from 16 intervals to 32");
  m = 16;
  densities<18>(0, 2);  // (the 18th is past the end, unused)
  if (end_stationary) {
    double d1, g1;
    one(1 - 1e-6, d1, g1);
    D[kSpreadSamples] = g1 > d1 * d1 * d1 ? cbrt_estimate(g1) : d1;
  }
  prefix<16>();
  if (16 * kSpreadRefine < C[16]) {
    densities<16>(1, 2);
    m = 32;
    prefix<32>();
  }
  total = C[m];
  // (a density undefined even beside its sample gives infinity or NaN here)
  if (!(total < kSpreadMax)) return false;
#if defined(__SSE2__)
  for (int i = 0; i < m; i += 2) {
    const v2d lo = {C[i], C[i + 1]}, hi = {C[i + 1], C[i + 2]};
    const v2d w = 1 / (hi - lo);
    W[i] = hi[0] > lo[0] ? w[0] : 0.0;
    W[i + 1] = hi[1] > lo[1] ? w[1] : 0.0;
  }
#else
  for (int i = 0; i < m; ++i) W[i] = C[i + 1] > C[i] ? 1 / (C[i + 1] - C[i]) : 0.0;
#endif
  inv_m = 1.0 / m;
  e = std::sqrt(longest_sagitta(plan_budget, 0, shift) / H2), e1 = std::sqrt(plan_budget / H2);
  return true;
}

// The piece's inflections (CubicPowerForm::inflections()), those not
// within 5 % of an end, ascending: the plan puts a vertex on the curve at
// each and plans the stretches between them apart (seg_end: the end of the
// stretch planned). A chord across an inflection has its ends shifted to
// opposite sides, so the curve crosses it and it fits only when very
// short: such planned chords often fail. Split there, the planned chords
// fail less often, for a few more chords (the vertex on the curve, and
// each stretch's count rounded up on its own).
//
// The plan's breaks, where it puts a vertex on the curve and plans the
// stretches on either side apart: the inflections, and the piece's tips
// (planar_tips(), where it turns back on itself: a chord across a tip has
// the curve poke past its end). The tips are looked for on pieces that
// need at most kTipPlan chords (beyond, a vertex more or less at a tip
// matters little): at once on those that need at most kTipEager (to pass
// over them from the start), else once a chord does not fit (where a tip
// costs).
template <class Emit>
void BandSpread<Emit>::inflections() {
  double r[2];
  const int n = P.inflections(r);
  for (int i = 0; i < n; ++i)
    if (r[i] > 0.05 && r[i] < 0.95) infl[n_infl++] = r[i];
  n_brk = n_infl;
  for (int i = 0; i < n_infl; ++i) brk_tip[i] = false, brk[i] = infl[i];
  tips_known = !(total <= kTipPlan);
  if (total <= kTipEager) add_tips(0);
}

// Adds the piece's tips to the breaks; returns whether there is one after
// `from`.
template <class Emit>
bool BandSpread<Emit>::add_tips(double from) {
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
    for (int k = i; k > 0 && brk[k - 1] > brk[k]; --k)
      std::swap(brk[k - 1], brk[k]), std::swap(brk_tip[k - 1], brk_tip[k]);
  return tip[n_tip - 1] > from + 1e-9;
}

// A break is passed over while the stretch beyond it still needs only one
// chord by the plan (a curve that doubles back along its chord within it,
// or a short one across an inflection), not counting the share of the
// integral a tip itself takes (at most kTipShare: the density's integral
// over a turn of radius r is about pi sqrt(r / (8 H)) chords); and beside
// a tip, where the density's model of a chord (a small turn) does not
// hold, a stretch that would take two chords by the plan tries one first.
// From `from` (the integral c there), the stretch to break k_next (cend
// there) being short enough for either: sets k_end, seg_end and trial,
// returns the integral at seg_end.
template <class Emit>
double BandSpread<Emit>::plan_trial(double from, double c, double room, double cend, int k_cap) {
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
}

// The plan from `from`, passing over no break after k_cap, and trying a
// single chord first only when `try_one`: returns the end of its first
// chord.
template <class Emit>
double BandSpread<Emit>::plan_from(double from, bool from_curve, int k_cap, bool try_one) {
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
}

template <class Emit>
void BandSpread<Emit>::vertex(double t, Vtx& v) const {
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
    v.onx = piece.back().x, v.ony = piece.back().y;
    v.d1x = c3x * 3 + c2x * 2 + c1x;
    v.d1y = c3y * 3 + c2y * 2 + c1y;
  }
  finish(v, sx, sy);
}

// The chord from the current vertex to v: its bound (infinity: it cannot
// fit) and budget.
template <class Emit>
double BandSpread<Emit>::chord(const Vtx& v, double& budget) const {
  budget = tol - margin - std::max(dA, v.disp);
  const double h = (v.t - t0) * (1.0 / 3);
  const XY S[4] = {{S0x, S0y}, {S0x + T0x * h, S0y + T0y * h}, {v.onx - v.d1x * h, v.ony - v.d1y * h}, {v.onx, v.ony}};
  count_spread_tries(1);
  return budget > 0 ? band_cubic_planar(S, XY{ax, ay}, XY{v.Bx, v.By}, budget, nullptr) : kInf;
}

// v becomes the current vertex (its chord proven, of bound dev).
template <class Emit>
void BandSpread<Emit>::accept(const Vtx& v, double dev) {
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
}

// The next end after an accepted vertex v.
template <class Emit>
double BandSpread<Emit>::next(const Vtx& v) {
  if (as_planned && --left > 1) {
    level += unit;
    return std::max(t0, at_level(level));
  }
  if (as_planned && left == 1 && v.side) return seg_end;
  return plan_from(t0, !v.side);
}

#if defined(__SSE2__)
// vertex() at two parameters below 1 at once (the same arithmetic).
template <class Emit>
void BandSpread<Emit>::vertex2(double ta, double tb, Vtx& va, Vtx& vb) const {
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
}

// chord() from the current vertex to va and from va to vb; the second
// only matters when the first fits.
template <class Emit>
void BandSpread<Emit>::chord2(const Vtx& va, const Vtx& vb, double& deva, double& ba, double& devb, double& bb) const {
  ba = tol - margin - std::max(dA, va.disp);
  bb = tol - margin - std::max(va.disp, vb.disp);
  const v2d h = v2d{va.t - t0, vb.t - va.t} * (1.0 / 3);
  const v2d Sx0 = {S0x, va.onx}, Sy0 = {S0y, va.ony}, onx = {va.onx, vb.onx}, ony = {va.ony, vb.ony};
  const v2d Sx[4] = {Sx0, Sx0 + v2d{T0x, va.d1x} * h, onx - v2d{va.d1x, vb.d1x} * h, onx};
  const v2d Sy[4] = {Sy0, Sy0 + v2d{T0y, va.d1y} * h, ony - v2d{va.d1y, vb.d1y} * h, ony};
  bool ok[2];
  double dev[2];
  band_sufficient2(Sx, Sy, v2d{ax, va.Bx}, v2d{ay, va.By}, v2d{va.Bx, vb.Bx}, v2d{va.By, vb.By}, v2d{ba, bb}, ok, dev);
  count_spread_tries(2);
  auto full = [&](int i, double budget) {
    if (!(budget > 0)) return kInf;
    const XY S[4] = {{Sx[0][i], Sy[0][i]}, {Sx[1][i], Sy[1][i]}, {Sx[2][i], Sy[2][i]}, {Sx[3][i], Sy[3][i]}};
    return i == 0 ? band_cubic_planar(S, XY{ax, ay}, XY{va.Bx, va.By}, budget, nullptr)
                  : band_cubic_planar(S, XY{va.Bx, va.By}, XY{vb.Bx, vb.By}, budget, nullptr);
  };
  deva = ok[0] && ba > 0 ? dev[0] : full(0, ba);
  devb = !(deva <= ba) ? kInf : ok[1] && bb > 0 ? dev[1] : full(1, bb);
}
#endif

// A chord to v that does not fit: the next try is shorter, as if the
// sagitta grew like the square of the step; the search takes over the
// rest of a piece where that runs on (false: it has).
template <class Emit>
bool BandSpread<Emit>::shrink(const Vtx& v, double dev, double budget) {
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
  count_spread_shrink();
  return true;
}

// The chords from the piece's start (A, its rounding moved by dispA),
// proven one by one, or two at a time where the plan gives two inner
// vertices ahead (with SSE2; one at a time without: the same chords).
template <class Emit>
void BandSpread<Emit>::run(const Vec3& A, double dispA) {
  ax = A.x, ay = A.y, dA = dispA;
  t0 = 0, S0x = piece.front().x, S0y = piece.front().y, T0x = c1x, T0y = c1y;
  t1 = plan_from(0, true);
  Vtx v1, v2;
  for (;;) {
#if defined(__SSE2__)
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
  count_spread_piece();
}

template <class Emit>
void band_planar_spread(const Bezier& piece, const Prepared& P, bool final_piece, const FlattenOptions& opt, double tol,
                        double margin, double rounding, double shift, size_t pi, const Vec3& A, Vec3& Ar, double dispA,
                        double& bound, size_t& emitted, Emit& emit) {
  const double plan_budget = tol - margin - std::max(rounding, dispA);
  if (!(plan_budget > 0))
    return band_planar_piece(piece, P, final_piece, opt, tol, margin, shift, pi, A, Ar, dispA, bound, emitted, emit);
  BandSpread<Emit> s(piece, P, final_piece, opt, tol, margin, shift, pi, Ar, bound, emitted, emit, plan_budget);
  if (!s.grid())
    return band_planar_piece(piece, P, final_piece, opt, tol, margin, shift, pi, A, Ar, dispA, bound, emitted, emit);
  s.inflections();
  s.run(A, dispA);
}

}  // namespace

}  // namespace bezcam
