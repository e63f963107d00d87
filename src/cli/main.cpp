// bezcam: the command-line front end. Thin: parsing options, mapping error
// families to exit codes (docs/cli.md): 0 success, 2 invalid input or usage,
// 3 I/O or connection failure, 4 the controller refused or lost the program.
#include <fcntl.h>
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
#include "bezcam/job/keys.hpp"
#include "bezcam/version.hpp"
#include "command.hpp"


namespace bezcam::cli {

std::vector<Command*>& commands() {
  static std::vector<Command*> list;
  return list;
}

bool stderr_is_tty() { return ::isatty(STDERR_FILENO) == 1; }

namespace {

[[noreturn]] void write_failed(const std::string& path, const std::string& what, int err) {
  throw IoError(errc::io_write, Place::at_file(path), what + ": " + std::strerror(err));
}

// Writes all of `data` to `fd`, checking every write (a device may take
// part of it, or refuse: /dev/full says "No space left on device").
void write_all(int fd, const std::string& path, std::string_view data) {
  size_t off = 0;
  while (off < data.size()) {
    const ssize_t n = ::write(fd, data.data() + off, data.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) write_failed(path, "write failed", n < 0 ? errno : EIO);
    off += static_cast<size_t>(n);
  }
}

// `path` with every symbolic link followed: a `current.nc` that points at
// the program of the day is written through, the link stays a link.
std::filesystem::path resolve_links(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) write_failed(path, "cannot read the symbolic link", ec.value());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  write_failed(path, "cannot follow the symbolic links", ELOOP);
}

// Anything but a regular file (a serial port for DNC, a FIFO, a terminal)
// is written through, never replaced.
void write_through(const std::string& path, const std::filesystem::path& target, const OutputProducer& produce) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) write_failed(path, "cannot open for writing", errno);
  try {
    produce([&](std::string_view piece) { write_all(fd, path, piece); });
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) write_failed(path, "write failed", errno);
}

// A regular file (or a new one): a temporary file beside it, renamed into
// place only when complete, with the mode and owner of the file it replaces.
void replace_regular(const std::string& path, const std::filesystem::path& target, const struct stat* old,
                     const OutputProducer& produce) {
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string tmpl = (dir / ("." + target.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) write_failed(path, "cannot create a file in " + dir.string(), errno);
  const auto fail = [&](const std::string& what) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmpl.c_str());
    write_failed(path, what, err);
  };
  try {
    // In pieces as they are made: the file is whole only when renamed.
    produce([&](std::string_view piece) { write_all(fd, path, piece); });
  } catch (...) {
    ::close(fd);
    ::unlink(tmpl.c_str());
    throw;
  }
  mode_t mode = 0;
  if (old) {
    mode = old->st_mode & 07777;
    // Keep the owner where we may (root writing a user's file); a user
    // cannot give a file away, and keeps it.
    if (::fchown(fd, old->st_uid, old->st_gid) != 0 && errno != EPERM) fail("cannot keep the owner");
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd, mode) != 0) fail("cannot set the mode");
  if (::fsync(fd) != 0) fail("write failed");
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmpl.c_str());
    write_failed(path, "write failed", err);
  }
  if (::rename(tmpl.c_str(), target.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmpl.c_str());
    write_failed(path, "cannot replace the file", err);
  }
}

}  // namespace

void write_output(const std::string& path, const OutputProducer& produce) {
  if (path == "-" || path.empty()) {
    produce([](std::string_view piece) {
      std::cout.write(piece.data(), static_cast<std::streamsize>(piece.size()));
      if (!std::cout) throw IoError(errc::io_write, Place::at_file("stdout"), "cannot write the program to standard output");
    });
    std::cout.flush();
    if (!std::cout) throw IoError(errc::io_write, Place::at_file("stdout"), "cannot write the program to standard output");
    return;
  }
  const std::filesystem::path target = resolve_links(path);
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) write_failed(path, "cannot write", errno);
    replace_regular(path, target, nullptr, produce);
    return;
  }
  if (S_ISDIR(st.st_mode)) throw IoError(errc::io_write, Place::at_file(path), "is a directory; give a file name for the output");
  if (S_ISREG(st.st_mode)) replace_regular(path, target, &st, produce);
  else write_through(path, target, produce);
}

void write_output(const std::string& path, const std::string& data) {
  write_output(path, [&](const OutputSink& out) { out(data); });
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
  if (place.setting && !place.option) {
    for (const auto& [setting, flag] : flags)
      if (*place.setting == setting) return e.with_option(flag);
    // A drawing's import settings (import/drawing.hpp): --set KEY, --layer.
    if (*place.setting == "layers") return e.with_option("--layer");
    if (place.setting->rfind("settings.", 0) == 0) return e.with_option("--set " + place.setting->substr(9));
  }
  return e;
}

// For `--tol 0.1`: the option of the command the user most likely meant (a
// unique prefix, or within a few edits), or "".
std::string option_meant(const CLI::App& cmd, const std::string& given) {
  const std::string name = given.substr(0, given.find('='));
  std::vector<std::string> longs;
  for (const CLI::Option* opt : cmd.get_options())
    for (const auto& l : opt->get_lnames()) longs.push_back("--" + l);
  std::vector<std::string> prefixed;
  for (const auto& l : longs)
    if (l.rfind(name, 0) == 0) prefixed.push_back(l);
  if (prefixed.size() == 1) return prefixed.front();
  std::vector<std::string_view> known(longs.begin(), longs.end());
  return bezcam::resembled_key(name, known).value_or("");
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
  // --help shows every option's default (timeouts, buffer, retries...).
  app.option_defaults()->always_capture_default(true);
  auto& cmds = cli::commands();
  std::sort(cmds.begin(), cmds.end(), [](auto* a, auto* b) { return a->name < b->name; });
  for (auto* c : cmds) c->app = c->add(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
      for (auto* c : cmds) {
        if (!c->app || !c->app->parsed()) continue;
        for (const auto& extra : c->app->remaining()) {
          if (extra.size() < 2 || extra[0] != '-') continue;
          if (const std::string meant = option_meant(*c->app, extra); !meant.empty()) {
            std::cerr << "bezcam: error: " << c->name << " has no option " << extra.substr(0, extra.find('='))
                      << ": did you mean " << meant << "?\n  (bezcam " << c->name << " --help lists its options)\n";
            return 2;
          }
        }
      }
    }
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
    // Independent refusals of the same input, each with its place.
    constexpr size_t kShown = 20;
    for (size_t i = 0; i < e.more().size() && i < kShown; ++i)
      std::cerr << "bezcam: error: " << e.more()[i].what() << "\n  (error id: " << e.more()[i].id() << ")\n";
    if (e.more().size() > kShown)
      std::cerr << "bezcam: error: ... and " << e.more().size() - kShown << " more refusals of the same input\n";
    return exit_status(e.family());
  } catch (const std::bad_alloc&) {
    std::cerr << "bezcam: error: out of memory; the input is too large for this machine\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bezcam: internal error: " << e.what() << "\n  (please report this with the input file)\n";
    return 70;
  }
}
