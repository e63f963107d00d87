// Programs written the way other CAM posts write them (tests/gcode/data/posts:
// dxf2gcode's LinuxCNC export, absolute and incremental; FreeCAD's LinuxCNC
// and Fanuc posts; a hand-written LinuxCNC program in every distance mode):
// they lint clean for the machines they are meant for (what `bezcam stream`
// checks before it sends), and the planner executes them through the end
// point of every block. linuxcnc_rs274_test.cpp holds their motion against
// LinuxCNC's own interpreter.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

#include "bezcam/gcode/lint.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/planner.hpp"
#include "support/files.hpp"

using namespace bezcam;

namespace {

std::string slurp(const std::string& name) {
  return bezcam::test::slurp(std::string(BEZCAM_SOURCE_DIR) + "/tests/gcode/data/posts/" + name);
}

struct Post {
  const char* file;
  std::vector<const char*> machines;
};

const Post kPosts[] = {
    {"dxf2gcode-plate.ngc", {"linuxcnc", "generic", "fanuc", "grbl"}},
    {"dxf2gcode-incremental.ngc", {"linuxcnc", "generic", "fanuc", "grbl"}},
    {"freecad-linuxcnc.ngc", {"linuxcnc", "generic", "fanuc"}},
    {"freecad-fanuc.nc", {"fanuc", "generic", "linuxcnc"}},
    {"linuxcnc-distance-modes.ngc", {"linuxcnc"}},
};

// Distance from p to the segment [a, b].
double to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = dot(d, d);
  const double t = dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return norm(p - (a + d * t));
}

}  // namespace

TEST(OtherPosts, LintCleanForTheirMachines) {
  for (const Post& post : kPosts) {
    const std::string text = slurp(post.file);
    for (const char* name : post.machines) {
      const MachineProfile m = load_machine_profile(name);
      std::string found;
      for (const auto& f : lint_gcode(text, m))
        found += std::to_string(f.line) + ": " + f.message + " [" + f.id + "]\n";
      EXPECT_EQ(found, "") << post.file << " on " << name;
    }
  }
}

TEST(OtherPosts, ThePlannerRunsThroughTheEndOfEveryBlock) {
  for (const Post& post : kPosts) {
    const std::string text = slurp(post.file);
    const MachineProfile m = load_machine_profile(post.machines.front());
    SCOPED_TRACE(std::string(post.file) + " on " + m.name);
    const auto blocks = read_gcode(text, &m);
    ASSERT_FALSE(blocks.empty());
    const MotionPlan plan = plan_motion(read_timeline(text, &m), *m.motion);
    ASSERT_EQ(plan.blocks.size(), blocks.size());
    std::vector<Vec3> path;
    sample_plan(plan, [&](double, const Vec3& p, double) { path.push_back(p); });
    ASSERT_GE(path.size(), 2u);
    // Corners are blended within the plan's deviation from the programmed
    // path; the corner's point itself is then up to 1 / cos(turn / 2) of it
    // away, sqrt(2) times at the right angles these programs turn at most
    // (reversals stop exactly). The path stops at the last end point.
    const double within = plan.max_path_deviation * std::sqrt(2.0) + 1e-6;
    for (const MotionBlock& b : blocks) {
      double nearest = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k + 1 < path.size(); ++k) nearest = std::min(nearest, to_segment(b.to, path[k], path[k + 1]));
      EXPECT_LE(nearest, within) << "the end of the block of line " << b.line;
    }
    EXPECT_LT(norm(path.back() - blocks.back().to), 1e-9);
  }
}
