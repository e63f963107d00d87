// The command a user runs, timed as a whole process: `bezcam convert` of
// the corpus (bench/corpus/cubics-10k.json) as one job (generic, lines,
// 0.01 mm, the independent measurement on), the program written to a
// temporary file. Prints the wall clock, the CPU time of all its threads
// (user and system) and its peak resident memory, as the kernel counts
// them for the child process (wait4). The program's size is printed too:
// the same job gives the same bytes on every machine.
//
//   build/convert_command [--quick] [--runs N] [CORPUS.json]
//
// --quick: the first 1,000 curves. --runs N: N runs, each printed (the
// least CPU time is the figure the load inflates least). Figures only:
// nothing is asserted (CI runs it on machines of any speed); the exit
// status is bezcam's when it fails.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "corpus_job.hpp"

namespace {

namespace fs = std::filesystem;

struct Run {
  double wall = 0, user = 0, sys = 0;
  long peak_kb = 0;
  int status = 0;
};

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); }

// Runs `argv` as a child process and returns its figures.
Run run(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  Run r;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    std::perror("convert_command: fork");
    std::exit(3);
  }
  if (pid == 0) {
    ::execv(argv[0], argv.data());
    std::perror("convert_command: exec");
    std::_Exit(127);
  }
  int status = 0;
  rusage ru{};
  if (::wait4(pid, &status, 0, &ru) != pid) {
    std::perror("convert_command: wait4");
    std::exit(3);
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.user = seconds(ru.ru_utime);
  r.sys = seconds(ru.ru_stime);
  r.peak_kb = ru.ru_maxrss;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::string corpus = BEZCAM_CORPUS;
  bool quick = false;
  int runs = 1;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    else
      corpus = argv[i];
  }
  std::ifstream in(corpus);
  if (!in) {
    std::fprintf(stderr, "convert_command: cannot read %s\n", corpus.c_str());
    return 3;
  }
  const size_t most = quick ? 1000 : SIZE_MAX;
  const nlohmann::json doc = nlohmann::json::parse(in);
  const size_t curves = std::min(most, doc["curves"].size());
  // bezcam beside this program (both are in the build folder's top).
  const fs::path bezcam = fs::canonical("/proc/self/exe").parent_path() / "bezcam";
  char tmpl[] = "/tmp/bezcam_convert_command.XXXXXX";
  if (!::mkdtemp(tmpl)) {
    std::perror("convert_command: mkdtemp");
    return 3;
  }
  const fs::path dir = tmpl;
  const fs::path job = dir / "corpus-job.json", out = dir / "corpus.nc";
  std::ofstream(job, std::ios::binary) << corpus_job_text(doc, most);

  std::printf("bezcam convert %s -o OUT.nc -q\ncorpus: %s, %zu curves%s; generic, lines, 0.01 mm\n\n",
              job.filename().c_str(), corpus.c_str(), curves, quick ? " (quick: the first 1,000)" : "");
  std::printf("| run | s (wall) | CPU s (user + sys) | user | sys | peak MB |\n|---:|---:|---:|---:|---:|---:|\n");
  int failed = 0;
  for (int k = 1; k <= runs && !failed; ++k) {
    const Run r = run({bezcam.string(), "convert", job.string(), "-o", out.string(), "-q"});
    if (r.status != 0) {
      std::fprintf(stderr, "convert_command: bezcam convert exited with status %d\n", r.status);
      failed = r.status;
      break;
    }
    std::printf("| %d | %.3f | %.3f | %.3f | %.3f | %.1f |\n", k, r.wall, r.user + r.sys, r.user, r.sys,
                static_cast<double>(r.peak_kb) / 1024);
  }
  if (!failed) {
    std::error_code ec;
    std::printf("\nprogram: %ju bytes%s\n", static_cast<std::uintmax_t>(fs::file_size(out, ec)),
                curves >= 10000 ? "; target: < 1 s wall on 2 cores and < 120 MB peak for 10,000 curves" : "");
  }
  fs::remove_all(dir);
  return failed;
}
