// bezcam: the command-line front end. Thin: parsing options, mapping error
// families to exit codes (docs/cli.md): 0 success, 2 invalid input or usage,
// 3 I/O or connection failure, 4 the controller refused or lost the program.
#include <unistd.h>

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "bezcam/error.hpp"
#include "bezcam/version.hpp"
#include "command.hpp"


namespace bezcam::cli {

std::vector<Command*>& commands() {
  static std::vector<Command*> list;
  return list;
}

bool stderr_is_tty() { return ::isatty(STDERR_FILENO) == 1; }

void write_output_atomically(const std::string& path, const std::string& data) {
  if (path == "-" || path.empty()) {
    std::cout << data << std::flush;
    if (!std::cout) throw IoError(errc::io_write, Place::at_file("stdout"), "cannot write the program to standard output");
    return;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (fs::is_directory(target)) throw IoError(errc::io_write, Place::at_file(path), "is a directory; give a file name for the output");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string tmpl = (dir / ("." + target.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw IoError(errc::io_write, Place::at_file(path), "cannot create a file in " + dir.string() + ": " + std::strerror(errno));
  size_t off = 0;
  while (off < data.size()) {
    const ssize_t n = ::write(fd, data.data() + off, data.size() - off);
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      ::unlink(tmpl.c_str());
      throw IoError(errc::io_write, Place::at_file(path), std::string("write failed: ") + std::strerror(err));
    }
    off += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(tmpl.c_str());
    throw IoError(errc::io_write, Place::at_file(path), std::string("write failed: ") + std::strerror(errno));
  }
  ::chmod(tmpl.c_str(), 0644);
  if (::rename(tmpl.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmpl.c_str());
    throw IoError(errc::io_write, Place::at_file(path), std::string("cannot replace the file: ") + std::strerror(err));
  }
}

}  // namespace bezcam::cli

namespace {
// The CLI's contract with scripts (docs/errors.md): the library says what
// kind of failure it was, the program turns that into a status.
// The library names the settings a caller passed (Place::setting); the
// program shows them as the options they came from.
bezcam::Error as_shown(const bezcam::Error& e) {
  static const std::pair<const char*, const char*> flags[] = {
      {"output", "--output"}, {"tolerance", "--tolerance"}, {"deviation", "--deviation"}};
  const auto& place = e.place();
  if (place.setting && !place.option)
    for (const auto& [setting, flag] : flags)
      if (*place.setting == setting) return e.with_option(flag);
  return e;
}

int exit_status(bezcam::ErrorFamily family) {
  switch (family) {
    case bezcam::ErrorFamily::input: return 2;
    case bezcam::ErrorFamily::io: return 3;
    case bezcam::ErrorFamily::controller: return 4;
  }
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace bezcam;
  CLI::App app{"bezcam: exact curves and surfaces (JSON) to CNC programs whose chord error is proven, "
               "streamed to controllers over Modbus TCP."};
  app.set_version_flag("--version", std::string("bezcam ") + kVersion);
  app.require_subcommand(1);
  auto& cmds = cli::commands();
  std::sort(cmds.begin(), cmds.end(), [](auto* a, auto* b) { return a->name < b->name; });
  for (auto* c : cmds) c->app = c->add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // Usage errors read like every other refusal: one sentence, then how
    // to find the right form.
    std::cerr << "bezcam: error: " << e.what()
              << "\n  (bezcam --help lists the commands, bezcam COMMAND --help their options)\n";
    return 2;
  }
  try {
    for (auto* c : cmds)
      if (c->app && c->app->parsed()) return c->run();
    return 2;
  } catch (const Error& error) {
    const Error e = as_shown(error);
    std::cerr << "bezcam: error: " << e.what() << "\n  (error id: " << e.id() << ")\n";
    return exit_status(e.family());
  } catch (const std::bad_alloc&) {
    std::cerr << "bezcam: error: out of memory; the input is too large for this machine\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bezcam: internal error: " << e.what() << "\n  (please report this with the input file)\n";
    return 70;
  }
}
