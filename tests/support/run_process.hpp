#pragma once
// Runs a program (the bezcam executable) for end-to-end tests: arguments
// without a shell, extra environment variables, stdout and stderr captured
// through temporary files, the exit status returned. Waits for the child by
// its pid; no sleeping.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "support/files.hpp"

extern char** environ;

namespace testproc {

struct Result {
  int status = -1;  ///< exit status, or 128 + signal
  std::string out, err;
  /// The first line of stderr, without its newline.
  std::string err_first_line() const { return err.substr(0, err.find('\n')); }
  std::string out_first_line() const { return out.substr(0, out.find('\n')); }
};

using bezcam::test::slurp;

/// Runs `exe` with `args` in `cwd` (empty: the current directory); `env`
/// entries are set (an empty value removes the variable).
inline Result run(const std::string& exe, const std::vector<std::string>& args,
                  const std::map<std::string, std::string>& env = {}, const std::string& cwd = {}) {
  namespace fs = std::filesystem;
  char tmpl[] = "/tmp/bezcam-run-XXXXXX";
  if (!::mkdtemp(tmpl)) throw std::runtime_error("mkdtemp failed");
  const fs::path dir(tmpl);
  const std::string out_path = (dir / "out").string(), err_path = (dir / "err").string();

  std::vector<std::string> envs;
  for (char** e = environ; *e; ++e) {
    const std::string kv = *e;
    if (!env.count(kv.substr(0, kv.find('=')))) envs.push_back(kv);
  }
  for (const auto& [k, v] : env)
    if (!v.empty()) envs.push_back(k + "=" + v);
  std::vector<char*> argv{const_cast<char*>(exe.c_str())}, envp;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (auto& e : envs) envp.push_back(e.data());
  envp.push_back(nullptr);

  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int o = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int e = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int n = ::open("/dev/null", O_RDONLY);
    if (o < 0 || e < 0 || n < 0) ::_exit(126);
    ::dup2(n, 0), ::dup2(o, 1), ::dup2(e, 2);
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::execve(exe.c_str(), argv.data(), envp.data());
    ::_exit(127);
  }
  int st = 0;
  while (::waitpid(pid, &st, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed");
  }
  Result r;
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  r.out = slurp(out_path);
  r.err = slurp(err_path);
  std::error_code ec;
  fs::remove_all(dir, ec);
  return r;
}

/// Runs `command` through /bin/sh (for pipes, redirections and cd); `out`
/// holds what it writes to stdout (add 2>&1 for stderr too), `status` its
/// exit status, or -1 when it did not exit normally.
inline Result shell(const std::string& command) {
  Result r;
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) throw std::runtime_error("popen failed: " + command);
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// Temporary folders and whole-file writes: the shared ones (files.hpp).
using bezcam::test::TempDir;
using bezcam::test::write_file;

}  // namespace testproc
