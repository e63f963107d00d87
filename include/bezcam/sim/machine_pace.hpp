#pragma once
/// Execution at machine pace (docs/motion.md, "Streaming at machine pace"):
/// the simulated controller's executor interprets lines ahead into a
/// look-ahead window, and the machine takes blocks from it only as fast as
/// the motion model (machine/planner.hpp) moves through them. Receding horizon:
/// when the machine needs work, the window (twice the look-ahead) is
/// planned from the speed the machine has and all but the last look-ahead's
/// worth of blocks are committed (each limited by what the planner sees
/// ahead of it, as in the whole program's plan); the rest waits for the
/// blocks behind it. When no more program is in reach the whole
/// window is committed with a stop at its end, and if the machine then
/// stands waiting for data, that is a stall (starvation).
///
/// What the machine has done at a given time (progress()) comes from the
/// committed plans: the blocks and pauses finished, the first program line
/// whose work is not, and the position on the planned path. Interpreted
/// work is not done work: the controller reports progress(), never what
/// the interpreter has read.
///
/// Machine time is in seconds from the program's first line; the caller
/// maps it to wall-clock time with its time scale. No clock inside: tests
/// drive it with the times they choose.
#include <climits>
#include <cstddef>
#include <deque>
#include <limits>
#include <memory>
#include <vector>

#include "bezcam/gcode/reader.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam::sim {

class MachinePace {
 public:
  explicit MachinePace(const MotionModel& model);

  /// The blocks (and pauses) one interpreted line produced.
  void add(const std::vector<MotionBlock>& blocks, const MachineState& before, const MachineState& after, int line);
  /// Blocks interpreted and not yet committed to the machine.
  std::size_t pending() const { return pending_.blocks.size() + (pending_.pauses.empty() ? 0 : 1); }
  /// Whether the look-ahead window is full (the executor takes no more
  /// lines until the machine commits some).
  bool window_full() const { return pending_.blocks.size() >= window_; }
  /// The machine needs work: commit the first half of the window, or, when
  /// `dry` (nothing more in reach: the buffer is empty, or the program is
  /// complete), all of it, stopping at its end.
  void commit(bool dry);
  /// Machine time at which the committed blocks are done.
  double committed_until() const { return until_; }
  /// The machine stood still until machine time `t` (a stall): committed
  /// work resumes from there.
  void idle_until(double t) {
    if (t > until_) until_ = t;
  }

  /// What the machine has done by machine time `t`.
  struct Progress {
    /// The first program line whose work (a block, a pause) is interpreted
    /// but not finished at `t`: committed and still running, or not yet
    /// committed. A block spanning lines counts from its first line.
    /// INT_MAX when every interpreted block and pause is finished.
    int open_line = INT_MAX;
    /// Blocks finished since the program's start.
    std::size_t blocks_done = 0;
    /// Where the machine is on the planned path (program units).
    Vec3 pos{0, 0, 0};
  };
  /// `t` must not be before the last forget().
  Progress progress(double t) const;
  /// Drops what is finished by machine time `t` (progress() at `t` and
  /// later gives the same answers).
  void forget(double t);
  /// When the first committed piece of work not forgotten is finished
  /// (infinity when there is none): progress() changes no sooner.
  double next_end() const { return items_.empty() ? std::numeric_limits<double>::infinity() : items_.front().end; }

 private:
  // One piece of committed work, in execution order.
  struct Item {
    int line = 0;
    double end = 0;  // machine time it is finished
    bool block = false;
  };
  // One committed plan: its committed segments (a prefix) run from t0.
  struct Window {
    double t0 = 0, t1 = 0;
    std::shared_ptr<const MotionPlan> plan;
    std::size_t segments = 0;
  };
  Vec3 position(double t) const;

  const MotionModel& model_;
  std::size_t look_;    // the controller's look-ahead, blocks
  std::size_t window_;  // blocks interpreted ahead: twice the look-ahead
  Timeline pending_;
  Vec3 start_{0, 0, 0};  // where the machine left the last committed block
  double speed_ = 0;     // and at what speed
  double until_ = 0;
  std::deque<Item> items_;  // committed, not yet forgotten
  std::size_t blocks_forgotten_ = 0;
  std::deque<Window> windows_;  // committed plans not yet forgotten
  Vec3 rest_{0, 0, 0};          // where the forgotten windows left the machine
};

}  // namespace bezcam::sim
