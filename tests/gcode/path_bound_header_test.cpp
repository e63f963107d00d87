// The time-optimal bound in the program (machine/path_bound.hpp,
// cam/program_motion.hpp): every curve sample cut at F800 and F6000 on the
// linuxcnc, fanuc, generic and unisurf (exact stop: the bound from rest to
// rest) profiles, in every output mode, plans its
// cuts along the curves (with the blends at their ends) in no less time
// than the bound of their exact paths, and its header says both, the
// bound rounded down.
#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "support/sample_job.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> curve_samples() {
  std::vector<fs::path> v;
  for (const auto& e : fs::directory_iterator(fs::path(BEZCAM_SOURCE_DIR) / "samples"))
    if (e.path().extension() == ".json" && e.path().filename().string().rfind("curve-", 0) == 0) v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST(PathBoundHeader, CutsAlongCurvesTakeNoLessThanTheBound) {
  const auto samples = curve_samples();
  ASSERT_GE(samples.size(), 10u);
  for (const char* machine : {"linuxcnc", "fanuc", "generic", "unisurf"})
    for (const double feed : {800.0, 6000.0}) {
      const MachineProfile m = load_machine_profile(machine);
      for (const auto& s : samples) {
        Job job = test::load_sample(s);
        job.params.feed = std::min(feed, m.max_feed_mm_min);
        job.tolerance = std::max(job.tolerance, 0.02);  // unisurf prints 2 decimals
        for (auto& e : job.entities) e.params.feed.reset();
        for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
          ConvertOptions o;
          o.output = mode;
          o.measure = false;
          const ConvertResult r = convert(job, m, o);
          SCOPED_TRACE(s.filename().string() + " " + machine + " F" + std::to_string(feed) + " " + to_string(mode));
          const double bound = exact_path_bound_s(r.program);
          ASSERT_GT(bound, 0);
          ASSERT_TRUE(r.plan);
          EXPECT_GE(r.plan->path_time_s, bound);
          EXPECT_LT(r.plan->path_time_s, r.plan->cutting_time_s);  // the plunges are not in it
          const std::string line = "(cutting along the curves " + format_time(r.plan->path_time_s) +
                                   "; the exact path's bound on this machine " + format_time(bound, true) + " [x";
          EXPECT_NE(r.gcode.find(line), std::string::npos) << r.gcode.substr(0, 600);
        }
      }
    }
}

TEST(PathBoundHeader, OnlyTheCutAlongTheCurveIsMarked) {
  Job job = test::load_sample(fs::path(BEZCAM_SOURCE_DIR) / "samples" / "curve-semicircle.json");
  const MachineProfile m = load_machine_profile("linuxcnc");
  const ConvertResult r = convert(job, m, ConvertOptions{});
  const Timeline tl = program_timeline(r.program);
  ASSERT_EQ(tl.on_path.size(), tl.blocks.size());
  size_t marked = 0;
  for (size_t i = 0; i < tl.blocks.size(); ++i) {
    if (!tl.on_path[i]) continue;
    ++marked;
    EXPECT_EQ(tl.blocks[i].kind, BlockKind::linear);
    EXPECT_EQ(tl.blocks[i].from.z, tl.blocks[i].to.z);  // no plunge, no retract
  }
  ASSERT_EQ(r.program.entities.size(), 1u);
  EXPECT_EQ(marked, r.program.entities[0].blocks);
  // Without a motion model, no bound and nothing marked.
  MachineProfile bare = m;
  bare.motion.reset();
  const ConvertResult r2 = convert(job, bare, ConvertOptions{});
  EXPECT_EQ(exact_path_bound_s(r2.program), 0);
  EXPECT_TRUE(program_timeline(r2.program).on_path.empty());
  EXPECT_EQ(r2.gcode.find("exact path's bound"), std::string::npos);
}

TEST(FormatTime, HundredthsRoundedOrRoundedDown) {
  EXPECT_EQ(format_time(8.236), "8.24 s");
  EXPECT_EQ(format_time(8.236, true), "8.23 s");
  EXPECT_EQ(format_time(125.319), "2 min 05.32 s");
  EXPECT_EQ(format_time(0.004, true), "0.00 s");
}
