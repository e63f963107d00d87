// Tool tables: a job's `tools` and a tools file, each refusal at its JSON
// path; a table's tool picked by `tool`, its diameter given to the entity,
// and refused where it disagrees with the entity's or job's.
#include "bezcam/job/tool_table.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job_builder.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/tools.hpp"
#include "bezcam/stock/tool_shape.hpp"
#include "support/refusal.hpp"

using namespace bezcam;
using bezcam::test::refusal_of;

namespace {

const char* kFive = R"({
  "1": {"shape": "flat", "diameter": 6, "flute_length": 20},
  "2": {"shape": "ball", "diameter": 6, "center_cutting": true},
  "3": {"shape": "bull", "diameter": 10, "corner_radius": 1},
  "4": {"shape": "vee", "diameter": 6, "angle": 60},
  "5": {"shape": "drill", "diameter": 5, "point_angle": 118}})";

const char* kLine = R"({"id": "slot", "type": "bezier", "points": [[0, 0], [50, 0]])";
const char* kPatch = R"({"id": "dome", "type": "bezier_patch", "toolpath": {"stepover": 2}, "points": [
    [[0,0,0],[10,0,2],[20,0,0]], [[0,10,2],[10,10,5],[20,10,2]], [[0,20,0],[10,20,2],[20,20,0]]])";

// A job with the table `tools` (JSON text), `job` keys and entities.
std::string job_of(const std::string& tools, const std::string& job, const std::string& entities,
                   const std::string& top = "") {
  return R"({"bezcam": 1,)" + top + R"( "tools": )" + tools +
         R"(, "job": {"feed": 600, "plunge_feed": 200, "safe_z": 5, "cut_z": -1)" + job + R"(}, "entities": [)" +
         entities + "]}";
}

// The refusal of a job whose table is `tools`.
InputError table_refusal(const std::string& tools) {
  return refusal_of([&] { parse_job(job_of(tools, "", std::string(kLine) + "}"), "t.json"); });
}

// Machine profile defaults giving one value.
JobParams defaults_tool(int n) {
  JobParams p;
  p.tool = n;
  return p;
}
JobParams defaults_diameter(double d) {
  JobParams p;
  p.tool_diameter = d;
  return p;
}
JobParams defaults_radius(double r) {
  JobParams p;
  p.tool_radius = r;
  return p;
}
ToolEntry entry(int number, ToolType shape, double diameter) {
  ToolEntry t;
  t.number = number;
  t.shape = shape;
  t.diameter = diameter;
  return t;
}

}  // namespace

TEST(ToolTable, FiveShapesAreReadInToolNumberOrder) {
  const Job j = parse_job(job_of(kFive, R"(, "tool": 2)", std::string(kLine) + "}"), "t.json");
  ASSERT_EQ(j.tools.entries.size(), 5u);
  const ToolEntry& flat = j.tools.entries[0];
  EXPECT_EQ(flat.number, 1);
  EXPECT_EQ(flat.shape, ToolType::flat);
  EXPECT_EQ(flat.diameter, 6);
  EXPECT_EQ(flat.flute_length, 20);
  EXPECT_FALSE(flat.center_cutting);
  EXPECT_TRUE(j.tools.find(2)->center_cutting);
  EXPECT_EQ(j.tools.find(3)->corner_radius, 1);
  EXPECT_EQ(j.tools.find(4)->angle, 60);
  EXPECT_EQ(j.tools.find(5)->point_angle, 118);
  EXPECT_TRUE(j.tools.find(5)->center_cutting);  // a drill always is
  EXPECT_EQ(j.tools.find(6), nullptr);
  EXPECT_EQ(j.tools.numbers(), "1, 2, 3, 4, 5");
  EXPECT_EQ(j.tools.find(3)->description(), "bull D10 r1");
  EXPECT_EQ(j.tools.find(1)->description(), "flat D6 flutes 20");
  EXPECT_EQ(j.tools.find(5)->description(), "drill D5 118deg");
}

TEST(ToolTable, NumbersAreWholeNumbersAndUserKeysAreKept) {
  const Job j = parse_job(job_of(R"({"10": {"shape": "flat", "diameter": 3}, "0": {"shape": "ball", "diameter": 2},
                                     "x-shop": "rack B"})",
                                 R"(, "tool": 10)", std::string(kLine) + "}"),
                          "t.json");
  ASSERT_EQ(j.tools.entries.size(), 2u);
  EXPECT_EQ(j.tools.entries[0].number, 0);  // by number, not as text ("0" < "10" either way)
  EXPECT_EQ(j.tools.entries[1].number, 10);
  for (const char* key : {"a", "-1", "1.5", "01", ""}) {
    const InputError e = table_refusal(std::string(R"({")") + key + R"(": {"shape": "flat", "diameter": 3}})");
    EXPECT_EQ(e.id(), "job.tool-table") << key;
    EXPECT_EQ(e.where(), std::string("t.json: tools.\"") + key + "\"") << key;
    EXPECT_NE(e.message().find("expected a tool number as the key"), std::string::npos) << e.message();
  }
}

TEST(ToolTable, EachBadValueIsRefusedAtItsJsonPath) {
  struct Case {
    const char* tools;
    const char* id;
    const char* where;
    const char* says;
  };
  const Case cases[] = {
      {R"({"1": {"shape": "endmill", "diameter": 6}})", "job.tool-table", "tools.\"1\".shape",
       R"(expected one of "flat", "ball", "bull", "vee", "drill", found the string "endmill")"},
      {R"({"1": {"shape": 3, "diameter": 6}})", "job.type", "tools.\"1\".shape", "found 3"},
      {R"({"1": {"diameter": 6}})", "job.missing", "tools.\"1\".shape", "\"shape\" is missing"},
      {R"({"1": {"shape": "flat"}})", "job.missing", "tools.\"1\".diameter", "\"diameter\" is missing"},
      {R"({"1": {"shape": "flat", "diameter": 0}})", "job.not-positive", "tools.\"1\".diameter",
       "expected a tool diameter > 0, found 0"},
      {R"({"1": {"shape": "flat", "diameter": "6"}})", "job.type", "tools.\"1\".diameter", "expected a number"},
      {R"({"3": {"shape": "bull", "diameter": 10}})", "job.missing", "tools.\"3\".corner_radius",
       "a \"bull\" tool needs \"corner_radius\""},
      {R"({"3": {"shape": "bull", "diameter": 10, "corner_radius": 5.5}})", "job.range", "tools.\"3\".corner_radius",
       "expected a corner radius above 0 and at most the tool's radius (5), found 5.5"},
      {R"({"3": {"shape": "bull", "diameter": 10, "corner_radius": 0}})", "job.range", "tools.\"3\".corner_radius",
       "found 0"},
      {R"({"4": {"shape": "vee", "diameter": 6}})", "job.missing", "tools.\"4\".angle",
       "a \"vee\" tool needs \"angle\""},
      {R"({"4": {"shape": "vee", "diameter": 6, "angle": 180}})", "job.range", "tools.\"4\".angle",
       "expected an angle above 0 and below 180 degrees, found 180"},
      {R"({"5": {"shape": "drill", "diameter": 5}})", "job.missing", "tools.\"5\".point_angle",
       "a \"drill\" tool needs \"point_angle\""},
      {R"({"5": {"shape": "drill", "diameter": 5, "point_angle": -118}})", "job.range", "tools.\"5\".point_angle",
       "found -118"},
      {R"({"1": {"shape": "flat", "diameter": 6, "corner_radius": 1}})", "job.tool-table", "tools.\"1\".corner_radius",
       "a \"flat\" tool has no corner radius"},
      {R"({"5": {"shape": "drill", "diameter": 5, "point_angle": 118, "angle": 118}})", "job.tool-table",
       "tools.\"5\".angle", "make the tool's shape \"vee\""},
      {R"({"5": {"shape": "drill", "diameter": 5, "point_angle": 118, "center_cutting": false}})", "job.tool-table",
       "tools.\"5\".center_cutting", "a drill always cuts at its centre"},
      {R"({"1": {"shape": "flat", "diameter": 6, "center_cutting": "yes"}})", "job.type", "tools.\"1\".center_cutting",
       "expected true or false"},
      {R"({"1": {"shape": "flat", "diameter": 6, "flute_length": -2}})", "job.not-positive", "tools.\"1\".flute_length",
       "expected a flute length > 0, found -2"},
      {R"({"1": {"shape": "flat", "diameter": 6, "diamter": 6}})", "job.key-typo", "tools.\"1\".diamter",
       "did you mean \"diameter\"?"},
      {R"({"1": {"shape": "flat", "diameter": 6, "holder": "ER11"}})", "job.unknown-key", "tools.\"1\".holder",
       "unknown key \"holder\""},
      {R"({"1": 6})", "job.type", "tools.\"1\"", "expected a tool object"},
      {R"([{"shape": "flat", "diameter": 6}])", "job.type", "tools", "expected an object of tools by number"},
  };
  for (const Case& c : cases) {
    const InputError e = table_refusal(c.tools);
    EXPECT_EQ(e.id(), c.id) << c.tools;
    EXPECT_EQ(e.where(), std::string("t.json: ") + c.where) << c.tools;
    EXPECT_NE(e.message().find(c.says), std::string::npos) << c.tools << "\n" << e.message();
  }
}

TEST(ToolTable, TwoBadEntriesAreBothReported) {
  const InputError e =
      table_refusal(R"({"1": {"shape": "flat", "diameter": -6}, "2": {"shape": "cone", "diameter": 6}})");
  EXPECT_EQ(e.where(), "t.json: tools.\"1\".diameter");
  ASSERT_EQ(e.more().size(), 1u);
  EXPECT_EQ(e.more()[0].where(), "t.json: tools.\"2\".shape");
}

TEST(ToolTable, AToolTheTableLacksIsRefusedNamingTheNumbersItHas) {
  const std::string tools = R"({"1": {"shape": "flat", "diameter": 6}, "2": {"shape": "ball", "diameter": 3}})";
  InputError e = refusal_of([&] { parse_job(job_of(tools, "", std::string(kLine) + R"(, "tool": 7})"), "t.json"); });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "t.json: entities[0].tool");
  EXPECT_EQ(e.message(),
            "tool 7 is not in the job's tool table (it has tools 1, 2): add it to \"tools\", or pick a tool the "
            "table has");
  e = refusal_of([&] { parse_job(job_of(tools, R"(, "tool": 3)", std::string(kLine) + "}"), "t.json"); });
  EXPECT_EQ(e.where(), "t.json: job.tool");
  EXPECT_EQ(e.message(),
            "tool 3 for slot is not in the job's tool table (it has tools 1, 2): add it to \"tools\", or pick a "
            "tool the table has");
  // Without a number anywhere, the machine's default tool is checked when
  // the profile is known (convert; tests/cam/tool_table_cut_test.cpp).
  const Job j = parse_job(job_of(tools, "", std::string(kLine) + "}"), "t.json");
  e = refusal_of([&] { entity_params(j, j.entities[0], defaults_tool(4)); });
  EXPECT_EQ(e.where(), "t.json: entities[0]");
  EXPECT_EQ(e.message(),
            "slot names no tool, so it is cut with the machine profile's default tool 4, which is not in the job's "
            "tool table (it has tools 1, 2): add it to \"tools\", or pick a tool the table has");
}

TEST(ToolTable, TheEntrysDiameterBecomesTheEntitysToolDiameter) {
  const Job j = parse_job(job_of(kFive, R"(, "tool": 3)", std::string(kLine) + R"(, "side": "left"})"), "t.json");
  EXPECT_EQ(entity_params(j, j.entities[0]).tool_diameter, 10);
  // Over the machine's defaults too (the table sits between job and profile).
  EXPECT_EQ(entity_params(j, j.entities[0], defaults_diameter(4)).tool_diameter, 10);
  const std::vector<JobTool> t = job_tools(j);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].number, 3);
  EXPECT_EQ(t[0].diameter, 10);
  EXPECT_EQ(t[0].shape, ToolType::bull);
  ASSERT_TRUE(t[0].entry);
  EXPECT_EQ(t[0].entry->corner_radius, 1);
}

TEST(ToolTable, ADifferentToolDiameterIsRefusedNamingBothPlaces) {
  InputError e = refusal_of(
      [] { parse_job(job_of(kFive, "", std::string(kLine) + R"(, "tool": 2, "tool_diameter": 3})"), "t.json"); });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "t.json: entities[0].tool_diameter");
  EXPECT_EQ(e.message(),
            "tool 2 is a 6 mm ball end mill in the job's tool table (tools.\"2\".diameter), but "
            "entities[0].tool_diameter gives 3 mm: one tool has one diameter; remove \"tool_diameter\" (the table "
            "gives it) or make the two agree");
  e = refusal_of(
      [] { parse_job(job_of(kFive, R"(, "tool_diameter": 5.99)", std::string(kLine) + R"(, "tool": 1})"), "t.json"); });
  EXPECT_EQ(e.where(), "t.json: job.tool_diameter");
  EXPECT_NE(e.message().find("(tools.\"1\".diameter), but job.tool_diameter gives 5.99 mm for slot:"),
            std::string::npos)
      << e.message();
  // Equal within 1e-9 relative: one diameter.
  const Job j =
      parse_job(job_of(kFive, R"(, "tool": 1, "tool_diameter": 6.000000000001)", std::string(kLine) + "}"), "t.json");
  EXPECT_EQ(entity_params(j, j.entities[0]).tool_diameter, 6);
}

TEST(ToolTable, ABallEntryGivesASurfaceItsToolRadius) {
  const Job j = parse_job(job_of(kFive, R"(, "tool": 2)", std::string(kPatch) + "}"), "t.json");
  EXPECT_EQ(entity_params(j, j.entities[0]).tool_radius, 3);
  // tool_radius 0 keeps the tip on the surface, whatever the tool.
  const Job tip = parse_job(job_of(kFive, R"(, "tool": 2)", std::string(kPatch) + R"(, "tool_radius": 0})"), "t.json");
  EXPECT_EQ(entity_params(tip, tip.entities[0]).tool_radius, 0);
  // A flat tool's tip follows the surface, even over the profile's default.
  const Job flat = parse_job(job_of(kFive, R"(, "tool": 1)", std::string(kPatch) + "}"), "t.json");
  EXPECT_EQ(entity_params(flat, flat.entities[0], defaults_radius(2)).tool_radius, 0);
  InputError e = refusal_of(
      [] { parse_job(job_of(kFive, R"(, "tool": 2)", std::string(kPatch) + R"(, "tool_radius": 2.5})"), "t.json"); });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "t.json: entities[0].tool_radius");
  EXPECT_EQ(e.message(),
            "tool 2 is a 6 mm ball end mill in the job's tool table (tools.\"2\".diameter), but "
            "entities[0].tool_radius gives a ball end of radius 2.5 mm: remove \"tool_radius\" (the table gives 3) "
            "or make the two agree");
  e = refusal_of(
      [] { parse_job(job_of(kFive, R"(, "tool": 1, "tool_radius": 3)", std::string(kPatch) + "}"), "t.json"); });
  EXPECT_EQ(e.where(), "t.json: job.tool_radius");
  EXPECT_NE(e.message().find("remove \"tool_radius\", or pick a ball tool"), std::string::npos) << e.message();
}

TEST(ToolTable, AStepDownDeeperThanTheFluteLengthIsRefusedNamingBoth) {
  const InputError e = refusal_of([] {
    parse_job(job_of(kFive, R"(, "tool": 1, "top_z": 0, "cut_z": -30, "step_down": 25)", std::string(kLine) + "}"),
              "t.json");
  });
  EXPECT_EQ(e.id(), "job.cut");
  EXPECT_EQ(e.where(), "t.json: job.step_down");
  EXPECT_EQ(e.message(),
            "step_down 25 mm for slot is deeper than the flute length of tool 1, 20 mm (tools.\"1\".flute_length): "
            "one pass would bury the tool beyond its flutes; make step_down at most 20, or leave it out: the passes "
            "are then split at the flute length");
  EXPECT_NO_THROW(parse_job(
      job_of(kFive, R"(, "tool": 1, "top_z": 0, "cut_z": -30, "step_down": 20)", std::string(kLine) + "}"), "t.json"));
}

TEST(ToolTable, AnInchJobsTableIsInInches) {
  const Job j = parse_job(job_of(R"({"1": {"shape": "bull", "diameter": 0.25, "corner_radius": 0.03125,
                                            "flute_length": 0.75}})",
                                 R"(, "tool": 1, "side": "left")", std::string(kLine) + "}", R"( "units": "inch",)"),
                          "t.json");
  EXPECT_EQ(j.tools.find(1)->diameter, 0.25);
  EXPECT_EQ(entity_params(j, j.entities[0]).tool_diameter, 0.25);
  const ToolTable mm = j.tools_mm();
  EXPECT_DOUBLE_EQ(mm.find(1)->diameter, 6.35);
  EXPECT_DOUBLE_EQ(*mm.find(1)->corner_radius, 0.79375);
  EXPECT_DOUBLE_EQ(*mm.find(1)->flute_length, 19.05);
  // A corner radius is checked against the inch radius, not a mm one.
  const InputError e = refusal_of([] {
    parse_job(job_of(R"({"1": {"shape": "bull", "diameter": 0.25, "corner_radius": 0.2}})", "",
                     std::string(kLine) + "}", R"( "units": "inch",)"),
              "t.json");
  });
  EXPECT_EQ(e.where(), "t.json: tools.\"1\".corner_radius");
  EXPECT_NE(e.message().find("at most the tool's radius (0.125), found 0.2"), std::string::npos) << e.message();
}

TEST(ToolTable, AToolsFileIsReadWithItsPlaces) {
  const ToolTable t = parse_tool_table(kFive, "shop.json");
  EXPECT_EQ(t.numbers(), "1, 2, 3, 4, 5");
  InputError e = refusal_of([] { parse_tool_table(R"({"3": {"shape": "bull", "diameter": 10}})", "shop.json"); });
  EXPECT_EQ(e.id(), "job.missing");
  EXPECT_EQ(e.where(), "shop.json: \"3\".corner_radius");
  e = refusal_of([] { parse_tool_table("{\"1\": {\"shape\": \"flat\",\n \"diameter\" 6}}", "shop.json"); });
  EXPECT_EQ(e.id(), "job.syntax");
  EXPECT_EQ(e.where(), "shop.json: line 2, column 13");
  e = refusal_of([] { parse_tool_table(R"([1, 2])", "shop.json"); });
  EXPECT_EQ(e.where(), "shop.json: (top level)");
  EXPECT_EQ(e.id(), "job.type");

  const std::filesystem::path file = std::filesystem::temp_directory_path() / "bezcam-tool-table-test.json";
  std::ofstream(file) << kFive;
  EXPECT_EQ(read_tool_table_file(file.string()).find(4)->angle, 60);
  std::filesystem::remove(file);
  try {
    (void)read_tool_table_file(file.string());
    ADD_FAILURE() << "expected an IoError";
  } catch (const IoError& io) {
    EXPECT_EQ(io.id(), "io.read");
  }
}

TEST(ToolTable, AJobBuiltInMemoryTakesATable) {
  ToolTable t;
  t.entries.push_back(entry(2, ToolType::ball, 4));
  t.entries.push_back(entry(1, ToolType::flat, 6));
  const Job j = JobBuilder("built").tools(t).tool(2).feed(600).bezier("a", Bezier::make({{0, 0}, {10, 0}})).build();
  EXPECT_EQ(j.tools.numbers(), "1, 2");
  EXPECT_EQ(entity_params(j, j.entities[0]).tool_diameter, 4);
  t.entries.push_back(entry(3, ToolType::vee, 4));
  InputError e = refusal_of([&] { JobBuilder("built").tools(t).bezier("a", Bezier::make({{0, 0}, {10, 0}})).build(); });
  EXPECT_EQ(e.where(), "built: tools.\"3\".angle");
  t.entries.back() = entry(1, ToolType::flat, 6);
  e = refusal_of([&] { JobBuilder("built").tools(t).bezier("a", Bezier::make({{0, 0}, {10, 0}})).build(); });
  EXPECT_EQ(e.id(), "job.tool-table");
  EXPECT_EQ(e.where(), "built: tools.\"1\"");
  e = refusal_of([&] {
    JobBuilder("built").tools(ToolTable{{t.entries[0]}}).tool(5).bezier("a", Bezier::make({{0, 0}, {10, 0}})).build();
  });
  EXPECT_EQ(e.id(), "job.tool");
  EXPECT_EQ(e.where(), "built: job.tool");
}

TEST(ToolTable, EntriesDescribeThemselvesAsTheStocksToolShapes) {
  // The machined-result model sweeps the table's tools: one TU holds both
  // names, and an entry reads as the shape built from it.
  const ToolTable t = parse_tool_table(kFive, "shop.json");
  const ToolEntry& f = *t.find(1);
  EXPECT_EQ(f.description(), ToolShape::flat(f.diameter).describe() + " flutes 20");
  EXPECT_EQ(t.find(2)->description(), ToolShape::ball(6).describe());
  EXPECT_EQ(t.find(3)->description(), ToolShape::bull(10, 1).describe());
  EXPECT_EQ(t.find(4)->description(), ToolShape::vee(6, 60).describe());
  EXPECT_EQ(t.find(5)->description(), ToolShape::drill(5, 118).describe());
}
