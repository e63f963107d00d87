// The `bspline` and `interpolate` entities of docs/job-format.md: parsed into
// exact pieces with the B-spline kept for exact output, errors naming the
// JSON path, the Lagrange overshoot warning.
#include <cmath>
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

using namespace bezcam;

namespace {

std::string job_with(const std::string& entities) {
  return R"({"bezcam": 1, "units": "mm", "tolerance": 0.01, "entities": [)" + entities + "]}";
}

InputError refusal(const std::string& text) {
  try {
    parse_job(text, "t.json");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a refusal of " << text;
  return InputError(ErrorId(""), Place{}, "");
}

const std::string kCircle =
    R"({"id": "circle", "type": "bspline", "degree": 2,
        "points": [[40,0],[40,40],[0,40],[-40,40],[-40,0],[-40,-40],[0,-40],[40,-40],[40,0]],
        "weights": [1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1],
        "knots": [0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1]})";

const std::string kLine = R"({"type": "bezier", "points": [[0,0],[10,0]]})";

}  // namespace

TEST(JobJsonNurbs, BsplineCircleIsExactAndKeepsItsNurbs) {
  const Job job = parse_job(job_with(kCircle), "t.json");
  ASSERT_EQ(job.entities.size(), 1u);
  const CurveGeometry& g = job.entities[0].curve;
  EXPECT_EQ(g.kind, "bspline");
  EXPECT_EQ(g.dim, 2);
  ASSERT_EQ(g.pieces.size(), 4u);
  EXPECT_TRUE(g.rational());
  EXPECT_EQ(g.max_degree(), 2);
  for (const auto& b : g.pieces)
    for (int i = 0; i <= 100; ++i) EXPECT_NEAR(norm(evaluate(b, i / 100.0)), 40, 1e-12 * 40);
  EXPECT_NEAR(g.length(), 2 * M_PI * 40, 1e-8);
  ASSERT_TRUE(g.segments[0].nurbs);
  const NurbsCurve& c = *g.segments[0].nurbs;
  EXPECT_EQ(c.knots, (std::vector<double>{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}));
  EXPECT_EQ(c.points.size(), 9u);
  EXPECT_EQ(c.degree, 2);
}

TEST(JobJsonNurbs, EqualWeightsMeanAPolynomialCurve) {
  const Job job =
      parse_job(job_with(R"({"type": "bspline", "degree": 3, "points": [[0,0],[10,20],[30,20],[40,0],[60,10]],
      "weights": [2,2,2,2,2], "knots": [0,0,0,0,0.5,1,1,1,1]})"),
                "t.json");
  const CurveGeometry& g = job.entities[0].curve;
  EXPECT_FALSE(g.rational());
  EXPECT_EQ(g.pieces.size(), 2u);
  EXPECT_FALSE(g.pieces[0].rational());
  EXPECT_TRUE(g.segments[0].nurbs->weights.empty());
}

TEST(JobJsonNurbs, UnclampedBsplineIsCutOverItsDomain) {
  // Uniform cubic: domain [knots[3], knots[6]] = [3, 6], three pieces.
  const Job job = parse_job(job_with(R"({"type": "bspline", "degree": 3,
      "points": [[0,0],[10,20],[30,25],[40,0],[60,-10],[70,10]], "knots": [0,1,2,3,4,5,6,7,8,9]})"),
                            "t.json");
  const CurveGeometry& g = job.entities[0].curve;
  ASSERT_EQ(g.pieces.size(), 3u);
  // A uniform cubic B-spline starts at (P0 + 4 P1 + P2) / 6.
  EXPECT_LE(dist(g.pieces.front().front(), Vec3{70.0 / 6, 105.0 / 6, 0}), 1e-12 * 70);
  EXPECT_FALSE(g.segments[0].nurbs->clamped());  // kept as given
}

TEST(JobJsonNurbs, PathOfBezierAndBsplineSegments) {
  const Job job = parse_job(job_with(R"({"id": "mixed", "type": "path", "segments": [
      {"type": "bezier", "points": [[0,0],[10,0],[20,10]]},
      {"type": "bspline", "degree": 2, "points": [[20,10],[30,20],[40,10],[50,0]], "knots": [0,0,0,0.5,1,1,1]},
      {"type": "bezier", "points": [[50,0],[60,-10],[70,0]]}]})"),
                            "t.json");
  const CurveGeometry& g = job.entities[0].curve;
  EXPECT_EQ(g.kind, "path");
  ASSERT_EQ(g.segments.size(), 3u);
  EXPECT_EQ(g.segments[1].kind, "bspline");
  EXPECT_EQ(g.segments[1].piece_count, 2u);
  EXPECT_TRUE(g.segments[1].nurbs);
  EXPECT_FALSE(g.segments[0].nurbs);
  ASSERT_EQ(g.pieces.size(), 4u);
  // Bézier end derivative 2 ((20,10) - (10,0)) = (20,20); the B-spline's
  // first piece covers [0, 0.5], so its start derivative per piece parameter
  // is 0.5 * 2 / 0.5 ((30,20) - (20,10)) = (20,20): C1 (second derivatives
  // differ). Likewise at the second joint, (20,-20) on both sides.
  ASSERT_EQ(g.joints.size(), 2u);
  EXPECT_EQ(g.joints[0], Continuity::C1);
  EXPECT_EQ(g.joints[1], Continuity::C1);
}

TEST(JobJsonNurbs, ErrorsNameTheJsonPath) {
  // The example of the brief: the knot at index 7 decreases.
  auto e =
      refusal(job_with(kLine + "," + kLine + "," +
                       R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0],[3,1],[4,0],[5,1],[6,0],[7,1]],
                                "knots": [0,0,0,0.1,0.2,0.3,0.5,0.25,1,1,1]})"));
  EXPECT_EQ(std::string(e.what()),
            "t.json: entities[2].knots[7]: expected a knot >= 0.5 (knots must not decrease), found 0.25");
  EXPECT_EQ(e.id(), "curve.knot-order");
  e = refusal(job_with(
      R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "weights": [1, 1, 0], "knots": [0,0,0,1,1,1]})"));
  EXPECT_EQ(std::string(e.what()), "t.json: entities[0].weights[2]: expected a finite weight > 0, found 0");
  e = refusal(job_with(R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,1,1,1]})"));
  EXPECT_EQ(std::string(e.what()), "t.json: entities[0].knots: expected 6 knots (3 points + degree 2 + 1), found 5");
  e = refusal(job_with(R"({"type": "bspline", "degree": 3, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,0,0,1,1,1]})"));
  EXPECT_EQ(std::string(e.what()),
            "t.json: entities[0].degree: a curve of degree 3 needs at least 4 control points, "
            "found 3; lower the degree or add points");
  e = refusal(job_with(R"({"type": "bspline", "degree": 1.5, "points": [[0,0],[1,1]], "knots": [0,0,1,1]})"));
  EXPECT_EQ(std::string(e.what()), "t.json: entities[0].degree: expected an integer, found 1.5");
  e = refusal(job_with(R"({"type": "bspline", "degree": 1, "points": [[0,0],[1,1]]})"));
  EXPECT_EQ(e.where(), "t.json: entities[0].knots");
  e = refusal(job_with(R"({"type": "bspline", "degree": 1, "points": [[0,0],[1,1]], "knots": [0,0,"x",1]})"));
  EXPECT_EQ(std::string(e.what()), "t.json: entities[0].knots[2]: expected a number, found the string \"x\"");
  // Inside a path.
  e = refusal(job_with(R"({"type": "path", "segments": [)" + kLine +
                       R"(, {"type": "bspline", "degree": 1, "points": [[10,0],[11,1]], "knots": [0,0,2,1]}]})"));
  EXPECT_EQ(std::string(e.what()),
            "t.json: entities[0].segments[1].knots[3]: expected a knot >= 2 (knots must not decrease), found 1");
}

TEST(JobJsonNurbs, InterpolateCubicSplineClosedAndLagrange) {
  const Job job = parse_job(job_with(R"(
      {"id": "open", "type": "interpolate", "through": [[0,0],[10,5],[20,0],[30,5]]},
      {"id": "loop", "type": "interpolate", "closed": true, "through": [[0,0],[10,0],[10,10],[0,10]]},
      {"id": "poly", "type": "interpolate", "method": "lagrange", "through": [[0,0],[10,5],[20,0]]},
      {"id": "wild", "type": "interpolate", "method": "lagrange",
       "through": [[0,0],[10,0],[20,0],[30,0],[40,0],[50,20],[60,20],[70,20],[80,20],[90,20],[100,20]]})"),
                            "t.json");
  ASSERT_EQ(job.entities.size(), 4u);
  const auto& open = job.entities[0].curve;
  EXPECT_EQ(open.kind, "interpolate");
  EXPECT_EQ(open.pieces.size(), 3u);
  EXPECT_EQ(open.max_degree(), 3);
  EXPECT_TRUE(open.segments[0].nurbs);
  EXPECT_FALSE(open.closed);
  EXPECT_EQ(open.pieces[1].front(), (Vec3{10, 5, 0}));
  const auto& loop = job.entities[1].curve;
  EXPECT_TRUE(loop.closed);
  EXPECT_EQ(loop.pieces.size(), 4u);
  EXPECT_LE(dist(loop.pieces.back().back(), Vec3{0, 0, 0}), 1e-12 * 10);
  const auto& poly = job.entities[2].curve;
  ASSERT_EQ(poly.pieces.size(), 1u);
  EXPECT_EQ(poly.max_degree(), 2);
  EXPECT_FALSE(poly.segments[0].nurbs);  // a Bézier: its piece is the exact form
  // A step through one polynomial overshoots; the warning gives the amount.
  ASSERT_EQ(job.warnings.size(), 1u);
  const std::string& w = job.warnings[0];
  EXPECT_EQ(
      w.rfind("t.json: entities[3]: the Lagrange polynomial through these 11 points leaves their bounding box by ", 0),
      0u)
      << w;
  EXPECT_NE(w.find("(one polynomial through many points oscillates between them); method \"cubic-spline\" stays close "
                   "to the points"),
            std::string::npos)
      << w;
}

TEST(JobJsonNurbs, InterpolateErrors) {
  auto e = refusal(job_with(R"({"type": "interpolate", "through": [[0,0],[1,1],[1,1],[2,0]]})"));
  EXPECT_EQ(std::string(e.what()),
            "t.json: entities[0].through[2]: expected a point different from through[1], found the same point (1, "
            "1): a repeated point gives a zero chord length, so no parameter can separate the two; remove the "
            "duplicate");
  e = refusal(job_with(R"({"type": "interpolate", "method": "akima", "through": [[0,0],[1,1]]})"));
  EXPECT_EQ(std::string(e.what()),
            "t.json: entities[0].method: expected \"cubic-spline\", \"hermite\" or \"lagrange\", found the string "
            "\"akima\"");
  e = refusal(
      job_with(R"({"type": "interpolate", "method": "lagrange", "closed": true, "through": [[0,0],[1,1],[2,0]]})"));
  EXPECT_EQ(e.where(), "t.json: entities[0].closed");
  e = refusal(job_with(R"({"type": "interpolate", "through": [[0,0]]})"));
  EXPECT_EQ(e.where(), "t.json: entities[0].through");
  e = refusal(job_with(R"({"type": "interpolate", "closed": true, "through": [[0,0],[1,1],[0,0]]})"));
  EXPECT_EQ(std::string(e.what()),
            "t.json: entities[0].through: a closed spline needs at least 3 distinct points, found 2");
}
