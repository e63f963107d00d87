#pragma once
// Internal to the post layer: the per-mode emitters of cutting moves. Each
// starts with the tool at the entity's first point at cutting depth and
// appends the moves that cut the entity, filling the report's blocks,
// measured deviation and bound.
#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "bezcam/cam/program.hpp"
#include "bezcam/flatten/exact_blocks.hpp"
#include "speed_stretches.hpp"

namespace bezcam::detail {

/// The independent measurements of a program's curve entities, run on
/// every core while the program is still being built (they are most of the
/// time a conversion takes, and independent of each other): a task added
/// for an entity waits until release() says the entity is complete (its
/// closure may read figures the entity fills in last), then a worker
/// thread takes it; finish() runs what is left on the calling thread too.
/// Each task returns the reading for the report at `report` (index into
/// Program::entities) and throws std::logic_error when the reading breaks
/// the tolerance. A task's closure (and the path it holds) is freed as soon
/// as it has run.
class Measurements {
 public:
  struct Task {
    size_t report = 0;
    std::function<double()> measure;
    double reading = 0;
    std::exception_ptr error;
  };
  Measurements() = default;
  Measurements(const Measurements&) = delete;
  Measurements& operator=(const Measurements&) = delete;
  /// Stops the workers (a refusal while building): tasks not yet taken
  /// never run.
  ~Measurements();

  void add(size_t report, std::function<double()> measure);
  /// The tasks added so far may run.
  void release();
  /// Runs every task (this thread working too) and waits for all; rethrows
  /// the failure of the earliest task that failed (in the order added, so
  /// the same one on every run). The tasks, in the order added, with their
  /// readings.
  const std::vector<std::unique_ptr<Task>>& finish();

 private:
  void work(bool until_empty);
  std::mutex m_;
  std::condition_variable more_, done_;
  std::vector<std::unique_ptr<Task>> tasks_;  // grows under m_; a Task never moves
  size_t released_ = 0, next_ = 0, finished_ = 0;
  size_t failed_ = SIZE_MAX;  // earliest failed task
  bool stop_ = false;
  std::vector<std::thread> pool_;
};

struct CutContext {
  const Job& job;
  const Entity& entity;
  const MachineProfile& machine;
  const CutParams& params;
  OutputMode output;  // the entity's output mode (ConvertOptions::output_of())
  int decimals;       // coordinate decimals of the program's units
  double tolerance;   // job units
  bool measure;
  Program& program;
  /// Where a curve emitter leaves its measurement (null: measure at once);
  /// `report` is the index its EntityReport will have.
  Measurements* later = nullptr;
  size_t report = 0;
  /// Geometry made while building (offsets, leads) that the deferred
  /// measurements read: kept alive until they have run.
  std::deque<Entity>* owned = nullptr;
  /// ConvertOptions::memo (null: none).
  ConversionMemo* memo = nullptr;
  /// Whether the tool is at rest where the cut starts and ends, or goes on
  /// at the feed from or into a tangent move (a part's leads and path):
  /// the direction a cut that goes on starts in (incoming_direction()), and
  /// on a controller whose arcs accelerate more slowly than its lines,
  /// where append_cruise() puts arcs and how keep_faster_cut() times the
  /// cut.
  CutEnds ends = {};
  /// Runs `f` now into `r.measured`, or leaves it for later.
  void measure_with(EntityReport& r, std::function<double()> f) const {
    if (later)
      later->add(report, std::move(f));
    else
      r.measured = f();
  }
};

/// The point the tool cuts at for a curve point (2D curves at cut_z).
Vec3 cut_point(const CutContext& c, const Vec3& p);

/// G01 polyline within the tolerance after rounding (flatten_curve.hpp).
void emit_lines(CutContext& c, EntityReport& r);
/// The G01 moves of a polyline within `bound` of the entity's curve (its
/// first vertex where the tool stands), with the independent measurement.
void emit_polyline(CutContext& c, EntityReport& r, std::vector<Vec3> poly, double bound);

/// build_program()'s running state, continued by an emitter that positions
/// the tool itself.
struct MotionState {
  int& tool;
  double& rpm;
  Vec3& pos;
  bool& pos_known;
  Coolant& coolant;
};

/// Before an entity (program.cpp): what a machinist's post writes when the
/// tool, spindle or coolant changes. A tool change stops the coolant and
/// the spindle (after the first tool), retracts to `safe` if below it, then
/// `T- M06` and the profile's tool length line, or, on a machine without a
/// tool changer, `M00` naming the tool (with a warning); then the spindle
/// (and the profile's dwell) and the coolant. Moves carry `entity`.
void change_tool_and_spindle(Program& p, const MachineProfile& m, const CutParams& cp, double safe, MotionState& ms,
                             int entity);
/// Retract (straight up) if not at `safe`, rapid over `start`, rapid down to
/// the clearance plane `clear` (when below safe), plunge to `start` at the
/// plunge feed. Leaves `ms.pos` as it was: the caller takes the position
/// from the cut that follows.
void approach(Program& p, int entity, const Vec3& start, double safe, double clear, double plunge_feed,
              const MotionState& ms);

/// Cuts a curve entity as a part (program.hpp CutParams::part_cut()):
/// the tool-centre path at the tool's radius on its side (offset.hpp), in
/// the direction asked, in depth passes with leads and tabs, in the output
/// mode's blocks, and measures the printed path against the part
/// independently (offset_measure.hpp). Starts after the tool change and the
/// entity's `before` lines; ends retracted at safe Z (`ms.pos`). Fills `r`.
void emit_part(CutContext& c, MotionState& ms, EntityReport& r, double safe, double clear);

/// Clears the region of the pocket entities `members` (the first is
/// c.entity): the passes (pocket_plan.hpp) at every depth level, entered
/// by a helix, a ramp or a plunge, linked at depth inside the cleared area
/// or over the clearance plane; then the certificate (pocket_check.hpp) of
/// the moves made, in `r.pocket`, the header and the warnings. Starts after
/// the tool change; ends retracted at safe Z (`ms.pos`) (pocket_emit.cpp).
void emit_pocket(CutContext& c, MotionState& ms, EntityReport& r, double safe, double clear,
                 const std::vector<const Entity*>& members);

/// The job with its entities in the cut order (`order: "shortest"`,
/// docs/cut-order.md): nested contours first, one tool at a time where the
/// nesting allows, then the shortest rapids; closed curves started at the
/// planned joint (their pieces rotated), open ones reversed where allowed.
/// With two contours or more, the figures go to `p.order` and a note
/// (program_order.cpp).
Job ordered(const Job& job, const MachineProfile& m, Program& p);

/// The name of the pocket region entity `x` belongs to (its `region`, else
/// its id or label) (pocket_regions.cpp).
std::string region_of(const Entity& x, const CutParams& c);

/// The entities of e's pocket region (docs/pocket.md), e first; none when
/// the region was cut already (a pocket's report is named after its
/// region) (pocket_regions.cpp).
std::vector<const Entity*> pocket_members(const Job& job, const Entity& e, const MachineProfile& m, const Program& p);
/// A warning for each pocket region with a curve inside a curve of another
/// pocket region: that region clears over it, which is right for a deeper
/// pocket in a shallower one and wrong for an island meant to stay.
std::vector<std::string> nested_pocket_warnings(const Job& job, const MachineProfile& m);

/// Cuts a surface entity completely (surface_emitter.cpp): bezier_patch and
/// coons_patch by their toolpath (zigzag, raster, boundary), curve_on_surface
/// along its curve; tool and spindle, rapids at safe Z, plunges, cutting
/// moves, links, gouge policy and the final retract. Returns the filled
/// report. In nurbs output on a profile with 3D NURBS blocks (Fanuc) the
/// cutting runs are exact or proven-approximate NURBS blocks; elsewhere
/// G01 lines, said once in a warning (docs/surfaces.md).
EntityReport emit_surface(CutContext& c, MotionState& st);

/// G02/G03 arcs and G01 lines within the tolerance after rounding
/// (arc_fit.hpp); refuses a profile with "arcs": false (cut_arcs.cpp).
void emit_arcs(CutContext& c, EntityReport& r);

/// Exact-curve blocks in the profile's NURBS dialect (nurbs_blocks.hpp),
/// with arcs or lines where a piece cannot be one, and arcs (or lines) for
/// the whole program on a profile without NURBS, said in the header and a
/// warning (cut_nurbs.cpp).
void emit_nurbs(CutContext& c, EntityReport& r);

/// Appends the move of one planned exact block (a G01 line, a G5/G5.1
/// Bézier move or a NURBS block in the profile's dialect), its points mapped
/// by `at` (model point -> cutting point); returns the G-code lines it
/// takes (cut_nurbs.cpp).
size_t append_exact_block(CutContext& c, const ExactBlock& b, const std::function<Vec3(const Vec3&)>& at);

/// The arc/line fallback for a run of pieces that starts at the current
/// printed position: appends the moves, adds their count to `blocks`, the
/// drawn path (model coordinates, dense) to `path`, returns the proven bound.
/// `direction` (planar pieces): in, the direction the move before ends in,
/// which a tangent chain then continues (zero: none); out, the direction
/// the last move ends in.
double append_arcs_or_lines(CutContext& c, std::span<const Bezier> pieces, std::vector<Vec3>& path, size_t& blocks,
                            Vec3* direction = nullptr);

/// Where the cut goes on from a tangent move (c.ends.from_rest false): the
/// unit direction in XY the program's last move ends in, when it is a feed
/// move in the plane ending where the cut starts, within a few hundredths
/// of a radian of `along` (the curve's own direction there); else zero.
/// The cut's tangent chain starts along it, so that the joint turns by no
/// more than the two printed moves' rounding.
Vec3 incoming_direction(const CutContext& c, std::span<const Bezier> pieces);

/// Appends the moves of a run of pieces where the tool cruises at the feed
/// (append_cruise()); `direction` as for append_arcs_or_lines(). Returns
/// the proven bound.
using SteadyEmitter = std::function<double(std::span<const Bezier> pieces, Vec3& direction)>;
/// Planar pieces on a controller whose arcs accelerate more slowly than
/// its lines (arcs_accelerate_slower()): the lines program's chords where
/// the tool changes speed, `steady`'s moves where it cruises at the feed,
/// joined by lines tangent to them where lines long enough for the feed
/// fit (else lines there too). Returns the proven bound (cruise_arcs.cpp).
double append_cruise(CutContext& c, std::span<const Bezier> pieces, std::vector<Vec3>& path, size_t& blocks,
                     const SteadyEmitter& steady);
/// Replaces the moves of c.program from `first` on (a cut along the curve
/// of `pieces`, `plain_blocks` blocks, ends as c.ends says) by the ones `make` appends
/// in their place (the same cut with lines where the tool changes speed,
/// append_cruise(); `make` returns its block count, or nullopt when it
/// cannot make it) when its plan is faster (take_cruise()); else puts the
/// first cut back. Returns the block count of the cut kept when it is
/// `make`'s (cruise_arcs.cpp).
std::optional<size_t> keep_faster_cut(CutContext& c, std::span<const Bezier> pieces, size_t first, size_t plain_blocks,
                                      const std::function<std::optional<size_t>()>& make);

/// The elements of `v` from `from` on, moved out of it (`v` keeps the
/// ones before): a cut set aside while another is made in its place.
template <class T>
std::vector<T> split_off(std::vector<T>& v, size_t from) {
  const auto at = v.begin() + static_cast<std::ptrdiff_t>(from);
  std::vector<T> tail(std::make_move_iterator(at), std::make_move_iterator(v.end()));
  v.erase(at, v.end());
  return tail;
}

/// Adds `note` to the program's header notes unless it is there already
/// (a rule said once per program).
inline void note_once(Program& p, const std::string& note) {
  if (std::find(p.notes.begin(), p.notes.end(), note) == p.notes.end()) p.notes.push_back(note);
}

/// A G01 to `to` (model point) at the feed, unless the tool is there
/// already (a piece shorter than the rounding); `path` and `blocks` follow.
void append_line(CutContext& c, const Vec3& to, std::vector<Vec3>& path, size_t& blocks);

}  // namespace bezcam::detail
