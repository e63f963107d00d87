// Words of real programs (issue "Safe on the shop floor", bug 8): tool
// length compensation, work offsets, G28 and G53, coolant, dwells and the
// safety line are read and executed, their state kept and traced, and
// their misuse refused naming the line.
#include <gtest/gtest.h>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/sim/trace.hpp"

using namespace bezcam;

namespace {

// What a machinist's post writes around a cut.
const char* kProgram =
    "%\n"
    "O0042 (two tools)\n"
    "G21 G90 G17\n"
    "G40 G49 G80\n"
    "G55\n"
    "T2 M06\n"
    "G43 H2\n"
    "S9000 M03\n"
    "G04 P1.5\n"
    "M08\n"
    "G00 X10 Y5 Z5\n"
    "G01 Z-1 F300\n"
    "G01 X20\n"
    "M09\n"
    "G28 Z10\n"
    "G53 G00 Z0\n"
    "G49\n"
    "M07 M05\n"
    "M30\n"
    "%\n";

MachineState run(const std::string& text, std::vector<MotionBlock>* blocks = nullptr, std::string* trace = nullptr) {
  GcodeInterpreter in;
  int n = 0;
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    const MachineState before = in.state();
    auto got = in.feed_line(line, ++n);
    if (trace) *trace += sim::trace_state(n, before, in.state());
    if (blocks) blocks->insert(blocks->end(), got.begin(), got.end());
    at = end == std::string::npos ? text.size() : end + 1;
  }
  in.finish();
  return in.state();
}

InputError refusal(const std::string& text) {
  try {
    read_gcode(text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return InputError(ErrorId(""), Place{}, "");
}

}  // namespace

TEST(MachinistWords, AreReadExecutedAndTraced) {
  std::vector<MotionBlock> blocks;
  std::string trace;
  const MachineState s = run(kProgram, &blocks, &trace);
  EXPECT_EQ(s.coord_system, WorkOffset::g55);
  EXPECT_FALSE(s.tool_length_comp);
  EXPECT_TRUE(s.coolant_mist);
  EXPECT_FALSE(s.coolant_flood);
  EXPECT_DOUBLE_EQ(s.dwell_seconds, 1.5);
  EXPECT_TRUE(s.program_end);
  for (const char* rec :
       {"line 5 work offset G55\n", "line 7 tool length H2\n", "line 9 dwell 1.500000\n", "line 10 coolant flood\n",
        "line 14 coolant off\n", "line 17 tool length off\n", "line 18 coolant mist\n"})
    EXPECT_NE(trace.find(rec), std::string::npos) << rec << "\n" << trace;
  // G28 Z10: up to the intermediate point, then Z home (machine zero) with
  // X and Y where they are; G53 G00 Z0: a rapid in machine coordinates.
  ASSERT_EQ(blocks.size(), 6u);
  EXPECT_EQ(blocks[3].kind, BlockKind::rapid);
  EXPECT_EQ(blocks[3].to.z, 10);
  EXPECT_EQ(blocks[3].to.x, 20);
  EXPECT_EQ(blocks[4].to.z, 0);
  EXPECT_EQ(blocks[4].to.x, 20);
  EXPECT_EQ(blocks[4].line, 15);
  EXPECT_EQ(blocks[5].line, 16);
}

TEST(MachinistWords, G28WithoutAxesSendsEveryAxisHome) {
  std::vector<MotionBlock> blocks;
  run("G21 G90\nG00 X10 Y20 Z5\nG28\n", &blocks);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].kind, BlockKind::rapid);
  EXPECT_EQ(blocks[1].to.x, 0);
  EXPECT_EQ(blocks[1].to.y, 0);
  EXPECT_EQ(blocks[1].to.z, 0);
}

TEST(MachinistWords, G43TakesTheToolInTheSpindleWithoutH) { EXPECT_EQ(run("T3 M06\nG43\n").tool_length_h, 3); }

TEST(MachinistWords, MisuseIsRefusedNamingTheLine) {
  auto e = refusal("G21 G90\nG28 G01 X5 F100\n");
  EXPECT_EQ(e.id(), "gcode.modal-group");
  EXPECT_EQ(e.where(), "line 2");
  e = refusal("G21 G90\nG53 X5\n");
  EXPECT_EQ(e.where(), "line 2");
  EXPECT_NE(std::string(e.what()).find("G53"), std::string::npos) << e.what();
  e = refusal("G21 G90\nG04 P1 G28\n");
  EXPECT_EQ(e.id(), "gcode.modal-group");
  e = refusal("G43 H-1\n");
  EXPECT_EQ(e.id(), "gcode.tool");
  e = refusal("G49 H2\n");  // H means something only with G43
  EXPECT_EQ(e.id(), "gcode.unexpected-word");
}
