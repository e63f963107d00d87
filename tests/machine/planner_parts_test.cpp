// A summary plan times a long program in parts as its blocks come (each
// part ends at a stop whose look-ahead windows it holds whole): its figures
// equal, bit for bit, those of the full plan of the same program, on every
// shipped profile (look-ahead windows of a few blocks to many, a jerk
// limit, LinuxCNC's corners with parabolic blends into ramps), on a
// program long enough to be timed in several parts, with pauses.
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/planner.hpp"

using namespace bezcam;

namespace {

// 1,200 groups: a rapid in, a plunge, 60 short lines zigzagging at a few
// feeds, an arc, a ramp into an arc (LinuxCNC: a parabolic blend), a
// retract; a dwell every 100 groups: 79,000 to 150,000 segments.
std::string long_program() {
  std::string s = "G21 G90 G17\nG0 X0 Y0 Z5\n";
  char buf[160];
  for (int g = 0; g < 1200; ++g) {
    const double x0 = (g % 40) * 20.0, y0 = (g / 40) * 20.0;
    std::snprintf(buf, sizeof buf, "G0 X%.3f Y%.3f\nG1 Z-1 F300\n", x0, y0);
    s += buf;
    for (int k = 1; k <= 60; ++k) {
      std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f F%d\n", x0 + 0.25 * k, y0 + (k % 2 ? 0.4 : 0.0),
                    k % 20 < 10 ? 3000 : 6000);
      s += buf;
    }
    std::snprintf(buf, sizeof buf, "G3 X%.3f Y%.3f I0 J2\nG1 X%.3f Y%.3f Z-2\nG2 X%.3f Y%.3f I0 J1\nG0 Z5\n", x0 + 15,
                  y0 + 4, x0 + 16, y0 + 4, x0 + 16, y0 + 6);
    s += buf;
    if (g % 100 == 99) s += "G4 P0.5\n";
  }
  return s + "M30\n";
}

}  // namespace

TEST(PlannerParts, ALongProgramsSummaryEqualsItsFullPlan) {
  const Timeline tl = read_timeline(long_program());
  for (const auto& name : machine_profile_names()) {
    const MachineProfile m = load_machine_profile(name);
    ASSERT_TRUE(m.motion) << name;
    SCOPED_TRACE(name);
    const MotionPlan full = plan_motion(tl, *m.motion, PlanDetail::full);
    const MotionPlan summary = plan_motion(tl, *m.motion, PlanDetail::summary);
    ASSERT_GT(full.segments.size(), size_t{1} << 16);  // timed in parts
    EXPECT_EQ(summary.cycle_time_s, full.cycle_time_s);
    EXPECT_EQ(summary.cutting_time_s, full.cutting_time_s);
    EXPECT_EQ(summary.rapid_time_s, full.rapid_time_s);
    EXPECT_EQ(summary.pause_time_s, full.pause_time_s);
    EXPECT_EQ(summary.programmed_feed_time_s, full.programmed_feed_time_s);
    EXPECT_EQ(summary.mean_feed_ratio, full.mean_feed_ratio);
    EXPECT_EQ(summary.starved_blocks, full.starved_blocks);
    EXPECT_EQ(summary.clamped_blocks, full.clamped_blocks);
    EXPECT_EQ(summary.max_path_deviation, full.max_path_deviation);
    EXPECT_GT(full.pause_time_s, 5.9);
  }
}
