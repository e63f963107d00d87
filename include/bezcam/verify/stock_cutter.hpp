#pragma once
/// A program's executed motion cut into a stock: each motion block (as the
/// G-code reader executes it, machine/motion.hpp) swept with the tool in the
/// spindle through a Z-dexel grid (stock/dexel_grid.hpp).
///
/// Lengths of the stock, the cell and the tools are millimetres; blocks are
/// in the program's units and converted (a G20 program is scaled by 25.4).
/// The programmed position is the tool's tip. Lines and arcs (helices and
/// spirals included, G17, G18, G19) are swept exactly; NURBS and Bézier
/// blocks along bezcam's certified flattening, whose bound is the grid's
/// added_error(). Rapids are swept too: a rapid through material cuts it,
/// and the cutter counts the rapids that did.
#include <cstddef>
#include <map>
#include <vector>

#include "bezcam/job/tool_table.hpp"
#include "bezcam/kernel/units.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/stock/dexel_grid.hpp"

namespace bezcam {

/// The tools a program cuts with, by T number, in millimetres.
using StockTools = std::map<int, ToolShape>;

/// A tool table's entries (lengths in mm) as the shapes the stock sweeps.
StockTools stock_tools(const ToolTable& mm);
/// One entry (mm) as its shape.
ToolShape stock_tool_shape(const ToolEntry& mm);

/// The tool a block cut with tool number `tool` in the spindle sweeps: the
/// table's entry; tool 0 (none loaded) takes the table's only tool when it
/// has one. Refuses a tool the table lacks with InputError `verify.tool` at
/// line `line`, naming the tools it has.
const ToolShape& stock_tool(const StockTools& tools, int tool, int line);

/// The tool that sweeps block `b` cut with tool number `tool` in the
/// spindle: stock_tool(), except that a rapid sweeps nothing (nullptr) when
/// no tool is loaded and the table does not say which tool that is, or when
/// it starts from where the tool is not known (before the program has set
/// all three axes). Refuses a missing tool as stock_tool() does.
const ToolShape* swept_tool(const StockTools& tools, const MotionBlock& b, int tool);

/// The block in millimetres (points scaled from `units`; knots and weights
/// as they are).
MotionBlock block_in_mm(const MotionBlock& b, Units units);

struct StockCutterOptions {
  std::size_t memory_limit = kDefaultStockMemoryLimit;
  unsigned threads = 0;  ///< 0: one per hardware thread (the floors are the same for any count)
  /// The flattening tolerance for NURBS and Bézier blocks (mm): their
  /// polyline is within it of the block, and the bound is reported.
  double curve_tolerance_mm = 0.0005;
};

class StockCutter {
 public:
  /// Refuses a box, cell or memory limit as DexelGrid does (`stock.box`,
  /// `stock.cell`, `stock.memory`) before allocating anything.
  StockCutter(const StockBox& box_mm, double cell_mm, StockTools tools, const StockCutterOptions& opt = {});

  /// Sweeps one block (program units `units`) with tool number `tool`.
  /// Moves are gathered and swept in batches (in parallel over columns);
  /// grid() sweeps what is pending first.
  void cut(const MotionBlock& b, int tool, Units units);
  /// The grid with every block so far swept.
  const DexelGrid& grid();

  std::size_t blocks() const { return blocks_; }
  /// Rapids that lowered a floor (they moved through material) and the
  /// line of the first.
  std::size_t rapid_cuts() const { return rapid_cuts_; }
  int first_rapid_cut_line() const { return first_rapid_cut_line_; }

 private:
  void flush();
  bool rapid_cuts_material(const Sweep& s, const ToolShape& t);
  DexelGrid grid_;
  StockTools tools_;
  double curve_tolerance_ = 0;
  std::vector<Sweep> pending_;
  const ToolShape* pending_tool_ = nullptr;
  std::size_t blocks_ = 0, rapid_cuts_ = 0;
  int first_rapid_cut_line_ = 0;
};

}  // namespace bezcam
