#pragma once
/// Canonical moves: the program as motion, before any text. Built from a job
/// and a profile, validated as a whole (validate.hpp), then printed by the
/// G-code writer in the profile's dialect.
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bezcam/cam/move.hpp"
#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/flatten/offset.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/tools.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {

/// How cutting moves are written: G01 lines, G02/G03 arcs (with lines
/// where no arc fits), or exact NURBS/Bezier blocks (docs/cli.md).
enum class OutputMode { lines, arcs, nurbs };
OutputMode parse_output_mode(const std::string& s);  ///< throws InputError
const char* to_string(OutputMode m);

/// What was asked for and achieved, per entity.
struct EntityReport {
  std::string label, type;
  int degree = 0;
  double length = 0;    ///< true curve length (units)
  size_t blocks = 0;    ///< cutting blocks emitted
  double measured = 0;  ///< largest deviation measured on the printed path
  double bound = 0;     ///< proven upper bound
  int entity = -1;      ///< index in the job's entities (Move::entity)
  /// The height of the entity's clearance plane (its `clearance` above
  /// `top_z`, or above the surface's top for patches) when it has one
  /// below safe Z: the tool rapids down to it and moves across at it
  /// between passes. NaN: none (safe Z).
  double clear_z = std::numeric_limits<double>::quiet_NaN();
  int tool = -1;  ///< the tool that cuts it
  /// The feed (units/min) it plunges at, the job's `plunge_feed` for it; the
  /// program's header records it for resuming (docs/resume.md).
  double plunge_feed = 0;
  /// Part cutting: the tool centre's distance from the curve (tool radius +
  /// stock to leave; 0 on the curve), and the stretches of the curve the
  /// tool cannot reach (material left).
  double offset = 0;
  double tool_width = 0;  ///< part cutting: the tool's diameter (0: none given)
  std::vector<MaterialLeft> left;
  /// Part cutting: the moves [first, end) of Program::moves that lead the
  /// tool in to its path and out of it, on every pass (measured against
  /// their own lines and arcs, not against the offset).
  std::vector<std::pair<size_t, size_t>> lead_moves;
  /// A pocket's region (type "pocket"): its certificate.
  std::optional<PocketCertificate> pocket;
  /// A curve cut along its line (not as a part, a pocket or a surface), on
  /// a machine with a motion model: the moves [cut_first, cut_end) of
  /// Program::moves that cut it, and the time-optimal bound of following
  /// its exact curve once at its feed (machine/path_bound.hpp; 0: none).
  size_t cut_first = 0, cut_end = 0;
  double time_bound_s = 0;
  /// The output mode it was cut in (ConvertOptions::output_of()).
  OutputMode output = OutputMode::lines;
};

/// What the conversions of one job in several output modes share
/// (convert_best(), `--compare-outputs`): a pocket's passes and certificate
/// made before from the same inputs (the same walls, tool, margins and, for
/// the certificate, the same moves) are taken from it, not made again; the
/// result is the same. Opaque; thread-safe.
struct ConversionMemo;
std::shared_ptr<ConversionMemo> make_conversion_memo();

struct ConvertOptions {
  OutputMode output = OutputMode::lines;
  /// Per entity (by Entity::index), the output mode that cuts it in place
  /// of `output`: what `--output best` chose (gcode/convert.hpp
  /// convert_best()). Empty, or an index beyond its end: `output`.
  std::vector<OutputMode> entity_output;
  OutputMode output_of(size_t entity) const { return entity < entity_output.size() ? entity_output[entity] : output; }
  std::optional<double> tolerance;  ///< overrides the job's
  bool measure = true;              ///< measure the printed path (header, report)
  /// Called by build_program() before each entity with (entities done so
  /// far, total entities, the entity's label), and once more with
  /// (total, total, "") at the end; for progress bars. May be empty.
  std::function<void(size_t done, size_t total, const std::string& label)> on_entity;
  /// Moves the part: added to every X and Y (`--offset`, `--origin`),
  /// rounded to the program's decimals so that the proven bound holds for
  /// the moved part as it does for the drawn one.
  Vec3 offset;
  /// Where the tool goes at the end, after the final retract (`--return-to
  /// X,Y,Z`): across at safe Z, then down to Z.
  std::optional<Vec3> return_to;
  /// Overrides the job's `program_number`.
  std::optional<long> program_number;
  /// Shared with the job's other conversions (null: none).
  std::shared_ptr<ConversionMemo> memo;
};

/// What the cut order (`order: "shortest"`) did, in the program's units.
struct OrderFigures {
  size_t nested = 0;  ///< nestings found (a contour inside a closed one)
  /// XY rapid length from the origin through the contours, written and planned.
  double rapid_as_written = 0, rapid_planned = 0;
  /// Changes of tool between consecutive contours, written and planned.
  size_t tool_changes_as_written = 0, tool_changes_planned = 0;
  bool by_tool = false;  ///< each tool's contours planned together
};

struct Program {
  std::string job_name;
  std::string machine;
  Units units = Units::mm;
  OutputMode output = OutputMode::lines;
  /// Each entity cut in its own output mode (ConvertOptions::entity_output,
  /// EntityReport::output); `best`: the modes convert_best() chose.
  bool per_entity_output = false, best = false;
  double tolerance = 0;
  double max_measured = 0;  ///< largest deviation measured (units)
  double max_bound = 0;     ///< largest proven bound (units)
  double safe_z = 0;        ///< lowest safe Z of the entities (rapids stay at or above it)
  int decimals = 3;
  std::optional<long> program_number;  ///< the job's or the caller's
  Vec3 offset;                         ///< by which the part was moved (ConvertOptions::offset, rounded)
  std::vector<Move> moves;
  std::vector<EntityReport> entities;
  /// The tools the job uses, each with its diameter and shape (the
  /// machine's default tool number filled in); the header lists them.
  std::vector<JobTool> tools;
  std::vector<std::string> warnings;
  /// Extra lines for the program's header comment: how an output mode the
  /// machine lacks was replaced (also one of `warnings`), decimals raised
  /// for the tolerance, the part moved by an offset.
  std::vector<std::string> notes;
  /// `order: "shortest"`: what the order saved (also one of `notes`).
  std::string order_summary;
  std::optional<OrderFigures> order;
};

/// How the program's header and reports name its output mode: "best",
/// "per entity" or the one mode.
std::string output_name(const Program& p);

/// Builds the canonical program: header state, per entity a retract, rapid,
/// plunge, cut and retract, and the final retract. Does not validate.
Program build_program(const Job& job, const MachineProfile& m, const ConvertOptions& opt);
/// The same, calling `while_measuring` with the program once its moves are
/// final (the part moved, the return move added) while the independent
/// measurements still run on the other cores: work that reads the moves
/// only (validation, the motion plan) overlaps them. The readings
/// (EntityReport::measured, Program::max_measured) are not in yet when it
/// is called. The program returned has them. A failed measurement is
/// thrown in preference to an exception from `while_measuring` (the
/// earliest-added failure, as build_program() throws it); an exception from
/// `while_measuring` is thrown as it is, after the measurements are done.
Program build_program(const Job& job, const MachineProfile& m, const ConvertOptions& opt,
                      const std::function<void(const Program&)>& while_measuring);

/// The profile with the D registers the program's cutter compensation
/// (G41/G42 D-) expects added to its tool table (tool_diameters_mm): how
/// bezcam reads back a program it wrote, as the machine set up for it.
MachineProfile with_compensation_registers(const MachineProfile& m, const Program& p);

/// The effective cutting parameters of an entity (entity > job > profile),
/// in job units; InputError naming the missing key when one is unset.
struct CutParams {
  double feed = 0, plunge_feed = 0, safe_z = 0, cut_z = 0, spindle_rpm = 0, tool_radius = 0;
  int tool = 1;
  Coolant coolant = Coolant::off;
  std::optional<double> clearance;  ///< above top_z; unset: plunge from safe Z
  double top_z = 0;
  std::vector<std::string> before, after;  ///< templates, as the job gives them
  /// Part cutting (job.hpp): unset optionals mean "not asked for".
  CutSide side = CutSide::on;
  std::optional<double> tool_diameter, step_down;
  /// A 2D curve's tool's flute length (the job's tool table): without
  /// step_down, a cut deeper than it below top_z is split into passes as
  /// if step_down were the flute length.
  std::optional<double> flute_length;
  double stock_to_leave = 0;
  CutDirection direction = CutDirection::as_drawn;
  std::optional<Lead> lead;
  std::optional<Tabs> tabs;
  bool controller_compensation = false;
  ToleranceSide tolerance_side = ToleranceSide::both;
  PocketKeys pocket;  ///< as the job gives them (docs/pocket.md)
  DrillKeys drill;    ///< as the job gives them (docs/holes.md)
  /// Whether the entity is cut as a part (any of the above asked for).
  bool part_cut() const {
    return side != CutSide::on || pass_depth() || lead || tabs || controller_compensation ||
           tolerance_side != ToleranceSide::both || direction != CutDirection::as_drawn;
  }
  /// The deepest cut of one pass: step_down, else the flute length where
  /// the cut from top_z to cut_z is deeper; nothing: one pass at cut_z.
  std::optional<double> pass_depth() const {
    if (step_down) return step_down;
    if (flute_length && top_z - cut_z > *flute_length) return flute_length;
    return std::nullopt;
  }
};

/// An entity's `before` / `after` line with its placeholders replaced
/// (numbers rounded to `decimals`).
std::string expand_entity_template(const std::string& text, const Entity& e, const CutParams& c, int decimals);
CutParams cut_params(const Job& job, const Entity& e, const MachineProfile& m);

}  // namespace bezcam
