#include "bezcam/error.hpp"
#include "bezcam/sim/sim_controller.hpp"
#include "bezcam/sim/trace.hpp"

// The simulated controller's stock (ControllerConfig::stock): each executed
// move is swept with the tool in the spindle, in the program's units, as
// `bezcam verify` sweeps a program (verify/stock_cutter.hpp). Only the
// executor thread cuts; at machine pace the moves wait in stock_queue_
// until the machine has run them. Member functions of SimController.
namespace bezcam::sim {

void SimController::check_stock_tools(const std::vector<MotionBlock>& blocks, const MachineState& s) const {
  if (!stock_) return;
  for (const MotionBlock& b : blocks) (void)swept_tool(cfg_.stock->tools, b, s.tool);
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
