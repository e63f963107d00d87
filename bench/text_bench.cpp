// Text to G-code (docs/benchmarks.md, "Text"): a job of 100 glyphs (four
// lines of 25 letters, DejaVu Sans and Nimbus Sans, engraved on the line)
// converted by `bezcam convert` as a child process, its CPU time (user +
// system) as the user pays it; and apart, in this process, opening the
// fonts (fontconfig's configuration, FreeType's and HarfBuzz's faces) and
// outlining the 100 glyphs once the fonts are open.
//
//   build/text_bench [--rounds N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "bezcam/text/font_text.hpp"

namespace fs = std::filesystem;

namespace {

const char* kLines[] = {"QuartzJigsVexBoldNymph012", "SphinxOfBlackQuartzJudge9", "PackMyBoxWithFiveDozenJug",
                        "AVATAR-WAVE-Today-0123456"};
const char* kFonts[] = {"DejaVu Sans", "Nimbus Sans", "DejaVu Sans", "Nimbus Sans"};

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

// Runs `argv` and returns the child's CPU seconds (user + system); -1 when it fails.
double child_cpu(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage u{};
  if (wait4(pid, &status, 0, &u) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 5;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--rounds") == 0) rounds = std::max(1, std::atoi(argv[i + 1]));
  const fs::path exe = fs::read_symlink("/proc/self/exe").parent_path() / "bezcam";
  const fs::path dir = fs::temp_directory_path() / ("bezcam-text-bench-" + std::to_string(getpid()));
  fs::create_directories(dir);

  // In this process: the fonts opened (cold), then the glyphs outlined.
  std::vector<bezcam::TextSpec> specs;
  for (int k = 0; k < 4; ++k) {
    bezcam::TextSpec s;
    s.text = kLines[k];
    s.font = kFonts[k];
    s.size = 6;
    s.at = {0, -8.0 * k, 0};
    specs.push_back(s);
  }
  const double c0 = cpu_seconds();
  size_t glyphs = 0;
  for (int k = 0; k < 2; ++k) glyphs += bezcam::text::outline_text(specs[k]).size();
  const double cold = cpu_seconds() - c0;
  double warm = 1e9;
  for (int r = 0; r < rounds; ++r) {
    const double t = cpu_seconds();
    glyphs = 0;
    for (const auto& s : specs) glyphs += bezcam::text::outline_text(s).size();
    warm = std::min(warm, cpu_seconds() - t);
  }

  // The job, converted by the program as users run it.
  std::string job = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
  "job": {"feed": 800, "plunge_feed": 200, "safe_z": 3, "cut_z": -0.2, "side": "on"},
  "entities": [)";
  for (int k = 0; k < 4; ++k)
    job += std::string(k ? ",\n" : "\n") + R"(    {"id": "line)" + std::to_string(k) +
           R"(", "type": "text", "text": ")" + kLines[k] + R"(", "font": ")" + kFonts[k] +
           R"(", "size": 6, "at": [0, )" + std::to_string(-8 * k) + "]}";
  job += "\n  ]\n}\n";
  std::ofstream(dir / "text-100.json") << job;
  double convert = 1e9;
  for (int r = 0; r < rounds; ++r) {
    const double t = child_cpu(
        {exe.string(), "convert", (dir / "text-100.json").string(), "-o", (dir / "text-100.nc").string(), "-q"});
    if (t < 0) {
      std::fprintf(stderr, "text_bench: %s convert failed\n", exe.c_str());
      return 1;
    }
    convert = std::min(convert, t);
  }
  std::printf("text_bench: %zu glyphs (DejaVu Sans, Nimbus Sans), tolerance 0.01 mm, lines, best of %d\n", glyphs,
              rounds);
  std::printf("  bezcam convert, child process CPU (user + system): %.4f s (goal: under 0.1 s)\n", convert);
  std::printf("  in process: opening two fonts and outlining 50 glyphs cold: %.4f s\n", cold);
  std::printf("  in process: outlining %zu glyphs, fonts open: %.5f s\n", glyphs, warm);
  fs::remove_all(dir);
  return 0;
}
