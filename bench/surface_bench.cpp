// Surface finishing benchmark: for each sample patch (and a patch stretched
// 28 times in one place), the passes and cutting blocks that meet the
// stepover and tolerance with adaptive pass spacing (plan_passes) against
// the baseline of uniform parameter steps (plan_uniform_passes, the fewest
// uniform passes that verify the same way), with the tool of the sample
// and with the tip on the surface (r = 0); then the time to convert each
// sample job to a validated program; then the cutting blocks per pass in
// each output mode (lines, arcs, nurbs on the sample's machine, and lines
// and nurbs on the Fanuc profile, whose G06.2 blocks carry X, Y and Z).
//
// Usage: surface_bench [--quick]   (--quick: one repetition)
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bezcam/cam/gouge.hpp"
#include "bezcam/cam/pass_plan.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"

using namespace bezcam;
using Clock = std::chrono::steady_clock;

namespace {

struct Row {
  std::string name;
  std::shared_ptr<const SurfaceGeometry> s;
  PassOptions o;
};

size_t blocks_of(const PassPlan& p) {
  size_t b = 0;
  for (const auto& x : p.passes) b += x.poly.points.size() - 1;
  return b;
}

template <class F>
double ms(F f, int reps) {
  const auto t0 = Clock::now();
  for (int i = 0; i < reps; ++i) f();
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / reps;
}

std::shared_ptr<const SurfaceGeometry> stretched() {
  // y(v) = 10 v + 90 v^3 over 100 mm (28x stretch near v = 1), a 10 mm
  // ridge in u over 50 mm.
  const double y[4] = {0, 10.0 / 3, 20.0 / 3, 100};
  const double x[3] = {0, 25, 50}, z[3] = {0, 10, 0};
  std::vector<std::vector<Vec3>> rows(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) rows[i].push_back({x[i], y[j], z[i]});
  return SurfaceGeometry::make(BezierPatch::make(rows));
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int reps = quick ? 1 : 3;
  const std::string dir = BEZCAM_SOURCE_DIR "/samples/";
  const char* files[] = {"patch-saddle.json", "patch-bonnet-bicubic.json", "patch-coons-curved.json",
                         "job-curve-on-surface.json"};
  std::vector<Row> rows;
  for (const char* f : files) {
    const Job job = load_job(dir + f);
    const Entity& e = job.entities[0];
    const MachineProfile m = load_machine_profile(job.machine.value_or("generic"));
    const CutParams cp = cut_params(job, e, m);
    PassOptions o;
    o.direction = e.toolpath.direction;
    o.stepover = *e.toolpath.stepover;
    o.tolerance = job.tolerance;
    o.decimals = m.decimals(job.units);
    o.tool_radius = cp.tool_radius;
    const std::string name = e.label() + " (" + m.name + ")";
    rows.push_back({name, e.surface, o});
    o.tool_radius = 0;
    rows.push_back({name, e.surface, o});
  }
  PassOptions so;
  so.stepover = 2;
  so.tolerance = 0.01;
  so.decimals = 3;
  rows.push_back({"stretched 28x (generic)", stretched(), so});

  std::printf("Surface passes: adaptive spacing (plan_passes) vs uniform parameter steps (plan_uniform_passes).\n");
  std::printf("Both verified: every pair of neighbouring printed passes within the stepover; every pass within\n");
  std::printf("the tolerance (proven bound, rounding included). Times are per patch, mean of %d run(s).\n\n", reps);
  std::printf("%-26s %5s %5s %6s | %7s %7s %8s %8s | %7s %7s %8s | %6s %6s\n", "patch", "r", "step", "tol", "passes",
              "blocks", "gap", "ms", "passes", "blocks", "ms", "passes", "blocks");
  std::printf("%-26s %5s %5s %6s | %34s | %25s | %13s\n", "", "", "", "", "adaptive", "uniform baseline",
              "uniform/adapt");
  for (const auto& r : rows) {
    PassPlan a, u;
    const double ta = ms([&] { a = plan_passes(*r.s, r.o); }, reps);
    const double tu = ms([&] { u = plan_uniform_passes(*r.s, r.o); }, reps);
    std::printf("%-26s %5g %5g %6g | %7zu %7zu %8.4f %8.1f | %7zu %7zu %8.1f | %6.2f %6.2f\n", r.name.c_str(),
                r.o.tool_radius, r.o.stepover, r.o.tolerance, a.passes.size(), blocks_of(a), a.gap_bound, ta,
                u.passes.size(), blocks_of(u), tu, double(u.passes.size()) / a.passes.size(),
                double(blocks_of(u)) / blocks_of(a));
  }

  std::printf("\nWhole conversion (parse, passes, gouge check, links, measurement, validation, G-code text):\n");
  std::printf("%-28s %8s %8s %10s %12s %12s\n", "sample", "blocks", "lines", "ms", "measured", "bound");
  for (const char* f : files) {
    ConvertResult res;
    const double t = ms(
        [&] {
          const Job job = load_job(dir + f);
          res = convert(job, load_machine_profile(job.machine.value_or("generic")), ConvertOptions{});
        },
        reps);
    size_t blocks = 0, lines = 0;
    for (const auto& e : res.program.entities) blocks += e.blocks;
    for (char ch : res.gcode) lines += ch == '\n';
    std::printf("%-28s %8zu %8zu %10.1f %12.5f %12.5f\n", f, blocks, lines, t, res.program.max_measured,
                res.program.max_bound);
  }

  std::printf("\nBlocks per pass by output mode (G-code lines of the surface entity's cutting moves / passes;\n");
  std::printf(
      "the first entity of each sample; arcs and nurbs plan their passes 4 tolerances closer, see "
      "docs/surfaces.md):\n");
  std::printf("%-28s %-9s %-6s %7s %8s %9s %10s %10s\n", "sample", "machine", "mode", "passes", "blocks", "per pass",
              "measured", "bound");
  struct Mode {
    const char* name;
    OutputMode mode;
    bool fanuc;
  };
  const Mode modes[] = {{"lines", OutputMode::lines, false},
                        {"arcs", OutputMode::arcs, false},
                        {"nurbs", OutputMode::nurbs, false},
                        {"lines", OutputMode::lines, true},
                        {"nurbs", OutputMode::nurbs, true}};
  for (const char* f : files) {
    const Job job = load_job(dir + f);
    for (const Mode& md : modes) {
      const MachineProfile m = load_machine_profile(md.fanuc ? "fanuc" : job.machine.value_or("generic"));
      ConvertOptions o;
      o.output = md.mode;
      const ConvertResult res = convert(job, m, o);
      const EntityReport& rep = res.program.entities[0];
      size_t passes = 0;
      for (const auto& mv : res.program.moves)
        if (const auto* c = std::get_if<Comment>(&mv.what); c && mv.entity == 0) passes += c->text.starts_with("pass ");
      if (passes == 0) passes = 1;
      std::printf("%-28s %-9s %-6s %7zu %8zu %9.1f %10.5f %10.5f\n", f, m.name.c_str(), md.name, passes, rep.blocks,
                  double(rep.blocks) / double(passes), rep.measured, rep.bound);
    }
  }
  return 0;
}
