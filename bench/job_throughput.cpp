// Whole-job throughput on the corpus (bench/corpus/cubics-10k.json)
// as one job: 10,000 cubic Béziers, generic profile, lines, 0.01 mm, the
// independent measurement on (what `bezcam convert` does). Prints curves/s
// of each stage and of the whole process, and the peak memory (of the
// whole process on its own too).
//
// The real binary on the same job: `build/job_throughput --job FILE`
// writes the job file, then
//   /usr/bin/time -v build/bezcam convert FILE -o OUT.nc -q
//
//   build/job_throughput [--quick] [--job FILE] [CORPUS.json]
//
// --quick: the first 1,000 curves. Figures only: nothing is asserted
// (CI runs it on machines of any speed).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <vector>

#include "bezcam/bezcam.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/report/report.hpp"
#include "corpus_job.hpp"

namespace {

using clk = std::chrono::steady_clock;

// The process's CPU time (every thread, user and system), in seconds: on a
// machine shared with other work, the figure the load does not inflate.
double cpu_s() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
         1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

double g_cpu0 = 0;
clk::time_point start() {
  g_cpu0 = cpu_s();
  return clk::now();
}
struct Lap {
  double wall, cpu;
};
Lap since(clk::time_point t0) { return {std::chrono::duration<double>(clk::now() - t0).count(), cpu_s() - g_cpu0}; }

// Peak resident memory (VmHWM) in kB; reset_peak_rss() starts it again
// from the current size (Linux: clear_refs 5).
long peak_rss_kb() {
  std::ifstream f("/proc/self/status");
  for (std::string line; std::getline(f, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss;
}

void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

void row(const char* stage, size_t curves, Lap s, const char* note = "") {
  std::printf("| %s | %.3f | %.3f | %.0f | %s |\n", stage, s.wall, s.cpu, s.wall > 0 ? curves / s.wall : 0.0, note);
}

}  // namespace

int main(int argc, char** argv) {
  std::string corpus = BEZCAM_CORPUS;
  bool quick = false;
  std::string job_file;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--job") && i + 1 < argc)
      job_file = argv[++i];
    else
      corpus = argv[i];
  }
  std::ifstream in(corpus);
  if (!in) {
    std::fprintf(stderr, "job_throughput: cannot read %s\n", corpus.c_str());
    return 3;
  }
  const nlohmann::json doc = nlohmann::json::parse(in);
  const std::string text = corpus_job_text(doc, quick ? 1000 : SIZE_MAX);
  if (!job_file.empty()) {
    std::ofstream(job_file, std::ios::binary) << text;
    std::printf("job_throughput: wrote the job to %s\n", job_file.c_str());
    return 0;
  }
  const bezcam::MachineProfile m =
      bezcam::load_machine_profile(std::string(BEZCAM_SOURCE_DIR) + "/machines/generic.json", {});
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "bezcam_job_throughput.nc";

  // Stages, each on its own.
  auto t = start();
  const bezcam::Job job = bezcam::parse_job(text, "corpus.json");
  const Lap parse_s = since(t);
  const size_t n = job.entities.size();

  bezcam::ConvertOptions unmeasured;
  unmeasured.measure = false;
  t = start();
  const bezcam::Program flat = bezcam::build_program(job, m, unmeasured);
  const Lap flatten_s = since(t);

  // The measurement, one thread, on the polylines the program cuts.
  std::vector<std::vector<bezcam::Vec3>> polys(n);
  for (size_t i = 0; i < n; ++i)
    bezcam::flatten_into(job.entities[i].curve.pieces, {job.tolerance, m.decimals(job.units)}, polys[i]);
  double worst = 0;
  t = start();
  for (size_t i = 0; i < n; ++i)
    worst = std::max(worst, bezcam::measure_deviation(job.entities[i].curve.pieces, polys[i], job.tolerance).max());
  const Lap measure_s = since(t);

  // The plan on the machine's motion model (the header's cycle time and
  // the report's planned figures), as convert_program() makes it.
  t = start();
  std::optional<bezcam::MotionPlan> plan;
  if (m.motion) plan = bezcam::plan_motion(bezcam::program_timeline(flat), *m.motion, bezcam::PlanDetail::summary);
  const Lap plan_s = since(t);

  // The text, streamed to a file in pieces as it is printed.
  bezcam::GcodeCounts counts;
  t = start();
  {
    std::ofstream f(out, std::ios::binary);
    bezcam::write_gcode(flat, m, plan ? &*plan : nullptr, [&](std::string_view piece) {
      counts.add(piece);
      f.write(piece.data(), static_cast<std::streamsize>(piece.size()));
    });
  }
  const Lap write_s = since(t);
  t = start();
  const bezcam::ProgramReport stage_report = bezcam::make_report(flat, m, counts, plan ? &*plan : nullptr, nullptr);
  const Lap report_s = since(t);
  if (stage_report.entities.size() != n) std::printf("unexpected report\n");
  polys = {};
  const long stages_peak_mb = peak_rss_kb() / 1024;

  // The whole process as `bezcam convert JOB -o OUT` runs it, through the
  // same library calls: read, build with the measurement on every core
  // (overlapping the build), validate and plan (overlapping the last
  // measurements), then the text streamed to the file with the report made
  // on the way (its motion totals on another core). Its own peak memory:
  // the peak is reset first (the stages above held their own copies).
  reset_peak_rss();
  const long base_mb = peak_rss_kb() / 1024;
  t = start();
  {
    const bezcam::Job j = bezcam::parse_job(text, "corpus.json");
    const bezcam::ConvertResult r = bezcam::convert_program(j, m, {});
    std::ofstream f(out, std::ios::binary);
    const bezcam::ProgramReport rep = bezcam::write_and_report(
        r.program, m, r.plan ? &*r.plan : nullptr,
        [&](std::string_view piece) { f.write(piece.data(), static_cast<std::streamsize>(piece.size())); });
    if (rep.entities.size() != n || rep.gcode_lines != counts.lines()) std::printf("unexpected report\n");
  }
  const Lap whole_s = since(t);
  const long whole_peak_mb = peak_rss_kb() / 1024;
  std::filesystem::remove(out);

  std::printf("corpus: %s, %zu curves%s; generic, lines, 0.01 mm; %u hardware threads\n\n", corpus.c_str(), n,
              quick ? " (quick: the first 1,000)" : "", std::thread::hardware_concurrency());
  std::printf("| stage | s (wall) | CPU s (all threads) | curves/s (wall) | |\n|---|---:|---:|---:|---|\n");
  row("parse (job JSON text to Job)", n, parse_s);
  row("flatten (build_program, measurement off)", n, flatten_s);
  row("measure (measure_deviation, one thread)", n, measure_s, "");
  row("plan (motion model, summary)", n, plan_s);
  row("write (G-code text streamed to a file)", n, write_s);
  row("report (make_report from the counts)", n, report_s);
  row("whole process (read, build, measure on every core, validate, plan, write, report; overlapped)", n, whole_s,
      n >= 10000 ? "target: < 1 s for 10,000" : "");
  std::printf("\n%zu program lines, %zu bytes; largest deviation measured %.6f mm\n", counts.lines(), counts.bytes,
              worst);
  std::printf("peak memory: %ld MB with the stages above; whole process %ld MB (%ld MB before it)\n", stages_peak_mb,
              whole_peak_mb, base_mb);
  return 0;
}
