#pragma once
// The stock options of verify and simulate: the box (--stock), the cell
// (--cell) and the memory limit (--memory-limit), read and refused the same
// way by both commands.
#include <cstddef>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/stock/dexel_grid.hpp"
#include "bezcam/verify/stock_cutter.hpp"

namespace bezcam::cli {

/// --stock x0,y0,z0,x1,y1,z1 in millimetres; refuses anything else
/// (stock.box, naming --stock). The box's extent is checked by the grid.
StockBox parse_stock_box(const std::string& text);

/// --memory-limit: a size such as 512MiB, 2GiB, 1.5GB or a number of
/// bytes; empty gives the default (kDefaultStockMemoryLimit). Refuses
/// anything else (usage.option, naming --memory-limit).
std::size_t parse_memory_limit(const std::string& text);

/// The cell when none is given: `tolerance_mm`, coarsened until the box
/// holds at most four million columns.
double default_stock_cell(const StockBox& box, double tolerance_mm);

/// The tools of a machine profile for the stock: tool Tn is a flat end
/// mill of the diameter register Dn holds (tool_diameters_mm, with
/// --tool-diameter applied); registers of diameter 0 hold no tool.
StockTools profile_stock_tools(const MachineProfile& m);

/// A refusal of the grid (stock.box, stock.cell, stock.memory) shown as
/// the option the user gives it with: the cell and the memory it needs
/// are --cell's, the box --stock's.
Error stock_option_error(const Error& e);

}  // namespace bezcam::cli
