// A job's tools: one diameter and one shape per tool number, from the job
// file, a job built in memory, and with the machine's defaults.
#include "bezcam/job/tools.hpp"

#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job_builder.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/refusal.hpp"

using namespace bezcam;
using bezcam::test::refusal_of;

namespace {

// A closed square of side 20 at (x, 0), for part cutting.
std::string square(const std::string& id, double x, const std::string& more = "") {
  const auto n = [](double v) { return std::to_string(v); };
  return R"({"id": ")" + id + R"(", "type": "path", "closed": true, "side": "inside")" + more + R"(, "segments": [
      {"type": "bezier", "points": [[)" +
         n(x) + "," + n(0) + "],[" + n(x + 20) + ",0]]}," + R"({"type": "bezier", "points": [[)" + n(x + 20) + ",0],[" +
         n(x + 20) + ",20]]}," + R"({"type": "bezier", "points": [[)" + n(x + 20) + ",20],[" + n(x) + ",20]]}," +
         R"({"type": "bezier", "points": [[)" + n(x) + ",20],[" + n(x) + ",0]]}]}";
}

const char* kPatch = R"({"id": "dome", "type": "bezier_patch", "toolpath": {"stepover": 2}, "points": [
    [[0,0,0],[10,0,2],[20,0,0]], [[0,10,2],[10,10,5],[20,10,2]], [[0,20,0],[10,20,2],[20,20,0]]])";

std::string job_of(const std::string& job, const std::string& entities) {
  return R"({"bezcam": 1, "job": {"feed": 600, "plunge_feed": 200, "safe_z": 5, "cut_z": -1)" + job +
         R"(}, "entities": [)" + entities + "]}";
}

}  // namespace

TEST(JobTools, OneToolNumberGivenTwoDiametersIsRefusedNamingBoth) {
  // The flange as it was: bolt holes offset for 3 mm, the outline for the
  // job's 6 mm, both T1 with no tool change.
  const InputError e = refusal_of([] {
    parse_job(job_of(R"(, "tool": 1, "tool_diameter": 6)",
                     square("bolt", 0, R"(, "tool_diameter": 3)") + "," + square("outline", 40)),
              "flange.json");
  });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "flange.json: entities[1]");
  EXPECT_EQ(e.message(),
            "tool 1 is given two diameters: 3 mm for bolt (entities[0].tool_diameter) and 6 mm for "
            "outline (job.tool_diameter); one tool number is one tool, and whichever is loaded cuts one "
            "of them wrong: give each its own \"tool\" number, or both one diameter");
}

TEST(JobTools, EachToolHasItsDiameterAndShape) {
  const Job j = parse_job(
      job_of(R"(, "tool": 1, "tool_diameter": 6)", square("bolt", 0, R"(, "tool": 2, "tool_diameter": 3)") + "," +
                                                       square("bore", 40) + "," + square("outline", 80)),
      "flange.json");
  const std::vector<JobTool> t = job_tools(j);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].number, 2);
  EXPECT_EQ(t[0].diameter, 3);
  EXPECT_EQ(t[0].shape, ToolType::flat);
  EXPECT_EQ(t[0].entities, std::vector<size_t>{0});
  EXPECT_EQ(t[1].number, 1);
  EXPECT_EQ(t[1].diameter, 6);
  EXPECT_EQ(t[1].entities, (std::vector<size_t>{1, 2}));
  EXPECT_STREQ(to_string(ToolType::flat), "flat end mill");
}

TEST(JobTools, ASurfaceCutWithARadiusMakesABallEnd) {
  // A ball of radius 3 is a 6 mm tool: a curve offset for 6 mm with it
  // agrees; one offset for 8 mm does not.
  const Job j = parse_job(job_of(R"(, "tool": 1)", std::string(kPatch) + R"(, "tool_radius": 3},)" +
                                                       square("edge", 40, R"(, "tool_diameter": 6)")),
                          "d.json");
  const auto t = job_tools(j);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].diameter, 6);
  EXPECT_EQ(t[0].shape, ToolType::ball);
  const InputError e = refusal_of([] {
    parse_job(job_of(R"(, "tool": 1, "tool_radius": 3)",
                     std::string(kPatch) + "}," + square("edge", 40, R"(, "tool_diameter": 8)")),
              "d.json");
  });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.message().rfind("tool 1 is given two diameters: 6 mm ball end mill for dome (job.tool_radius) and 8 mm "
                              "for edge (entities[1].tool_diameter); ",
                              0),
            0u)
      << e.message();
  // A tip that follows the surface (tool_radius 0) gives no diameter.
  EXPECT_NO_THROW(parse_job(
      job_of(R"(, "tool": 1)", std::string(kPatch) + "}," + square("edge", 40, R"(, "tool_diameter": 8)")), "d.json"));
}

TEST(JobTools, TheMachinesDefaultToolIsOneOfTheNumbers) {
  // Without a number, an entity is cut with the machine's default tool:
  // the reader cannot tell which that is, the program can.
  const Job j = parse_job(job_of("", square("a", 0, R"(, "tool": 1, "tool_diameter": 3)") + "," +
                                         square("b", 40, R"(, "tool_diameter": 6)")),
                          "t.json");
  const auto t = job_tools(j);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1].number, -1);
  JobParams machine;
  machine.tool = 2;
  EXPECT_EQ(job_tools(j, machine).size(), 2u);
  machine.tool = 1;
  const InputError e = refusal_of([&] { job_tools(j, machine); });
  EXPECT_EQ(e.where(), "t.json: entities[1]");
  // Entities without a number share that one tool.
  const InputError d = refusal_of([] {
    parse_job(job_of("", square("a", 0, R"(, "tool_diameter": 3)") + "," + square("b", 40, R"(, "tool_diameter": 6)")),
              "t.json");
  });
  EXPECT_EQ(d.message().rfind("the default tool (no \"tool\" given) is given two diameters: 3 mm for a "
                              "(entities[0].tool_diameter) and 6 mm for b (entities[1].tool_diameter); ",
                              0),
            0u)
      << d.message();
}

TEST(JobTools, AJobBuiltInMemoryIsCheckedAlike) {
  JobParams three, six;
  three.tool_diameter = 3;
  three.side = CutSide::left;
  six.tool_diameter = 6;
  six.side = CutSide::left;
  JobBuilder b("mem");
  b.feed(600).plunge_feed(200).safe_z(5).cut_z(-1).tool(1);
  b.bezier("a", Bezier::make({{0, 0, 0}, {10, 0, 0}}), three).bezier("b", Bezier::make({{0, 10, 0}, {10, 10, 0}}), six);
  const InputError e = refusal_of([&] { b.build(); });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "mem: entities[1]");
}
