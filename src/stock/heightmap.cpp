#include "bezcam/stock/heightmap.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "bezcam/error.hpp"

namespace bezcam {

std::string heightmap_npy(const DexelGrid& grid) {
  // Header: magic, version 1.0, a little-endian uint16 length, then the
  // dictionary padded with spaces and a newline so that the data starts at
  // a multiple of 64 bytes (NumPy's own alignment).
  std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(grid.ny()) + ", " +
                     std::to_string(grid.nx()) + "), }";
  const std::size_t prefix = 10;
  std::size_t total = prefix + dict.size() + 1;
  total = (total + 63) / 64 * 64;
  dict.append(total - prefix - dict.size() - 1, ' ');
  dict.push_back('\n');
  std::string out;
  out.reserve(total + grid.floors().size() * 8);
  out.append("\x93NUMPY", 6);
  out.push_back('\x01');
  out.push_back('\x00');
  const auto len = static_cast<std::uint16_t>(dict.size());
  out.push_back(static_cast<char>(len & 0xff));
  out.push_back(static_cast<char>(len >> 8));
  out += dict;
  for (double v : grid.floors()) {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    for (int b = 0; b < 8; ++b) out.push_back(static_cast<char>((u >> (8 * b)) & 0xff));
  }
  return out;
}

void write_heightmap_npy(const DexelGrid& grid, const std::string& path) {
  const std::string bytes = heightmap_npy(grid);
  bool opened = false;
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    opened = static_cast<bool>(f);
    if (f) f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (f && f.flush()) return;
  }
  std::error_code ec;
  if (opened) std::filesystem::remove(path, ec);  // a partial file
  throw IoError(errc::io_write, Place::at_file(path), "cannot write the heightmap");
}

}  // namespace bezcam
