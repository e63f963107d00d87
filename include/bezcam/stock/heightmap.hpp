#pragma once
/// The floors as a NumPy array (.npy, format version 1.0): float64,
/// little-endian, C order, shape (ny, nx); row j holds the columns at
/// y = y0 + (j + 1/2) C from y0 upward, column i those at x = x0 + (i + 1/2) C.
/// `numpy.load()` reads it; the cell size and the origin travel beside it
/// (the verifier's report).
#include <string>

#include "bezcam/stock/dexel_grid.hpp"

namespace bezcam {

/// The file's bytes.
std::string heightmap_npy(const DexelGrid& grid);
/// Writes heightmap_npy() to `path`; IoError `io.write` naming the file
/// when it cannot be written (then nothing is left at `path`).
void write_heightmap_npy(const DexelGrid& grid, const std::string& path);

}  // namespace bezcam
