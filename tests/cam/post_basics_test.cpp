// Post layer basics: number format, profiles, validation before writing,
// the writer's program structure (docs/cli.md "What every program looks like").
#include <algorithm>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/job/job_json.hpp"

using namespace bezcam;

TEST(NumberFormat, FanucStyleAndExactReadBack) {
  EXPECT_EQ(format_number(10, 3), "10.");
  EXPECT_EQ(format_number(0.5, 3), "0.5");
  EXPECT_EQ(format_number(-1.25, 3), "-1.25");
  EXPECT_EQ(format_number(-0.0001, 3), "0.");
  for (double v : {0.1234567, -99999.9996, 1e5 + 0.0004, 2.675}) {
    EXPECT_EQ(std::stod(format_number(v, 3)), quantize(v, 3)) << v;
    EXPECT_LE(std::abs(quantize(v, 3) - v), 0.0005 + 1e-12);
  }
}

TEST(MachineProfiles, AllShippedProfilesLoad) {
  const auto names = machine_profile_names();
  for (const char* want : {"generic", "fanuc", "fanuc-g063", "linuxcnc", "grbl", "unisurf"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  for (const auto& n : names) {
    const MachineProfile m = load_machine_profile(n);
    EXPECT_EQ(m.name, n);
  }
  const MachineProfile u = load_machine_profile("unisurf");
  EXPECT_EQ(u.travel_mm[0][1] - u.travel_mm[0][0], 1500);
  EXPECT_EQ(u.travel_mm[1][1] - u.travel_mm[1][0], 1200);
  EXPECT_EQ(u.travel_mm[2][1] - u.travel_mm[2][0], 800);
  EXPECT_EQ(u.max_feed_mm_min, 2000);
  EXPECT_EQ(load_machine_profile("fanuc").nurbs_start_word, "G06.2");
  EXPECT_EQ(load_machine_profile("fanuc-g063").nurbs_start_word, "G06.3");
  EXPECT_THROW(load_machine_profile("../etc/passwd"), Error);
  EXPECT_THROW(parse_machine_profile("{\"name\": \"x\", \"decimals\": {\"mm\": 12}}", "x.json"), InputError);
}

namespace {
Job job_of(const std::string& entities, const std::string& extra = "") {
  return parse_job(
      R"({"bezcam": 1, )" + extra +
          R"( "job": {"feed": 800, "plunge_feed": 200, "safe_z": 5, "cut_z": -1, "spindle_rpm": 9000, "tool": 3},
                    "entities": [)" +
          entities + "]}",
      "t.json");
}
}  // namespace

TEST(Program, StructureOfEveryProgram) {
  const Job j = job_of(R"({"id": "a", "type": "bezier", "points": [[0,0],[10,5],[20,0]]},
                          {"id": "b", "type": "bezier", "points": [[0,10,2],[10,15,1],[20,10,0]]})");
  const MachineProfile m = load_machine_profile("generic");
  const ConvertResult r = convert(j, m, {});
  std::istringstream in(r.gcode);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  EXPECT_EQ(lines[0], "%");
  EXPECT_NE(lines[1].find("bezcam"), std::string::npos);
  EXPECT_NE(lines[2].find("tolerance 0.01 mm; largest deviation measured"), std::string::npos);
  // The tool list (each tool with the entities it cuts) and the estimate.
  EXPECT_EQ(lines[3], "(T3: a, b)");
  EXPECT_EQ(lines[4], "(T3 plunge feed 200 mm/min)");  // what a resumed program plunges at
  EXPECT_EQ(lines[5].rfind("(estimated cycle time ", 0), 0u) << lines[5];
  // The cuts along the curves beside their exact path's bound.
  EXPECT_EQ(lines[6].rfind("(cutting along the curves ", 0), 0u) << lines[6];
  EXPECT_NE(lines[6].find("; the exact path's bound on this machine "), std::string::npos) << lines[6];
  // The cut order and what it saved: b's end is nearer the origin.
  EXPECT_EQ(lines[7].rfind("(order shortest: 0 nested contours cut before what encloses them; rapids ", 0), 0u)
      << lines[7];
  EXPECT_EQ(lines[8], "G21 G90 G17");
  EXPECT_EQ(lines[9], "G40 G49 G80 G94");  // the profile's preamble: the safety line
  EXPECT_EQ(lines[10], "T3 M06");
  EXPECT_EQ(lines[11], "S9000 M03");
  EXPECT_EQ(lines.back(), "%");
  EXPECT_EQ(lines[lines.size() - 2], "M30");
  // One retract at the end, then the spindle stops: not two retracts.
  EXPECT_EQ(lines[lines.size() - 3], "M05");
  EXPECT_EQ(lines[lines.size() - 4].rfind("G00 Z", 0), 0u) << lines[lines.size() - 4];
  EXPECT_EQ(std::count_if(lines.end() - 6, lines.end(), [](const std::string& l) { return l.rfind("G00 Z", 0) == 0; }),
            1);
  EXPECT_NE(r.gcode.find("(entity a: bezier, degree 2, 2D)"), std::string::npos);
  EXPECT_NE(r.gcode.find("(entity b: bezier, degree 2, 3D)"), std::string::npos);
  // Every G00 after the first XY move happens at safe Z; plunges at the plunge feed.
  EXPECT_NE(r.gcode.find("G01 Z-1. F200."), std::string::npos);
  EXPECT_NE(r.gcode.find("F800."), std::string::npos);
  // The measured deviation is reported and within the tolerance.
  EXPECT_GT(r.program.max_measured, 0);
  EXPECT_LE(r.program.max_measured, r.program.max_bound);
  EXPECT_LE(r.program.max_bound, 0.01);
  ASSERT_EQ(r.program.entities.size(), 2u);
  EXPECT_GT(r.program.entities[0].blocks, 1u);
}

TEST(Program, TheToolListNamesEachEntityOnce) {
  // Two contours under one id (the contours of a glyph share its label).
  const Job j = job_of(R"({"id": "g", "type": "bezier", "points": [[0,0],[10,5],[20,0]]},
                          {"id": "g", "type": "bezier", "points": [[0,10],[10,15],[20,10]]},
                          {"id": "h", "type": "bezier", "points": [[0,20],[10,25],[20,20]]})");
  const ConvertResult r = convert(j, load_machine_profile("generic"), {});
  EXPECT_NE(r.gcode.find("\n(T3: g, h)\n"), std::string::npos) << r.gcode.substr(0, 400);
}

TEST(Program, LineNumbersAndDecimalsFromTheProfile) {
  const Job j = job_of(R"({"type": "bezier", "points": [[0,0],[10,5],[20,0]]})");
  const ConvertResult f = convert(j, load_machine_profile("fanuc"), {});
  EXPECT_NE(f.gcode.find("\nN10 ("), std::string::npos);
  EXPECT_NE(f.gcode.find("O1000"), std::string::npos);
  const ConvertResult u = convert(j, load_machine_profile("unisurf"), {});
  EXPECT_NE(u.gcode.find("\nN1 "), std::string::npos);
  // unisurf prints 2 decimals: no coordinate has 3.
  std::istringstream in(u.gcode);
  for (std::string l; std::getline(in, l);) {
    for (size_t p = l.find_first_of("XY"); p != std::string::npos; p = l.find_first_of("XY", p + 1)) {
      const auto dot = l.find('.', p);
      const auto end = l.find(' ', p);
      if (dot != std::string::npos && dot < end)
        EXPECT_LE((end == std::string::npos ? l.size() : end) - dot - 1, 2u) << l;
    }
  }
}

TEST(Program, InchJobsPrintG20AndConvertTheLimits) {
  const Job j = parse_job(
      R"({"bezcam": 1, "units": "inch", "tolerance": 0.0005, "job": {"feed": 100, "plunge_feed": 20, "safe_z": 0.2, "cut_z": -0.05},
                            "entities": [{"type": "bezier", "points": [[0,0],[1,1],[2,0]]}]})",
      "i.json");
  const ConvertResult r = convert(j, load_machine_profile("generic"), {});
  EXPECT_NE(r.gcode.find("G20 G90 G17"), std::string::npos);
  // grbl's 5000 mm/min is 196.85 inch/min: a 200 inch/min feed is refused.
  const Job fast = parse_job(
      R"({"bezcam": 1, "units": "inch", "job": {"feed": 200, "plunge_feed": 20, "safe_z": 0.2, "cut_z": -0.05},
                            "entities": [{"type": "bezier", "points": [[0,0],[1,1],[2,0]]}]})",
      "i.json");
  EXPECT_THROW(convert(fast, load_machine_profile("grbl"), {}), InputError);
  EXPECT_NO_THROW(convert(j, load_machine_profile("grbl"), {}));
}

TEST(Program, RefusalsBeforeAnythingIsWritten) {
  const MachineProfile u = load_machine_profile("unisurf");
  try {
    convert(job_of(R"({"id": "far", "type": "bezier", "points": [[0,0],[10,1400],[20,0]]})"), u, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "program.travel");
    EXPECT_EQ(e.where(), "t.json: entities[0] (id \"far\")");
    EXPECT_NE(e.message().find("Y"), std::string::npos) << e.message();
  }
  // A 3D curve rising above safe Z would be crossed by rapids.
  try {
    convert(job_of(R"({"type": "bezier", "points": [[0,0,0],[10,0,12],[20,0,0]]})"), u, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "job.above-safe-z");
  }
  // A feed above the machine's maximum.
  EXPECT_THROW(convert(job_of(R"({"type": "bezier", "points": [[0,0],[1,1]], "feed": 2500})"), u, {}), InputError);
}
