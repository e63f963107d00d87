#include "bezcam/stock/heightmap.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>

#include "bezcam/error.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

DexelGrid sample_grid() {
  DexelGrid g({-3, 2, -5, 9, 10, 0.5}, 0.25);  // 48 x 32 columns
  g.cut(Sweep::line({-1, 4, -1}, {7, 8, -2.5}), ToolShape::ball(3));
  return g;
}

}  // namespace

TEST(Heightmap, NpyRoundTrip) {
  const DexelGrid g = sample_grid();
  const fs::path dir = fs::temp_directory_path() / ("bezcam_npy_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "h.npy";
  write_heightmap_npy(g, file.string());
  const std::string b = slurp(file);
  // header: magic, version 1.0, length, dictionary; data at a multiple of 64
  ASSERT_GT(b.size(), 10u);
  EXPECT_EQ(b.substr(0, 6), std::string("\x93NUMPY", 6));
  EXPECT_EQ(b[6], 1);
  EXPECT_EQ(b[7], 0);
  const std::size_t hlen = static_cast<unsigned char>(b[8]) | (static_cast<unsigned char>(b[9]) << 8);
  EXPECT_EQ((10 + hlen) % 64, 0u);
  const std::string header = b.substr(10, hlen);
  EXPECT_EQ(header.back(), '\n');
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      header, m, std::regex(R"(\{'descr': '<f8', 'fortran_order': False, 'shape': \((\d+), (\d+)\), \})")))
      << header;
  EXPECT_EQ(std::stoul(m[1]), g.ny());
  EXPECT_EQ(std::stoul(m[2]), g.nx());
  ASSERT_EQ(b.size(), 10 + hlen + g.nx() * g.ny() * 8);
  // values: little-endian float64, rows from y0 up, x from x0
  for (std::size_t j = 0; j < g.ny(); ++j)
    for (std::size_t i = 0; i < g.nx(); ++i) {
      std::uint64_t u = 0;
      for (int k = 0; k < 8; ++k)
        u |= static_cast<std::uint64_t>(static_cast<unsigned char>(b[10 + hlen + (j * g.nx() + i) * 8 + k])) << (8 * k);
      double v;
      std::memcpy(&v, &u, 8);
      ASSERT_EQ(v, g.floor(i, j)) << i << "," << j;
    }
  // NumPy reads it the same way, where Debian's python3-numpy is installed.
  if (std::system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") == 0) {
    const auto d = g.deepest();
    std::ostringstream py;
    py.precision(17);
    py << "/usr/bin/python3 -c 'import numpy, sys; a = numpy.load(\"" << file.string() << "\"); "
       << "assert a.dtype == numpy.float64 and a.shape == (" << g.ny() << ", " << g.nx() << "); "
       << "assert a[" << d.j << ", " << d.i << "] == " << d.z << " and a.min() == " << d.z << "; "
       << "assert a[0, 0] == " << g.floor(0, 0) << " and a[-1, -1] == " << g.floor(g.nx() - 1, g.ny() - 1) << "'";
    EXPECT_EQ(std::system(py.str().c_str()), 0) << py.str();
  }
  fs::remove_all(dir);
}

TEST(Heightmap, UnwritablePathIsAnIoErrorAndLeavesNothing) {
  const DexelGrid g = sample_grid();
  const fs::path bad = fs::temp_directory_path() / "bezcam_no_such_dir_x" / "h.npy";
  try {
    write_heightmap_npy(g, bad.string());
    ADD_FAILURE() << "written";
  } catch (const IoError& e) {
    EXPECT_EQ(e.id(), "io.write");
    EXPECT_EQ(e.where(), bad.string());
  }
  EXPECT_FALSE(fs::exists(bad));
}
