// Drilled holes in the program text (docs/holes.md): canned cycles on the
// profiles that run them, the same motion as G00/G01 moves on Grbl, and
// the cycle time with every peck.
#include <gtest/gtest.h>
#include <regex>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam {
namespace {

// Five holes: two plain (G81, the drill at R between them: G99), a peck
// (G83), a chip-breaking peck (G73) and a dwell (G82), each back to the
// initial level (G98): their R planes differ.
const char* kHoles = R"({"bezcam":1,"units":"mm","tolerance":0.01,
 "tools":{"2":{"shape":"drill","diameter":5,"point_angle":118,"flute_length":30}},
 "job":{"feed":800,"plunge_feed":150,"safe_z":5,"top_z":0,"clearance":1,"spindle_rpm":3000,"tool":2,
        "cut_z":-10,"operation":"drill","to":"tip"},
 "entities":[
  {"type":"point","at":[10,10],"id":"a"},
  {"type":"point","at":[20,10],"id":"b"},
  {"type":"point","at":[30,10],"id":"c","peck":3,"retract_z":2},
  {"type":"point","at":[40,10],"id":"d","peck":3,"chip_break":true,"retract_z":3},
  {"type":"point","at":[50,10],"id":"e","dwell":0.5,"retract_z":4}]})";

ConvertResult convert_with(const MachineProfile& m, const char* text = kHoles) {
  return convert(parse_job(text, "holes.json"), m, {});
}

std::vector<std::string> matching(const std::string& text, const std::string& re) {
  std::vector<std::string> out;
  const std::regex r(re);
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, r)) out.push_back(line);
  return out;
}

TEST(DrillOutput, LinuxcncAndFanucPrintCannedCycles) {
  for (const char* machine : {"linuxcnc", "fanuc"}) {
    SCOPED_TRACE(machine);
    const std::string g = convert_with(load_machine_profile(machine)).gcode;
    const auto cycles = matching(g, R"(^(N\d+ )?(G9[89] |G80$|X20\. Y))");
    const std::string n = machine == std::string("fanuc") ? R"(N\d+ )" : "";
    const std::vector<std::string> want = {"G99 G81 X10. Y10. Z-10. R1. F150.",
                                           "X20. Y10.",
                                           "G80",
                                           "G98 G83 X30. Y10. Z-10. R2. Q3. F150.",
                                           "G98 G73 X40. Y10. Z-10. R3. Q3. F150.",
                                           "G98 G82 X50. Y10. Z-10. R4. P0.5 F150.",
                                           "G80"};
    ASSERT_EQ(cycles.size(), want.size()) << g;
    for (size_t i = 0; i < want.size(); ++i)
      EXPECT_TRUE(std::regex_match(cycles[i], std::regex(n + want[i]))) << cycles[i];
  }
}

TEST(DrillOutput, GrblGetsPlainMoves) {
  const std::string g = convert_with(load_machine_profile("grbl")).gcode;
  EXPECT_TRUE(matching(g, R"(G(73|8[1-3]|98|99)\b)").empty()) << g;
  EXPECT_FALSE(matching(g, R"(G4 P0\.5)").empty()) << g;  // G82's dwell
}

// The canned form read back and the plain form read back are the same
// blocks: a profile, and the same profile without canned cycles.
TEST(DrillOutput, PlainMovesAreTheCannedCyclesMotion) {
  for (const char* machine : {"linuxcnc", "fanuc"}) {
    SCOPED_TRACE(machine);
    const MachineProfile canned = load_machine_profile(machine);
    MachineProfile plain = canned;
    plain.cycles.dialect = CannedCycles::Dialect::none;
    const ConvertResult a = convert_with(canned), b = convert_with(plain);
    EXPECT_FALSE(matching(a.gcode, "G83").empty());
    EXPECT_TRUE(matching(b.gcode, "G83").empty());
    const auto ra = read_gcode(a.gcode, &canned), rb = read_gcode(b.gcode, &plain);
    ASSERT_EQ(ra.size(), rb.size());
    double dwell_a = 0, dwell_b = 0;
    for (size_t i = 0; i < ra.size(); ++i) {
      EXPECT_EQ(ra[i].kind, rb[i].kind) << i;
      EXPECT_LE(dist(ra[i].to, rb[i].to), 1e-12) << i;
      EXPECT_EQ(ra[i].feed, rb[i].feed) << i;
      dwell_a += ra[i].dwell_s;
    }
    // The program's own moves are the same blocks as the text read back.
    // (The text has the profile's own moves before the first tool too.)
    const auto own = program_motion(a.program);
    ASSERT_LE(own.size(), ra.size());
    const size_t skip = ra.size() - own.size();
    for (size_t i = 0; i < own.size(); ++i) {
      EXPECT_EQ(own[i].kind, ra[skip + i].kind) << i;
      EXPECT_LE(dist(own[i].to, ra[skip + i].to), 1e-12) << i;
    }
    const Timeline tb = read_timeline(b.gcode, &plain);
    for (const auto& p : tb.pauses)
      if (p.kind == PlanPause::Kind::dwell && p.seconds == 0.5) dwell_b += p.seconds;
    EXPECT_EQ(dwell_a, 0.5);
    EXPECT_EQ(dwell_b, 0.5);
    // Pecks: from R 2 down to -10 by 3 (to -1, -4, -7), then the bottom.
    size_t feeds_c = 0;
    for (const auto& blk : ra) feeds_c += blk.kind == BlockKind::linear && blk.to.x == 30 ? 1 : 0;
    EXPECT_EQ(feeds_c, 4u);
  }
}

// The header's cycle time is the planned text's, every peck counted: the
// same job without pecks is faster by what the pecks take.
TEST(DrillOutput, CycleTimeCountsEveryPeck) {
  const MachineProfile m = load_machine_profile("linuxcnc");
  ASSERT_TRUE(m.motion);
  const ConvertResult r = convert_with(m);
  const MotionPlan text = plan_motion(read_timeline(r.gcode, &m), *m.motion);
  const MotionPlan header = plan_motion(program_timeline(r.program), *m.motion);
  EXPECT_NEAR(header.cycle_time_s, text.cycle_time_s, 1e-9 * text.cycle_time_s);
  ASSERT_TRUE(r.plan);
  EXPECT_NEAR(r.plan->cycle_time_s, text.cycle_time_s, 1e-9 * text.cycle_time_s);
  std::string no_pecks = kHoles;
  for (const char* k : {R"("peck":3,"chip_break":true,)", R"("peck":3,)"})
    for (size_t at; (at = no_pecks.find(k)) != std::string::npos;) no_pecks.erase(at, std::string(k).size());
  const ConvertResult s = convert_with(m, no_pecks.c_str());
  const MotionPlan fewer = plan_motion(read_timeline(s.gcode, &m), *m.motion);
  // Each of the 2 x 3 pecks at least goes out and back in at the rapid
  // rate: more time than none.
  EXPECT_GT(text.cycle_time_s, fewer.cycle_time_s + 0.1);
}

}  // namespace
}  // namespace bezcam
