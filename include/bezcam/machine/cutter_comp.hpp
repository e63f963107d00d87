#pragma once
/// Cutter radius compensation (G41 / G42 / G40) as a controller performs
/// it: the programmed path is the part's edge, and the tool's centre runs at
/// its radius r on the left (G41) or the right (G42) of it, in the direction
/// of travel. One model, used where a program becomes motion: the G-code
/// reader (so `lint`, `simulate`, the preview and the simulated controller
/// move the tool where a controller would) and cam/program_motion.hpp (so a built
/// program is measured on the path the tool really takes).
///
/// The model follows LinuxCNC's interpreter (and Fanuc's type C start-up):
///  - lines are offset by r, arcs keep their centre and change radius by r
///    (an arc whose radius would not stay positive on its inside is refused);
///  - at a corner where the tool is on the outside, it rolls round the
///    corner point on an arc of radius r; on the inside, both offset moves
///    end at their intersection (a move too short for that is refused: the
///    tool would gouge);
///  - the entry: the first XY move after G41/G42 must be a straight line
///    longer than r; it starts where the tool stands (not offset) and ends
///    where the next move's offset begins (the corner as above);
///  - G40: the last compensated move ends at its own offset end; the next XY
///    move (the exit) must be a straight line and starts from there;
///  - Z-only moves keep the tool's XY; NURBS and spline blocks are refused
///    (Fanuc refuses G06.2 in G41/G42, LinuxCNC refuses G5 and G5.1 and
///    ignores compensation for G5.2).
/// Only the XY plane (G17) is compensated. The output is exact: lines,
/// arcs and corner arcs of the tool-centre path, one move behind the input
/// (a move's end depends on the next one).
#include <optional>
#include <stdexcept>
#include <vector>

#include "bezcam/machine/motion.hpp"

namespace bezcam {

/// What compensation cannot do with the program; what() says why, with the
/// G-code words concerned. The reader adds the line.
struct CompensationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class CutterComp {
 public:
  /// G41 (side +1: the tool on the left of the path) or G42 (side -1), with
  /// the tool's radius (> 0). The next XY move enters compensation.
  void on(int side, double radius);
  /// G40: returns the blocks still held; the next XY move is the exit.
  std::vector<MotionBlock> off();
  /// One programmed block (absolute program coordinates, `from` where the
  /// program stands). Returns the tool-centre blocks it completes, in order.
  std::vector<MotionBlock> push(const MotionBlock& b);
  /// End of program: the blocks still held (as G40).
  std::vector<MotionBlock> finish() { return off(); }

  bool active() const { return side_ != 0; }
  /// Whether push() would hand `b` back unchanged: compensation is off and
  /// no exit move is pending. Callers on a hot path skip push() then.
  bool idle() const { return side_ == 0 && !exit_from_; }
  int side() const { return side_; }
  double radius() const { return r_; }

 private:
  std::vector<MotionBlock> release(const MotionBlock* next);

  int side_ = 0;
  double r_ = 0;
  bool entering_ = false;               ///< on() seen, no XY move yet
  std::optional<MotionBlock> pending_;  ///< an XY move whose end waits for the next move
  Vec3 pending_start_;                  ///< where the tool starts it (compensated)
  std::vector<MotionBlock> held_;       ///< Z-only moves after pending_
  std::optional<Vec3> exit_from_;       ///< after off(): the tool's XY until the exit move
};

}  // namespace bezcam
