#pragma once
#include <algorithm>
// Helpers for the link tests: child processes (the real bezcam executable)
// with readiness read from their stdout, never a sleep; in-process servers
// on ports the system chooses; programs and traces.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "support/files.hpp"

extern char** environ;

namespace bezcam::test {

/// A child process with stdout on a pipe (read line by line with a
/// timeout) and stderr in a file. Killed (SIGKILL) if still running when
/// destroyed.
class Child {
 public:
  Child(const std::vector<std::string>& args, const std::filesystem::path& stderr_file) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fds[1], 1);
    posix_spawn_file_actions_addopen(&fa, 2, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int rc = ::posix_spawn(&pid_, argv[0], &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    ::close(fds[1]);
    out_ = fds[0];
    if (rc != 0) {
      ::close(out_);
      throw std::runtime_error("cannot start " + args[0]);
    }
    stderr_file_ = stderr_file;
  }
  ~Child() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    if (out_ >= 0) ::close(out_);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  pid_t pid() const { return pid_; }

  /// The next line of stdout, or nothing at end of file or after `timeout`.
  std::optional<std::string> read_line(std::chrono::milliseconds timeout = std::chrono::milliseconds(10000)) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      if (const auto nl = buf_.find('\n'); nl != std::string::npos) {
        std::string line = buf_.substr(0, nl);
        buf_.erase(0, nl + 1);
        return line;
      }
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      pollfd p{out_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) return std::nullopt;
      char b[4096];
      const ssize_t n = ::read(out_, b, sizeof b);
      if (n <= 0) return std::nullopt;
      buf_.append(b, static_cast<std::size_t>(n));
    }
  }

  /// Everything left on stdout until the child closes it.
  std::string read_rest() {
    std::string all = buf_;
    buf_.clear();
    char b[4096];
    ssize_t n;
    while ((n = ::read(out_, b, sizeof b)) > 0) all.append(b, static_cast<std::size_t>(n));
    return all;
  }

  void signal(int sig) { ::kill(pid_, sig); }

  /// Waits for the exit; returns the exit status, or 128 + signal.
  int wait() {
    if (exited_) return status_;
    int st = 0;
    ::waitpid(pid_, &st, 0);
    exited_ = true;
    status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    return status_;
  }

  std::string stderr_text() const { return slurp(stderr_file_); }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::string buf_;
  bool exited_ = false;
  int status_ = -1;
  std::filesystem::path stderr_file_;
};

/// Result of a command run to completion.
struct Run {
  int status = -1;
  std::string out, err;
};

/// Runs a program (absolute path first) and waits for it.
inline Run run_command(const std::vector<std::string>& argv, const TempDir& dir) {
  static int counter = 0;
  Child c(argv, dir / ("stderr-" + std::to_string(++counter) + ".txt"));
  Run r;
  r.out = c.read_rest();
  r.status = c.wait();
  r.err = c.stderr_text();
  return r;
}

/// Runs the bezcam executable with `args` and waits for it.
inline Run run_bezcam(const std::vector<std::string>& args, const TempDir& dir) {
  std::vector<std::string> argv{BEZCAM_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_command(argv, dir);
}

/// The absolute path of a program on PATH, or "" when it is not installed.
inline std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string all = path ? path : "/usr/bin:/bin";
  std::size_t i = 0;
  while (i <= all.size()) {
    const auto j = all.find(':', i);
    const std::string d = all.substr(i, j == std::string::npos ? std::string::npos : j - i);
    const auto p = std::filesystem::path(d.empty() ? "." : d) / name;
    if (::access(p.c_str(), X_OK) == 0) return p.string();
    if (j == std::string::npos) break;
    i = j + 1;
  }
  return {};
}

/// `bezcam simulate --listen 127.0.0.1:PORT` as a child process; the port
/// (0: the system's choice) is read from the line it prints when ready.
class SimProcess {
 public:
  SimProcess(const TempDir& dir, std::vector<std::string> extra, std::uint16_t port = 0) {
    static int counter = 0;
    std::vector<std::string> argv{BEZCAM_EXE, "simulate", "--listen", "127.0.0.1:" + std::to_string(port)};
    argv.insert(argv.end(), extra.begin(), extra.end());
    // As fast as the CPU allows unless the test asks for machine pace.
    if (std::find(extra.begin(), extra.end(), "--time-scale") == extra.end()) {
      argv.push_back("--time-scale");
      argv.push_back("max");
    }
    child_ = std::make_unique<Child>(argv, dir / ("sim-stderr-" + std::to_string(++counter) + ".txt"));
    const auto line = child_->read_line();
    if (!line) throw std::runtime_error("the simulator did not become ready: " + child_->stderr_text());
    const auto colon = line->rfind(':', line->find(" (machine"));
    port_ = static_cast<std::uint16_t>(std::stoi(line->substr(colon + 1)));
  }
  std::uint16_t port() const { return port_; }
  Child& child() { return *child_; }
  /// SIGTERM, then the exit status.
  int stop() {
    child_->signal(SIGTERM);
    return child_->wait();
  }

 private:
  std::unique_ptr<Child> child_;
  std::uint16_t port_ = 0;
};

/// A G-code program of `lines` linear moves along a zig-zag, inside the
/// generic profile's travel, with the usual header and footer.
inline std::string zigzag_program(int lines) {
  std::string p = "%\nG21 G90 G17\nT1 M06\nS10000 M03\nG00 Z5.\nX0. Y0.\nG01 Z-1. F300.\n";
  char b[96];
  for (int i = 1; i <= lines; ++i) {
    std::snprintf(b, sizeof b, "X%d.%03d Y%d.%03d F1000.\n", i % 97, (i * 37) % 1000, (i * 7) % 53, (i * 11) % 1000);
    p += b;
  }
  p += "M05\nG00 Z5.\nM30\n%\n";
  return p;
}

/// The program's lines as the controller numbers them (1-based, no '\n').
inline std::vector<std::string> split_lines(const std::string& program) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < program.size()) {
    const auto nl = program.find('\n', i);
    out.push_back(program.substr(i, nl == std::string::npos ? std::string::npos : nl - i));
    if (nl == std::string::npos) break;
    i = nl + 1;
  }
  return out;
}

}  // namespace bezcam::test
