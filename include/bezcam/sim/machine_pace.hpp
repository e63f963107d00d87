#pragma once
/// Execution at machine pace (docs/motion.md, "Streaming at machine pace"):
/// the simulated controller's executor interprets lines ahead into a
/// look-ahead window, and the machine takes blocks from it only as fast as
/// the motion model (cam/planner.hpp) moves through them. Receding horizon:
/// when the machine needs work, the window (twice the look-ahead) is
/// planned from the speed the machine has and all but the last look-ahead's
/// worth of blocks are committed (each limited by what the planner sees
/// ahead of it, as in the whole program's plan); the rest waits for the
/// blocks behind it. When no more program is in reach the whole
/// window is committed with a stop at its end, and if the machine then
/// stands waiting for data, that is a stall (starvation).
///
/// Machine time is in seconds from the program's first line; the caller
/// maps it to wall-clock time with its time scale. No clock inside: tests
/// drive it with the times they choose.
#include <cstddef>
#include <vector>

#include "bezcam/cam/planner.hpp"
#include "bezcam/gcode/reader.hpp"

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

 private:
  const MotionModel& model_;
  std::size_t look_;    // the controller's look-ahead, blocks
  std::size_t window_;  // blocks interpreted ahead: twice the look-ahead
  Timeline pending_;
  Vec3 start_{0, 0, 0};  // where the machine left the last committed block
  double speed_ = 0;     // and at what speed
  double until_ = 0;
};

}  // namespace bezcam::sim
