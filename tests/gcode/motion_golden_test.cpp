// Golden motion summaries: every sample, converted for linuxcnc and fanuc in
// every output mode the machine takes, planned on the machine's motion
// model (machine/planner.hpp). One row per program in
// tests/golden/motion/<machine>.tsv: a change that slows (or speeds) a
// program shows in review as a changed row.
//
// Regenerate after an intended change with
//   BEZCAM_UPDATE_GOLDEN=1 ctest --test-dir build -R MotionGolden
// and review `git diff tests/golden/motion`.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/planner.hpp"
#include "support/sample_job.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

const fs::path kRoot = BEZCAM_SOURCE_DIR;

std::vector<fs::path> samples() {
  std::vector<fs::path> v;
  for (const auto& e : fs::directory_iterator(kRoot / "samples"))
    if (e.path().extension() == ".json") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> t;
  std::istringstream in(line);
  for (std::string w; std::getline(in, w, '\t');) t.push_back(w);
  return t;
}

// Numbers may differ by 1e-6 relative (compilers' last bits); words not.
bool same_row(const std::string& a, const std::string& b) {
  const auto x = tokens(a), y = tokens(b);
  if (x.size() != y.size()) return false;
  for (size_t i = 0; i < x.size(); ++i) {
    if (x[i] == y[i]) continue;
    char* ex = nullptr;
    char* ey = nullptr;
    const double dx = std::strtod(x[i].c_str(), &ex), dy = std::strtod(y[i].c_str(), &ey);
    if (*ex || *ey || x[i].empty() || y[i].empty()) return false;
    if (std::abs(dx - dy) > 1e-6 * std::max({1.0, std::abs(dx), std::abs(dy)})) return false;
  }
  return true;
}

std::string summary_rows(const char* machine) {
  const MachineProfile m = load_machine_profile(machine);
  std::string out =
      "sample\toutput\tcutting_blocks\tcycle_time_s\tcutting_time_s\trapid_time_s\tpause_time_s\t"
      "programmed_feed_time_s\tmean_feed_ratio\tstarved_blocks\tmax_path_deviation\n";
  for (const auto& s : samples()) {
    const Job job = test::load_sample(s);
    // As --compare-outputs: the modes share a pocket's passes and certificate.
    const auto memo = make_conversion_memo();
    for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
      if (mode == OutputMode::nurbs && m.nurbs == NurbsDialect::none) continue;
      ConvertOptions o;
      o.output = mode;
      o.memo = memo;
      const ConvertResult r = convert(job, m, o);
      if (r.program.output != mode) continue;  // replaced (surfaces stay in lines)
      const MotionPlan plan = plan_motion(read_timeline(r.gcode, &m), *m.motion);
      // convert() plans once, from the program's moves, for the header and
      // the report: the same figures as the text read back and planned.
      if (r.plan) {
        const MotionPlan& once = *r.plan;
        auto near = [](double a, double b) {
          return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
        };
        const std::string where = s.stem().string() + " " + to_string(mode) + " on " + machine;
        EXPECT_TRUE(near(once.cycle_time_s, plan.cycle_time_s))
            << where << ": " << once.cycle_time_s << " vs " << plan.cycle_time_s;
        EXPECT_TRUE(near(once.cutting_time_s, plan.cutting_time_s)) << where;
        EXPECT_TRUE(near(once.rapid_time_s, plan.rapid_time_s)) << where;
        EXPECT_TRUE(near(once.pause_time_s, plan.pause_time_s)) << where;
        EXPECT_TRUE(near(once.programmed_feed_time_s, plan.programmed_feed_time_s)) << where;
        EXPECT_TRUE(near(once.mean_feed_ratio, plan.mean_feed_ratio)) << where;
        EXPECT_TRUE(near(once.max_path_deviation, plan.max_path_deviation)) << where;
        EXPECT_EQ(once.starved_blocks, plan.starved_blocks) << where;
        EXPECT_EQ(once.clamped_blocks, plan.clamped_blocks) << where;
        EXPECT_TRUE(once.segments.empty() && once.motion.empty()) << where;  // summary only
      }
      // The header's cycle time (the program's moves planned) is the text's:
      // the first approach from home included (MotionBlock::from_known).
      // Not yet where the profile's tool change position lines (G53 ...)
      // move the machine between tools: the program's moves do not have
      // that retract.
      bool retracts = false, moved = false;
      for (const Move& mv : r.program.moves) {
        moved = moved || motion_of(mv) != nullptr;
        retracts = retracts ||
                   (moved && std::holds_alternative<ToolChangePosition>(mv.what) && !m.tool_change_position.empty());
      }
      const MotionPlan header = plan_motion(program_timeline(r.program), *m.motion);
      if (!retracts)
        EXPECT_LE(std::abs(header.cycle_time_s - plan.cycle_time_s), 1e-9 * std::max(1.0, plan.cycle_time_s))
            << s.stem() << " " << to_string(mode) << " on " << machine << ": header " << header.cycle_time_s
            << " s, read back " << plan.cycle_time_s << " s";
      size_t blocks = 0;
      for (const auto& e : r.program.entities) blocks += e.blocks;
      char b[400];
      std::snprintf(b, sizeof b, "%s\t%s\t%zu\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%zu\t%.6f\n", s.stem().c_str(),
                    to_string(mode), blocks, plan.cycle_time_s, plan.cutting_time_s, plan.rapid_time_s,
                    plan.pause_time_s, plan.programmed_feed_time_s, plan.mean_feed_ratio, plan.starved_blocks,
                    plan.max_path_deviation);
      out += b;
    }
  }
  return out;
}

void check(const char* machine) {
  const fs::path golden = kRoot / "tests/golden/motion" / (std::string(machine) + ".tsv");
  const std::string actual = summary_rows(machine);
  if (const char* u = std::getenv("BEZCAM_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  std::ifstream in(golden, std::ios::binary);
  ASSERT_TRUE(in) << golden << " is missing; regenerate with BEZCAM_UPDATE_GOLDEN=1";
  std::istringstream act(actual);
  std::string g, a;
  int line = 0;
  while (true) {
    ++line;
    const bool hg = static_cast<bool>(std::getline(in, g)), ha = static_cast<bool>(std::getline(act, a));
    if (!hg && !ha) break;
    ASSERT_TRUE(hg && ha && same_row(g, a))
        << golden.filename() << " differs at line " << line << ":\n  golden: " << (hg ? g : "<end>")
        << "\n  actual: " << (ha ? a : "<end>");
  }
}

}  // namespace

TEST(MotionGolden, EverySampleInEveryModeOnLinuxcnc) { check("linuxcnc"); }
TEST(MotionGolden, EverySampleInEveryModeOnFanuc) { check("fanuc"); }
