// Output modes compared on the curve samples: how many cutting blocks and
// G-code lines each of --output lines, arcs and nurbs takes per profile, the
// ratios to lines, the proven bound and the conversion time.
//
//   build/output_modes_bench            # markdown table on stdout
//   build/output_modes_bench --corpus [--quick] [CORPUS.json]
//     arcs output's blocks on the corpus of cubics
//     (bench/corpus/cubics-10k.json; --quick: every 10th curve) at 0.1, 0.01
//     and 0.001 mm, as given (planar) and lifted into ramps (G01 only),
//     with every span end on the curve and with the band
//     (ArcFitOptions::band), and the largest deviation measured
//     independently (deviation.hpp on the drawn path, arcs sampled to
//     1e-4 tol).
//
// Blocks: motion blocks as the G-code reader sees them (a NURBS block of n
// points is one); lines: the G-code lines a controller reads for them (a
// Fanuc block is n + rank lines, G5.2 n + 1, G5/G5.1 one). The plunge is
// not counted.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/sample_job.hpp"

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

// The corpus tables (see the top).
int corpus_arcs(const std::string& path, bool quick) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "output_modes_bench: cannot read %s\n", path.c_str());
    return 3;
  }
  const nlohmann::json doc = nlohmann::json::parse(in);
  // The curves as given (planar: arcs) and lifted into ramps, control point
  // i at z = i mm (not planar: G01 lines only).
  std::vector<Bezier> flat, ramps;
  const auto& cs = doc["curves"];
  for (size_t i = 0; i < cs.size(); ++i) {
    if (quick && i % 10) continue;
    std::vector<Vec3> pts, lifted;
    for (const auto& p : cs[i]) {
      pts.push_back({p[0].get<double>(), p[1].get<double>()});
      lifted.push_back({p[0].get<double>(), p[1].get<double>(), static_cast<double>(lifted.size())});
    }
    flat.push_back(Bezier::make(pts));
    ramps.push_back(Bezier::make(lifted, {}, 3));
  }
  std::printf("corpus: %s, %zu curves%s; arcs output (G02/G03, G01 where no arc fits), no rounding\n", path.c_str(),
              flat.size(), quick ? " (quick: every 10th)" : "");
  for (const auto* curves : {&flat, &ramps}) {
    std::printf("\n%s\n\n", curves == &flat ? "planar curves (arcs; the band leaves them as they are):"
                                            : "the same lifted into ramps (G01 only; the band's lines):");
    std::printf(
        "| tol mm | on-curve blocks | band blocks | band / on-curve | arcs on / band | max dev / tol on / band | "
        "curves over tol | s on / band |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (double tol : {0.1, 0.01, 0.001}) {
      size_t blocks[2] = {0, 0}, arcs[2] = {0, 0}, over = 0;
      double worst[2] = {0, 0}, secs[2] = {0, 0};
      for (int k = 0; k < 2; ++k) {
        ArcFitOptions o{tol, -1, 0.002};
        o.band = k == 1;
        std::vector<ArcFitResult> rs;
        rs.reserve(curves->size());
        const auto t0 = std::chrono::steady_clock::now();
        for (const auto& b : *curves) rs.push_back(fit_arcs(std::span(&b, 1), o));
        secs[k] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        for (size_t i = 0; i < curves->size(); ++i) {
          const auto& r = rs[i];
          std::vector<Vec3> poly{r.start};
          Vec3 from = r.start;
          for (const auto& m : r.moves) {
            ++blocks[k];
            if (m.kind == FitKind::line) {
              poly.push_back(m.to);
            } else {
              ++arcs[k];
              const auto pts = sample_arc(PrintedArc{from, m.to, m.center, m.kind == FitKind::arc_ccw}, 1e-4 * tol);
              poly.insert(poly.end(), pts.begin() + 1, pts.end());
            }
            from = m.to;
          }
          const double d = measure_deviation(std::span(&(*curves)[i], 1), poly, tol).max();
          over += d > tol;
          worst[k] = std::max(worst[k], d / tol);
        }
      }
      std::printf("| %g | %zu | %zu | %.3f | %zu / %zu | %.5f / %.5f | %zu | %.2f / %.2f |\n", tol, blocks[0],
                  blocks[1], ratio(blocks[1], blocks[0]), arcs[0], arcs[1], worst[0], worst[1], over, secs[0], secs[1]);
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && !std::strcmp(argv[1], "--corpus")) {
    bool quick = false;
    std::string corpus = BEZCAM_CORPUS;
    for (int i = 2; i < argc; ++i) {
      if (!std::strcmp(argv[i], "--quick"))
        quick = true;
      else
        corpus = argv[i];
    }
    return corpus_arcs(corpus, quick);
  }
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(BEZCAM_SOURCE_DIR "/samples")) {
    const std::string n = e.path().filename().string();
    if (e.path().extension() == ".json" && (n.rfind("curve-", 0) == 0 || n.rfind("path-", 0) == 0))
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  const char* profiles[] = {"generic", "fanuc", "linuxcnc"};
  const OutputMode modes[] = {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs};
  std::printf(
      "| sample | profile | lines | arcs (lines, ratio) | nurbs (lines, ratio) | bound lines / arcs / nurbs | ms lines "
      "/ arcs / nurbs |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  std::map<std::string, std::array<Count, 3>> totals;
  for (const auto& f : files) {
    const Job job = test::load_sample(f);
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
          const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
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
                  f.stem().c_str(), p, c[0].lines, c[1].blocks, c[1].lines, ratio(c[1].lines, c[0].lines), c[2].blocks,
                  c[2].lines, ratio(c[2].lines, c[0].lines), c[0].bound, c[1].bound, c[2].bound, c[0].ms, c[1].ms,
                  c[2].ms);
    }
  }
  std::printf(
      "\nTotals (G-code lines that cut; ratio to lines):\n\n| profile | lines | arcs | nurbs | ms lines / arcs / nurbs "
      "|\n|---|---|---|---|---|\n");
  for (const auto& [p, t] : totals)
    std::printf("| %s | %zu | %zu (%.2f) | %zu (%.2f) | %.0f / %.0f / %.0f |\n", p.c_str(), t[0].lines, t[1].lines,
                ratio(t[1].lines, t[0].lines), t[2].lines, ratio(t[2].lines, t[0].lines), t[0].ms, t[1].ms, t[2].ms);
  return 0;
}
