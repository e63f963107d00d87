// `bezcam verify` as users run it, on the program of the contract's speed
// target: a G01 raster of 100,000 blocks over 100 x 100 mm with a 6 mm
// ball end, verified at 0.05 mm cells (4 million columns). Runs the
// command as a child process and prints its wall time, its CPU time (all
// threads), its peak memory and the column evaluations per second its
// report gives. The targets: under 10 s, within 1 GiB.
//
//   build/verify_bench            the full program (the test command's run)
//   build/verify_bench --quick    20 x 20 mm, 4,000 blocks
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Passes along X at y = 0.5, 1.5, ... (stepover 1 mm), alternating, in
// blocks of 0.1 mm at z = -1, with the 1 mm step between passes.
std::string raster_program(int size) {
  std::ostringstream o;
  o << "%\nG21 G90 G17\nT1 M6\nS12000 M3\nG0 Z5\nG0 X0 Y0.5\nG1 Z-1 F300\nF3000\n";
  const int blocks = size * 10;
  char buf[64];
  for (int p = 0; p < size; ++p) {
    for (int b = 1; b <= blocks; ++b) {
      const double x = p % 2 == 0 ? b * 0.1 : size - b * 0.1;
      std::snprintf(buf, sizeof buf, "G1 X%.1f\n", x);
      o << buf;
    }
    if (p + 1 < size) {
      std::snprintf(buf, sizeof buf, "G1 Y%.1f\n", p + 1.5);
      o << buf;
    }
  }
  o << "G0 Z5\nM5\nM30\n%\n";
  return o.str();
}

// A number after `"key": ` in the report.
double report_number(const std::string& text, const std::string& key) {
  const auto at = text.find("\"" + key + "\": ");
  return at == std::string::npos ? -1 : std::strtod(text.c_str() + at + key.size() + 4, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int size = quick ? 20 : 100;
  const fs::path exe = fs::canonical("/proc/self/exe").parent_path() / "bezcam";
  const fs::path dir = fs::temp_directory_path() / ("bezcam-verify-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string program = raster_program(size);
  std::ofstream(dir / "raster.nc") << program;
  std::ofstream(dir / "tools.json") << R"({"1": {"shape": "ball", "diameter": 6}})";
  const std::string box = "-4,-4,-3," + std::to_string(size + 4) + "," + std::to_string(size + 4) + ",0";
  std::vector<std::string> args{exe.string(),
                                "verify",
                                (dir / "raster.nc").string(),
                                "--tools",
                                (dir / "tools.json").string(),
                                "--stock",
                                box,
                                "--cell",
                                "0.05",
                                "--report",
                                (dir / "r.json").string(),
                                "-q"};
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> av;
    for (auto& a : args) av.push_back(a.data());
    av.push_back(nullptr);
    ::execv(av[0], av.data());
    std::_Exit(127);
  }
  int status = 0;
  rusage ru{};
  ::wait4(pid, &status, 0, &ru);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::stringstream rep;
  rep << std::ifstream(dir / "r.json").rdbuf();
  fs::remove_all(dir);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "verify_bench: bezcam verify failed (status %d)\n", status);
    return 1;
  }
  const double cpu = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                     1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  const double evals = report_number(rep.str(), "all"), mem = report_number(rep.str(), "memory_bytes");
  std::size_t lines = 0;
  for (char c : program) lines += c == '\n';
  std::printf("bezcam verify, %d x %d mm G01 raster (%zu lines), 6 mm ball, 0.05 mm cells:\n", size, size, lines);
  const std::string r = rep.str();
  const auto cols = r.find("\"columns\": [");
  char* end = nullptr;
  const double nx = cols == std::string::npos ? 0 : std::strtod(r.c_str() + cols + 12, &end);
  const double ny = end ? std::strtod(end + 1, nullptr) : 0;
  std::printf("  blocks %.0f, columns %.0f x %.0f = %.2f million, grid %.1f MiB\n", report_number(r, "blocks"), nx, ny,
              nx * ny / 1e6, mem / (1 << 20));
  std::printf("  wall %.2f s (target < 10 s), CPU %.2f s, peak memory %.0f MiB (target < 1024 MiB)\n", wall, cpu,
              static_cast<double>(ru.ru_maxrss) / 1024.0);
  std::printf("  %.0f million column evaluations, %.0f million per CPU second\n", evals / 1e6, evals / 1e6 / cpu);
  return 0;
}
