// The flattener's stated limits (limits.hpp, docs/limits.md): pathological
// but valid inputs finish or are refused quickly. "Quickly" is checked by
// ctest's TIMEOUT for *Limits* tests (CMakeLists.txt), not by assertions.
#include "bezcam/limits.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "bezcam/cam/gouge.hpp"
#include "bezcam/cam/pass_plan.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "support/surface_fixtures.hpp"

namespace bezcam {
namespace {

std::string refusal_id(const std::function<void()>& f, std::string* message = nullptr) {
  try {
    f();
  } catch (const InputError& e) {
    if (message) *message = e.message();
    return e.id();
  }
  return "";
}

}  // namespace

TEST(Limits, DegreeSixtyFlattensWithinTheToleranceQuickly) {
  std::vector<Vec3> pts;
  for (int k = 0; k <= 60; ++k) pts.push_back({double(k), 10 * std::sin(0.7 * k), 0});
  const Bezier b = Bezier::make(pts);
  const FlattenResult r = flatten(b, {0.01, 3});
  EXPECT_LE(r.bound, 0.01);
  EXPECT_GT(r.points.size(), 2u);
  EXPECT_LE(measure_deviation(std::span<const Bezier>(&b, 1), r.points, 0.01).max(), 0.01);
}

TEST(Limits, ACurveTooLongForItsToleranceIsRefusedBeforeTheWork) {
  // 10^5 S-shaped cubics end to end, 10^6 mm long, at 0.001 mm: millions of
  // chords. The estimate refuses it before the first chord.
  std::vector<Bezier> pieces;
  for (int k = 0; k < 100'000; ++k) {
    const double x = 10.0 * k;
    pieces.push_back(Bezier::make({{x, 0, 0}, {x + 3, 8, 0}, {x + 7, -8, 0}, {x + 10, 0, 0}}));
  }
  const double estimate = estimate_segments(pieces, 0.001);
  EXPECT_GT(estimate, double(kMaxProgramLines));
  std::string msg;
  EXPECT_EQ(refusal_id([&] { flatten(pieces, {0.001, -1}); }, &msg), "limit.segments");
  EXPECT_NE(msg.find("more than the 1000000 a program may hold"), std::string::npos) << msg;
}

TEST(Limits, TheEstimateIsCloseToTheCountAndTheCountIsCheckedToo) {
  // A semicircle of radius 10 (two rational quarters): the estimate is the
  // count to within 10 %: at twice the tolerance for the band (the default,
  // whose chords may use the tolerance on both sides of the curve), at the
  // tolerance with vertices on the curve.
  const double w = std::sqrt(0.5);
  const std::vector<Bezier> arc = {Bezier::make({{10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, {1, w, 1}),
                                   Bezier::make({{0, 10, 0}, {-10, 10, 0}, {-10, 0, 0}}, {1, w, 1})};
  const FlattenResult full = flatten(arc, {0.01, -1});
  const double segments = double(full.points.size() - 1);
  const double estimate = estimate_segments(arc, 0.02);
  EXPECT_NEAR(estimate, segments, 0.1 * segments);
  const double on_curve = double(flatten(arc, {.tolerance = 0.01, .decimals = -1, .on_curve = true}).points.size() - 1);
  EXPECT_NEAR(estimate_segments(arc, 0.01), on_curve, 0.1 * on_curve);
  // A limit the estimate allows but the flattening exceeds: refused while
  // flattening, as soon as the count is passed.
  FlattenOptions o{0.01, -1};
  o.max_vertices = full.points.size() - 1;
  ASSERT_LE(estimate, double(o.max_vertices));
  std::string msg;
  EXPECT_EQ(refusal_id([&] { flatten(arc, o); }, &msg), "limit.segments");
  EXPECT_NE(msg.find("at least " + std::to_string(full.points.size())), std::string::npos) << msg;
}

TEST(Limits, ANanometreAtAHundredMetresIsRefused) {
  // 1e-9 mm at 1e5 mm: below what double precision can honour.
  const Bezier b = Bezier::make({{1e5, 0, 0}, {1e5 + 10, 10, 0}, {1e5 + 20, 0, 0}});
  std::string msg;
  EXPECT_EQ(refusal_id([&] { flatten(b, {1e-9, -1}); }, &msg), "flatten.tolerance-below-precision");
  EXPECT_NE(msg.find("magnitude 100020"), std::string::npos) << msg;
}

TEST(Limits, ATinyStepoverIsRefusedBeforeAnyPassIsComputed) {
  // A 100 mm wide patch at a stepover of 0.004 mm: 25000 passes.
  const auto s = SurfaceGeometry::make(fixtures::paraboloid(50, 100));
  PassOptions o;
  o.tolerance = 0.001;
  o.stepover = 0.004;
  std::string msg;
  EXPECT_EQ(refusal_id([&] { plan_passes(*s, o); }, &msg), "toolpath.too-many-passes");
  EXPECT_NE(msg.find("more than the 10000 one patch may have"), std::string::npos) << msg;
  EXPECT_EQ(refusal_id([&] { plan_uniform_passes(*s, o); }), "toolpath.too-many-passes");
}

TEST(Limits, AHugeStepoverWithATinyToleranceIsRefusedOrFinishes) {
  // A wavy bicubic patch, stepover far larger than the patch: two passes.
  std::mt19937 rng(7);
  const auto s = SurfaceGeometry::make(fixtures::random_patch(rng, 3, 3, false));
  PassOptions o;
  o.stepover = 1e6;
  o.tolerance = 0.01;
  EXPECT_EQ(plan_passes(*s, o).passes.size(), 2u);
  // Chords grow like sqrt(tolerance): pick the tolerance at which the two
  // passes need about 3 million together, more than a program may hold.
  // Refused from the estimate, before either pass is flattened.
  const double at_one = estimate_segments(iso_curve(*s, 'u', 0, false).points, 1.0) +
                        estimate_segments(iso_curve(*s, 'u', 1, false).points, 1.0);
  o.tolerance = std::pow(at_one / 3e6, 2);
  std::string msg;
  EXPECT_EQ(refusal_id([&] { plan_passes(*s, o); }, &msg), "limit.segments");
  EXPECT_NE(msg.find("the patch's 2 passes need about"), std::string::npos) << msg;
}

}  // namespace bezcam
