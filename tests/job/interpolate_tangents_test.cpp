// More ways through points (curve-file.md): `method: "hermite"` with a
// tangent per point, and `end_tangents` clamping the cubic spline. Checked
// against the definitions, not against the code that builds them: the
// curve passes through every point, with the given derivatives (Hermite:
// per piece, t in [0, 1]; clamped spline: with respect to the chord-length
// parameter, at both ends), C1 (Hermite) or C2 (spline) at the joints.
#include <cmath>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "support/refusal.hpp"

namespace {

using namespace bezcam;

Job job_of(const std::string& entity) { return parse_job(R"({"bezcam": 1, "entities": [)" + entity + "]}", "t.json"); }

InputError refusal(const std::string& entity) {
  return test::refusal_of([&] { job_of(entity); });
}

void expect_near(const Vec3& a, const Vec3& b, double eps, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, eps) << what;
  EXPECT_NEAR(a.y, b.y, eps) << what;
  EXPECT_NEAR(a.z, b.z, eps) << what;
}

}  // namespace

TEST(Hermite, ThroughThePointsWithTheirDerivativesC1) {
  const Job j = job_of(R"({"type": "interpolate", "method": "hermite",
      "through": [[0, 0], [10, 5], [20, 0], [30, 8]],
      "tangents": [[12, 0], [6, -6], [10, 3], [0, 15]]})");
  const auto& g = j.entities[0].curve;
  ASSERT_EQ(g.pieces.size(), 3u);
  const Vec3 through[] = {{0, 0, 0}, {10, 5, 0}, {20, 0, 0}, {30, 8, 0}};
  const Vec3 tangents[] = {{12, 0, 0}, {6, -6, 0}, {10, 3, 0}, {0, 15, 0}};
  for (size_t i = 0; i < 3; ++i) {
    const Bezier& b = g.pieces[i];
    // The classic Hermite basis, evaluated here, against the piece.
    for (double t : {0.0, 0.25, 0.5, 0.8, 1.0}) {
      const double h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t;
      const double h01 = -2 * t * t * t + 3 * t * t, h11 = t * t * t - t * t;
      const Vec3 want = through[i] * h00 + tangents[i] * h10 + through[i + 1] * h01 + tangents[i + 1] * h11;
      expect_near(evaluate(b, t), want, 1e-12, "piece " + std::to_string(i) + " t " + std::to_string(t));
    }
    expect_near(derivative(b, 0), tangents[i], 1e-12, "start derivative");
    expect_near(derivative(b, 1), tangents[i + 1], 1e-12, "end derivative");
  }
  // Closed: a fourth piece back to the first point.
  const Job c = job_of(R"({"type": "interpolate", "method": "hermite", "closed": true,
      "through": [[0, 0], [10, 0], [5, 8]], "tangents": [[5, -5], [5, 5], [-10, 0]]})");
  ASSERT_EQ(c.entities[0].curve.pieces.size(), 3u);
  expect_near(c.entities[0].curve.pieces.back().back(), {0, 0, 0}, 0, "closing point");
  EXPECT_TRUE(c.entities[0].curve.closed);
}

TEST(Hermite, ConvertsInEveryModeWithinTolerance) {
  const Job j = job_of(R"({"type": "interpolate", "method": "hermite",
      "through": [[0, 0], [10, 5], [20, 0]], "tangents": [[12, 0], [6, -6], [10, 3]]})");
  for (const char* machine : {"generic", "fanuc", "linuxcnc"})
    for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
      ConvertOptions o;
      o.output = mode;
      const ConvertResult r = convert(j, load_machine_profile(machine), o);
      EXPECT_LE(r.program.max_measured, j.tolerance * (1 + 1e-3)) << machine << " " << to_string(mode);
    }
}

TEST(ClampedSpline, EndDerivativesHoldAndThePointsAreMet) {
  const Job j = job_of(R"({"type": "interpolate", "through": [[0, 0], [10, 5], [20, 0], [30, 8], [40, 0]],
      "end_tangents": [[0, 1], [1, 0]]})");
  const CurveSegment& seg = j.entities[0].curve.segments[0];
  ASSERT_TRUE(seg.nurbs);
  const NurbsCurve& c = *seg.nurbs;
  // The chord-length parameters, computed here.
  const Vec3 pts[] = {{0, 0, 0}, {10, 5, 0}, {20, 0, 0}, {30, 8, 0}, {40, 0, 0}};
  double t = 0;
  for (size_t k = 0; k < 5; ++k) {
    if (k) t += dist(pts[k - 1], pts[k]);
    expect_near(evaluate(c, t), pts[k], 1e-9, "point " + std::to_string(k));
  }
  // Derivatives with respect to that parameter, by central differences on
  // the exact curve (one-sided at the ends).
  const double h = 1e-6, T = t;
  expect_near((evaluate(c, h) - evaluate(c, 0)) / h, {0, 1, 0}, 1e-4, "start derivative");
  expect_near((evaluate(c, T) - evaluate(c, T - h)) / h, {1, 0, 0}, 1e-4, "end derivative");
  // Different end tangents make a different curve than the natural spline.
  const Job n = job_of(R"({"type": "interpolate", "through": [[0, 0], [10, 5], [20, 0], [30, 8], [40, 0]]})");
  EXPECT_GT(dist(evaluate(*n.entities[0].curve.segments[0].nurbs, 1.0), evaluate(c, 1.0)), 1e-3);
}

TEST(MoreWaysThroughPoints, MistakesAreRefusedNamingThePath) {
  InputError e =
      refusal(R"({"type": "interpolate", "method": "hermite", "through": [[0, 0], [1, 1]], "tangents": [[1, 0]]})");
  EXPECT_EQ(e.id(), "curve.tangent-count");
  EXPECT_EQ(e.where(), "t.json: entities[0].tangents");
  e = refusal(R"({"type": "interpolate", "method": "hermite", "through": [[0, 0], [1, 1]]})");
  EXPECT_EQ(e.where(), "t.json: entities[0].tangents");
  e = refusal(R"({"type": "interpolate", "through": [[0, 0], [1, 1]], "tangents": [[1, 0], [1, 0]]})");
  EXPECT_EQ(e.id(), "job.method");
  e = refusal(
      R"({"type": "interpolate", "through": [[0, 0], [1, 1], [2, 0]], "closed": true, "end_tangents": [[1, 0], [1, 0]]})");
  EXPECT_EQ(e.id(), "job.method");
  e = refusal(R"({"type": "interpolate", "through": [[0, 0], [1, 1]], "end_tangents": [[1, 0]]})");
  EXPECT_EQ(e.id(), "curve.tangent-count");
  e = refusal(R"({"type": "interpolate", "method": "hermit", "through": [[0, 0], [1, 1]]})");
  EXPECT_EQ(e.id(), "job.method");
}
