#pragma once
/// The machined stock as a Z-dexel grid: one floor height per column, at the
/// centre of each C x C cell of the stock box.
///
/// Column (i, j) has its centre at x = x0 + (i + 1/2) C, y = y0 + (j + 1/2) C,
/// for 0 <= i < nx, 0 <= j < ny; nx = ceil((x1 - x0) / C) (a quotient within
/// 1e-9 of a whole number counts as that number), likewise ny. Every floor
/// starts at z1, the top of the stock. Sweeping a tool along a move lowers
/// each column's floor to the lowest point of the swept tool over the
/// column's centre, never below z0 (a column cut through is empty).
///
/// The floors are exact: for every move and tool shape the lowest point is
/// found in closed form or by a certified search to machine precision, not
/// by sampling the move (docs/verify.md says which is which). Each floor is
/// the minimum over the moves, so the result does not depend on the order of
/// the moves nor on the number of threads.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bezcam/stock/sweep.hpp"
#include "bezcam/stock/tool_shape.hpp"

namespace bezcam {

/// The stock: the box x0 <= x <= x1, y0 <= y <= y1, z0 <= z <= z1.
struct StockBox {
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
};

/// The memory a grid may take unless the caller says otherwise: 1 GiB.
inline constexpr std::size_t kDefaultStockMemoryLimit = std::size_t{1} << 30;

/// The size of the grid of `box` at `cell`, and the memory it needs.
struct StockGridSize {
  std::size_t nx = 0, ny = 0;
  double bytes = 0;  ///< the floors (8 bytes a column) and the grid's own bookkeeping
};

/// The grid's size, without allocating anything. Refuses a box that is not
/// finite or has no extent (InputError `stock.box`, setting `box`) and a
/// cell that is not a finite number > 0 (`stock.cell`, setting `cell`).
StockGridSize stock_grid_size(const StockBox& box, double cell);

/// What the grid's cuts did (for benchmarks and the report's detail).
struct SweepStats {
  std::uint64_t columns = 0;           ///< column evaluations
  std::uint64_t searched_columns = 0;  ///< of them by the certified search (spirals, G18/G19, bull on arcs)
  std::uint64_t search_intervals = 0;  ///< intervals the search examined
  std::uint64_t depth_limited = 0;     ///< intervals it closed at a width of a few ulps
};

class DexelGrid {
 public:
  /// Refuses, before allocating, a grid that needs more than
  /// `memory_limit` bytes (InputError `stock.memory`, setting `cell`; the
  /// message gives the smallest cell that fits), besides what
  /// stock_grid_size() refuses.
  DexelGrid(const StockBox& box, double cell, std::size_t memory_limit = kDefaultStockMemoryLimit);

  /// Threads for cut() (0: one per hardware thread). The floors are the
  /// same for any count.
  void set_threads(unsigned n);
  unsigned threads() const { return threads_; }

  /// Sweeps `tool` along one move, or along each of `moves`.
  void cut(const Sweep& move, const ToolShape& tool);
  void cut(std::span<const Sweep> moves, const ToolShape& tool);

  const StockBox& box() const { return box_; }
  double cell() const { return cell_; }
  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  double x_center(std::size_t i) const { return box_.x0 + (static_cast<double>(i) + 0.5) * cell_; }
  double y_center(std::size_t j) const { return box_.y0 + (static_cast<double>(j) + 0.5) * cell_; }
  /// The floor of column (i, j).
  double floor(std::size_t i, std::size_t j) const { return floors_[j * nx_ + i]; }
  /// All floors, row by row (row j = y index, from y0 upward; x from x0).
  std::span<const double> floors() const { return floors_; }
  /// Bytes the grid holds.
  double memory_bytes() const;

  /// Sum over the columns of (z1 - floor) C^2: the removed volume in this
  /// model (exact for it; a column stands for its whole cell).
  double removed_volume() const;
  struct Deepest {
    double z = 0, x = 0, y = 0;
    std::size_t i = 0, j = 0;
  };
  /// The lowest floor and its column (the first in row order on a tie).
  Deepest deepest() const;
  /// FNV-1a (64 bits) over, as little-endian 64-bit integers, nx, ny and
  /// each floor in micrometres rounded to the nearest (llround(z * 1000),
  /// z in millimetres), row by row: the same on every platform with IEEE
  /// doubles. Equal hashes mean equal floors to 1 um.
  std::uint64_t hash() const;
  /// hash() as 16 lowercase hexadecimal digits.
  std::string hash_hex() const;
  /// The largest bound of the polylines swept so far (0 when every move was
  /// swept exactly): the machined surface is within it of the true path's.
  double added_error() const { return added_error_; }
  const SweepStats& stats() const { return stats_; }

 private:
  StockBox box_;
  double cell_ = 0;
  std::size_t nx_ = 0, ny_ = 0;
  std::vector<double> floors_;
  unsigned threads_ = 1;
  double added_error_ = 0;
  SweepStats stats_;
};

}  // namespace bezcam
