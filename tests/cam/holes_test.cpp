// Holes (docs/holes.md): circles recognised within the tolerance, drills
// and bores checked against them, bores cut by a helix and a circle, holes
// ordered like contours, and what is refused, with its JSON path.
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>

#include "bezcam/cam/program.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error_ids.hpp"
#include "bezcam/job/job_json.hpp"
#include "cam/hole_cut.hpp"
#include "support/refusal.hpp"

namespace bezcam {
namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A circle as four rational quarters, its radius scaled by `sx` along X
// (an ellipse when sx != 1).
std::string circle(double cx, double cy, double r, double sx = 1) {
  const double w = std::sqrt(0.5);
  std::string s = R"({"type":"path","closed":true,"segments":[)";
  for (int k = 0; k < 4; ++k) {
    const double a0 = k * std::numbers::pi / 2, a1 = a0 + std::numbers::pi / 2;
    auto pt = [&](double x, double y) { return "[" + num(cx + sx * x) + "," + num(cy + y) + "]"; };
    s += std::string(k ? "," : "") + R"({"type":"bezier","points":[)" + pt(r * std::cos(a0), r * std::sin(a0)) + "," +
         pt(r * (std::cos(a0) - std::sin(a0)), r * (std::sin(a0) + std::cos(a0))) + "," +
         pt(r * std::cos(a1), r * std::sin(a1)) + "],\"weights\":[1," + num(w) + ",1]}";
  }
  return s + "]";
}

const char* kTools = R"("tools":{"1":{"shape":"flat","diameter":6,"flute_length":20},)"
                     R"("2":{"shape":"drill","diameter":5,"point_angle":118,"flute_length":12},)"
                     R"("3":{"shape":"flat","diameter":4}},)";

Job holes(const std::string& job_keys, const std::vector<std::string>& entities, bool table = true) {
  std::string s = std::string(R"({"bezcam":1,"tolerance":0.01,)") + (table ? kTools : "") +
                  R"("job":{"feed":600,"plunge_feed":150,"safe_z":5,"top_z":0,"clearance":1,"cut_z":-6)" +
                  (job_keys.empty() ? "" : ",") + job_keys + R"(},"entities":[)";
  for (size_t i = 0; i < entities.size(); ++i) s += (i ? "," : "") + entities[i];
  return parse_job(s + "]}", "holes.json");
}

Program build(const Job& j, const char* machine = "linuxcnc", OutputMode mode = OutputMode::lines) {
  ConvertOptions o;
  o.output = mode;
  return build_program(j, load_machine_profile(machine), o);
}

TEST(Holes, ACircleIsRecognisedWithinTheTolerance) {
  const Job j = holes(R"("operation":"drill","tool":2)", {circle(10, 20, 2.5) + "}"});
  const auto h = detail::fit_circle(j.entities[0].curve.pieces, true, 0.01);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->centre.x, 10, 1e-9);
  EXPECT_NEAR(h->centre.y, 20, 1e-9);
  EXPECT_NEAR(*h->diameter, 5, 1e-9);
  EXPECT_LE(h->bound, 2e-5);  // refined to a thousandth of the tolerance
  // An ellipse 0.1 % wider: 2.5 um off, within 0.01; 1 % wider is not.
  const Job e1 = holes("", {circle(0, 0, 2.5, 1.001) + "}"}), e2 = holes("", {circle(0, 0, 2.5, 1.01) + "}"});
  const auto f1 = detail::fit_circle(e1.entities[0].curve.pieces, true, 0.01);
  ASSERT_TRUE(f1);
  EXPECT_GT(f1->bound, 1e-4);
  EXPECT_LE(f1->bound, 0.01);
  EXPECT_FALSE(detail::fit_circle(e2.entities[0].curve.pieces, true, 0.01));
}

TEST(Holes, ADrilledCircleIsOneCycleAtItsCentre) {
  const Program p = build(holes(R"("operation":"drill","tool":2)", {circle(10, 20, 2.5) + "}"}));
  size_t cycles = 0;
  for (const Move& mv : p.moves)
    if (const auto* c = std::get_if<CannedCycle>(&mv.what)) {
      ++cycles;
      EXPECT_EQ(c->at.x, 10);
      EXPECT_EQ(c->at.y, 20);
      // The full diameter at cut_z: the tip 2.5 / tan(59 deg) lower.
      EXPECT_NEAR(c->z, -6 - 2.5 / std::tan(59 * std::numbers::pi / 180), 1e-3);
      EXPECT_EQ(c->r, 1);
      EXPECT_EQ(c->code, 81);
    }
  EXPECT_EQ(cycles, 1u);
}

TEST(Holes, ABoreIsAHelixAndAFullCircleInsideTheWall) {
  // A 20 mm circle, a 6 mm tool: the centre on a circle of 7.
  for (OutputMode mode : {OutputMode::arcs, OutputMode::lines}) {
    SCOPED_TRACE(to_string(mode));
    const Program p =
        build(holes(R"("operation":"bore","tool":1,"cut_z":-5)", {circle(50, 35, 10) + "}"}), "linuxcnc", mode);
    size_t arcs = 0;
    double lowest = 0, max_r = 0, min_r = 1e9;
    for (const MotionBlock& b : program_motion(p)) {
      // The cutting moves; not the way back to the centre.
      if (b.kind == BlockKind::rapid || b.entity != 0 || (b.to.x == 50 && b.to.y == 35)) continue;
      arcs += b.kind == BlockKind::arc_ccw;
      for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const Vec3 q = evaluate_block(b, t);
        const double r = std::hypot(q.x - 50, q.y - 35);
        if (q.z < 0 && r > 1) max_r = std::max(max_r, r), min_r = std::min(min_r, r);
        lowest = std::min(lowest, q.z);
      }
    }
    EXPECT_EQ(lowest, -5);
    EXPECT_LE(max_r, 7 + 1e-4 * std::sqrt(0.5));        // into the wall by the rounding of the digits at most
    EXPECT_GE(min_r, 7 - 0.01);                         // within the tolerance of it
    if (mode == OutputMode::arcs) EXPECT_GE(arcs, 4u);  // two half turns per turn, and the bottom circle
    if (mode == OutputMode::lines) EXPECT_EQ(arcs, 0u);
    EXPECT_LE(p.entities[0].measured, p.entities[0].bound);
    EXPECT_LE(p.entities[0].bound, 0.01);
  }
}

TEST(Holes, HolesAreOrderedLikeContours) {
  std::vector<std::string> pts;
  for (double x : {0.0, 30.0, 10.0, 20.0}) pts.push_back(R"({"type":"point","at":[)" + num(x) + ",0]}");
  Job j = holes(R"("operation":"drill","tool":2)", pts);
  j.order_shortest = true;
  std::vector<double> xs;
  for (const Move& mv : build(j).moves)
    if (const auto* c = std::get_if<CannedCycle>(&mv.what)) xs.push_back(c->at.x);
  EXPECT_EQ(xs, (std::vector<double>{0, 10, 20, 30}));
}

TEST(Holes, BadHolesAreRefusedWithTheirPath) {
  const std::string pt = R"({"type":"point","at":[1,2])";
  struct Case {
    std::string job_keys, entity;
    const char* id;
    const char* path;
    bool table = true;
  } cases[] = {
      // A 6 mm circle drilled with the 5 mm drill, naming both.
      {R"("operation":"drill")", circle(0, 0, 3) + R"(,"tool":2})", "job.hole", "entities[0].tool"},
      {R"("operation":"drill","tool_diameter":5)", circle(0, 0, 3) + "}", "job.hole", "job.tool_diameter", false},
      // Without a table or tool_diameter, a circle's drill is unknown.
      {R"("operation":"drill")", circle(0, 0, 3) + "}", "job.hole", "entities[0]", false},
      // 12 mm flutes: the tip of a hole whose full diameter is at -11 is
      // deeper.
      {R"("operation":"drill","tool":2)", pt + R"(,"cut_z":-11})", "job.hole", "entities[0].cut_z"},
      {R"("operation":"drill","tool":1)", pt + "}", "job.hole", "job.tool"},
      {R"("operation":"drill","tool":2)", pt + R"(,"chip_break":true})", "job.hole", "entities[0].chip_break"},
      {R"("operation":"drill","tool":2)", pt + R"(,"peck":2,"dwell":1})", "job.hole", "entities[0].dwell"},
      {R"("operation":"drill","tool":2)", pt + R"(,"retract_z":6})", "job.hole", "entities[0].retract_z"},
      {R"("operation":"drill","tool":2)", pt + R"(,"retract_z":-1})", "job.hole", "entities[0].retract_z"},
      {R"("operation":"drill","tool":2)", circle(0, 0, 2.5, 1.01) + "}", "job.hole", "entities[0].operation"},
      // A bore: smaller than the tool, a point, a drill for it.
      {R"("operation":"bore","tool":1)", circle(0, 0, 2.9) + "}", "job.hole", "job.tool"},
      {R"("operation":"bore","tool":1)", pt + "}", "job.hole", "entities[0].operation"},
      {R"("operation":"bore","tool":2)", circle(0, 0, 5) + "}", "job.hole", "job.tool"},
      // A point that is not a hole.
      {R"("tool":2)", pt + "}", "job.operation", "entities[0]"},
      {R"("tool":2)", pt + R"(,"operation":"pocket"})", "job.pocket", "entities[0].operation"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.job_keys + " " + c.entity.substr(0, 60));
    const InputError e = test::refusal_of([&] { build(holes(c.job_keys, {c.entity}, c.table)); });
    EXPECT_EQ(e.id(), c.id) << e.what();
    EXPECT_EQ(e.place().json_path.value_or(""), c.path) << e.what();
  }
  // The refusal of another diameter names both.
  const InputError e =
      test::refusal_of([&] { build(holes(R"("operation":"drill")", {circle(0, 0, 3) + R"(,"tool":2})"})); });
  EXPECT_NE(std::string(e.what()).find("diameter 6"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("drills 5"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace bezcam
