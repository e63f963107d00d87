// Bounded file reading (limits.hpp): a file larger than its limit is refused
// before it is read, so that a huge or endless input never fills memory.
#include "bezcam/limits.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {

std::string size_text(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 20)) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// `size` 0: not known (a pipe), only that it is over the limit.
[[noreturn]] void too_large(const std::filesystem::path& file, std::uintmax_t size, std::size_t max_bytes,
                            const std::string& what) {
  throw InputError(errc::limit_file_size, Place::at_file(file.string()),
                   "the " + what + " is " + (size ? size_text(size) + ", more" : std::string("more")) +
                       " than bezcam reads (" + size_text(max_bytes) +
                       ", docs/limits.md); split it into smaller files");
}

}  // namespace

std::string read_bounded(const std::filesystem::path& file, std::size_t max_bytes, const std::string& what) {
  // A regular file is measured first; a pipe or device is read up to one
  // byte past the limit.
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw IoError(errc::io_read, Place::at_file(file.string()), "is a directory; give the " + what);
  if (std::filesystem::is_regular_file(file, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (!ec && size > max_bytes) too_large(file, size, max_bytes, what);
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw IoError(errc::io_read, Place::at_file(file.string()),
                  "cannot open the " + what + ": " + std::strerror(err ? err : ENOENT));
  }
  std::string text;
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) too_large(file, 0, max_bytes, what);
  }
  if (in.bad()) throw IoError(errc::io_read, Place::at_file(file.string()), "error while reading the " + what);
  return text;
}

}  // namespace bezcam
