#include <algorithm>
#include <climits>
#include <limits>

#include "bezcam/error.hpp"
#include "bezcam/sim/sim_controller.hpp"
#include "bezcam/sim/trace.hpp"

// The simulated controller at machine pace (ControllerConfig::time_scale):
// the executor reads lines ahead into the machine's look-ahead window
// (MachinePace), and what is reported (status registers, the trace, an
// alarm's line, DONE) is what the machine has done by now. Member functions
// of SimController; the lock is held on entry unless a function says
// otherwise.
namespace bezcam::sim {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

double SimController::pace_now() const {
  return std::chrono::duration<double>(Clock::now() - pace_origin_).count() * cfg_.time_scale;
}

void SimController::reset_paced_locked() {
  pace_started_ = pace_stalled_ = false;
  ahead_.clear();
  settled_ = last_block_line_ = 0;
  retired_settled_ = -1;
  failure_.reset();
  interp_finished_ = false;
}

bool SimController::paced_locked() const {
  return pace_ && pace_started_ && !stop_ && (state_ == State::receiving || state_ == State::finishing);
}

SimController::MachineView SimController::view_locked(double t) const {
  const MachinePace::Progress pr = pace_->progress(t);
  const long open = pr.open_line == INT_MAX ? std::numeric_limits<long>::max() : pr.open_line;
  MachineView v;
  v.state = machine_;
  v.lines = lines_done_;
  v.blocks = static_cast<long>(pr.blocks_done);
  v.done_line = std::min(settled_, open - 1);
  for (const Ahead& a : ahead_) {
    if (a.line <= v.done_line) {
      v.state = a.after;
      v.lines += a.counts ? 1 : 0;
      continue;
    }
    // The line in progress: its modal changes (spindle, coolant, feed,
    // tool) come before its motion.
    if (a.line == open) v.state = a.after;
    break;
  }
  v.reached = open == v.done_line + 1 ? open : v.done_line;
  v.state.pos = pr.pos;
  return v;
}

std::string SimController::retire_locked(double t, bool all) {
  const MachineView v = view_locked(t);
  std::string text;
  while (!ahead_.empty() && (all || ahead_.front().line <= v.done_line)) {
    Ahead& a = ahead_.front();
    text += a.trace;
    for (StockMove& m : a.cuts) stock_queue_.push_back(std::move(m));
    lines_done_ += a.counts ? 1 : 0;
    machine_ = std::move(a.after);
    ahead_.pop_front();
  }
  blocks_done_ = v.blocks;
  pace_->forget(t);
  retired_settled_ = settled_;
  return text;
}

SimController::MachineView SimController::freeze_locked(std::string& trace) {
  const double t = pace_now();
  const MachineView v = view_locked(t);
  trace = retire_locked(t, false);
  ahead_.clear();
  machine_ = v.state;
  lines_done_ = v.lines;
  blocks_done_ = v.blocks;
  return v;
}

bool SimController::retire_step(std::unique_lock<std::mutex>& lk) {
  if (!pace_started_ || (pace_->next_end() > pace_now() && settled_ == retired_settled_)) return false;
  const std::string done = retire_locked(pace_now(), false);
  if (done.empty()) return false;
  const std::vector<StockMove> moves = take_stock_locked();
  lk.unlock();
  emit_trace(done, false);
  cut_moves(moves);
  lk.lock();
  return true;
}

void SimController::machine_fed_locked() {
  if (!pace_started_) pace_started_ = true, pace_origin_ = Clock::now();
  if (!pace_stalled_) return;
  // The machine stood still from stall_from_ until now.
  const double now = pace_now();
  const double ms = std::max(0.0, now - stall_from_) * 1000;
  starved_ms_ += static_cast<std::uint32_t>(std::lround(ms));
  ++stalls_;
  pace_->idle_until(now);
  pace_stalled_ = false;
  log_locked("machine starved " + std::to_string(std::lround(ms)) + " ms before line " + std::to_string(line_no_ + 1) +
             ": the buffer ran dry");
}

bool SimController::machine_step(std::unique_lock<std::mutex>& lk, std::uint64_t cur_epoch, bool line_ready,
                                 std::optional<Clock::time_point>& wake) {
  if (!pace_started_) {
    if (!failure_) return false;
    raise_failure(lk, cur_epoch);  // refused before the machine started
    return true;
  }
  // When the machine needs more, the planner commits from the window (all
  // of it when no more program is in reach); when there is nothing, it
  // stands: a stall (or, after a refused line, the alarm).
  const double now = pace_now();
  if (pace_->committed_until() > now) {
    wake = pace_origin_ + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(pace_->committed_until() / cfg_.time_scale));
    return false;
  }
  if (pace_->pending() > 0) {
    pace_->commit(!line_ready || failure_.has_value());
    return true;
  }
  if (failure_) {  // the machine has run everything before the refused line
    raise_failure(lk, cur_epoch);
    return true;
  }
  if (state_ == State::receiving && !pace_stalled_) {
    pace_stalled_ = true;
    stall_from_ = pace_->committed_until();
  }
  return false;
}

// A line read (or refused) at machine pace: it goes to the machine and is
// reported, and traced, once the machine has run it. `lk` is held on entry
// and on return.
void SimController::read_ahead_locked(const GcodeInterpreter& interp, std::uint64_t cur_epoch, long no,
                                      const MachineState& before, const std::vector<MotionBlock>& blocks,
                                      const std::optional<std::pair<Alarm, std::string>>& failed, const std::string& id,
                                      std::string text) {
  if (epoch_ != cur_epoch || state_ == State::alarm) return;  // replaced or stopped meanwhile: it never runs
  if (failed) {
    failure_ = Failure{failed->first, no, id, failed->second, std::move(text)};
    return;
  }
  pace_->add(blocks, before, interp.state(), static_cast<int>(no));
  for (const auto& b : blocks) last_block_line_ = std::max<long>(last_block_line_, b.line);
  // A line's blocks may come later: a NURBS block is complete on its last
  // line, and cutter compensation holds a move until the next one.
  const auto cont = interp.continuation();
  long settled = no;
  if (cont.open_block != ModalMotion::none)
    settled = cont.open_line - 1;
  else if (interp.state().cutter_comp != CutterCompMode::off)
    settled = last_block_line_ - 1;
  settled_ = std::max(settled_, settled);
  ahead_.push_back({no, true, interp.state(), std::move(text), stock_moves(blocks, interp.state())});
}

// Machine pace, every byte confirmed and read: the interpreter's last
// blocks (a move cutter compensation held) go to the machine; DONE waits
// for the machine (finish_paced()).
void SimController::finish_interpreter(std::unique_lock<std::mutex>& lk, GcodeInterpreter& interp,
                                       std::uint64_t cur_epoch) {
  const long lines = line_no_;
  lk.unlock();
  std::string text;
  std::vector<MotionBlock> blocks;
  std::optional<std::pair<std::string, std::string>> failed;
  try {
    blocks = interp.finish();
    check_stock_tools(blocks, interp.state());
    for (const auto& b : blocks) text += trace_block(b);
  } catch (const Error& e) {
    failed.emplace(e.id(), e.message());
  }
  lk.lock();
  if (epoch_ != cur_epoch || state_ != State::finishing) return;
  if (!pace_started_) pace_started_ = true, pace_origin_ = Clock::now();  // a program of no lines
  interp_finished_ = true;
  if (failed) {
    // A move held until the end refused for its tool is the program's
    // fault, not a program cut short.
    const Alarm a = failed->first == errc::verify_tool.str() ? Alarm::gcode : Alarm::incomplete;
    failure_ = Failure{a, lines, failed->first, failed->second,
                       trace_alarm(static_cast<int>(lines), to_string(a), failed->first, failed->second)};
    return;
  }
  pace_->add(blocks, interp.state(), interp.state(), static_cast<int>(lines));
  settled_ = lines;
  ahead_.push_back({lines, false, interp.state(), std::move(text), stock_moves(blocks, interp.state())});
  cv_.notify_all();
}

// Machine pace: the machine has run the whole program; DONE.
void SimController::finish_paced(std::unique_lock<std::mutex>& lk, const GcodeInterpreter& interp,
                                 std::uint64_t cur_epoch) {
  const std::string done = retire_locked(pace_now(), true);
  const long lines = line_no_, blocks = blocks_done_;
  const Vec3 pos = interp.state().pos;
  const std::vector<StockMove> moves = take_stock_locked();
  lk.unlock();
  emit_trace(done + trace_done(lines, blocks, pos) + stock_record(moves), false);
  lk.lock();
  if (epoch_ != cur_epoch || state_ != State::finishing) return;
  machine_ = interp.state();
  state_ = State::done;  // only now: the trace on disk is complete
  log_locked("program done: " + std::to_string(lines) + " lines, " + std::to_string(blocks) + " motion blocks");
  final_traced_ = true;
  cv_.notify_all();
}

// Machine pace: the machine has run every line before the refused one; the
// alarm names that line, as it would without machine pace.
void SimController::raise_failure(std::unique_lock<std::mutex>& lk, std::uint64_t cur_epoch) {
  const Failure f = std::move(*failure_);
  failure_.reset();
  const std::string done = retire_locked(pace_now(), true);
  const std::vector<StockMove> moves = take_stock_locked();
  lk.unlock();
  emit_trace(done + f.trace + stock_record(moves), false);
  lk.lock();
  if (epoch_ != cur_epoch || state_ == State::alarm || state_ == State::done) return;
  machine_.spindle_on = machine_.coolant_mist = machine_.coolant_flood = false;
  record_alarm_locked(f.alarm, f.line, f.id, f.message);
  final_traced_ = true;
  cv_.notify_all();
}

}  // namespace bezcam::sim
