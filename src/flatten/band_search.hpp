#pragma once
// The band's search for the longest chord that fits, chord by chord: its
// constants and model (sagitta(), the cross search across an inflection),
// and its fast form on planar polynomial cubics, band_planar_piece().
// Built with -DBEZCAM_FLATTEN_COUNTERS it counts its tries.
// Part of the flattener's translation unit (included by flatten_curve.cpp
// alone, so that its kernels inline into the loops that call them).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "flatten/chord_bounds.hpp"

namespace bezcam {

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
  double f_lo = kInf, f_hi = kInf;                              // f at lo and hi; infinity: not known
  int last = 0;                                                 // which end moved last: -1 lo, +1 hi
  double dt_last = 0, in_last = -1, dt_prev = 0, in_prev = -1;  // the last two tries on the side `last`
  double aim_budget = -1,
         aim_cbrt = 0;  // cbrt(kBandAim budget) for the last budget seen (the same for every try without rounding)
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
    std::fprintf(stderr, "planned    pieces %ld tries %ld shortened %ld\n", spread_pieces, spread_tries,
                 spread_shrinks);
    const char* names[3] = {"steered", "inflection", "last"};
    for (int k = 0; k < 3; ++k) {
      std::fprintf(stderr, "%-10s searches %ld tries %ld (%.2f)", names[k], searches[k], tries[k],
                   searches[k] ? double(tries[k]) / searches[k] : 0.0);
      for (int i = 0; i < 8; ++i) std::fprintf(stderr, " %ld", hist[k][i]);
      std::fprintf(stderr, "\n");
    }
  }
} g_counters;
#endif

// The counters' updates (nothing unless built with BEZCAM_FLATTEN_COUNTERS).
inline void count_spread_tries([[maybe_unused]] long n) {
#ifdef BEZCAM_FLATTEN_COUNTERS
  g_counters.spread_tries += n;
#endif
}
inline void count_spread_shrink() {
#ifdef BEZCAM_FLATTEN_COUNTERS
  ++g_counters.spread_shrinks;
#endif
}
inline void count_spread_piece() {
#ifdef BEZCAM_FLATTEN_COUNTERS
  ++g_counters.spread_pieces;
#endif
}

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

// One try's chord: its end B (exact, rounded), its bound and budget, the
// sub-curve's sagitta H (sagitta(); -infinity: not known), bend() at t1,
// the cross part's largest interior extreme (-1: not known), the curve's
// point M and tangent dM at t1, and whether B is on the curve.
struct BandTry {
  double t1 = 0, dev = 0, disp = 0, H = -kInf, budget = 0;
  double Bx = 0, By = 0, Brx = 0, Bry = 0, bend = 0, inner = -1;
  double Mx = 0, My = 0, dMx = 0, dMy = 0;
  bool on = false;
};

// band_planar_piece() on one piece: from the current vertex, the search
// for the next chord (search(), each try by try_chord()), then the chord
// accepted (accept()), until the piece's end.
template <class Emit>
struct BandPiece {
  // The piece and the flattening (band_planar_piece()'s parameters).
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

  // The power form's coordinates.
  double c0x = P.c0.x, c0y = P.c0.y, c1x = P.c1.x, c1y = P.c1.y;
  double c2x = P.c2.x, c2y = P.c2.y, c3x = P.c3.x, c3y = P.c3.y;
  // The current vertex: off the curve at (ax, ay) by offA, its rounding
  // moved by dispA; on the curve at t0, M(t0) = (S0x, S0y), M'(t0) =
  // (T0x, T0y); bend() there; the step to try first.
  double dispA = 0, offA = 0, bend0 = 0, t0 = 0, dt = 0;
  double ax = 0, ay = 0, S0x = 0, S0y = 0, T0x = 0, T0y = 0;
  // Two slots, the best chord so far and the one being tried, swapped by
  // index rather than copied, kept across the piece's searches.
  BandTry slot[2];
  // Without rounding every try of a search has the same budget, and so the
  // same largest sagittas (the one for B on the curve only when asked: it
  // takes a square root).
  double budget0 = 0, ls_shift = 0, ls_on_ = -1;

  BandPiece(const Bezier& piece_, const Prepared& P_, bool final_piece_, const FlattenOptions& opt_, double tol_,
            double margin_, double shift_, size_t pi_, Vec3& Ar_, double& bound_, size_t& emitted_, Emit& emit_)
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
        emit(emit_) {}

  double ls_on() { return ls_on_ >= 0 ? ls_on_ : (ls_on_ = longest_sagitta(budget0, offA, 0)); }
  void run(const Vec3& A, double dispA_start, double t_start, double offA_start, double dt_start);
  int search(double& lo);
  inline __attribute__((always_inline)) bool try_chord(BandTry& c, double t1, bool zero);
  void accept(const BandTry& best, double lo);
};

// One try to t1: B shifted across the curve, then (when allowed and of
// use, `zero`) B on the curve. Fills c; returns whether it fits.
template <class Emit>
bool BandPiece<Emit>::try_chord(BandTry& c, double t1, bool zero) {
  const int decimals = opt.decimals;
  bool ok = false;
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
    onx = piece.back().x, ony = piece.back().y;
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
  return ok;
}

// The search for the next chord from the current vertex, steered as
// described above; returns the slot of the chord found, and in lo its step.
template <class Emit>
int BandPiece<Emit>::search(double& lo) {
  lo = 0;
  double hi = kInf;  // largest dt known to fit (lo), smallest known not to
  // Without a bulge (chords across an inflection), the cross part's
  // interior extreme at lo and hi steers the search.
  CrossSearch cross;
  bool found = false;
  for (BandTry& c : slot) c.dev = 0, c.budget = 0, c.H = -kInf, c.on = false;
  int cur = 0;
  double step = kBandStep;
  budget0 = tol - margin - dispA;
  ls_shift = longest_sagitta(budget0, offA, shift);
  ls_on_ = -1;
#ifdef BEZCAM_FLATTEN_COUNTERS
  int n_tries = 0;
  bool unsteered = false;
#endif
  for (int iter = 0; iter < 200; ++iter) {
    const bool last = dt >= 1 - t0;
    if (last) dt = 1 - t0;
    BandTry& c = slot[cur];
    const double t1 = last ? 1.0 : t0 + dt;
    const bool ok = try_chord(c, t1, !found || slot[cur ^ 1].on);
    const bool shifted = !(ok && c.on);
    const double ls = opt.decimals >= 0 || c.budget != budget0 ? longest_sagitta(c.budget, offA, shifted ? shift : 0)
                      : shifted                                ? ls_shift
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
      double nd = !std::isfinite(fill) ? dt * (1 + step)
                  : fill > 0           ? dt * std::min(4.0, std::sqrt(kBandAim / fill))
                                       : 2 * dt;
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
#ifdef BEZCAM_FLATTEN_COUNTERS
  count_search(slot[cur ^ 1].t1 >= 1 ? 2 : unsteered ? 1 : 0, n_tries);
#endif
  return cur ^ 1;
}

// The chord found (of step lo) proven: its end becomes the current vertex,
// and the next search's first step is this one's, scaled by the room it
// left and the change of bending.
template <class Emit>
void BandPiece<Emit>::accept(const BandTry& best, double lo) {
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
  dispA = best.Brx == best.Bx && best.Bry == best.By
              ? 0.0
              : std::sqrt((best.Brx - best.Bx) * (best.Brx - best.Bx) + (best.Bry - best.By) * (best.Bry - best.By));
  S0x = best.Mx, S0y = best.My, T0x = best.dMx, T0y = best.dMy;
  offA = best.on ? 0.0 : shift;
}

template <class Emit>
void BandPiece<Emit>::run(const Vec3& A, double dispA_start, double t_start, double offA_start, double dt_start) {
  dispA = dispA_start;
  offA = offA_start;
  bend0 = P.bend(t_start);
  t0 = t_start;
  dt = dt_start > 0 ? dt_start : P.first_step(longest_sagitta(tol - margin - dispA, 0, shift));
  ax = A.x, ay = A.y;
  const Vec3 T0v = P.tangent(t_start), S0v = P.point(t_start);
  S0x = S0v.x, S0y = S0v.y, T0x = T0v.x, T0y = T0v.y;
  while (t0 < 1) {
    double lo;
    const int best = search(lo);
    accept(slot[best], lo);
  }
}

// The band's search on one planar polynomial cubic piece (the common case),
// steered by the bulge as described above. It works on plain x and y values
// (no z; the curve's point and tangent at t0 carried from the chord that
// ended there; the largest sagittas computed once per search when there is
// no rounding), for speed: it gives the same vertices as the general
// search (flatten_bench --only hash-all). bound_band() calls it for such
// pieces and searches every other one itself. `A`, `Ar` (the last vertex,
// exact and rounded) and `dispA` come in for the piece's start; `Ar` leaves
// as the piece's last vertex; `bound` and `emitted` accumulate.
template <class Emit>
void band_planar_piece(const Bezier& piece, const Prepared& P, bool final_piece, const FlattenOptions& opt, double tol,
                       double margin, double shift, size_t pi, const Vec3& A, Vec3& Ar, double dispA, double& bound,
                       size_t& emitted, Emit& emit, double t_start = 0, double offA_start = 0, double dt_start = 0) {
  BandPiece<Emit>(piece, P, final_piece, opt, tol, margin, shift, pi, Ar, bound, emitted, emit)
      .run(A, dispA, t_start, offA_start, dt_start);
}

}  // namespace

}  // namespace bezcam
