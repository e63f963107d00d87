#include "bezcam/cam/pass_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/limits.hpp"

namespace bezcam {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
const Vec3 kZ{0, 0, 1};
}  // namespace

namespace {

// Segment index of `p` whose parameter range holds t.
size_t segment_of(const TipPolyline& p, double t) {
  const size_t n = p.points.size();
  if (n < 2) return 0;
  size_t k = static_cast<size_t>(std::upper_bound(p.params.begin(), p.params.end(), t) - p.params.begin());
  k = k == 0 ? 0 : k - 1;
  return std::min(k, n - 2);
}

double dist_to_polyline(const Vec3& x, const TipPolyline& p, size_t from, size_t to) {
  if (p.points.size() == 1) return dist(x, p.points[0]);
  double m = kInf;
  for (size_t j = from; j < to; ++j) m = std::min(m, dist_to_segment(x, p.points[j], p.points[j + 1]));
  return m;
}

// Largest sampled distance from a's samples to b (each an upper bound of
// the true nearest distance; exact where it matters).
double directed_gap(const TipPolyline& a, const TipPolyline& b, double resolution, double limit) {
  constexpr size_t kWindow = 6;
  const size_t nb = b.points.size() > 1 ? b.points.size() - 1 : 1;
  double worst = 0;
  auto sample = [&](const Vec3& x, double t) {
    const size_t j = segment_of(b, t);
    const size_t lo = j > kWindow ? j - kWindow : 0, hi = std::min(nb, j + kWindow + 1);
    double d = dist_to_polyline(x, b, lo, hi);
    if (d + 0.5 * resolution > limit) d = dist_to_polyline(x, b, 0, nb);
    worst = std::max(worst, d);
  };
  for (size_t i = 0; i + 1 < a.points.size(); ++i) {
    const Vec3 &P = a.points[i], &Q = a.points[i + 1];
    const size_t steps = std::max<size_t>(1, static_cast<size_t>(std::ceil(dist(P, Q) / resolution)));
    for (size_t s = 0; s < steps; ++s) {
      const double f = double(s) / double(steps);
      sample(lerp(P, Q, f), a.params[i] + f * (a.params[i + 1] - a.params[i]));
    }
  }
  sample(a.points.back(), a.params.back());
  return worst;
}

}  // namespace

double polyline_gap_bound(const TipPolyline& a, const TipPolyline& b, double resolution, double limit) {
  return std::max(directed_gap(a, b, resolution, limit), directed_gap(b, a, resolution, limit)) + 0.5 * resolution;
}

namespace {

// Tool tip at surface parameters (t along the pass, c across), with its
// derivative along the pass: T' = P' + r N', N' = (n' - N <N, n'>) / |n|,
// n' = Suu x Sv + Su x Suv along u (Suv x Sv + Su x Svv along v).
struct TipSample {
  Vec3 p, d;
};
struct TipField {
  const SurfaceGeometry& s;
  char dir;
  double r;
  TipSample at(double t, double c) const {
    const double u = dir == 'u' ? t : c, v = dir == 'u' ? c : t;
    const PatchDerivs d = evaluate_derivs(s, u, v);
    const Vec3 pt = dir == 'u' ? d.su : d.sv;
    if (r == 0) return {d.p, pt};
    const Vec3 n = cross(d.su, d.sv) * s.orientation;
    const double l = norm(n);
    if (!(l > 0)) return {d.p, pt};
    const Vec3 N = n / l;
    const Vec3 nt = (dir == 'u' ? cross(d.suu, d.sv) + cross(d.su, d.suv) : cross(d.suv, d.sv) + cross(d.su, d.svv)) *
                    s.orientation;
    const Vec3 Nt = (nt - N * dot(N, nt)) / l;
    return {d.p + (N - kZ) * r, pt + Nt * r};
  }
};

// Estimated distance between passes c0 and c1 (both ways): at each sample
// along the pass, the distance from one tip curve to the other's tangent
// line at the same parameter, or to its end point where the foot of the
// perpendicular falls beyond the end. Accurate to second order in the
// stepover; the verification on polylines makes the result rigorous.
struct GapEstimator {
  TipField f;
  std::vector<double> ts;

  struct Row {
    double c = 0;
    std::vector<TipSample> s;
  };
  Row row(double c) const {
    Row r{c, {}};
    r.s.reserve(ts.size());
    for (double t : ts) r.s.push_back(f.at(t, c));
    return r;
  }
  double one_way(const Vec3& x, const TipSample& y, double t, double c) const {
    const double sp = norm(y.d);
    const Vec3 D = x - y.p;
    if (!(sp > 0)) return norm(D);
    const Vec3 e = y.d / sp;
    const double along = dot(D, e);
    const double foot = t + along / sp;
    if (foot < 0 || foot > 1) return dist(x, f.at(std::clamp(foot, 0.0, 1.0), c).p);
    return norm(D - e * along);
  }
  double gap(const Row& a, const Row& b) const {
    double g = 0;
    for (size_t i = 0; i < ts.size(); ++i) {
      g = std::max(g, one_way(a.s[i].p, b.s[i], ts[i], b.c));
      g = std::max(g, one_way(b.s[i].p, a.s[i], ts[i], a.c));
    }
    return g;
  }
};

std::vector<double> along_samples(const SurfaceGeometry& s, char dir) {
  constexpr int n = 96;
  std::vector<double> ts;
  for (int i = 0; i <= n; ++i) ts.push_back(double(i) / n);
  const auto& br = dir == 'u' ? s.grid.ubreaks : s.grid.vbreaks;
  ts.insert(ts.end(), br.begin(), br.end());
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

void check_options(const PassOptions& o) {
  if (!(o.stepover >= 4 * o.tolerance))
    throw InputError(errc::toolpath_stepover, Place::at_json("toolpath.stepover"),
                     "expected a stepover of at least 4 times the tolerance (" + fmt_num(4 * o.tolerance) +
                         "), found " + fmt_num(o.stepover) +
                         ": each pass may stray from the surface by the tolerance, which the spacing must absorb");
  if (o.direction != 'u' && o.direction != 'v') throw std::logic_error("pass direction must be u or v");
}

// `max_vertices`: what is left of the patch's share of the program
// (limits.hpp); flatten_tip() refuses more.
Pass make_pass(const SurfaceGeometry& s, const PassOptions& o, double at, size_t max_vertices) {
  Pass p;
  p.at = at;
  p.curve = iso_curve(s, o.direction, at, o.tool_radius > 0);
  FlattenOptions fo{o.tolerance, o.decimals};
  fo.max_vertices = max_vertices;
  p.poly = flatten_tip(p.curve, o.tool_radius, fo);
  return p;
}

// Stated limit (limits.hpp): the passes of one patch together produce at
// most kMaxProgramLines vertices. Estimated from the exact pass curves
// before any is flattened (the tip of a ball-end tool bends about as its
// surface curve does), so a stepover and a tolerance that would need
// millions are refused at once; counted while flattening as well.
void check_pass_segments(const SurfaceGeometry& s, const PassOptions& o, const std::vector<double>& ats) {
  const double budget = o.tolerance - max_rounding_displacement(o.decimals, 3);
  if (!(budget > 0)) return;  // the flattener refuses that, naming the decimals
  double total = 0;
  for (double c : ats) total += estimate_segments(iso_curve(s, o.direction, c, false).points, budget);
  if (total > static_cast<double>(kMaxProgramLines))
    throw InputError(errc::limit_segments, Place::at_json("tolerance"),
                     "the patch's " + std::to_string(ats.size()) + " passes need about " +
                         (std::isfinite(total) ? fmt_num(std::round(total)) : std::string("infinitely many")) +
                         " segments within tolerance " + fmt_num(o.tolerance) + ", more than the " +
                         std::to_string(kMaxProgramLines) +
                         " a program may hold (docs/limits.md); raise the tolerance or the stepover");
}

double target_gap(const PassOptions& o) { return 0.97 * (o.stepover - 2 * o.tolerance); }
double resolution_of(const PassOptions& o) { return o.stepover / 40; }

// Flattens the passes at `ats`, then verifies every neighbouring pair,
// inserting a pass midway where the bound exceeds the stepover.
// Stated limit (limits.hpp): passes on one patch.
[[noreturn]] void too_many_passes(const PassOptions& o, const std::string& found) {
  throw InputError(errc::toolpath_too_many_passes, Place::at_json("toolpath.stepover"),
                   "the patch needs " + found + " passes at stepover " + fmt_num(o.stepover) + ", more than the " +
                       std::to_string(kMaxPassesPerPatch) +
                       " one patch may have (docs/limits.md); use a larger stepover or split the patch");
}

PassPlan build_and_verify(const SurfaceGeometry& s, const PassOptions& o, const std::vector<double>& ats,
                          bool allow_insert) {
  if (ats.size() > kMaxPassesPerPatch) too_many_passes(o, std::to_string(ats.size()));
  check_pass_segments(s, o, ats);
  PassPlan plan;
  size_t vertices = 0;  // of every pass so far
  auto pass_at = [&](double c) {
    Pass p = make_pass(s, o, c, kMaxProgramLines - std::min(vertices, kMaxProgramLines));
    vertices += p.poly.points.size();
    return p;
  };
  for (double c : ats) plan.passes.push_back(pass_at(c));
  const double res = resolution_of(o);
  for (size_t i = 0; i + 1 < plan.passes.size();) {
    const double g = polyline_gap_bound(plan.passes[i].poly, plan.passes[i + 1].poly, res, o.stepover);
    if (g <= o.stepover) {
      plan.gap_bound = std::max(plan.gap_bound, g);
      ++i;
      continue;
    }
    if (!allow_insert) {
      plan.gap_bound = kInf;
      return plan;
    }
    const double a = plan.passes[i].at, b = plan.passes[i + 1].at;
    if (b - a < 1e-9)
      throw InputError(errc::toolpath_stepover, Place::at_json("toolpath.stepover"),
                       "neighbouring passes near " + std::string(1, o.direction == 'u' ? 'v' : 'u') + " = " +
                           fmt_num(a) + " stay " + fmt_num(g) +
                           " apart however close their parameters are: "
                           "the tool path jumps there (a crease under a ball-end tool?); use a larger stepover or a "
                           "smaller tool_radius");
    if (plan.passes.size() >= kMaxPassesPerPatch) too_many_passes(o, "more than " + std::to_string(plan.passes.size()));
    plan.passes.insert(plan.passes.begin() + static_cast<std::ptrdiff_t>(i) + 1, pass_at(0.5 * (a + b)));
    ++plan.refined;
  }
  for (const auto& p : plan.passes) plan.bound = std::max(plan.bound, p.poly.bound);
  return plan;
}

}  // namespace

PassPlan plan_passes(const SurfaceGeometry& s, const PassOptions& o) {
  check_options(o);
  const GapEstimator est{{s, o.direction, o.tool_radius}, along_samples(s, o.direction)};
  const double target = target_gap(o);
  std::vector<double> ats{0};
  double c = 0, step = 1.0 / 64;
  GapEstimator::Row here = est.row(0);
  // The first and last passes' distance needs this many steps at least:
  // refuse a stepover far too small for the patch before planning.
  const double across = est.gap(here, est.row(1));
  if (across > target * static_cast<double>(kMaxPassesPerPatch))
    too_many_passes(o, "about " + fmt_num(std::ceil(across / target)) + " or more");
  while (c < 1) {
    if (ats.size() > kMaxPassesPerPatch) too_many_passes(o, "more than " + std::to_string(kMaxPassesPerPatch));
    // The gap grows about linearly with the step: secant steps aimed at
    // 99.7 % of the target, accepted from 99.4 % (then the step is within
    // about 0.6 % of the largest that fits), bisection as a fallback.
    double lo = 0, hi = kInf, s_try = std::min(step, 1 - c);
    GapEstimator::Row best;
    for (int iter = 0; iter < 60; ++iter) {
      const bool last = s_try >= 1 - c;
      GapEstimator::Row next = est.row(last ? 1.0 : c + s_try);
      const double g = est.gap(here, next);
      if (g <= target) {
        lo = s_try;
        best = std::move(next);
        if (last || g >= 0.994 * target || lo >= 0.995 * hi) break;
        double nx = g > 0 ? s_try * std::min(0.997 * target / g, 4.0) : 4 * s_try;
        if (nx >= hi) nx = 0.5 * (lo + hi);
        s_try = std::min(nx, 1 - c);
      } else {
        hi = s_try;
        if (lo > 0 && lo >= 0.995 * hi) break;
        double nx = s_try * std::clamp(0.997 * target / g, 0.1, 0.999);
        if (nx <= lo) nx = 0.5 * (lo + hi);
        s_try = nx;
      }
      if (lo == 0 && s_try < 1e-9) break;
    }
    if (lo == 0) {  // nothing fits however small: let the verification decide
      lo = std::min(s_try, 1 - c);
      best = est.row(c + lo >= 1 - 1e-12 ? 1.0 : c + lo);
    }
    c = c + lo >= 1 - 1e-12 ? 1.0 : c + lo;
    best.c = c;
    ats.push_back(c);
    here = std::move(best);
    step = lo;
  }
  return build_and_verify(s, o, ats, true);
}

PassPlan plan_uniform_passes(const SurfaceGeometry& s, const PassOptions& o) {
  check_options(o);
  const GapEstimator est{{s, o.direction, o.tool_radius}, along_samples(s, o.direction)};
  const double target = target_gap(o);
  auto fits = [&](size_t n) {  // n intervals
    GapEstimator::Row a = est.row(0);
    for (size_t k = 0; k < n; ++k) {
      GapEstimator::Row b = est.row(double(k + 1) / double(n));
      if (est.gap(a, b) > target) return false;
      a = std::move(b);
    }
    return true;
  };
  // Smallest interval count whose estimated gaps all fit (doubling, then
  // bisection), then the smallest that also verifies on the polylines.
  size_t hi = 1;
  while (!fits(hi)) {
    if (hi >= kMaxPassesPerPatch) too_many_passes(o, "more than " + std::to_string(hi));
    hi = std::min<size_t>(2 * hi, kMaxPassesPerPatch);
  }
  size_t lo = hi / 2;
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    (fits(mid) ? hi : lo) = mid;
  }
  for (size_t n = hi;; n += std::max<size_t>(1, n / 50)) {
    std::vector<double> ats;
    for (size_t k = 0; k <= n; ++k) ats.push_back(double(k) / double(n));
    PassPlan p = build_and_verify(s, o, ats, false);
    if (std::isfinite(p.gap_bound)) return p;
  }
}
}  // namespace bezcam
