#pragma once
// The search with every vertex on the curve (FlattenOptions::on_curve):
// from each vertex, the longest chord whose bound fits the budget, found by
// a step search steered by how much of the budget each try uses.
// Part of the flattener's translation unit (included by flatten_curve.cpp
// alone, so that its kernels inline into the loops that call them).

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "flatten/chord_bounds.hpp"

namespace bezcam {

namespace {

// The vertices after the first (Ar, rounded, already emitted) of the
// flattening of `pieces` on the curve, each sent to `emit`; returns the
// bound. `margin`: the tolerance's floating-point margin (ToleranceBudget).
template <class Emit>
double on_curve_search(std::span<const Bezier> pieces, const FlattenOptions& opt, double margin, Vec3 Ar,
                       Emit& emit_counted) {
  const double tol = opt.tolerance;
  double bound = 0;
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

}  // namespace bezcam
