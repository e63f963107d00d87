// Resume from a line (gcode/resume.hpp), in the library: where it starts and
// why, the preamble's modal state against the full run's at that line (the
// preamble run through a fresh reader), and the motion of the resumed
// program's tail against the full run's from that line, block by block and
// exactly. The same cases over real sockets, through the simulated
// controller's trace: tests/sim/resume_stream_test.cpp.
#include "bezcam/gcode/resume.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/gcode/reader.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "support/files.hpp"
#include "support/refusal.hpp"

using namespace bezcam;

namespace {

std::string slurp(const std::string& rel) {
  return bezcam::test::slurp(std::string(BEZCAM_SOURCE_DIR) + "/tests/gcode/data/resume/" + rel);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Runs lines [1, upto) of `text` through a fresh reader; the motion blocks
// of every line when upto is 0.
struct Ran {
  MachineState state;
  GcodeInterpreter::Continuation cont;
  std::vector<MotionBlock> blocks;
};
Ran run(const std::string& text, const MachineProfile& m, int upto = 0) {
  GcodeInterpreter in(&m);
  Ran r;
  const auto ls = lines_of(text);
  for (int i = 0; i < static_cast<int>(ls.size()) && (upto == 0 || i + 1 < upto); ++i)
    for (auto& b : in.feed_line(ls[static_cast<size_t>(i)], i + 1)) r.blocks.push_back(b);
  r.state = in.state();
  r.cont = in.continuation();
  return r;
}

// The modal state the spec lists (units, plane, distance mode, work offset,
// tool, spindle and speed, coolant, feed, path mode), the tool length
// offset, the selected tool and the position.
void expect_same_state(const Ran& want, const Ran& got) {
  const MachineState &w = want.state, &g = got.state;
  EXPECT_EQ(g.units, w.units);
  EXPECT_EQ(g.units_set, w.units_set);
  EXPECT_EQ(g.plane, w.plane);
  EXPECT_EQ(g.distance, w.distance);
  EXPECT_EQ(g.arc_centers, w.arc_centers);
  EXPECT_EQ(g.coord_system, w.coord_system);
  EXPECT_EQ(g.tool, w.tool);
  EXPECT_EQ(got.cont.selected_tool, want.cont.selected_tool);
  EXPECT_EQ(g.tool_length_comp, w.tool_length_comp);
  EXPECT_EQ(g.tool_length_h, w.tool_length_h);
  EXPECT_EQ(g.spindle_on, w.spindle_on);
  EXPECT_EQ(g.spindle_ccw, w.spindle_ccw);
  EXPECT_EQ(g.spindle_rpm, w.spindle_rpm);
  EXPECT_EQ(g.coolant_mist, w.coolant_mist);
  EXPECT_EQ(g.coolant_flood, w.coolant_flood);
  EXPECT_EQ(g.feed, w.feed);
  EXPECT_EQ(g.path_mode, w.path_mode);
  EXPECT_EQ(g.known_axes, w.known_axes);
  for (int a = 0; a < 3; ++a)
    if (w.known_axes & (1u << a)) EXPECT_EQ(g.pos[a], w.pos[a]) << "axis " << a;
  EXPECT_EQ(got.cont.open_block, ModalMotion::none);
}

void expect_same_block(const MotionBlock& w, const MotionBlock& g, long offset) {
  EXPECT_EQ(static_cast<int>(g.kind), static_cast<int>(w.kind));
  EXPECT_EQ(g.first_line + offset, w.first_line);
  EXPECT_EQ(g.line + offset, w.line);
  EXPECT_EQ(g.from, w.from);
  EXPECT_EQ(g.to, w.to);
  EXPECT_EQ(g.from_known, w.from_known);
  EXPECT_EQ(g.feed, w.feed);
  EXPECT_EQ(g.center, w.center);
  EXPECT_EQ(g.order, w.order);
  EXPECT_EQ(g.ctrl, w.ctrl);
  EXPECT_EQ(g.weights, w.weights);
  EXPECT_EQ(g.knots, w.knots);
}

// Plans the resume at `asked`, expects it to start at `start`, and checks
// the preamble's state and the tail's motion against the full run.
ResumePlan check_resume_text(const std::string& text, const std::string& machine, int asked, int start) {
  const MachineProfile m = load_machine_profile(machine);
  const ResumePlan plan = plan_resume(text, &m, asked);
  EXPECT_EQ(plan.asked_line, asked);
  EXPECT_EQ(plan.start_line, start) << plan.reason;
  EXPECT_EQ(plan.reason.empty(), asked == start) << plan.reason;
  EXPECT_EQ(plan.program.substr(0, plan.preamble.size()), plan.preamble);
  EXPECT_EQ(static_cast<int>(lines_of(plan.preamble).size()), plan.preamble_lines);

  // The preamble alone: the full run's state before the start line.
  const Ran full_before = run(text, m, start);
  const Ran preamble = run(plan.preamble, m);
  expect_same_state(full_before, preamble);

  // The tail: every block of the full run from the start line on, the same
  // (lines mapped by the plan's offset), after the preamble's own blocks.
  const Ran full = run(text, m);
  const Ran resumed = run(plan.program, m);
  std::vector<MotionBlock> want, pre, tail;
  for (const auto& b : full.blocks)
    if (b.first_line >= start) want.push_back(b);
  for (const auto& b : resumed.blocks) (b.line <= plan.preamble_lines ? pre : tail).push_back(b);
  EXPECT_EQ(tail.size(), want.size());
  for (size_t i = 0; i < std::min(tail.size(), want.size()); ++i) {
    SCOPED_TRACE("block " + std::to_string(i) + " of the tail, line " + std::to_string(want[i].line));
    expect_same_block(want[i], tail[i], plan.line_offset());
  }
  for (const auto& b : tail) EXPECT_EQ(plan.original_line(b.line), b.line + plan.line_offset());
  // The resumed program ends in the same state as the full run.
  expect_same_state(full, resumed);
  EXPECT_EQ(resumed.state.program_end, full.state.program_end);
  // The preamble's moves: retract, over, plunge at the plunge feed.
  if (full_before.state.known_axes == 7 && !pre.empty()) {
    EXPECT_EQ(pre.front().kind, BlockKind::rapid);
    EXPECT_EQ(pre.front().to.z, std::max(plan.safe_z, full_before.state.pos.z));
    if (full_before.state.pos.z < plan.safe_z) {
      EXPECT_EQ(pre.back().kind, BlockKind::linear);
      EXPECT_EQ(pre.back().feed, plan.plunge_feed);
      EXPECT_EQ(pre.back().to, full_before.state.pos);
    }
  }
  return plan;
}

ResumePlan check_resume(const std::string& file, const std::string& machine, int asked, int start) {
  return check_resume_text(slurp(file), machine, asked, start);
}

}  // namespace

TEST(Resume, InsideAG06_2BlockStartsAtTheBlock) {
  // Lines 22-29 are one G06.2 block: line 25 is inside it.
  const ResumePlan p = check_resume("two-tools-fanuc.nc", "fanuc", 25, 22);
  EXPECT_NE(p.reason.find("line 25"), std::string::npos) << p.reason;
  EXPECT_NE(p.reason.find("G06.2 NURBS block that starts at line 22"), std::string::npos) << p.reason;
  // The first knot-only K line, and the last line of the block.
  check_resume("two-tools-fanuc.nc", "fanuc", 26, 22);
  check_resume("two-tools-fanuc.nc", "fanuc", 29, 22);
  // The next block's first line follows a completed block (NURBS mode
  // still on): it names its own motion, so a cut may begin there.
  check_resume("two-tools-fanuc.nc", "fanuc", 31, 31);
  check_resume("two-tools-fanuc.nc", "fanuc", 36, 31);
}

TEST(Resume, InsideAG5_2BlockStartsAtTheBlock) {
  const ResumePlan p = check_resume("keyhole-linuxcnc.nc", "linuxcnc", 19, 17);
  EXPECT_NE(p.reason.find("G5.2 NURBS block that starts at line 17"), std::string::npos) << p.reason;
  check_resume("keyhole-linuxcnc.nc", "linuxcnc", 20, 17);  // its G5.3
  check_resume("keyhole-linuxcnc.nc", "linuxcnc", 21, 21);  // the next block
  check_resume("keyhole-linuxcnc.nc", "linuxcnc", 27, 25);
}

TEST(Resume, InAG5ChainStartsAtTheG5ThatGivesItsTangent) {
  // Lines 10 and 11 take their tangent from the G5 before them, back to
  // line 9 (I and J given); line 13 from line 12.
  const ResumePlan p = check_resume("g5-chain-linuxcnc.nc", "linuxcnc", 11, 9);
  EXPECT_NE(p.reason.find("G5 that takes its start tangent from the G5 before it"), std::string::npos) << p.reason;
  check_resume("g5-chain-linuxcnc.nc", "linuxcnc", 10, 9);
  check_resume("g5-chain-linuxcnc.nc", "linuxcnc", 9, 9);
  check_resume("g5-chain-linuxcnc.nc", "linuxcnc", 12, 12);  // after a G5, with its own I and J
  check_resume("g5-chain-linuxcnc.nc", "linuxcnc", 13, 12);
  check_resume("g5-chain-linuxcnc.nc", "linuxcnc", 14, 14);  // G1 after the chain
}

TEST(Resume, AtAnArc) {
  // An arc after an arc names its own motion: it is where the cut begins.
  check_resume("two-tools-arcs.nc", "generic", 21, 21);
  check_resume("two-tools-arcs.nc", "generic", 19, 19);
  // An arc left modal (no G03 on the line) cannot be entered: the mode
  // cannot be restored without moving.
  std::string text = slurp("two-tools-arcs.nc");
  const auto at = text.find("G03 X49.856");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, 4);  // line 21: "X49.856 Y18.827 I-13.902 J5.655"
  const MachineProfile m = load_machine_profile("generic");
  const ResumePlan p = plan_resume(text, &m, 21);
  EXPECT_EQ(p.start_line, 20);
  EXPECT_NE(p.reason.find("modal motion there is G03"), std::string::npos) << p.reason;
  const Ran full = run(text, m), resumed = run(p.program, m);
  std::vector<MotionBlock> want, tail;
  for (const auto& b : full.blocks)
    if (b.first_line >= 20) want.push_back(b);
  for (const auto& b : resumed.blocks)
    if (b.line > p.preamble_lines) tail.push_back(b);
  ASSERT_EQ(tail.size(), want.size());
  for (size_t i = 0; i < tail.size(); ++i) expect_same_block(want[i], tail[i], p.line_offset());
}

TEST(Resume, AfterAToolChange) {
  // Tool 2 (line 33), spindle 18000, mist coolant (line 35): line 40 is the
  // first arc of the second tool.
  const ResumePlan p = check_resume("two-tools-arcs.nc", "generic", 40, 40);
  EXPECT_EQ(p.state.tool, 2);
  EXPECT_EQ(p.state.spindle_rpm, 18000);
  EXPECT_TRUE(p.state.coolant_mist);
  EXPECT_FALSE(p.state.coolant_flood);
  EXPECT_NE(p.preamble.find("T2 M06\n"), std::string::npos) << p.preamble;
  // The Fanuc program: tool length offset H2, work offset G54.
  const ResumePlan f = check_resume("two-tools-fanuc.nc", "fanuc", 53, 52);
  EXPECT_EQ(f.state.tool, 2);
  EXPECT_TRUE(f.state.tool_length_comp);
  EXPECT_EQ(f.state.tool_length_h, 2);
  EXPECT_NE(f.preamble.find("G43 H2\n"), std::string::npos) << f.preamble;
  // Right at the tool change's line and just after it.
  check_resume("two-tools-fanuc.nc", "fanuc", 43, 43);
  check_resume("two-tools-fanuc.nc", "fanuc", 44, 44);
}

TEST(Resume, InchProgramsGetTheSafeHeightAndPlungeFeedInInches) {
  const ResumePlan p = check_resume("semicircle-inch.nc", "generic", 17, 17);
  EXPECT_EQ(p.state.units, Units::inch);
  EXPECT_DOUBLE_EQ(p.safe_z, 5 / 25.4);
  EXPECT_DOUBLE_EQ(p.plunge_feed, 300 / 25.4);
  // Given values replace the profile's.
  const MachineProfile m = load_machine_profile("generic");
  const ResumePlan q = plan_resume(slurp("semicircle-inch.nc"), &m, 17, ResumeSettings{25.4, 127});
  EXPECT_DOUBLE_EQ(q.safe_z, 1);
  EXPECT_DOUBLE_EQ(q.plunge_feed, 5);
  EXPECT_NE(q.preamble.find("G00 Z1\n"), std::string::npos) << q.preamble;
  EXPECT_NE(q.preamble.find(" F5\n"), std::string::npos) << q.preamble;
}

TEST(Resume, ThePreambleSaysWhereTheTailStarts) {
  const MachineProfile m = load_machine_profile("fanuc");
  const ResumePlan p = plan_resume(slurp("two-tools-fanuc.nc"), &m, 25);
  const std::string first = p.preamble.substr(0, p.preamble.find('\n'));
  EXPECT_EQ(first, "(bezcam resume: lines 1-" + std::to_string(p.preamble_lines) +
                       " restore the state of line 22, line " + std::to_string(p.preamble_lines + 1) +
                       " is line 22 of the program, asked 25)");
  EXPECT_EQ(p.original_line(1), 0);
  EXPECT_EQ(p.original_line(p.preamble_lines), 0);
  EXPECT_EQ(p.original_line(p.preamble_lines + 1), 22);
  // The tail is the file's text from line 22 on, byte for byte.
  const std::string text = slurp("two-tools-fanuc.nc");
  EXPECT_EQ(p.program.substr(p.preamble.size()), text.substr(text.find("N200 G06.2")));
}

TEST(Resume, BadLinesAreRefusedNamingTheLine) {
  const MachineProfile m = load_machine_profile("generic");
  const std::string prog = "%\nG21 G90 G17\n\n(a comment)\nG00 Z5.\nX1. Y1.\nM30\n%\n";
  auto e = test::refusal_of([&] { plan_resume(prog, &m, 9); });
  EXPECT_EQ(e.id(), "resume.no-line");
  EXPECT_EQ(e.where(), "line 9");
  EXPECT_NE(e.message().find("has 8 lines"), std::string::npos) << e.message();
  e = test::refusal_of([&] { plan_resume(prog, &m, 0); });
  EXPECT_EQ(e.id(), "resume.no-line");
  for (int blank : {1, 3, 4, 8}) {
    e = test::refusal_of([&] { plan_resume(prog, &m, blank); });
    EXPECT_EQ(e.id(), "resume.no-code") << blank;
    EXPECT_EQ(e.where(), "line " + std::to_string(blank));
  }
  // After M30: nothing runs there.
  const std::string after = "G21 G90\nG00 Z5.\nM30\nG00 X1.\n";
  e = test::refusal_of([&] { plan_resume(after, &m, 4); });
  EXPECT_EQ(e.id(), "resume.after-end");
  EXPECT_EQ(e.where(), "line 4");
  // ... also with blocks between the end and the line.
  e = test::refusal_of([&] { plan_resume(after + "G00 X2.\n", &m, 5); });
  EXPECT_EQ(e.id(), "resume.after-end");
  EXPECT_EQ(e.where(), "line 5");
  EXPECT_NE(e.message().find("ended at line 3"), std::string::npos) << e.message();
  // A G93 program (inverse-time feeds): the state before line 4 cannot be
  // known; the refusal names the G93 line and the line asked.
  const std::string g93 = "G21 G90\nG93\nG00 X1.\nG00 X2.\nM30\n";
  e = test::refusal_of([&] { plan_resume(g93, &m, 4); });
  EXPECT_EQ(e.id(), "resume.state-unknown");
  EXPECT_EQ(e.where(), "line 2");
  EXPECT_NE(e.message().find("cannot resume at line 4"), std::string::npos) << e.message();
  EXPECT_NE(e.message().find("gcode.unsupported"), std::string::npos) << e.message();
  // An unsupported word before the line.
  const std::string g38 = "G21 G90\nG00 Z5.\nG38.2 Z-5.\nG00 X1.\nM30\n";
  e = test::refusal_of([&] { plan_resume(g38, &m, 4); });
  EXPECT_EQ(e.id(), "resume.state-unknown");
  EXPECT_EQ(e.where(), "line 3");
  // ... but not after it: the lines after N are the controller's to check.
  EXPECT_EQ(plan_resume(g38, &m, 2).start_line, 2);
}

TEST(Resume, SafeHeightAndPlungeFeedMustBeKnownAndAccepted) {
  const std::string prog = "G21 G90\nG00 Z5.\nX1. Y1.\nG01 Z-1. F100.\nX2.\nM30\n";
  auto e = test::refusal_of([&] { plan_resume(prog, nullptr, 5); });
  EXPECT_EQ(e.id(), "resume.setting");
  EXPECT_EQ(e.where(), "safe_z");
  e = test::refusal_of([&] { plan_resume(prog, nullptr, 5, ResumeSettings{10, std::nullopt}); });
  EXPECT_EQ(e.where(), "plunge_feed");
  EXPECT_EQ(plan_resume(prog, nullptr, 5, ResumeSettings{10, 50}).start_line, 5);
  const MachineProfile m = load_machine_profile("fanuc");  // Z travel -600..600 mm
  // A safe height outside the machine's travel: the preamble's retract is refused.
  e = test::refusal_of([&] { plan_resume(prog, &m, 5, ResumeSettings{5000, std::nullopt}); });
  EXPECT_EQ(e.id(), "resume.setting");
  EXPECT_EQ(e.where(), "safe_z");
  EXPECT_NE(e.message().find("gcode.travel"), std::string::npos) << e.message();
  // A plunge feed above the machine's maximum.
  e = test::refusal_of([&] { plan_resume(prog, &m, 5, ResumeSettings{std::nullopt, 1e6}); });
  EXPECT_EQ(e.where(), "plunge_feed");
}

TEST(Resume, EveryLineOfTheSamplesResumesToTheSameTail) {
  // Every line with a block, in every program here: the plan holds, and the
  // tail is the full run's.
  const std::pair<const char*, const char*> files[] = {{"two-tools-fanuc.nc", "fanuc"},
                                                       {"keyhole-linuxcnc.nc", "linuxcnc"},
                                                       {"g5-chain-linuxcnc.nc", "linuxcnc"},
                                                       {"two-tools-arcs.nc", "generic"}};
  for (const auto& [file, machine] : files) {
    const MachineProfile m = load_machine_profile(machine);
    const std::string text = slurp(file);
    const auto ls = lines_of(text);
    for (int n = 1; n <= static_cast<int>(ls.size()); ++n) {
      ResumePlan p;
      try {
        p = plan_resume(text, &m, n);
      } catch (const InputError& e) {
        EXPECT_TRUE(e.id() == "resume.no-code" || e.id() == "resume.after-end") << file << ":" << n << ": " << e.what();
        continue;
      }
      SCOPED_TRACE(std::string(file) + " from line " + std::to_string(n));
      EXPECT_LE(p.start_line, n);
      check_resume(file, machine, n, p.start_line);
    }
  }
}

// A program in G91 with absolute arc centres (G90.1): the preamble moves in
// absolute coordinates, then hands over in the program's own modes, and the
// tail moves exactly as in the full run.
TEST(Resume, AnIncrementalProgramResumesInItsOwnDistanceModes) {
  const std::string prog =
      "G21 G90 G17\nT1 M06\nS9000 M03\nG00 X0. Y0. Z5.\nG91 G90.1\nG01 Z-6. F200.\nX10. F800.\n"
      "G02 X10. Y0. I15. J0.\nG01 Y10.\nG00 Z6.\nG90 G91.1\nM30\n";
  const ResumePlan p = check_resume_text(prog, "generic", 9, 9);
  EXPECT_EQ(p.state.distance, DistanceMode::incremental);
  EXPECT_EQ(p.state.arc_centers, ArcCenterMode::absolute);
  EXPECT_NE(p.preamble.find("G17 G90 G94 G40 G21 G54 G90.1\n"), std::string::npos) << p.preamble;
  EXPECT_EQ(p.preamble.substr(p.preamble.size() - 4), "G91\n") << p.preamble;
  // At the arc: its centre, a point, is restored with it.
  check_resume_text(prog, "generic", 8, 8);
}

TEST(Resume, ThePreambleRestoresEveryModalGroupTheReaderTracks) {
  // Work offset G55, exact stop G61.1, spindle counter-clockwise, both
  // coolants, tool 3 in the spindle and tool 4 selected, no tool length
  // offset, a rapid left modal.
  const std::string prog =
      "G20 G90 G17\nG55 G61.1\nT3 M06\nT4\nS8000 M04\nM07\nM08\nG00 Z0.5\nX1. Y1.\nG01 Z-0.05 F12.\n"
      "X2. F30.\nG00 Z0.5\nX3.\nY2.\nM05\nM09\nM30\n";
  const ResumePlan p = check_resume_text(prog, "generic", 14, 14);
  EXPECT_EQ(p.state.coord_system, WorkOffset::g55);
  EXPECT_EQ(p.state.path_mode, PathMode::exact_path);
  EXPECT_TRUE(p.state.spindle_on);
  EXPECT_TRUE(p.state.spindle_ccw);
  EXPECT_TRUE(p.state.coolant_mist && p.state.coolant_flood);
  EXPECT_EQ(p.state.motion, ModalMotion::rapid);
  EXPECT_EQ(p.preamble.substr(p.preamble.find('\n') + 1),
            "G17 G90 G94 G40 G20 G55 G61.1\nT3 M06\nT4\nS8000 M04\nM07\nM08\nG00 Z0.5\nG00 X3 Y1\nF30\n");
  // Below the safe height (0.19685 in): retract, over, plunge at 300 mm/min
  // in inches, the feed back, G00 again.
  const ResumePlan q = check_resume_text(prog, "generic", 11, 11);
  EXPECT_EQ(q.preamble.substr(q.preamble.find("G00 Z")),
            "G00 Z" + std::string("0.1968503937007874") + "\nG00 X1 Y1\nG01 Z-0.05 F11.811023622047244\nF12\n");
  // Before any move: no motion in the preamble, nothing to retract.
  const ResumePlan r = check_resume_text(prog, "generic", 6, 6);
  EXPECT_EQ(r.preamble.find("G00"), std::string::npos) << r.preamble;
}
