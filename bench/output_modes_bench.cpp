// Output modes compared on the curve samples: how many cutting blocks and
// G-code lines each of --output lines, arcs and nurbs takes per profile, the
// ratios to lines, the proven bound and the conversion time.
//
//   build/output_modes_bench            # markdown table on stdout
//
// Blocks: motion blocks as the G-code reader sees them (a NURBS block of n
// points is one); lines: the G-code lines a controller reads for them (a
// Fanuc block is n + rank lines, G5.2 n + 1, G5/G5.1 one). The plunge is
// not counted.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

struct Count {
  size_t blocks = 0, lines = 0;
  double bound = 0, ms = 0;
};

// Cutting blocks and lines: every feed block after the first of each run
// between rapids (the plunge).
Count count(const std::string& gcode, const MachineProfile& m) {
  Count c;
  bool plunged = false;
  for (const auto& b : read_gcode(gcode, &m)) {
    if (b.kind == BlockKind::rapid) {
      plunged = false;
      continue;
    }
    if (!plunged) {
      plunged = true;
      continue;
    }
    ++c.blocks;
    c.lines += static_cast<size_t>(b.line - b.first_line + 1);
  }
  return c;
}

double ratio(size_t a, size_t b) { return static_cast<double>(a) / static_cast<double>(b); }

}  // namespace

int main() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(BEZCAM_SOURCE_DIR "/samples")) {
    const std::string n = e.path().filename().string();
    if (e.path().extension() == ".json" && (n.rfind("curve-", 0) == 0 || n.rfind("path-", 0) == 0)) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  const char* profiles[] = {"generic", "fanuc", "linuxcnc"};
  const OutputMode modes[] = {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs};
  std::printf("| sample | profile | lines | arcs (lines, ratio) | nurbs (lines, ratio) | bound lines / arcs / nurbs | ms lines / arcs / nurbs |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  std::map<std::string, std::array<Count, 3>> totals;
  for (const auto& f : files) {
    const Job job = load_job(f);
    for (const char* p : profiles) {
      const MachineProfile m = load_machine_profile(p);
      std::array<Count, 3> c;
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        ConvertOptions o;
        o.output = modes[k];
        o.measure = false;
        try {
          const auto t0 = std::chrono::steady_clock::now();
          const ConvertResult r = convert(job, m, o);
          const double ms =
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          c[k] = count(r.gcode, m);
          c[k].bound = r.program.max_bound;
          c[k].ms = ms;
        } catch (const Error&) {
          ok = false;  // the machine refuses the job (travel, decimals): not compared
        }
      }
      if (!ok || c[0].lines == 0) continue;
      for (int k = 0; k < 3; ++k) {
        totals[p][k].blocks += c[k].blocks;
        totals[p][k].lines += c[k].lines;
        totals[p][k].ms += c[k].ms;
      }
      std::printf("| %s | %s | %zu | %zu (%zu, %.2f) | %zu (%zu, %.2f) | %.4f / %.4f / %.4f | %.1f / %.1f / %.1f |\n",
                  f.stem().c_str(), p, c[0].lines, c[1].blocks, c[1].lines, ratio(c[1].lines, c[0].lines),
                  c[2].blocks, c[2].lines, ratio(c[2].lines, c[0].lines), c[0].bound, c[1].bound, c[2].bound,
                  c[0].ms, c[1].ms, c[2].ms);
    }
  }
  std::printf("\nTotals (G-code lines that cut; ratio to lines):\n\n| profile | lines | arcs | nurbs | ms lines / arcs / nurbs |\n|---|---|---|---|---|\n");
  for (const auto& [p, t] : totals)
    std::printf("| %s | %zu | %zu (%.2f) | %zu (%.2f) | %.0f / %.0f / %.0f |\n", p.c_str(), t[0].lines, t[1].lines,
                ratio(t[1].lines, t[0].lines), t[2].lines, ratio(t[2].lines, t[0].lines), t[0].ms, t[1].ms,
                t[2].ms);
  return 0;
}
