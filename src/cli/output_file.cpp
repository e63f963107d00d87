// Writing a command's output: atomically to a regular file, through
// symbolic links, devices and FIFOs, or to standard output.
#include "output_file.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

#include "bezcam/error.hpp"

namespace bezcam::cli {

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
      if (!std::cout)
        throw IoError(errc::io_write, Place::at_file("stdout"), "cannot write the program to standard output");
    });
    std::cout.flush();
    if (!std::cout)
      throw IoError(errc::io_write, Place::at_file("stdout"), "cannot write the program to standard output");
    return;
  }
  const std::filesystem::path target = resolve_links(path);
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) write_failed(path, "cannot write", errno);
    replace_regular(path, target, nullptr, produce);
    return;
  }
  if (S_ISDIR(st.st_mode))
    throw IoError(errc::io_write, Place::at_file(path), "is a directory; give a file name for the output");
  if (S_ISREG(st.st_mode))
    replace_regular(path, target, &st, produce);
  else
    write_through(path, target, produce);
}

void write_output(const std::string& path, const std::string& data) {
  write_output(path, [&](const OutputSink& out) { out(data); });
}

void require_output_extension(const std::string& path, const std::string& option,
                              std::initializer_list<std::string_view> exts, const std::string& writes) {
  const std::string given = std::filesystem::path(path).extension().string();
  if (given.empty()) return;
  std::string ext = given;
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  std::string names;
  for (std::string_view e : exts) {
    if (ext == e) return;
    names += (names.empty() ? "" : " or ") + std::string(e);
  }
  throw InputError(errc::usage_option, Place::at_option(option),
                   writes + ", and \"" + path + "\" names a " + given + " file; give a file name ending in " + names +
                       " (or without an extension)");
}

}  // namespace bezcam::cli
