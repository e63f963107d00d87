// The G-code reader: exact geometry read back (lines, arcs, Fanuc NURBS
// blocks, LinuxCNC G5 / G5.1 / G5.2), every refusal with its line, id and
// message, the state left unchanged by a refused line, and the seeds'
// corrupted butterfly listing.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <unistd.h>

#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/sim/trace.hpp"
#include "support/files.hpp"
#include "support/run_process.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

using bezcam::test::slurp;

InputError refusal(std::string_view program, const MachineProfile* m = nullptr) {
  try {
    read_gcode(program, m);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a refusal of:\n" << program;
  return InputError(ErrorId(""), Place{}, "");
}

const std::string kPre = "G21 G90 G17 F100\nG00 X0 Y0 Z0\n";  // two lines: errors below are on line 3

}  // namespace

TEST(GcodeReader, LinesAndModes) {
  const std::string prog =
      "%\n"
      "O1000 (BEZCAM)\n"
      "N10 G21 G90 G17 (units, absolute, plane)\n"
      "N20 T1 M06\n"
      "N30 S12000 M03 ; spindle\n"
      "N40 G00 Z5.\n"
      "N50 G00 X10. Y20.\n"
      "N60 G01 Z-1. F300.\n"
      "N70 X30. Y20. F1200.\n"
      "n80 y40.\n"
      "N90 M05\n"
      "N100 G00 Z5.\n"
      "N110 M30\n"
      "%\n";
  GcodeInterpreter in;
  std::vector<MotionBlock> blocks;
  int no = 0;
  std::istringstream ss(prog);
  for (std::string l; std::getline(ss, l);) {
    auto b = in.feed_line(l, ++no);
    blocks.insert(blocks.end(), b.begin(), b.end());
  }
  EXPECT_TRUE(in.finish().empty());
  ASSERT_EQ(blocks.size(), 6u);
  EXPECT_EQ(blocks[0].kind, BlockKind::rapid);
  EXPECT_EQ(blocks[0].line, 6);
  EXPECT_EQ(blocks[0].from_known, 0u);  // nothing was known before
  EXPECT_EQ(blocks[0].to.z, 5);
  EXPECT_EQ(blocks[1].to, (Vec3{10, 20, 5}));
  EXPECT_EQ(blocks[1].from_known, 4u);
  EXPECT_EQ(blocks[2].kind, BlockKind::linear);
  EXPECT_EQ(blocks[2].feed, 300);
  EXPECT_EQ(blocks[2].from, (Vec3{10, 20, 5}));
  EXPECT_EQ(blocks[2].to, (Vec3{10, 20, -1}));
  EXPECT_EQ(blocks[3].to, (Vec3{30, 20, -1}));
  EXPECT_EQ(blocks[3].feed, 1200);
  EXPECT_EQ(blocks[4].to, (Vec3{30, 40, -1}));  // lower-case words, modal G01
  EXPECT_EQ(blocks[4].line, 10);
  EXPECT_EQ(blocks[5].kind, BlockKind::rapid);
  EXPECT_EQ(evaluate_block(blocks[3], 0.25), (Vec3{15, 20, -1}));
  const MachineState& s = in.state();
  EXPECT_EQ(s.units, Units::mm);
  EXPECT_TRUE(s.units_set);
  EXPECT_EQ(s.tool, 1);
  EXPECT_EQ(s.spindle_rpm, 12000);
  EXPECT_FALSE(s.spindle_on);
  EXPECT_TRUE(s.program_end);
  EXPECT_EQ(s.known_axes, 7u);
  EXPECT_EQ(read_gcode(prog).size(), 6u);
}

TEST(GcodeReader, ArcsReadBackExactly) {
  const auto b = read_gcode(kPre +
                            "G01 X10 Y0\n"
                            "G03 X0 Y10 I-10 J0\n"      // quarter CCW around the origin
                            "G02 X10 Y0 I0 J-10\n"      // and back CW
                            "G03 X10 Y0 I-10 J0\n"      // full circle: end = start
                            "G02 X0 Y10 R10\n"          // minor CW arc: centre (10, 10)
                            "G02 X10 Y0 R-10\n"         // major CW arc back
                            "G03 X0 Y10 Z-2 I-10 J0\n"  // helix
  );
  ASSERT_EQ(b.size(), 8u);
  const MotionBlock& q = b[2];
  EXPECT_EQ(q.kind, BlockKind::arc_ccw);
  EXPECT_EQ(q.center, (Vec3{0, 0, 0}));
  EXPECT_EQ(q.from, (Vec3{10, 0, 0}));
  EXPECT_EQ(q.to, (Vec3{0, 10, 0}));
  EXPECT_EQ(q.feed, 100);
  const double c45 = 10 * std::cos(std::numbers::pi / 4);
  EXPECT_NEAR(dist(evaluate_block(q, 0.5), Vec3{c45, c45, 0}), 0, 1e-12);
  for (int i = 0; i <= 20; ++i) EXPECT_NEAR(norm(evaluate_block(q, i / 20.0)), 10, 1e-12);
  EXPECT_EQ(b[3].kind, BlockKind::arc_cw);
  EXPECT_NEAR(dist(evaluate_block(b[3], 0.5), Vec3{c45, c45, 0}), 0, 1e-12);
  // Full circle: half way is the opposite point.
  EXPECT_NEAR(dist(evaluate_block(b[4], 0.5), Vec3{-10, 0, 0}), 0, 1e-12);
  EXPECT_NEAR(dist(evaluate_block(b[4], 0.25), Vec3{0, 10, 0}), 0, 1e-12);
  // R10 from (10,0) to (0,10) clockwise, the short way: around (10, 10).
  EXPECT_NEAR(dist(b[5].center, Vec3{10, 10, 0}), 0, 1e-12);
  EXPECT_NEAR(dist(evaluate_block(b[5], 0.5), Vec3{10 - c45, 10 - c45, 0}), 0, 1e-12);
  // R-10 from (0,10) back to (10,0) clockwise, the long way (270 degrees):
  // around (10, 10) too, through (10, 20) and (20, 10).
  EXPECT_NEAR(dist(b[6].center, Vec3{10, 10, 0}), 0, 1e-12);
  EXPECT_NEAR(dist(evaluate_block(b[6], 1.0 / 3), Vec3{10, 20, 0}), 0, 1e-12);
  EXPECT_NEAR(dist(evaluate_block(b[6], 2.0 / 3), Vec3{20, 10, 0}), 0, 1e-12);
  // Helix: Z runs with the angle.
  EXPECT_NEAR(dist(evaluate_block(b[7], 0.5), Vec3{c45, c45, -1}), 0, 1e-12);
  // Exact pieces: a quarter is one rational quadratic on the circle.
  const auto pieces = block_to_bezier(q);
  ASSERT_EQ(pieces.size(), 1u);
  for (int i = 0; i <= 50; ++i) EXPECT_NEAR(norm(evaluate(pieces[0], i / 50.0)), 10, 1e-12);
  EXPECT_EQ(block_to_bezier(b[4]).size(), 4u);
  EXPECT_THROW(block_to_bezier(b[7]), std::invalid_argument);
}

TEST(GcodeReader, ArcToleranceFollowsTheProfile) {
  // The centre is 10 from the start and 10.003 from the end.
  const std::string prog = kPre + "G01 X10 Y0\nG03 X0 Y10.003 I-10 J0\n";
  const auto e = refusal(prog);
  EXPECT_EQ(e.id(), "gcode.arc-radius");
  EXPECT_EQ(e.where(), "line 4");
  EXPECT_EQ(e.message(),
            "G03: the centre (0, 0) is 10 from the start and 10.003 from the end; they differ by 0.003 mm, "
            "more than the arc tolerance (0.002 mm): the end point or the centre is wrong");
  // UNISURF allows 0.01 mm.
  const MachineProfile unisurf = load_machine_profile("unisurf");
  EXPECT_EQ(read_gcode(prog, &unisurf).size(), 3u);
  // In inches the tolerance is converted: 0.002 mm = 0.0000787 inch.
  const auto inch = refusal("G20 G90 G17 F10\nG00 X0 Y0 Z0\nG01 X1 Y0\nG03 X0 Y1.0001 I-1 J0\n");
  EXPECT_EQ(inch.id(), "gcode.arc-radius");
  EXPECT_NE(inch.message().find("(7.874015748e-05 inch)"), std::string::npos) << inch.message();
}

TEST(GcodeReader, FanucNurbsBlockReadsBackAsWritten) {
  // The block of docs/gcode-dialects.md: a cubic Bézier in NURBS form.
  const auto b = read_gcode(
      "G21 G90 G17\n"
      "G00 X0 Y0 Z0\n"
      "G06.2 P4 K0. X0. Y0. Z0. R1. F1000.\n"
      "K0. X10. Y10. Z0. R1.\n"
      "K0. X20. Y10. R1.\n"  // Z left out: keeps 0
      "K0. X30. Y0. Z0. R1.\n"
      "K1.\n"
      "K1.\n"
      "\n"  // a blank line inside the block is harmless
      "K1.\n"
      "K1.\n"
      "G01 X40.\n");
  ASSERT_EQ(b.size(), 3u);
  const MotionBlock& n = b[1];
  EXPECT_EQ(n.kind, BlockKind::nurbs);
  EXPECT_EQ(n.first_line, 3);
  EXPECT_EQ(n.line, 11);
  EXPECT_EQ(n.order, 4);
  EXPECT_EQ(n.feed, 1000);
  EXPECT_EQ(n.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(n.weights, (std::vector<double>{1, 1, 1, 1}));
  ASSERT_EQ(n.ctrl.size(), 4u);
  EXPECT_EQ(n.ctrl[2], (Vec3{20, 10, 0}));
  EXPECT_EQ(n.from, (Vec3{0, 0, 0}));
  EXPECT_EQ(n.to, (Vec3{30, 0, 0}));
  // With clamped knots 0^4 1^4 the block is the cubic Bézier of its points.
  const Bezier z = Bezier::make({{0, 0}, {10, 10}, {20, 10}, {30, 0}});
  for (int i = 0; i <= 10; ++i) EXPECT_NEAR(dist(evaluate_block(n, i / 10.0), evaluate(z, i / 10.0)), 0, 1e-12);
  EXPECT_EQ(b[2].from, (Vec3{30, 0, 0}));
  EXPECT_EQ(b[2].to, (Vec3{40, 0, 0}));
}

TEST(GcodeReader, FanucRationalQuarterCircleIsExact) {
  const std::string w = "R0.70710678118654757";  // sqrt(2)/2 to the last bit
  const auto b = read_gcode("G21 G90 G17 F500\nG00 X25 Y0 Z-1\nG06.3 P3 K0. X25. Y0. Z-1. R1.\nK0. X25. Y25. " + w +
                            "\nK0. X0. Y25. R1.\nK1.\nK1.\nK1.\n");
  ASSERT_EQ(b.size(), 2u);
  for (int i = 0; i <= 100; ++i) {
    const Vec3 p = evaluate_block(b[1], i / 100.0);
    EXPECT_NEAR(std::hypot(p.x, p.y), 25, 1e-12);
    EXPECT_EQ(p.z, -1);
  }
  const auto pieces = block_to_bezier(b[1]);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_TRUE(pieces[0].rational());
}

// LinuxCNC meanings relied on (its interpreter's source, src/emc/rs274ngc:
// interp_convert.cc convert_spline() and convert_nurbs(),
// nurbs_additional_functions.cc knot_vector_creator()):
//  - G5: P1 = start + (I, J), P2 = end + (P, Q); without I and J a G5 goes on
//    with minus the previous G5's P and Q (its cycle_i/cycle_j);
//  - G5.1: P1 = start + (I, J), both required;
//  - G5.2: the current position is the first control point; on a G5.2 line
//    with X and Y it gets weight 1 and X Y P is the second point; the order
//    is 3 unless an L above 3 is given; G5.3 needs at least `order` points;
//  - the knot vector: for n + 1 points and order k, k zeros, then
//    1 .. n - k + 1, then k times n - k + 2 (clamped, uniform, integers).
TEST(GcodeReader, LinuxCncBezierAndNurbsWords) {
  const auto b = read_gcode(
      "G21 G90 G17 F500\n"
      "G0 X0 Y0 Z1\n"
      "G5 I10 J0 P-10 Q0 X30 Y10\n"
      "G5 P0 Q-5 X40 Y0\n"  // I, J continue the previous G5: (10, 0)
      "G5.1 X50 Y0 I5 J5\n"
      "G5.2 X60 Y10 P1 L4\n"
      "X70 Y10 P2\n"
      "X80 Y0 P1\n"
      "G5.3\n"
      "G5.2 P1\n"  // order 3, first point weight P1
      "X90 Y10 P1\n"
      "X100 Y10 P0.5\n"
      "X110 Y0 P1\n"
      "X120 Y0 P1\n"
      "G5.3\n");
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[1].kind, BlockKind::bezier);
  EXPECT_EQ(b[1].order, 4);
  EXPECT_EQ(b[1].ctrl, (std::vector<Vec3>{{0, 0, 1}, {10, 0, 1}, {20, 10, 1}, {30, 10, 1}}));
  EXPECT_EQ(b[2].ctrl, (std::vector<Vec3>{{30, 10, 1}, {40, 10, 1}, {40, -5, 1}, {40, 0, 1}}));
  EXPECT_EQ(b[3].ctrl, (std::vector<Vec3>{{40, 0, 1}, {45, 5, 1}, {50, 0, 1}}));
  EXPECT_EQ(b[3].order, 3);
  EXPECT_EQ(evaluate_block(b[3], 0.5), (Vec3{45, 2.5, 1}));
  const MotionBlock& n = b[4];
  EXPECT_EQ(n.kind, BlockKind::nurbs);
  EXPECT_EQ(n.first_line, 6);
  EXPECT_EQ(n.line, 9);
  EXPECT_EQ(n.order, 4);
  EXPECT_EQ(n.ctrl, (std::vector<Vec3>{{50, 0, 1}, {60, 10, 1}, {70, 10, 1}, {80, 0, 1}}));
  EXPECT_EQ(n.weights, (std::vector<double>{1, 1, 2, 1}));
  EXPECT_EQ(n.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  const MotionBlock& m = b[5];
  EXPECT_EQ(m.order, 3);
  EXPECT_EQ(m.ctrl.size(), 5u);
  EXPECT_EQ(m.knots, (std::vector<double>{0, 0, 0, 1, 2, 3, 3, 3}));
  EXPECT_EQ(evaluate_block(m, 1), (Vec3{120, 0, 1}));
  EXPECT_EQ(linuxcnc_knots(6, 4), (std::vector<double>{0, 0, 0, 0, 1, 2, 3, 3, 3, 3}));
}

// RS274/NGC takes the blanks out of a line before reading it (comments
// aside): dxf2gcode writes "G0 Z   5.0000", and "G 0 1", "X - 1 . 5" are
// legal too. LinuxCNC and Fanuc read these; so must bezcam.
TEST(GcodeReader, BlanksMayStandInsideAWord) {
  const auto b = read_gcode(
      "G21 G90 G17\n"
      "G0 Z   5.0000\n"
      "G0 X  -3.000 Y  50.000\n"
      "g 0 1 z - 1 . 5 f 1 5 0\n"
      "N 1 0 G1 X 1 2 . 5 Y 5 0 .\n"
      "G 2 X 1 2 . 5 Y 4 0 I 0 J - 5 (a half circle)\n"
      "M 3 0\n");
  ASSERT_EQ(b.size(), 5u);
  EXPECT_EQ(b[0].kind, BlockKind::rapid);
  EXPECT_EQ(b[0].to.z, 5);
  EXPECT_EQ(b[1].to, (Vec3{-3, 50, 5}));
  EXPECT_EQ(b[2].kind, BlockKind::linear);
  EXPECT_EQ(b[2].to, (Vec3{-3, 50, -1.5}));
  EXPECT_EQ(b[2].feed, 150);
  EXPECT_EQ(b[3].to, (Vec3{12.5, 50, -1.5}));
  EXPECT_EQ(b[4].kind, BlockKind::arc_cw);
  EXPECT_EQ(b[4].center, (Vec3{12.5, 45, -1.5}));
  // Messages name the word without its blanks; a blank before anything
  // but a digit (or the number's one point) ends the number.
  auto e = refusal(kPre + "G0 X 1 X 2\n");
  EXPECT_EQ(e.message(), "X appears twice on the line (X1 and X2); a block gives each address once");
  e = refusal(kPre + "G0 X1 -2\n");
  EXPECT_EQ(e.message(), "unexpected character '-': expected a word (a letter and a number)");
  e = refusal(kPre + "G0 X 1.5 .5\n");
  EXPECT_EQ(e.message(), "unexpected character '.': expected a word (a letter and a number)");
  e = refusal(kPre + "G0 X - Y1\n");
  EXPECT_EQ(e.message(), "expected a number after 'X', found '-'");
}

// G91: X Y Z are the travel from where the tool is, for lines, arcs and
// LinuxCNC's curves; the trace says so. I J stay offsets from the start.
TEST(GcodeReader, G91MovesTravelFromWhereTheToolIs) {
  GcodeInterpreter in;
  std::vector<MotionBlock> b;
  std::string trace;  // the simulated controller's records of the state
  const std::string prog =
      "G21 G90 G17 F100\n"
      "G0 X1 Y2 Z3\n"
      "G91\n"
      "G1 X1 Y1\n"
      "Z-4\n"
      "G2 X2 Y0 I1 J0\n"
      "G18 G3 X2 Z0 I1 K0\n"
      "G17 G5 X4 Y0 I1 J1 P-1 Q1\n"
      "G5.2 P1 L3\n"
      "X1 Y1 P1\n"
      "X2 Y0 P1\n"
      "G5.3\n"
      "G90 G1 X0\n";
  std::istringstream ss(prog);
  int no = 0;
  for (std::string l; std::getline(ss, l);) {
    const MachineState before = in.state();
    for (auto& x : in.feed_line(l, ++no)) b.push_back(x);
    trace += sim::trace_state(no, before, in.state());
  }
  EXPECT_EQ(trace, "line 1 units mm\nline 3 distance incremental\nline 13 distance absolute\n");
  ASSERT_EQ(b.size(), 8u);
  EXPECT_EQ(b[1].to, (Vec3{2, 3, 3}));
  EXPECT_EQ(b[2].to, (Vec3{2, 3, -1}));
  EXPECT_EQ(b[3].kind, BlockKind::arc_cw);
  EXPECT_EQ(b[3].to, (Vec3{4, 3, -1}));
  EXPECT_EQ(b[3].center, (Vec3{3, 3, -1}));
  EXPECT_EQ(b[4].plane, Plane::zx);
  EXPECT_EQ(b[4].to, (Vec3{6, 3, -1}));
  EXPECT_EQ(b[4].center, (Vec3{5, 3, -1}));
  EXPECT_EQ(b[5].ctrl, (std::vector<Vec3>{{6, 3, -1}, {7, 4, -1}, {9, 4, -1}, {10, 3, -1}}));
  // G5.2: every point from where the block began, as LinuxCNC's
  // interpreter reads it (its end is (12, 3), not (13, 4)).
  EXPECT_EQ(b[6].ctrl, (std::vector<Vec3>{{10, 3, -1}, {11, 4, -1}, {12, 3, -1}}));
  EXPECT_EQ(b[7].to, (Vec3{0, 3, -1}));
  EXPECT_EQ(in.state().distance, DistanceMode::absolute);
}

// Each modal group's value is a named enum whose value is its G number.
TEST(GcodeReader, ModalGroupsReadAsNamedValues) {
  GcodeInterpreter in;
  const MachineState& s = in.state();
  EXPECT_EQ(s.plane, Plane::xy);
  EXPECT_EQ(s.distance, DistanceMode::absolute);
  EXPECT_EQ(s.arc_centers, ArcCenterMode::incremental);
  EXPECT_EQ(s.coord_system, WorkOffset::g54);
  EXPECT_EQ(s.path_mode, PathMode::unset);
  EXPECT_EQ(s.cutter_comp, CutterCompMode::off);
  in.feed_line("G18 G91 G90.1 G59 G61.1", 1);
  EXPECT_EQ(s.plane, Plane::zx);
  EXPECT_EQ(s.distance, DistanceMode::incremental);
  EXPECT_EQ(s.arc_centers, ArcCenterMode::absolute);
  EXPECT_EQ(s.coord_system, WorkOffset::g59);
  EXPECT_EQ(s.path_mode, PathMode::exact_path);
  in.feed_line("G17 G90 G64 P0.01", 2);
  EXPECT_EQ(s.plane, Plane::xy);
  EXPECT_EQ(s.path_mode, PathMode::blend);
  EXPECT_EQ(s.path_tolerance, 0.01);
  in.set_tool_diameters_mm({{3, 6.0}});
  in.feed_line("G00 X0 Y0 Z5", 3);
  in.feed_line("G42 D3", 4);
  EXPECT_EQ(s.cutter_comp, CutterCompMode::right);
  EXPECT_EQ(static_cast<int>(s.cutter_comp), 42);
  EXPECT_EQ(s.cutter_comp_radius, 3.0);
}

TEST(GcodeReader, G91FromAPositionNoMoveHasSetIsRefusedUnlessItStaysPut) {
  auto e = refusal("G21 G91 G17\nG0 X5\n");
  EXPECT_EQ(e.where(), "line 2");
  EXPECT_EQ(e.id(), "gcode.incremental");
  EXPECT_EQ(e.message(),
            "X5 in G91 (incremental distances) travels from the current X, which no earlier move has set: set it with "
            "an absolute (G90) move first");
  // Travels that add up beyond a double.
  const std::string huge = "17" + std::string(307, '0');
  e = refusal("G21 G90 G17\nG0 X" + huge + "\nG91 G0 X" + huge + "\n");
  EXPECT_EQ(e.where(), "line 3");
  EXPECT_EQ(e.id(), "gcode.number");
  // No travel: nothing moves, and the axis stays unknown.
  GcodeInterpreter in;
  in.feed_line("G21 G90 G17", 1);
  in.feed_line("G0 Z5", 2);
  EXPECT_TRUE(in.feed_line("G91 G0 X0 Y0", 3).empty());
  const auto b = in.feed_line("G0 X0 Y0 Z-2", 4);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].to.z, 3);
  EXPECT_EQ(in.state().known_axes, 4u);
}

// The end of many Fanuc programs: Z home straight from where it is (the
// intermediate point is where the tool stands), then X and Y.
TEST(GcodeReader, G91G28Z0SendsZHomeStraightFromWhereItIs) {
  const auto b = read_gcode(
      "G21 G90 G17\n"
      "G0 X10 Y20 Z5\n"
      "G91 G28 Z0.\n"
      "G28 X0. Y0.\n"
      "G90\n"
      "G0 X1 Y1 Z1\n"
      "G91 G30 X1\n"
      "G90 G28 Z4\n");
  ASSERT_EQ(b.size(), 8u);
  EXPECT_EQ(b[1].kind, BlockKind::rapid);
  EXPECT_EQ(b[1].from, (Vec3{10, 20, 5}));
  EXPECT_EQ(b[1].to, (Vec3{10, 20, 0}));
  EXPECT_EQ(b[2].to, (Vec3{0, 0, 0}));
  EXPECT_EQ(b[3].to, (Vec3{1, 1, 1}));
  EXPECT_EQ(b[4].to, (Vec3{2, 1, 1}));  // G30 through X + 1 ...
  EXPECT_EQ(b[5].to, (Vec3{0, 1, 1}));  // ... to its reference point, for X only
  EXPECT_EQ(b[6].to, (Vec3{0, 1, 4}));  // G90: through Z4 ...
  EXPECT_EQ(b[7].to, (Vec3{0, 1, 0}));  // ... to Z home
  // At the start of a program, with Z unknown: one move, and Z known.
  GcodeInterpreter in;
  in.feed_line("G21 G90 G17", 1);
  const auto h = in.feed_line("G28 G91 Z0", 2);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].from_known, 0u);
  EXPECT_EQ(h[0].to.z, 0);
  EXPECT_EQ(in.state().known_axes, 4u);
  EXPECT_EQ(in.state().distance, DistanceMode::incremental);
}

// G90.1: an arc's centre words are a point; G91.1 (the default): the
// centre's offset from the start. R arcs and G5's I J are not affected.
TEST(GcodeReader, G90_1TakesArcCentresAsPointsAndG91_1AsOffsets) {
  const auto b = read_gcode(
      "G21 G90 G17 F100\n"
      "G0 X10 Y0 Z0\n"
      "G90.1\n"
      "G3 X0 Y10 I0 J0\n"
      "G18 G2 X-10 Z0 I-5 K0\n"
      "G17 G91 G2 X2 Y0 I-9 J10\n"
      "G91.1 G2 X2 Y0 I1 J0\n"
      "G90.1 G90 G2 X-4 Y10 R1\n");
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[1].center, (Vec3{0, 0, 0}));
  EXPECT_EQ(b[2].center, (Vec3{-5, 10, 0}));
  EXPECT_EQ(b[2].to, (Vec3{-10, 10, 0}));
  EXPECT_EQ(b[3].to, (Vec3{-8, 10, 0}));
  EXPECT_EQ(b[3].center, (Vec3{-9, 10, 0}));
  EXPECT_EQ(b[4].to, (Vec3{-6, 10, 0}));
  EXPECT_EQ(b[4].center, (Vec3{-7, 10, 0}));
  EXPECT_EQ(b[5].to, (Vec3{-4, 10, 0}));
  EXPECT_EQ(b[5].center, (Vec3{-5, 10, 0}));
  const auto e = refusal(kPre + "G90.1 G2 X2 Y0 I1\n");
  EXPECT_EQ(e.id(), "gcode.arc");
}

// Fanuc reads a NURBS block's points in G91 as the travel from the point
// before (the first, from where the tool is, must be 0).
TEST(GcodeReader, FanucNurbsBlockInG91TravelsFromPointToPoint) {
  const auto b = read_gcode(
      "G21 G90 G17 F500\n"
      "G0 X10 Y0 Z-1\n"
      "G91\n"
      "G06.2 P3 K0 X0 Y0 Z0 R1\n"
      "K0 X5 Y5 R0.5\n"
      "K0 X5 Y-5 R1\n"
      "K1\nK1\nK1\n"
      "G01 X1\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[1].ctrl, (std::vector<Vec3>{{10, 0, -1}, {15, 5, -1}, {20, 0, -1}}));
  EXPECT_EQ(b[2].to, (Vec3{21, 0, -1}));
  const auto e = refusal(kPre + "G91 G06.2 P3 K0 X1 Y0 Z0\nK0 X1\nK0 X1\nK1\nK1\nK1\n");
  EXPECT_EQ(e.id(), "gcode.nurbs-start");
  EXPECT_EQ(e.message(),
            "X1: the first control point of a NURBS block must be the current position (in G91 (incremental "
            "distances): X0)");
}

// Each refusal: the line, the stable id and the sentence.
struct Bad {
  std::string program;  // after kPre
  std::string where, id, message;
};

class GcodeRefusal : public ::testing::TestWithParam<Bad> {};

TEST_P(GcodeRefusal, NamesLineIdAndMessage) {
  const Bad& c = GetParam();
  const auto e = refusal(kPre + c.program);
  EXPECT_EQ(e.where(), c.where) << c.program;
  EXPECT_EQ(e.id(), c.id) << c.program;
  EXPECT_EQ(e.message(), c.message) << c.program;
}

// Fanuc block prefix: a rank-4 block opened at line 3.
#define NB "G06.2 P4 K0 X0 Y0 Z0\n"

INSTANTIATE_TEST_SUITE_P(
    Syntax, GcodeRefusal,
    ::testing::Values(
        Bad{"G01 X1 Y\n", "line 3", "gcode.syntax", "expected a number after 'Y', found nothing"},
        Bad{"G01 X1 Yabc\n", "line 3", "gcode.syntax", "expected a number after 'Y', found 'abc'"},
        Bad{"G01 X1 (comment\n", "line 3", "gcode.syntax",
            "a comment opened with '(' is not closed on this line: add ')'"},
        Bad{"G01 X1 # 2\n", "line 3", "gcode.syntax",
            "unexpected character '#': expected a word (a letter and a number)"},
        Bad{"G01 X1 X2\n", "line 3", "gcode.repeated-word",
            "X appears twice on the line (X1 and X2); a block gives each address once"},
        Bad{"G01 N5 X1\n", "line 3", "gcode.syntax", "the line number N5 must be the first word of the line"},
        Bad{"X1\nG80\nX2\n", "line 5", "gcode.no-motion",
            "X2: axis words without a motion mode (none is active): give G00 or G01"},
        Bad{"G01 X1 P3\n", "line 3", "gcode.unexpected-word", "word P3 has no meaning on this line (G01): remove it"},
        Bad{"G01 X1 A5\n", "line 3", "gcode.unsupported",
            "axis A (A5) is not supported by this reader: X, Y and Z only"},
        Bad{"/G01 X1\n", "line 3", "gcode.unsupported",
            "block delete ('/' at the start of a line) is not supported: remove it or the line"}));

INSTANTIATE_TEST_SUITE_P(
    Modes, GcodeRefusal,
    ::testing::Values(
        Bad{"G18\nG5 X1 Y1 I1 J0 P0 Q1\n", "line 4", "gcode.plane",
            "G5 moves in the XY plane: select it with G17 first (G18 is in force)"},
        Bad{"G91 G53 G00 Z0\n", "line 3", "gcode.incremental",
            "G53 (machine coordinates) takes absolute coordinates: it cannot be used in G91 (incremental distances); "
            "give G90 first"},
        Bad{"G90.1 G02 X2 Y0 I1\n", "line 3", "gcode.arc",
            "G02 in G90.1 (absolute arc centres) needs both I and J: the centre's coordinates"},
        Bad{"G00 G01 X1\n", "line 3", "gcode.modal-group", "G00 and G01 are in the same modal group: give one"},
        Bad{"G38.2 Z-5\n", "line 3", "gcode.unsupported", "G-code G38.2 is not supported by this reader"},
        Bad{"M98\n", "line 3", "gcode.unsupported", "M-code M98 is not supported by this reader"},
        Bad{"M03 M05\n", "line 3", "gcode.modal-group", "M03 and M05 are in the same modal group: give one"},
        Bad{"G41 D3 G01 X1\n", "line 3", "gcode.cutter-comp",
            "G41 D3: the diameter register D3 is not set: give its diameter in the machine profile's "
            "tool_diameters_mm, or on the command line"},
        Bad{"G01 X1\nG20\n", "line 4", "gcode.units-change",
            "G20 changes the units after the first move: positions would change meaning; set the units once, before "
            "any move"},
        Bad{"M30\nG01 X1\n", "line 4", "gcode.after-end",
            "the program ended at line 3 (M02/M30): nothing after it runs; remove this line or move the end"},
        Bad{"G04\n", "line 3", "gcode.dwell", "G04 needs its duration P (seconds) >= 0"},
        Bad{"G01 X1 F-5\n", "line 3", "gcode.feed", "expected a feed rate F >= 0, found F-5"}));

INSTANTIATE_TEST_SUITE_P(
    Arcs, GcodeRefusal,
    ::testing::Values(
        Bad{"G02 X1 Y1\n", "line 3", "gcode.arc", "G02 needs the centre offsets I and J (or a radius R)"},
        Bad{"G02 X10 Y0 I5 J0 K0\n", "line 3", "gcode.arc",
            "K0: K is not a centre word in the G17 plane (some controllers refuse even K0): give I and J only"},
        Bad{"G03 X10 Y0 I5 R5\n", "line 3", "gcode.arc",
            "G03: give either I and J (the centre) or R (the radius), not both"},
        Bad{"G02 X10 Y0 R2\n", "line 3", "gcode.arc",
            "R2 is too small for the chord of 10 mm between start and end (the radius must be at least half of it)"},
        Bad{"G02 X10 Y0 I0 J0\n", "line 3", "gcode.arc",
            "G02: the centre coincides with the start point (I and J are both 0)"},
        Bad{"G18\nG02 X10 Z0 I5 J0\n", "line 4", "gcode.arc",
            "J0: J is not a centre word in the G18 plane (some controllers refuse even J0): give I and K only"},
        Bad{"G19\nG03 Y1 Z1\n", "line 4", "gcode.arc", "G03 (G19) needs the centre offsets J and K (or a radius R)"},
        Bad{"G19 G03 Y0 Z0 J0 K0\n", "line 3", "gcode.arc",
            "G03 (G19): the centre coincides with the start point (J and K are both 0)"}));

INSTANTIATE_TEST_SUITE_P(
    FanucBlocks, GcodeRefusal,
    ::testing::Values(
        Bad{NB "K0 X1\nK0 X2\nK0 X3\nK0.5 X4\nK0.25 X5\nK1\nK1\nK1\nK1\n", "line 8", "gcode.knot-order",
            "K0.25: expected a knot >= 0.5 (knots must not decrease; the previous knot is on line 7), found 0.25"},
        Bad{NB "K0 X1\nK0.1 X2\n", "line 5", "gcode.knot-clamped",
            "K0.1 is knot 3 of the block: the first P (4) knots must be equal (a clamped start: the curve starts at "
            "the current position), but the first is 0 (line 3)"},
        Bad{NB "K0 X1\nK0 X2\nK0 X3\nK1\nK1\nK2\n", "line 9", "gcode.knot-clamped",
            "K2: the last P (4) knots, the knot-only blocks, must be equal (a clamped end: the curve ends at its last "
            "control point), but the first of them is 1 (line 7)"},
        Bad{NB "K0 X1\nK0 X2\nK0 X3\nK0 X4\n", "line 7", "gcode.knot-multiplicity",
            "K0: knot 0 now appears 5 times (from line 3); no knot may repeat more than the rank P (4) times"},
        Bad{NB "K0 X1\nK0 X2\nK0 X3\nK1\nK0 X4\n", "line 8", "gcode.knot-count",
            "a control point after the knot-only blocks that began at line 7: a NURBS block lists every control "
            "point first, then exactly P (4) knot-only K blocks"},
        Bad{NB "K0 X1 R0\n", "line 4", "gcode.weight", "weight R0: expected a weight R > 0"},
        Bad{NB "K0 X1 P3\n", "line 4", "gcode.nurbs-word",
            "P (the rank) is only given on the first block of a NURBS block, found P3"},
        Bad{NB "K0 X1\nG01 X5\n", "line 5", "gcode.nurbs-open",
            "the NURBS block opened at line 3 is incomplete: it has 2 control points and 0 of its 4 knot-only "
            "blocks; until the last knot every line must be 'K- [X- Y- Z- R-]'"},
        Bad{"G06.2 P5 K0 X0 Y0 Z0\n", "line 3", "gcode.rank", "rank P5: expected P from 2 to 4 (order = degree + 1)"},
        Bad{"G06.2 P4 K0 X1 Y0 Z0\n", "line 3", "gcode.nurbs-start",
            "X1: the first control point of a NURBS block must be the current position (X = 0)"},
        Bad{"G06.2 P4 X0 Y0 Z0\n", "line 3", "gcode.knot-missing",
            "the first block of a NURBS block needs its knot K (K- X- Y- Z- R-)"},
        Bad{"K0 X1\n", "line 3", "gcode.nurbs-start",
            "K word outside a NURBS block: a block starts with G06.2 P- K- X- Y- Z-"},
        Bad{"G06.2 P2 K0 X0 Y0 Z0\nK0 X1\nK1\nK1\nX5\n", "line 7", "gcode.nurbs-mode",
            "X5 in NURBS mode (G6.2 since line 3) outside a block: start a new block with G6.2, or leave the mode "
            "with G00 or G01"},
        Bad{NB "K0 X1\n", "line 4", "gcode.nurbs-open",
            "the program ends inside the NURBS block opened at line 3: it has 2 control points and 0 of its 4 "
            "knot-only K blocks"}));

INSTANTIATE_TEST_SUITE_P(
    LinuxCncWords, GcodeRefusal,
    ::testing::Values(
        Bad{"G5 I1 J0 P-1 Q0 X5 Y0 Z1\n", "line 3", "gcode.bezier",
            "G5 moves in X and Y only: a Z word (Z1) is not allowed"},
        Bad{"G5 I1 J0 X5 Y0\n", "line 3", "gcode.bezier",
            "G5 needs both P and Q (the second control point's offset from the end point)"},
        Bad{"G5 P-1 Q0 X5 Y0\n", "line 3", "gcode.bezier",
            "G5 without I and J continues the tangent of a G5 just before it, and there is none: give I and J"},
        Bad{"G5.1 X5 Y0 I1\n", "line 3", "gcode.bezier",
            "G5.1 needs both I and J (the middle control point's offset from the start)"},
        Bad{"G5.2 P1 L2\n", "line 3", "gcode.rank",
            "G5.2 order L2: LinuxCNC ignores an order below 3 (it then uses 3); give L3 or more"},
        Bad{"G5.2 L3\n", "line 3", "gcode.weight",
            "the G5.2 line needs P, the weight of its first control point (the current position): without it the "
            "weight differs between LinuxCNC versions"},
        Bad{"G5.2 P1\nX1 Y1\n", "line 4", "gcode.weight",
            "a G5.2 control point needs its weight P (LinuxCNC refuses a point without it)"},
        Bad{"G5.2 P1\nX1 P1\n", "line 4", "gcode.nurbs-point",
            "a G5.2 control point needs both X and Y, found only X1"},
        Bad{"G5.2 P1\nX1 Y1 P1\nG5.3\n", "line 5", "gcode.knot-count",
            "the G5.2 block opened at line 3 has 2 control points; order L3 needs at least 3"},
        Bad{"G5.2 P1\nX1 Y1 P1\nG01 X5\n", "line 5", "gcode.nurbs-open",
            "the G5.2 block opened at line 3 is still open: only control points 'X- Y- P-' may follow until G5.3"},
        Bad{"G5.3\n", "line 3", "gcode.nurbs-start", "G5.3 ends a G5.2 block, and none is open"}));

TEST(GcodeReader, FeedIsRequiredForCuttingMoves) {
  const auto e = refusal("G21 G90 G17\nG00 X0 Y0 Z0\nG01 X1\n");
  EXPECT_EQ(e.where(), "line 3");
  EXPECT_EQ(e.id(), "gcode.no-feed");
  EXPECT_EQ(e.message(), "G01 needs a feed rate, and no F word has set one (F is in mm/min)");
  // Rapids need none.
  EXPECT_EQ(read_gcode("G21 G90 G17\nG00 X0 Y0 Z0\nG00 X5\n").size(), 2u);
}

TEST(GcodeReader, ArcFromUnknownPositionIsRefused) {
  const auto e = refusal("G21 G90 G17 F100\nG03 X0 Y10 I-10 J0\n");
  EXPECT_EQ(e.id(), "gcode.position-unknown");
  EXPECT_EQ(e.message(), "G03 cannot start from an unknown position: no earlier move has set X and Y");
}

TEST(GcodeReader, ProfileLimitsAndDialect) {
  const MachineProfile grbl = load_machine_profile("grbl");
  auto e = refusal("G21 G90 G17 F100\nG0 X0 Y0 Z0\nG1 X500\n", &grbl);
  EXPECT_EQ(e.where(), "line 3");
  EXPECT_EQ(e.id(), "gcode.travel");
  EXPECT_EQ(e.message(), "the move reaches X = 500 mm, outside the travel of machine \"grbl\" (X from -400 to 400 mm)");
  e = refusal("G21 G90 G17\nG0 X0 Y0 Z0\nG1 X1 F6000\n", &grbl);
  EXPECT_EQ(e.id(), "gcode.feed-limit");
  EXPECT_EQ(e.message(), "feed F6000 (mm/min) exceeds the maximum feed of machine \"grbl\", 5000 mm/min");
  // An arc is checked by its full extent, not its ends: this one bulges to Y = 410.
  e = refusal("G21 G90 G17 F100\nG0 X-10 Y400 Z0\nG2 X10 Y400 I10 J0\n", &grbl);
  EXPECT_EQ(e.id(), "gcode.travel");
  EXPECT_EQ(e.message(), "the move reaches Y = 410 mm, outside the travel of machine \"grbl\" (Y from -400 to 400 mm)");
  // Inch programs: limits converted (grbl: 400 mm = 15.748 inch).
  e = refusal("G20 G90 G17 F10\nG0 X0 Y0 Z0\nG1 X16\n", &grbl);
  EXPECT_EQ(e.message(),
            "the move reaches X = 16 inch, outside the travel of machine \"grbl\" (X from -15.7480315 to "
            "15.7480315 inch)");
  e = refusal(kPre + "G06.2 P4 K0 X0 Y0 Z0\n", &grbl);
  EXPECT_EQ(e.id(), "gcode.dialect");
  EXPECT_EQ(e.message(), "machine \"grbl\" does not take Fanuc-style NURBS blocks (G06.2)");
  const MachineProfile fanuc = load_machine_profile("fanuc");
  e = refusal(kPre + "G06.3 P4 K0 X0 Y0 Z0\n", &fanuc);
  EXPECT_EQ(e.message(), "machine \"fanuc\" starts a NURBS block with G06.2, not G06.3");
  e = refusal(kPre + "G5.1 X1 Y1 I1 J0\n", &fanuc);
  EXPECT_EQ(e.message(), "G5.1 is a LinuxCNC word; machine \"fanuc\" does not take it");
  // A NURBS block is checked by its curve: control points may lie outside.
  const MachineProfile g063 = load_machine_profile("fanuc-g063");
  EXPECT_EQ(read_gcode("G21 G90 G17 F100\nG0 X0 Y1490 Z0\nG06.3 P3 K0 X0 Y1490 Z0\nK0 X10 Y1508\nK0 X20 "
                       "Y1490\nK1\nK1\nK1\n",
                       &g063)
                .size(),
            2u);
  e = refusal("G21 G90 G17 F100\nG0 X0 Y1490 Z0\nG06.3 P3 K0 X0 Y1490 Z0\nK0 X10 Y1530\nK0 X20 Y1490\nK1\nK1\nK1\n",
              &g063);
  EXPECT_EQ(e.where(), "line 8");
  EXPECT_EQ(e.id(), "gcode.travel");
  EXPECT_EQ(e.message().rfind("the move reaches Y = 1510", 0), 0u) << e.message();  // 1510 up to the bound's 1e-12
  EXPECT_NE(e.message().find("outside the travel of machine \"fanuc-g063\" (Y from -1500 to 1500 mm)"),
            std::string::npos);
}

TEST(GcodeReader, RefusedLineLeavesTheStateUnchanged) {
  GcodeInterpreter in;
  in.feed_line("G21 G90 G17 F100", 1);
  in.feed_line("G00 X1 Y2 Z3", 2);
  const MachineState before = in.state();
  // F, S and M03 are executed before the arc is found wrong; none may stick.
  EXPECT_THROW(in.feed_line("G02 X5 Y5 F900 S3000 M03", 3), InputError);
  EXPECT_THROW(in.feed_line("G20 G01 X7 Y", 4), InputError);
  const MachineState& after = in.state();
  EXPECT_EQ(after.pos, before.pos);
  EXPECT_EQ(after.feed, before.feed);
  EXPECT_EQ(after.spindle_on, before.spindle_on);
  EXPECT_EQ(after.spindle_rpm, before.spindle_rpm);
  EXPECT_EQ(after.units, before.units);
  EXPECT_EQ(after.motion, before.motion);
  // An open NURBS block is not disturbed by a refused line either.
  in.feed_line("G06.2 P2 K0 X1 Y2 Z3", 5);
  EXPECT_THROW(in.feed_line("K-1 X4", 6), InputError);  // decreasing knot
  in.feed_line("K0 X4", 7);
  in.feed_line("K1", 8);
  const auto done = in.feed_line("K1", 9);
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0].knots, (std::vector<double>{0, 0, 1, 1}));
  EXPECT_EQ(done[0].to, (Vec3{4, 2, 3}));
}

// The corrupted NURBS listing of the seeds (Figure I.48), as printed.
TEST(GcodeReader, SeedsButterflyListingIsRefused) {
  const std::string text = slurp(BEZCAM_SOURCE_DIR "/tests/bad/butterfly-g063.nc");
  const MachineProfile g063 = load_machine_profile("fanuc-g063");
  // Its first line is garbled too (Z, R and P each appear twice and there
  // is no K), so in line order that is the first refusal.
  const auto e = refusal(text, &g063);
  std::string expected = slurp(BEZCAM_SOURCE_DIR "/tests/bad/butterfly-g063.nc.expected");
  while (!expected.empty() && expected.back() == '\n') expected.pop_back();
  EXPECT_EQ(std::string(e.what()), expected);
  EXPECT_EQ(e.where(), "line 1");
  EXPECT_EQ(e.id(), "gcode.repeated-word");
  // With that first line read as its OCR probably garbled it (K0 on the
  // first point, X for Z, F for P), the knot column is what fails, at the
  // first decreasing knot: K0.03118 after K0.04978, on line 7 (the digest
  // names a later one, K0.259080 after K0.343467 on line 13; lint lists both).
  const std::string repaired =
      "G06.3 P4 K0.000000 X34.400 Y31.139 Z0.000 R1.000 F900\n" + text.substr(text.find('\n') + 1);
  const auto k = refusal(repaired, &g063);
  EXPECT_EQ(k.where(), "line 7");
  EXPECT_EQ(k.id(), "gcode.knot-order");
  EXPECT_EQ(k.message(),
            "K0.03118: expected a knot >= 0.04978 (knots must not decrease; the previous knot is on line 6), found "
            "0.03118");
}

TEST(GcodeReader, ModalMotionGoesOnWithoutItsWord) {
  const auto b = read_gcode(kPre +
                            "G01 X10\n"
                            "G03 X0 Y10 I-10 J0\n"
                            "X-10 Y0 I0 J-10\n"  // still G03
                            "G5 I0 J-5 P0 Q-5 X-10 Y-20\n"
                            "X-10 Y-40 P0 Q-5\n");  // still G5, I/J from the previous one
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[3].kind, BlockKind::arc_ccw);
  EXPECT_EQ(b[3].center, (Vec3{0, 0, 0}));
  EXPECT_EQ(b[5].kind, BlockKind::bezier);
  EXPECT_EQ(b[5].ctrl, (std::vector<Vec3>{{-10, -20, 0}, {-10, -15, 0}, {-10, -45, 0}, {-10, -40, 0}}));
}

// Interoperability: LinuxCNC's own interpreter (rs274, Debian package
// linuxcnc-uspace, listed in .ci/packages) reads the same program. Its
// canonical calls give arc ends, centres and directions (4 decimals) and
// the control-point count of each G5 / G5.1 / G5.2 curve (NURBS_FEED(n, ...)),
// which pins down the meaning of R arcs and of the G5.2 first line. Checked
// with linuxcnc-uspace 2.9.0~pre1.
TEST(GcodeReader, AgreesWithLinuxCncInterpreter) {
  if (std::system("command -v rs274 >/dev/null 2>&1") != 0) GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed";
  const std::string prog =
      "G21 G90 G17\nF500\nG0 X10 Y0 Z0\n"
      "G2 X0 Y10 R10\n"   // minor CW
      "G2 X10 Y0 R-10\n"  // major CW
      "G3 X-10 Y0 R10\n"  // R arcs the other way
      "G3 X10 Y0 R-10\n"
      "G3 X10 Y0 I-10 J0\n"    // full circle
      "G2 X20 Y0 I5 J0 Z-1\n"  // helix half
      "G1 X25 Y5\n"
      "G5 I5 J0 P-5 Q0 X35 Y15\n"
      "G5 P0 Q-3 X45 Y5\n"  // I, J continued
      "G5.1 X55 Y5 I5 J5\n"
      "G5.2 X65 Y15 P1 L4\nX75 Y15 P2\nX85 Y5 P1\nG5.3\n"  // first line with a point: 4 points
      "G5.2 P1\nX95 Y15 P1\nX105 Y5 P1\nG5.3\n"            // first line without: 3 points
      "G3 X105 Y5 I-5 J3\n"
      "M2\n";
  const fs::path dir = fs::temp_directory_path() / ("bezcam-rs274-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "p.ngc") << prog;
  // Two rs274 processes at once share LinuxCNC's shared memory and die of
  // SIGBUS: hold the same lock as linuxcnc_rs274_test.cpp (flock(1)).
  const std::string lock = (fs::temp_directory_path() / "bezcam-rs274.lock").string();
  const std::string out = testproc::shell("cd " + dir.string() + " && flock " + lock + " rs274 -g p.ngc 2>&1").out;
  fs::remove_all(dir);
  // Their calls, in order.
  struct Call {
    std::string name;
    std::vector<double> args;
  };
  std::vector<Call> calls;
  std::istringstream ls(out);
  for (std::string l; std::getline(ls, l);) {
    for (const char* name : {"STRAIGHT_TRAVERSE(", "STRAIGHT_FEED(", "ARC_FEED(", "NURBS_FEED("}) {
      const size_t at = l.find(name);
      if (at == std::string::npos) continue;
      Call c{std::string(name, std::strlen(name) - 1), {}};
      std::string args = l.substr(at + std::strlen(name));
      for (char& ch : args)
        if (ch == ',' || ch == ')') ch = ' ';
      std::istringstream as(args);
      for (std::string tok; as >> tok;)
        if (tok != "...") c.args.push_back(std::stod(tok));
      calls.push_back(c);
    }
  }
  const auto blocks = read_gcode(prog);
  ASSERT_EQ(calls.size(), blocks.size()) << out;
  for (size_t i = 0; i < blocks.size(); ++i) {
    const MotionBlock& b = blocks[i];
    const Call& c = calls[i];
    SCOPED_TRACE("block of line " + std::to_string(b.line) + ", " + c.name);
    switch (b.kind) {
      case BlockKind::rapid:
      case BlockKind::linear:
        EXPECT_EQ(c.name, b.kind == BlockKind::rapid ? "STRAIGHT_TRAVERSE" : "STRAIGHT_FEED");
        EXPECT_NEAR(c.args[0], b.to.x, 5e-5);
        EXPECT_NEAR(c.args[1], b.to.y, 5e-5);
        EXPECT_NEAR(c.args[2], b.to.z, 5e-5);
        break;
      case BlockKind::arc_cw:
      case BlockKind::arc_ccw:
        ASSERT_EQ(c.name, "ARC_FEED");
        EXPECT_NEAR(c.args[0], b.to.x, 5e-5);
        EXPECT_NEAR(c.args[1], b.to.y, 5e-5);
        EXPECT_NEAR(c.args[2], b.center.x, 5e-5);
        EXPECT_NEAR(c.args[3], b.center.y, 5e-5);
        EXPECT_EQ(c.args[4], b.kind == BlockKind::arc_ccw ? 1 : -1);
        EXPECT_NEAR(c.args[5], b.to.z, 5e-5);
        break;
      case BlockKind::bezier:
      case BlockKind::nurbs:
        ASSERT_EQ(c.name, "NURBS_FEED");
        EXPECT_EQ(c.args[0], static_cast<double>(b.ctrl.size()));
        break;
    }
  }
}
