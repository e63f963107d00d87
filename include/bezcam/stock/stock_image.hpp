#pragma once
/// A picture of the machined stock: the floors as a shaded height map seen
/// from above (+y up), coloured by height from the deepest floor to the top
/// of the stock and lit from the north-west (a hillshade of the floors'
/// gradient), with classified columns drawn over it (gouges in alarm red,
/// excess in blue), a legend (the colours and the z range) and a scale bar
/// in millimetres. PNG (written with zlib) or SVG (the shaded map as an
/// embedded PNG, the legend as text and shapes).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bezcam/stock/dexel_grid.hpp"

namespace bezcam {

/// What a column is against a design (the verifier classifies them).
enum class ColumnClass : std::uint8_t { none = 0, gouge = 1, excess = 2 };

struct StockImageOptions {
  /// One class per column in the order of DexelGrid::floors(), or empty.
  std::span<const ColumnClass> classes;
  /// Largest side of the map in pixels: a larger grid is drawn with one
  /// pixel per block of columns (the block's lowest floor, a gouge before
  /// an excess). A small grid is drawn with several pixels per column.
  int max_side = 4096;
};

/// The PNG file's bytes (map and legend). Throws std::invalid_argument when
/// `classes` is neither empty nor one per column.
std::vector<std::uint8_t> stock_png(const DexelGrid& grid, const StockImageOptions& opt = {});
/// The SVG document.
std::string stock_svg(const DexelGrid& grid, const StockImageOptions& opt = {});
/// Write them; IoError `io.write` naming the file when it cannot be written
/// (then nothing is left at `path`).
void write_stock_png(const DexelGrid& grid, const std::string& path, const StockImageOptions& opt = {});
void write_stock_svg(const DexelGrid& grid, const std::string& path, const StockImageOptions& opt = {});

}  // namespace bezcam
