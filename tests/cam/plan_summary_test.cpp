// The summary plan of a built program made block by block
// (plan_program_summary(), which `bezcam convert` prints) against the plan
// of its whole timeline: the same figures, bit for bit, on samples with
// lines, arcs, exact blocks, cutter compensation, 3D moves and tool changes.
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

#include "bezcam/cam/program_motion.hpp"
#include "support/sample_job.hpp"

namespace bezcam {
namespace {

void expect_same(const MotionPlan& a, const MotionPlan& b) {
  EXPECT_EQ(a.units, b.units);
  EXPECT_EQ(a.period_s, b.period_s);
  EXPECT_EQ(a.cycle_time_s, b.cycle_time_s);
  EXPECT_EQ(a.cutting_time_s, b.cutting_time_s);
  EXPECT_EQ(a.rapid_time_s, b.rapid_time_s);
  EXPECT_EQ(a.pause_time_s, b.pause_time_s);
  EXPECT_EQ(a.programmed_feed_time_s, b.programmed_feed_time_s);
  EXPECT_EQ(a.mean_feed_ratio, b.mean_feed_ratio);
  EXPECT_EQ(a.starved_blocks, b.starved_blocks);
  EXPECT_EQ(a.clamped_blocks, b.clamped_blocks);
  EXPECT_EQ(a.max_path_deviation, b.max_path_deviation);
  EXPECT_EQ(a.max_deviation_line, b.max_deviation_line);
  EXPECT_EQ(a.path_time_s, b.path_time_s);
  EXPECT_TRUE(a.blocks.empty() && a.segments.empty() && a.motion.empty() && a.pause_start_s.empty());
}

TEST(PlanProgramSummary, EqualsThePlanOfTheWholeTimeline) {
  const std::string dir = BEZCAM_SOURCE_DIR;
  int planned = 0, on_path = 0;
  for (const char* sample : {"samples/curve-exercise-1.json", "samples/curve-nurbs-circle.json",
                             "samples/job-two-tools.json", "samples/controller-comp/flange-g41.json",
                             "samples/curve-helix-xz.json", "samples/patch-saddle.json", "samples/part-flange.json"}) {
    const Job job = test::load_sample(dir + "/" + sample);
    for (const char* machine : {"generic", "linuxcnc", "fanuc"}) {
      const MachineProfile m = load_machine_profile(dir + "/machines/" + machine + ".json");
      if (!m.motion) continue;
      for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
        SCOPED_TRACE(std::string(sample) + " on " + machine + ", " + to_string(mode));
        ConvertOptions opt;
        opt.output = mode;
        opt.measure = false;
        Program p;
        try {
          p = build_program(job, m, opt);
        } catch (const std::exception&) {
          continue;  // an output the machine does not take
        }
        const MotionPlan whole = plan_motion(program_timeline(p), *m.motion, PlanDetail::summary);
        expect_same(plan_program_summary(p, *m.motion), whole);
        EXPECT_GT(whole.cycle_time_s, 0);
        ++planned;
        if (whole.path_time_s > 0) ++on_path;  // cuts along curves with an exact path's bound
      }
    }
  }
  EXPECT_GE(planned, 30);
  EXPECT_GE(on_path, 10);
}

TEST(PlanMotionSummary, RefusesBlocksThatDifferBetweenItsTwoPasses) {
  MotionModel model;
  MotionBlock b;
  b.to = {10, 0, 0};
  b.feed = 600;
  int calls = 0;
  const BlockStream growing = [&](const std::function<void(MotionBlock&)>& each) {
    ++calls;
    for (int k = 0; k < calls; ++k) {
      MotionBlock c = b;
      c.to.y = k;
      each(c);
    }
  };
  EXPECT_THROW(plan_motion_summary(Timeline{}, growing, model), std::logic_error);
}

}  // namespace
}  // namespace bezcam
