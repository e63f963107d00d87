// The flattener's entry points (flatten_curve.hpp): the chord bounds asked
// alone, the estimate of a flattening's size, and the flattening itself,
// by the band (bound_band(), planning or searching piece by piece) or on
// the curve (on_curve_search.hpp). One translation unit with the headers
// it includes, so that the kernels inline into the loops.
#include "bezcam/flatten/flatten_curve.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "flatten/band_plan.hpp"
#include "flatten/on_curve_search.hpp"

namespace bezcam {

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
      throw too_many("about " +
                     (std::isfinite(estimate) ? fmt_num(std::round(estimate)) : std::string("infinitely many")));
  }
  std::size_t emitted = 0;
  // (the refusal out of line: the sink stays inlined with the flattener)
  auto refuse = [&]() __attribute__((noinline, cold)) { throw too_many("at least " + std::to_string(emitted)); };
  auto emit_counted = [&](const FlatVertex& v) __attribute__((always_inline)) {
    if (++emitted > opt.max_vertices) [[unlikely]]
      refuse();
    emit(v);
  };

  const Vec3 Ar = quantize(pieces.front().front(), opt.decimals);
  emit_counted({Ar, 0, 0});
  if (!opt.on_curve) return bound_band(pieces, opt, tb, Ar, emit_counted);
  return on_curve_search(pieces, opt, margin, Ar, emit_counted);
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
  // The vertices go straight into the result, given room for a quarter
  // more than the thread's last result held (curves flattened one after
  // another are often alike): one allocation per call unless the curve
  // needs more room than that, no copy.
  thread_local size_t last = 0;
  FlattenResult r;
  r.points.reserve(std::min<size_t>(last + last / 4 + 4, size_t{1} << 16));
  r.bound = flatten_into(pieces, opt, r.points);
  last = r.points.size();
  return r;
}

}  // namespace bezcam
