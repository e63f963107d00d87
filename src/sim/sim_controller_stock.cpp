#include "bezcam/error.hpp"
#include "bezcam/sim/sim_controller.hpp"
#include "bezcam/sim/trace.hpp"

// The simulated controller's stock (ControllerConfig::stock): each executed
// move is swept with the tool in the spindle, in the program's units, as
// `bezcam verify` sweeps a program (verify/stock_cutter.hpp). Only the
// executor thread cuts; at machine pace the moves wait in stock_queue_
// until the machine has run them. Member functions of SimController.
namespace bezcam::sim {

namespace {

// StockCutter::cut() sweeps nothing for a rapid with no tool loaded when
// the table does not say which tool that is; every other move needs its
// tool in the table.
bool needs_tool(const MotionBlock& b, int tool, const StockTools& tools) {
  return !(b.kind == BlockKind::rapid && tool == 0 && tools.size() != 1 && !tools.count(0));
}

}  // namespace

void SimController::check_stock_tools(const std::vector<MotionBlock>& blocks, const MachineState& s) const {
  if (!stock_) return;
  for (const MotionBlock& b : blocks)
    if (needs_tool(b, s.tool, cfg_.stock->tools)) (void)stock_tool(cfg_.stock->tools, s.tool, b.line);
}

std::vector<SimController::StockMove> SimController::stock_moves(const std::vector<MotionBlock>& blocks,
                                                                 const MachineState& s) const {
  std::vector<StockMove> out;
  if (!stock_) return out;
  out.reserve(blocks.size());
  for (const MotionBlock& b : blocks) out.push_back({b, s.tool, s.units});
  return out;
}

void SimController::cut_stock(const std::vector<MotionBlock>& blocks, const MachineState& s) {
  if (!stock_) return;
  check_stock_tools(blocks, s);
  for (const MotionBlock& b : blocks) stock_->cut(b, s.tool, s.units);
}

void SimController::cut_moves(const std::vector<StockMove>& moves) {
  for (const StockMove& m : moves) stock_->cut(m.block, m.tool, m.units);
}

std::vector<SimController::StockMove> SimController::take_stock_locked() {
  std::vector<StockMove> out;
  out.swap(stock_queue_);
  return out;
}

std::string SimController::stock_record(const std::vector<StockMove>& moves) {
  if (!stock_) return {};
  cut_moves(moves);
  return trace_stock(stock_->grid());
}

}  // namespace bezcam::sim
