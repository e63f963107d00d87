// The `linuxcnc` planner's corner rules (docs/motion.md, "The linuxcnc
// planner"), each on a program whose plan they decide: rapid and feed meet
// at a stop, a corner leaving an arc's plane is a parabolic blend that
// halves both moves' acceleration, a wide arc keeps more than half of the
// acceleration for the tangent. The cycle times against LinuxCNC itself
// are the anchor's (tests/lcnc/).
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <utility>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/machine/planner.hpp"

using namespace bezcam;

namespace {

// 6000 mm/min (100 mm/s) and 1000 mm/s^2 on every axis, 1 ms periods.
MotionModel linuxcnc_model() {
  MotionModel m;
  m.max_velocity_mm_min = {6000, 6000, 6000};
  m.max_acceleration_mm_s2 = {1000, 1000, 1000};
  m.period_s = 0.001;
  m.min_segment_periods = 0;
  m.block_rate_hz = 0;
  m.lookahead_blocks = 1000;
  m.blend_tolerance_mm = 0.01;
  m.planner = MotionModel::Planner::linuxcnc;
  return m;
}

MotionPlan plan(const std::string& body) {
  return plan_motion(read_timeline("G21 G90 G17\nG0 X0 Y0 Z0\n" + body + "M30\n"), linuxcnc_model());
}

// The segments of the block of program line `line`.
std::vector<const PlanSegment*> segments_of(const MotionPlan& p, int line) {
  std::vector<const PlanSegment*> out;
  for (const PlanSegment& s : p.segments)
    if (s.block >= 0 && p.motion[static_cast<size_t>(s.block)].line == line && !s.blend) out.push_back(&s);
  return out;
}

}  // namespace

TEST(LinuxcncPlanner, RapidAndFeedMeetAtAStop) {
  // Straight on, yet LinuxCNC never blends a rapid into a feed move: the
  // rapid stops (20 mm at 100 mm/s, 1000 mm/s^2: 0.3 s), the line starts
  // from rest and, being last, plans with half its acceleration (20 mm at
  // 50 mm/s, 500 mm/s^2: 0.5 s).
  const MotionPlan p = plan("G0 X20\nG1 X40 F3000\n");
  EXPECT_NEAR(p.cycle_time_s, 0.3 + 0.5, 1e-9);
  const MotionPlan back = plan("G1 X20 F3000\nG0 X40\n");  // and the other way
  EXPECT_NEAR(back.cycle_time_s, (20.0 / 50 + 50.0 / 1000) + (20.0 / 100 + 100.0 / 500), 1e-9);
}

TEST(LinuxcncPlanner, ACornerLeavingTheArcsPlaneIsAParabolicBlend) {
  // The same arc, once followed by a line in its plane (a blend arc joins
  // them), once by a ramp leaving it: then both moves keep half their
  // acceleration and the arc takes longer.
  const std::string arc = "G1 X20 Y0 F3000\nG3 X40 Y20 I0 J20\n";
  const MotionPlan flat = plan(arc + "G1 X40 Y40\n");
  const MotionPlan ramp = plan(arc + "G1 X40 Y40 Z-2\n");
  const auto flat_arc = segments_of(flat, 4), ramp_arc = segments_of(ramp, 4);
  const auto flat_line = segments_of(flat, 5), ramp_line = segments_of(ramp, 5);
  ASSERT_EQ(flat_arc.size(), 1u);
  ASSERT_EQ(ramp_arc.size(), 1u);
  ASSERT_FALSE(flat_line.empty());
  ASSERT_FALSE(ramp_line.empty());
  EXPECT_FALSE(flat_arc[0]->parabolic);
  EXPECT_TRUE(ramp_arc[0]->parabolic);
  EXPECT_TRUE(ramp_line.front()->parabolic);
  EXPECT_NEAR(ramp_arc[0]->overall_accel, 0.5 * flat_arc[0]->overall_accel, 1e-9);
  // The arc (R 20, top speed 100 mm/s in its plane: 500 mm/s^2 across)
  // keeps sqrt(1 - 0.5^2) of 1000 mm/s^2 for the tangent; with half of
  // the acceleration 500 mm/s^2 across is more than sqrt(3)/2 of it, so
  // half of 500.
  EXPECT_NEAR(flat_arc[0]->accel, std::sqrt(0.75) * 1000, 1e-9);
  EXPECT_NEAR(ramp_arc[0]->accel, 0.5 * 500, 1e-9);
  EXPECT_GT(ramp.cycle_time_s, flat.cycle_time_s + 0.02);
}

TEST(LinuxcncPlanner, AnArcKeepsForTheTangentWhatItsTopSpeedLeaves) {
  // At F6000 (the top speed). R 5: 100 mm/s across needs 2000 mm/s^2, more than sqrt(3)/2 of 1000:
  // half for the tangent and the speed capped at sqrt(866 x 5). R 100:
  // 100 mm/s across needs 100 mm/s^2, leaving sqrt(1 - 0.1^2) of it.
  const MotionPlan tight = plan("G1 X10 Y0 F6000\nG3 X10 Y10 I0 J5\nG1 X0 Y10\n");
  const MotionPlan wide = plan("G1 X10 Y0 F6000\nG3 X10 Y200 I0 J100\nG1 X0 Y200\n");
  const auto t = segments_of(tight, 4), w = segments_of(wide, 4);
  ASSERT_EQ(t.size(), 1u);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NEAR(t[0]->vmax, std::sqrt(std::sqrt(0.75) * 1000 * 5), 1e-9);
  EXPECT_NEAR(t[0]->accel, 0.5 * 1000, 1e-9);
  EXPECT_NEAR(w[0]->accel, std::sqrt(1 - 0.01) * 1000, 1e-9);
}

TEST(LinuxcncPlanner, ALastArcBlendedParabolicallyKeepsHalfOfHalf) {
  // A ramp into a wide arc that ends the program: the parabolic blend
  // halves its acceleration, and as the last move LinuxCNC never sizes its
  // tangential share for its radius: half of that half.
  const MotionPlan p = plan("G1 X20 Y0 Z0 F6000\nG1 X40 Y0 Z-2\nG3 X40 Y200 I0 J100\n");
  const auto arc = segments_of(p, 5);
  ASSERT_EQ(arc.size(), 1u);
  EXPECT_TRUE(arc[0]->parabolic);
  EXPECT_NEAR(arc[0]->overall_accel, 500, 1e-9);
  EXPECT_NEAR(arc[0]->accel, 0.5 * 500, 1e-9);
}

TEST(LinuxcncPlanner, ANearTangentJointBetweenArcsIsAKinkWhereItsBlendArcIsSlower) {
  // Two arcs turning the same way (R 20 then R 80) meet at a kink of 1e-3
  // rad. LinuxCNC sizes a blend circle tangent to both: its radius is huge
  // but the arcs turn along it, so it is 0.04 mm long and could run at 40
  // mm/s (its length in one period). LinuxCNC takes the faster of the
  // three ways: here the kink, at the speed whose one-period turn is 0.1
  // of the axes' limits (doubled at arcs), and the two arcs lose 0.1 of
  // their acceleration.
  MotionModel m = linuxcnc_model();
  m.max_velocity_mm_min = {10000, 10000, 5000};
  m.max_acceleration_mm_s2 = {1000, 1000, 500};
  const MotionPlan p = plan_motion(read_timeline("G21 G90 G17\nG0 X0 Y0 Z0\nG1 X10 Y0 F6000\n"
                                                 "G3 X20 Y2.6795 I0 J20\n"
                                                 "G3 X31.431 Y10.6665 I-39.9307 J69.322\nM30\n"),
                                   m);
  const auto first = segments_of(p, 4), second = segments_of(p, 5);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(second.size(), 1u);
  // The directions at the joint (a ccw tangent is the radius turned by
  // 90 degrees) and the spike of turning between them within a period at
  // 100 mm/s.
  const double px = 20, py = 2.6795;
  auto ccw = [&](double cx, double cy) {
    const double rx = px - cx, ry = py - cy, r = std::hypot(rx, ry);
    return std::pair<double, double>{-ry / r, rx / r};
  };
  const auto [ax, ay] = ccw(10, 20);
  const auto [bx, by] = ccw(20 - 39.9307, 2.6795 + 69.322);
  const double a_inst = 100 / 0.001 + 1000;
  const double spike = std::max(std::abs(bx - ax), std::abs(by - ay)) * a_inst / 1000 / 0.5;
  ASSERT_GT(spike, 0.1);  // not tangent for LinuxCNC
  const double v_kink = 100 * 0.1 / spike;
  EXPECT_NEAR(first[0]->v1, v_kink, 0.005 * v_kink);
  EXPECT_NEAR(second[0]->v0, v_kink, 0.005 * v_kink);
  EXPECT_NEAR(first[0]->kink_reduce, 0.1, 1e-12);
  EXPECT_NEAR(second[0]->kink_reduce, 0.1, 1e-12);
}
