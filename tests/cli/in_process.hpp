#pragma once
// bezcam command lines run in this process (src/cli/run_command_line.hpp): the
// exit status and what the command printed on stdout and stderr, as
// testproc::run gives them for the executable, without starting it. For
// tests of options, refusals and exit statuses; what needs a real process
// (signals, streaming to the simulated controller, files replaced
// atomically) runs BEZCAM_EXE.
//
// Relative paths are taken from the working directory: the repository's
// root under ctest, as for the executable's tests.
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_command_line.hpp"
#include "support/run_process.hpp"

namespace bezcam::test {

/// Runs `bezcam ARGS...` in-process; `program` is argv[0] (the name in
/// --help's usage line). Progress is off, as BEZCAM_PROGRESS=off gives it
/// the executable's tests: nothing but the command's own lines is printed.
inline testproc::Result run_cli(const std::vector<std::string>& args, const std::string& program = "bezcam") {
  // std::cout and std::cerr into strings for the run, whatever it throws.
  struct Capture {
    std::ostringstream out, err;
    std::streambuf* old_out = std::cout.rdbuf(out.rdbuf());
    std::streambuf* old_err = std::cerr.rdbuf(err.rdbuf());
    std::optional<std::string> old_progress;
    Capture() {
      if (const char* p = std::getenv("BEZCAM_PROGRESS")) old_progress = p;
      ::setenv("BEZCAM_PROGRESS", "off", 1);
    }
    ~Capture() {
      std::cout.rdbuf(old_out);
      std::cerr.rdbuf(old_err);
      std::cout.clear();
      std::cerr.clear();
      if (old_progress)
        ::setenv("BEZCAM_PROGRESS", old_progress->c_str(), 1);
      else
        ::unsetenv("BEZCAM_PROGRESS");
    }
  };
  std::vector<std::string> argv{program};
  argv.insert(argv.end(), args.begin(), args.end());
  testproc::Result r;
  Capture capture;
  r.status = cli::run_command_line(argv);
  r.out = capture.out.str();
  r.err = capture.err.str();
  return r;
}

}  // namespace bezcam::test
