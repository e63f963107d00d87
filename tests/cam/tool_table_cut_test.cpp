// A job's tool table in the cut: the entry's diameter offsets the part as
// `tool_diameter` does, a ball entry rides a surface as `tool_radius`
// does, the flute length splits a deep cut into passes, and the header
// describes each tool.
#include <gtest/gtest.h>
#include <string>

#include "bezcam/cam/program.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/refusal.hpp"

namespace bezcam {
namespace {

using test::refusal_of;

// A 40 x 30 rectangle, counter-clockwise, as a closed path.
const char* kRect = R"({"id": "outline", "type": "path", "closed": true, "segments": [
    {"type": "bezier", "points": [[0, 0], [40, 0]]}, {"type": "bezier", "points": [[40, 0], [40, 30]]},
    {"type": "bezier", "points": [[40, 30], [0, 30]]}, {"type": "bezier", "points": [[0, 30], [0, 0]]}])";
const char* kPatch = R"({"id": "dome", "type": "bezier_patch", "toolpath": {"stepover": 2}, "points": [
    [[0,0,0],[10,0,2],[20,0,0]], [[0,10,2],[10,10,5],[20,10,2]], [[0,20,0],[10,20,2],[20,20,0]]])";

std::string job_of(const std::string& top, const std::string& job, const std::string& entities) {
  return R"({"bezcam": 1, "tolerance": 0.01,)" + top + R"( "job": {"feed": 600, "plunge_feed": 100, "safe_z": 5)" +
         job + R"(}, "entities": [)" + entities + "]}";
}

std::string gcode(const std::string& json, const char* machine = "generic") {
  return convert(parse_job(json, "job.json"), load_machine_profile(machine), ConvertOptions{}).gcode;
}

// The depth of each plunge of the program.
std::vector<double> plunge_depths(const Program& p) {
  std::vector<double> z;
  bool in = false;
  for (const Move& mv : p.moves) {
    if (std::holds_alternative<RapidMove>(mv.what)) {
      in = false;
      continue;
    }
    const Motion* m = motion_of(mv);
    if (m && !in) z.push_back(m->to.z);
    in = m != nullptr;
  }
  return z;
}

const char* kTable = R"( "tools": {"1": {"shape": "flat", "diameter": 6, "flute_length": 2.5},
                                   "2": {"shape": "ball", "diameter": 6}},)";

}  // namespace

TEST(ToolTableCut, ATableEntryCutsExactlyAsTheSameToolDiameter) {
  for (const char* machine : {"generic", "fanuc"}) {
    const std::string part = R"(, "tool": 1, "side": "outside", "top_z": 0, "cut_z": -2)";
    const std::string with_table = gcode(job_of(kTable, part, std::string(kRect) + "}"), machine);
    const std::string with_diameter =
        gcode(job_of("", part + R"(, "tool_diameter": 6)", std::string(kRect) + "}"), machine);
    EXPECT_EQ(with_table, with_diameter) << machine;
    EXPECT_NE(with_table.find("(T1: 6 mm flat end mill: outline)"), std::string::npos) << with_table;
  }
}

TEST(ToolTableCut, AnInchTableCutsAsTheInchToolDiameter) {
  const std::string part = R"(, "tool": 3, "side": "inside", "top_z": 0, "cut_z": -0.1)";
  const std::string rect = std::string(kRect) + "}";
  const std::string with_table = gcode(job_of(
      R"( "units": "inch", "tools": {"3": {"shape": "bull", "diameter": 0.25, "corner_radius": 0.02}},)", part, rect));
  const std::string with_diameter = gcode(job_of(R"( "units": "inch",)", part + R"(, "tool_diameter": 0.25)", rect));
  // The same cut; the header says more: the table's shape and corner radius.
  EXPECT_NE(with_table.find("(T3: 0.25 in bull nose end mill [bull D0.25 r0.02]: outline)"), std::string::npos)
      << with_table;
  EXPECT_NE(with_diameter.find("(T3: 0.25 in flat end mill: outline)"), std::string::npos) << with_diameter;
  const auto body = [](const std::string& g) {
    return g.substr(g.find("(T3:")).substr(g.substr(g.find("(T3:")).find('\n'));
  };
  EXPECT_EQ(body(with_table), body(with_diameter));
}

TEST(ToolTableCut, ABallEntryRidesASurfaceAsItsToolRadius) {
  const std::string with_table = gcode(job_of(kTable, R"(, "tool": 2)", std::string(kPatch) + "}"));
  const std::string with_radius = gcode(job_of("", R"(, "tool": 2, "tool_radius": 3)", std::string(kPatch) + "}"));
  EXPECT_EQ(with_table, with_radius);
  EXPECT_NE(with_table.find("(T2: 6 mm ball end mill: dome)"), std::string::npos) << with_table;
}

TEST(ToolTableCut, TheHeaderDescribesATableToolOnALine) {
  const std::string line = R"({"id": "engraving", "type": "bezier", "points": [[0, 0], [50, 0]], "tool": 2})";
  const std::string with_table = gcode(job_of(kTable, R"(, "cut_z": -0.5)", line));
  const std::string without = gcode(job_of("", R"(, "cut_z": -0.5)", line));
  EXPECT_NE(with_table.find("(T2: 6 mm ball end mill: engraving)"), std::string::npos) << with_table;
  EXPECT_NE(without.find("(T2: engraving)"), std::string::npos) << without;
}

TEST(ToolTableCut, ACutDeeperThanTheFluteLengthIsSplitIntoPasses) {
  const std::string rect = std::string(kRect) + "}";
  const Job j =
      parse_job(job_of(kTable, R"(, "tool": 1, "side": "outside", "top_z": 0, "cut_z": -6)", rect), "job.json");
  const Program p = build_program(j, load_machine_profile("generic"), ConvertOptions{});
  const std::vector<double> z = plunge_depths(p);
  ASSERT_EQ(z.size(), 3u);  // ceil(6 / 2.5) passes of 2 each
  EXPECT_NEAR(z[0], -2, 1e-12);
  EXPECT_NEAR(z[1], -4, 1e-12);
  EXPECT_NEAR(z[2], -6, 1e-12);
  // As if step_down were the flute length.
  EXPECT_EQ(
      gcode(job_of(kTable, R"(, "tool": 1, "side": "outside", "top_z": 0, "cut_z": -6)", rect)),
      gcode(job_of(kTable, R"(, "tool": 1, "side": "outside", "top_z": 0, "cut_z": -6, "step_down": 2.5)", rect)));
  // A line cut on the curve is split too; one no deeper than the flutes is not.
  const std::string line = R"({"id": "groove", "type": "bezier", "points": [[0, 0], [50, 0]]})";
  const auto depths = [&](const std::string& job) {
    return plunge_depths(build_program(parse_job(job_of(kTable, job, line), "job.json"),
                                       load_machine_profile("generic"), ConvertOptions{}));
  };
  EXPECT_EQ(depths(R"(, "tool": 1, "cut_z": -3)"), (std::vector<double>{-1.5, -3}));
  EXPECT_EQ(depths(R"(, "tool": 1, "cut_z": -2.5)"), (std::vector<double>{-2.5}));
  EXPECT_EQ(depths(R"(, "tool": 1, "top_z": 1, "cut_z": -1)"), (std::vector<double>{-1}));
  // The ball tool has no flute length: one pass.
  EXPECT_EQ(depths(R"(, "tool": 2, "cut_z": -6)"), (std::vector<double>{-6}));
}

TEST(ToolTableCut, TheMachinesDefaultToolMustBeInTheTable) {
  const std::string json = job_of(R"( "tools": {"2": {"shape": "ball", "diameter": 6}},)", R"(, "cut_z": -1)",
                                  R"({"id": "groove", "type": "bezier", "points": [[0, 0], [50, 0]]})");
  const Job j = parse_job(json, "job.json");  // no tool named: the profile's default is not known yet
  const InputError e = refusal_of([&] { build_program(j, load_machine_profile("generic"), ConvertOptions{}); });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "job.json: entities[0]");
  EXPECT_EQ(e.message(),
            "groove names no tool, so it is cut with the machine profile's default tool 1, which is not in the job's "
            "tool table (it has tool 2): add it to \"tools\", or pick a tool the table has");
}

}  // namespace bezcam
