// Speed of the simulated controller's motion planning:
// simulated seconds per wall-clock second for a long G01 program and for a
// NURBS program, planned on the linuxcnc and generic motion models (the
// interpreter's reading included, as `simulate --program --report` does),
// and with the per-period samples written (`--motion`).
//
//   build/motion_bench
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/report/motion_report.hpp"

using namespace bezcam;
using Clock = std::chrono::steady_clock;

namespace {

std::string g01_program(int n) {
  std::string p = "G21 G90 G17\nG0 X0 Y0 Z0\nS10000 M3\nG1 F6000\n";
  double x = 0, y = 0;
  char b[64];
  for (int i = 0; i < n; ++i) {
    const double a = (i % 400) / 400.0 * 6.283185307179586;
    x += 0.2 * std::cos(a);
    y += 0.2 * std::sin(a);
    std::snprintf(b, sizeof b, "X%.4f Y%.4f\n", x, y);
    p += b;
  }
  return p + "M30\n";
}

// LinuxCNC G5.2 cubic blocks of 8 points each, a wave along X.
std::string nurbs_program(int blocks) {
  std::string p = "G21 G90 G17\nG0 X0 Y0 Z0\nS10000 M3\nG1 F3000\n";
  char b[80];
  double x = 0;
  for (int k = 0; k < blocks; ++k) {
    p += "G5.2 P1 L4\n";
    for (int i = 1; i <= 8; ++i) {
      std::snprintf(b, sizeof b, "X%.3f Y%.3f P1\n", x + 10 * i, i == 8 ? 0.0 : (i % 2 ? 15.0 : -15.0));
      p += b;
    }
    p += "G5.3\n";
    x += 80;
    if (x > 800) {
      x = 0;
      p += "G1 X0 Y0\n";
    }
  }
  return p + "M30\n";
}

void run(const char* what, const std::string& program, const char* machine) {
  const MachineProfile m = load_machine_profile(std::string(BEZCAM_SOURCE_DIR) + "/machines/" + machine + ".json", {});
  const auto t0 = Clock::now();
  const MotionPlan plan = plan_motion(read_timeline(program), *m.motion);
  const double plan_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto t1 = Clock::now();
  const std::string tsv = motion_samples_tsv(plan);
  const double tsv_s = std::chrono::duration<double>(Clock::now() - t1).count();
  std::printf("  %-26s %-9s %8zu %10.1f s %8.3f s %9.0f x   %8.3f s %7.0f x (%zu MB)\n", what, machine,
              plan.blocks.size(), plan.cycle_time_s, plan_s, plan.cycle_time_s / plan_s, plan_s + tsv_s,
              plan.cycle_time_s / (plan_s + tsv_s), tsv.size() >> 20);
}

}  // namespace

int main() {
  std::printf("bezcam motion planning speed: simulated seconds per wall-clock second (target >= 1000 x for G01)\n");
  std::printf("  %-26s %-9s %8s %12s %10s %11s   %s\n", "program", "machine", "blocks", "simulated", "planned in",
              "speed", "with --motion samples");
  const std::string g01 = g01_program(100000), nurbs = nurbs_program(2000);
  for (const char* m : {"linuxcnc", "generic"}) {
    run("100000 G01 lines, 0.2 mm", g01, m);
    run("2000 G5.2 blocks (8 points)", nurbs, m);
  }
  return 0;
}
