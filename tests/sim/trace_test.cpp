// The trace: fixed-decimal numbers without "-0", exact record text, arcs
// sampled on their circle, the golden comparison and its tolerance.
#include "bezcam/sim/trace.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

using namespace bezcam;
using namespace bezcam::sim;

TEST(Trace, NumbersHaveFixedDecimalsAndNoNegativeZero) {
  EXPECT_EQ(trace_number(1.5), "1.500000");
  EXPECT_EQ(trace_number(-2.25), "-2.250000");
  EXPECT_EQ(trace_number(-0.0), "0.000000");
  EXPECT_EQ(trace_number(-1e-9), "0.000000");
  EXPECT_EQ(trace_number(-4e-7), "0.000000");
  EXPECT_EQ(trace_number(-6e-7), "-0.000001");
  EXPECT_EQ(trace_number(12345.6789), "12345.678900");
}

TEST(Trace, LinearAndRapidRecords) {
  MotionBlock b;
  b.kind = BlockKind::linear;
  b.line = b.first_line = 12;
  b.from = {0, 0, 0};
  b.to = {1, -2.5, -0.0};
  b.feed = 800;
  EXPECT_EQ(trace_block(b), "line 12 linear to 1.000000 -2.500000 0.000000 feed 800.000000\n");
  b.kind = BlockKind::rapid;
  b.feed = 0;
  EXPECT_EQ(trace_block(b), "line 12 rapid to 1.000000 -2.500000 0.000000\n");
  EXPECT_EQ(trace_sample_count(b), 0);
}

TEST(Trace, ArcSamplesLieOnTheCircleInOrder) {
  MotionBlock b;
  b.kind = BlockKind::arc_ccw;
  b.line = b.first_line = 3;
  b.from = {10, 0, 0};
  b.to = {0, 10, 0};
  b.center = {0, 0, 0};
  b.feed = 500;
  const std::string t = trace_block(b);
  std::istringstream in(t);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "line 3 arc_ccw to 0.000000 10.000000 0.000000 center 0.000000 0.000000 0.000000 feed 500.000000");
  int n = 0;
  double last_angle = 0;
  while (std::getline(in, line)) {
    double tt, x, y, z;
    ASSERT_EQ(std::sscanf(line.c_str(), "  at %lf %lf %lf %lf", &tt, &x, &y, &z), 4) << line;
    ++n;
    EXPECT_NEAR(tt, static_cast<double>(n) / kArcSamples, 1e-6);
    EXPECT_NEAR(std::hypot(x, y), 10.0, 2e-6) << line;
    const double a = std::atan2(y, x);
    EXPECT_GT(a, last_angle);
    last_angle = a;
  }
  EXPECT_EQ(n, kArcSamples - 1);
  EXPECT_EQ(trace_sample_count(b), kArcSamples - 1);
}

TEST(Trace, NurbsAreSampledPerNonEmptyKnotSpan) {
  MotionBlock b;
  b.kind = BlockKind::nurbs;
  b.order = 3;
  b.ctrl = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
  b.weights = {1, 1, 1, 1};
  b.knots = {0, 0, 0, 0.5, 1, 1, 1};  // two non-empty spans
  EXPECT_EQ(trace_sample_count(b), 2 * kSpanSamples - 1);
  b.ctrl.pop_back();  // a single Bézier span
  b.weights.pop_back();
  b.knots = {0, 0, 0, 1, 1, 1};
  EXPECT_EQ(trace_sample_count(b), kSpanSamples - 1);
}

TEST(Trace, ModalChangesAreRecordedOnlyWhenTheyHappen) {
  MachineState a, b;
  EXPECT_EQ(trace_state(4, a, b), "");
  b.tool = 2;
  b.spindle_on = true;
  b.spindle_rpm = 12000;
  b.program_end = true;
  EXPECT_EQ(trace_state(7, a, b), "line 7 tool 2\nline 7 spindle on 12000.000000\nline 7 program end\n");
  MachineState c = b;
  c.spindle_on = false;
  EXPECT_EQ(trace_state(9, b, c), "line 9 spindle off\n");
}

TEST(Trace, AlarmAndDoneRecords) {
  EXPECT_EQ(trace_alarm(12, "gcode", "gcode.syntax", "bad\nword"), "alarm line 12 gcode gcode.syntax: bad word\n");
  EXPECT_EQ(trace_done(40, 31, {1, 2, 3}), "done lines 40 blocks 31 at 1.000000 2.000000 3.000000\n");
}

TEST(Trace, ComparisonAllowsTheStatedToleranceOnNumbersOnly) {
  const std::string a = "bezcam-trace 1 machine generic\nline 3 linear to 1.000000 2.000000 0.000000 feed 800.000000\n";
  EXPECT_FALSE(compare_traces(a, a));
  const std::string near =
      "bezcam-trace 1 machine generic\nline 3 linear to 1.000009 2.000000 0.000000 feed 800.000000\n";
  EXPECT_FALSE(compare_traces(a, near));
  const std::string far =
      "bezcam-trace 1 machine generic\nline 3 linear to 1.000011 2.000000 0.000000 feed 800.000000\n";
  const auto m = compare_traces(a, far);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->line, 2u);
  EXPECT_NE(m->why.find("1.000000 vs 1.000011"), std::string::npos) << m->why;
  // Words are never "near": a different kind or line number is a difference.
  EXPECT_TRUE(compare_traces(
      a, "bezcam-trace 1 machine generic\nline 3 rapid to 1.000000 2.000000 0.000000 feed 800.000000\n"));
  EXPECT_TRUE(compare_traces(
      a, "bezcam-trace 1 machine generic\nline 4 linear to 1.000000 2.000000 0.000000 feed 800.000000\n"));
  EXPECT_TRUE(compare_traces(a, a + "done lines 3 blocks 1 at 0 0 0\n"));
  EXPECT_TRUE(
      compare_traces(a, "bezcam-trace 1 machine fanuc\nline 3 linear to 1.000000 2.000000 0.000000 feed 800.000000\n"));
}
