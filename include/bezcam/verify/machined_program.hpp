#pragma once
/// A program's executed motion (a timeline read from its text, with the
/// tool in the spindle for each block) cut into a stock
/// (verify/stock_cutter.hpp), and the stock it fills when none is given.
#include "bezcam/machine/planner.hpp"
#include "bezcam/verify/stock_cutter.hpp"

namespace bezcam {

/// The stock a program fills when none is given (millimetres): the box of
/// its feed moves (arcs and curves by their extent) grown sideways by the
/// radius of the largest tool it uses, from 1 mm below the deepest tip up to
/// the highest point of a feed move. `tl` is read from a program
/// (read_timeline(): one tool per block). Throws InputError `verify.empty`
/// when the program has no feed move, `verify.tool` as StockCutter does.
StockBox program_stock_box(const Timeline& tl, const StockTools& tools);

/// Refuses (InputError `verify.stock-outside`, setting `stock`) a stock box
/// that the tool of no feed move reaches: every one passes beside it, above
/// it or below it.
void check_stock_holds_program(const StockBox& box, const Timeline& tl, const StockTools& tools);

/// Sweeps every block of `tl` through `cutter`, each with its tool.
void cut_timeline(StockCutter& cutter, const Timeline& tl);

}  // namespace bezcam
