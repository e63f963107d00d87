// Canned drilling cycles G81, G82, G83 and G73 (docs/gcode-dialects.md):
// the moves each hole becomes in both dialects, G90 and G91, G98 and G99,
// L repeats, pecks that do not divide the depth, the move up to R when the
// cycle starts below it, and the refusals, naming the line. LinuxCNC's own
// interpreter judges the LinuxCNC dialect in linuxcnc_rs274_test.cpp.
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/gcode/lint.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/gcode/resume.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "support/refusal.hpp"

using namespace bezcam;

namespace {

// An expected move: 'R' rapid or 'F' feed, to (x, y, z).
struct Want {
  char kind;
  double x, y, z;
};

std::string show(const std::vector<MotionBlock>& got) {
  std::ostringstream s;
  for (const MotionBlock& b : got)
    s << (b.kind == BlockKind::rapid ? 'R' : 'F') << "(" << b.to.x << ", " << b.to.y << ", " << b.to.z << ") line "
      << b.line << "\n";
  return s.str();
}

void expect_moves(const std::vector<MotionBlock>& got, const std::vector<Want>& want) {
  ASSERT_EQ(got.size(), want.size()) << show(got);
  for (size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("move " + std::to_string(i + 1) + "\n" + show(got));
    EXPECT_EQ(got[i].kind, want[i].kind == 'R' ? BlockKind::rapid : BlockKind::linear);
    EXPECT_NEAR(got[i].to.x, want[i].x, 1e-9);
    EXPECT_NEAR(got[i].to.y, want[i].y, 1e-9);
    EXPECT_NEAR(got[i].to.z, want[i].z, 1e-9);
    if (i > 0) EXPECT_EQ(got[i].from, got[i - 1].to);
  }
}

// The blocks of the program's lines from `first` on (1-based).
std::vector<MotionBlock> blocks_from(const std::vector<MotionBlock>& all, int first) {
  std::vector<MotionBlock> out;
  for (const MotionBlock& b : all)
    if (b.line >= first) out.push_back(b);
  return out;
}

InputError refusal(const std::string& text, const MachineProfile* m = nullptr) {
  return test::refusal_of([&] { read_gcode(text, m); });
}

const char* kStart = "G21 G90 G17\nG0 X0 Y0 Z10\nF100\n";  // lines 1-3

}  // namespace

TEST(CannedCycles, G81InG99ReturnsToRAndAnXLineDrillsTheNextHole) {
  // LinuxCNC starts in G99.
  const auto got = read_gcode(std::string(kStart) + "G81 X1 Y1 Z-2 R2\nX2\nG80\nM2\n");
  expect_moves(blocks_from(got, 4), {{'R', 1, 1, 10},
                                     {'R', 1, 1, 2},
                                     {'F', 1, 1, -2},
                                     {'R', 1, 1, 2},
                                     {'R', 2, 1, 2},
                                     {'F', 2, 1, -2},
                                     {'R', 2, 1, 2}});
  EXPECT_EQ(got[3].line, 4);
  EXPECT_EQ(got.back().line, 5);
}

TEST(CannedCycles, G98ReturnsToTheInitialLevelOfTheFirstHole) {
  const auto got = read_gcode(std::string(kStart) + "G98 G81 X1 Y1 Z-2 R2\nX2\nM2\n");
  expect_moves(blocks_from(got, 4), {{'R', 1, 1, 10},
                                     {'R', 1, 1, 2},
                                     {'F', 1, 1, -2},
                                     {'R', 1, 1, 10},
                                     {'R', 2, 1, 10},
                                     {'R', 2, 1, 2},
                                     {'F', 2, 1, -2},
                                     {'R', 2, 1, 10}});
}

TEST(CannedCycles, G83PecksThatDoNotDivideTheDepthAfterAMoveUpToR) {
  // Starting below R (Z1 < R2): LinuxCNC rapids straight up to R first.
  // Depth 5.5 by Q1: five full pecks and a last one of 0.5; back into the
  // hole 0.254 mm (0.010 inch) above the last depth.
  const auto got = read_gcode(std::string(kStart) + "G0 X2 Y1 Z1\nG98 G83 X5 Y5 Z-3.5 R2 Q1\nM2\n");
  expect_moves(blocks_from(got, 5), {{'R', 2, 1, 2},
                                     {'R', 5, 5, 2},
                                     {'F', 5, 5, 1},
                                     {'R', 5, 5, 2},
                                     {'R', 5, 5, 1.254},
                                     {'F', 5, 5, 0},
                                     {'R', 5, 5, 2},
                                     {'R', 5, 5, 0.254},
                                     {'F', 5, 5, -1},
                                     {'R', 5, 5, 2},
                                     {'R', 5, 5, -0.746},
                                     {'F', 5, 5, -2},
                                     {'R', 5, 5, 2},
                                     {'R', 5, 5, -1.746},
                                     {'F', 5, 5, -3},
                                     {'R', 5, 5, 2},
                                     {'R', 5, 5, -2.746},
                                     {'F', 5, 5, -3.5},
                                     {'R', 5, 5, 2}});
}

TEST(CannedCycles, G73InG91RepeatsWithLFromTheCurrentHole) {
  // G91: R from the initial level (10 - 12 = -2), Z from R (-2 - 2.1 =
  // -4.1); X1 and L2: two holes one apart. G73 backs off 0.254 mm.
  const auto got = read_gcode(std::string(kStart) + "G0 X5 Y5\nG91 G99 G73 X1 Z-2.1 R-12 Q0.7 L2\nM2\n");
  const std::vector<Want> hole6 = {{'R', 6, 5, -2},     {'F', 6, 5, -2.7}, {'R', 6, 5, -2.446}, {'F', 6, 5, -3.4},
                                   {'R', 6, 5, -3.146}, {'F', 6, 5, -4.1}, {'R', 6, 5, -2}};
  std::vector<Want> want = {{'R', 6, 5, 10}};
  want.insert(want.end(), hole6.begin(), hole6.end());
  want.push_back({'R', 7, 5, -2});
  for (size_t i = 1; i < hole6.size(); ++i) want.push_back({hole6[i].kind, 7, 5, hole6[i].z});
  expect_moves(blocks_from(got, 5), want);
}

TEST(CannedCycles, G82DwellsAfterTheFeedToTheBottomAndTheTimelineStopsThere) {
  const std::string text = std::string(kStart) + "G82 X1 Y1 Z-2 R2 P0.5\nX3\nM2\n";
  const auto got = read_gcode(text);
  ASSERT_EQ(got.size(), 8u) << show(got);
  for (size_t i = 0; i < got.size(); ++i)
    EXPECT_EQ(got[i].dwell_s, (i == 3 || i == 6) ? 0.5 : 0.0) << show(got);  // the feeds to Z-2
  const Timeline tl = read_timeline(text);
  ASSERT_EQ(tl.pauses.size(), 2u);
  EXPECT_EQ(tl.pauses[0].kind, PlanPause::Kind::dwell);
  EXPECT_EQ(tl.pauses[0].seconds, 0.5);
  EXPECT_EQ(tl.pauses[0].before_block, 4u);  // after the block of index 3
  EXPECT_EQ(tl.pauses[1].before_block, 7u);
  EXPECT_EQ(tl.pauses[1].line, 5);
  // G04 still dwells before its line's (absent) motion.
  const Timeline g4 = read_timeline(std::string(kStart) + "G4 P2\nG0 X1\nM2\n");
  ASSERT_EQ(g4.pauses.size(), 1u);
  EXPECT_EQ(g4.pauses[0].seconds, 2);
  EXPECT_EQ(g4.pauses[0].before_block, 1u);
}

TEST(CannedCycles, TheRetainedWordsDifferByDialect) {
  // LinuxCNC takes R and Z over only from a line of the same cycle; Fanuc
  // keeps the drilling data for every cycle until the mode ends.
  const std::string text = std::string(kStart) + "G81 X1 Y1 Z-2 R2\nG82 X2 P1\nM2\n";
  const InputError e = refusal(text);
  EXPECT_EQ(e.id(), errc::gcode_cycle);
  EXPECT_EQ(e.place().line, 5);
  EXPECT_NE(e.message().find("R plane R-"), std::string::npos) << e.message();
  const MachineProfile fanuc = load_machine_profile("fanuc");
  const auto got = read_gcode(text, &fanuc);
  // Fanuc starts in G98: back to the initial level, 10.
  expect_moves(blocks_from(got, 4), {{'R', 1, 1, 10},
                                     {'R', 1, 1, 2},
                                     {'F', 1, 1, -2},
                                     {'R', 1, 1, 10},
                                     {'R', 2, 1, 10},
                                     {'R', 2, 1, 2},
                                     {'F', 2, 1, -2},
                                     {'R', 2, 1, 10}});
  // G80 ends the mode, and with it the data: R is needed again.
  const InputError after = refusal(std::string(kStart) + "G81 X1 Y1 Z-2 R2\nG80\nG81 X2 Z-2\nM2\n", &fanuc);
  EXPECT_EQ(after.id(), errc::gcode_cycle);
  EXPECT_EQ(after.place().line, 6);
}

TEST(CannedCycles, FanucPecksWithItsClearanceAndPositionsAtTheCurrentHeight) {
  const MachineProfile fanuc = load_machine_profile("fanuc");
  ASSERT_EQ(fanuc.cycles.dialect, CannedCycles::Dialect::fanuc);
  // G99 then G98 on the next hole: Fanuc moves in XY where the drill is
  // (at R), then to R; LinuxCNC would rapid straight to the initial level.
  const std::string text = std::string(kStart) + "G99 G83 X1 Y1 Z-3 R2 Q2\nG98 X4\nM2\n";
  const auto got = read_gcode(text, &fanuc);
  expect_moves(blocks_from(got, 4), {{'R', 1, 1, 10},
                                     {'R', 1, 1, 2},
                                     {'F', 1, 1, 0},
                                     {'R', 1, 1, 2},
                                     {'R', 1, 1, 1},  // 1 mm (parameter 5115) above the last depth
                                     {'F', 1, 1, -2},
                                     {'R', 1, 1, 2},
                                     {'R', 1, 1, -1},
                                     {'F', 1, 1, -3},
                                     {'R', 1, 1, 2},
                                     {'R', 4, 1, 2},
                                     {'F', 4, 1, 0},
                                     {'R', 4, 1, 2},
                                     {'R', 4, 1, 1},
                                     {'F', 4, 1, -2},
                                     {'R', 4, 1, 2},
                                     {'R', 4, 1, -1},
                                     {'F', 4, 1, -3},
                                     {'R', 4, 1, 10}});
  const auto lcnc = read_gcode(text);
  EXPECT_EQ(blocks_from(lcnc, 5).front().to, (Vec3{4, 1, 10})) << show(lcnc);
  // A Fanuc control would position below R: refused.
  const InputError e = refusal(std::string(kStart) + "G0 Z1\nG81 X1 Y1 Z-2 R2\nM2\n", &fanuc);
  EXPECT_EQ(e.id(), errc::gcode_cycle);
  EXPECT_EQ(e.place().line, 5);
  EXPECT_NE(e.message().find("below the R plane"), std::string::npos) << e.message();
}

TEST(CannedCycles, GrblHasNone) {
  const MachineProfile grbl = load_machine_profile("grbl");
  const InputError e = refusal(std::string(kStart) + "G81 X1 Y1 Z-2 R2\nM2\n", &grbl);
  EXPECT_EQ(e.id(), errc::gcode_dialect);
  EXPECT_EQ(e.place().line, 4);
  EXPECT_NE(e.message().find("has none"), std::string::npos) << e.message();
}

TEST(CannedCycles, InTheG19PlaneXIsTheDrillingAxis) {
  const auto got = read_gcode("G21 G90 G19\nG0 X10 Y0 Z0\nF100\nG81 Y1 Z1 X-2 R2\nM2\n");
  expect_moves(blocks_from(got, 4), {{'R', 10, 1, 1}, {'R', 2, 1, 1}, {'F', -2, 1, 1}, {'R', 2, 1, 1}});
}

TEST(CannedCycles, RefusalsNameTheLineAndTheWord) {
  struct Case {
    std::string line;  // line 4
    ErrorId id;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"G81 X1 Y1 R2", errc::gcode_cycle, "bottom of the hole Z-"},
      {"G81 X1 Y1 Z-2", errc::gcode_cycle, "R plane R-"},
      {"G81 X1 Y1 Z2 R-1", errc::gcode_cycle, "below the bottom of the hole"},
      {"G83 X1 Y1 Z-2 R2", errc::gcode_cycle, "peck depth Q-"},
      {"G83 X1 Y1 Z-2 R2 Q0", errc::gcode_cycle, "Q > 0, found Q0"},
      {"G73 X1 Y1 Z-2 R2 Q-1", errc::gcode_cycle, "Q > 0, found Q-1"},
      {"G82 X1 Y1 Z-2 R2", errc::gcode_cycle, "dwell P-"},
      {"G82 X1 Y1 Z-2 R2 P-1", errc::gcode_dwell, "P >= 0"},
      {"G81 X1 Y1 Z-2 R2 L0", errc::gcode_cycle, "found L0"},
      {"G81 X1 Y1 Z-2 R2 L1.5", errc::gcode_cycle, "found L1.5"},
      {"G81 X1 Y1 Z-2 R2 Q1", errc::gcode_unexpected_word, "Q1"},
      {"G83 X1 Y1 Z-100000 R2 Q0.001", errc::gcode_cycle, "more than the 100000"},
      {"G41 D0 G81 X1 Y1 Z-2 R2", errc::gcode_cutter_comp, "cutter radius compensation"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.line);
    const InputError e = refusal(std::string(kStart) + c.line + "\nM2\n");
    EXPECT_EQ(e.id(), c.id);
    EXPECT_EQ(e.place().line, 4);
    EXPECT_NE(e.message().find(c.says), std::string::npos) << e.message();
  }
  // In cycle mode P, Q or L alone drill nothing; after G80 X alone is no move.
  const InputError alone = refusal(std::string(kStart) + "G83 X1 Y1 Z-2 R2 Q1\nQ2\nM2\n");
  EXPECT_EQ(alone.id(), errc::gcode_unexpected_word);
  EXPECT_EQ(alone.place().line, 5);
  EXPECT_NE(alone.message().find("Q2 alone in canned cycle mode (G83 since line 4)"), std::string::npos)
      << alone.message();
  const InputError cancelled = refusal(std::string(kStart) + "G81 X1 Y1 Z-2 R2\nG80\nX3\nM2\n");
  EXPECT_EQ(cancelled.id(), errc::gcode_no_motion);
  EXPECT_EQ(cancelled.place().line, 6);
  // Without an earlier move the initial level is unknown.
  const InputError unknown = refusal("G21 G90 G17\nF100\nG81 X1 Y1 Z-2 R2\nM2\n");
  EXPECT_EQ(unknown.id(), errc::gcode_position_unknown);
  EXPECT_EQ(unknown.place().line, 3);
}

TEST(CannedCycles, LintReadsACycleProgramCleanAndGoesOnAfterARefusal) {
  const MachineProfile m = load_machine_profile("linuxcnc");
  const std::string good =
      std::string(kStart) + "S1000 M3\nG98 G83 X1 Y1 Z-3 R2 Q1\nX2\nG99 G82 X3 Z-1 R1 P0.2\nG80\nM2\n";
  EXPECT_TRUE(lint_gcode(good, m).empty());
  const auto findings = lint_gcode(std::string(kStart) + "S1000 M3\nG81 X1 Y1 Z-2\nG81 X1 Y1 Z-2 R2\nM2\n", m);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].line, 5);
  EXPECT_EQ(findings[0].id, errc::gcode_cycle);
}

TEST(CannedCycles, AResumeStartsBeforeTheCycleModeBegan) {
  // Line 7 (X3) drills with the initial level, R and Z of line 5: the
  // resume goes back to the line before the cycle mode began; after G80,
  // the preamble restores G98.
  const MachineProfile m = load_machine_profile("linuxcnc");
  const std::string text = std::string(kStart) + "S1000 M3\nG98 G81 X1 Y1 Z-2 R2\nX2\nX3\nG80\nM2\n";
  const ResumePlan p = plan_resume(text, &m, 7);
  EXPECT_EQ(p.start_line, 4);
  EXPECT_NE(p.reason.find("canned cycle"), std::string::npos) << p.reason;
  const ResumePlan at80 = plan_resume(text, &m, 8);
  EXPECT_EQ(at80.start_line, 8);
  EXPECT_NE(at80.preamble.find(" G98"), std::string::npos) << at80.preamble;
}
