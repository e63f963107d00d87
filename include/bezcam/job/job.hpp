#pragma once
/// A job: what the curve file (docs/job-format.md, version 1) holds,
/// validated. Built by the JSON reader (job_json.hpp) or in memory
/// (job_builder.hpp); after construction the invariants hold
/// (finite numbers, positive tolerance, meeting path joints, ...).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "bezcam/job/tool_table.hpp"
#include "bezcam/kernel/curve.hpp"
#include "bezcam/kernel/surface.hpp"
#include "bezcam/kernel/units.hpp"

namespace bezcam {

/// What to do where a ball-end tool would gouge a surface (key `gouge`):
/// refuse the job (exit 2, naming entity, u and v) or leave those regions uncut.
enum class GougePolicy { refuse, skip };

/// Coolant while cutting (key `coolant`): M07 mist, M08 flood, M09 off.
enum class Coolant { off, mist, flood };
const char* to_string(Coolant c);
/// "flood", "mist" or "off"; nothing for any other text.
std::optional<Coolant> coolant_from(std::string_view text);

/// Cutting a part, not only a curve (docs/job-format.md, "Cutting a part"):
/// which side of the curve the tool is on.
enum class CutSide { on, left, right, inside, outside };
/// Direction of travel: as drawn, climb (the part on the tool's right,
/// spindle M03) or conventional.
enum class CutDirection { as_drawn, climb, conventional };
/// Where the path may deviate from its true curve.
enum class ToleranceSide { both, left, right, waste };
/// Tangent lead-in and lead-out: a line of `length` and a quarter arc of
/// `radius`, on the waste side.
struct Lead {
  double radius = 0, length = 0;
};
/// Holding tabs: `count` spans of `width`, evenly spaced along the curve,
/// where passes below cut_z + height rise to it.
struct Tabs {
  int count = 0;
  double width = 0, height = 0;
};

/// What an entity's cut does (key `operation`): follow the curve (a
/// profile, today's cut), clear the region it bounds (docs/pocket.md), or
/// make a hole at a point or a circle: drill it, or bore it with an end
/// mill (docs/holes.md).
enum class Operation { profile, pocket, drill, bore };
/// How a pocket is cleared: rings parallel to the walls, parallel lines,
/// or passes that keep the tool's engagement at or below what `load` gives.
enum class PocketPattern { offset, zigzag, adaptive };
/// How the tool gets down into a pocket.
struct PocketEntry {
  enum class Kind { helix, ramp, plunge };
  Kind kind = Kind::helix;
  std::optional<double> radius;  ///< helix: the tool centre's circle
  double angle = 3;              ///< helix and ramp: degrees below the horizontal
};
/// The pocket keys (docs/pocket.md); unset values take the defaults there.
struct PocketKeys {
  std::optional<Operation> operation;
  std::optional<std::string> region;
  std::optional<PocketPattern> pattern;
  std::optional<double> angle, stepover, finish_stock, rest_from, load;
  std::optional<PocketEntry> entry;
  /// Values set here win; the rest come from `base`.
  PocketKeys over(const PocketKeys& base) const;
};

/// The drilling keys (docs/holes.md); unset values take the defaults there.
struct DrillKeys {
  std::optional<bool> to_tip;       ///< `"to": "tip"` (true) or `"diameter"`: what cut_z is the depth of
  std::optional<double> peck;       ///< 0: none
  std::optional<bool> chip_break;   ///< G73 instead of G83
  std::optional<double> dwell;      ///< seconds at the bottom (G82)
  std::optional<double> retract_z;  ///< the R plane
  /// Values set here win; the rest come from `base`.
  DrillKeys over(const DrillKeys& base) const;
};

/// Cutting parameters (file units); unset values fall back to the entity's
/// job, then to the machine profile.
struct JobParams {
  std::optional<double> feed, plunge_feed, safe_z, cut_z, spindle_rpm, tool_radius;
  std::optional<int> tool;
  std::optional<GougePolicy> gouge;  ///< surfaces with tool_radius > 0; default refuse
  std::optional<Coolant> coolant;    ///< default off
  /// Clearance height: the tool rapids down to `clearance` above `top_z`
  /// (the stock's top, default 0) and feeds only from there; surface
  /// passes link at that height. Unset: plunge at the plunge feed from
  /// safe Z, as before.
  std::optional<double> clearance, top_z;
  /// Per-entity start and end sequences (dxf2gcode's templates): lines
  /// printed as given before the entity's approach and after its retract,
  /// with {entity}, {tool}, {rpm}, {feed}, {plunge_feed}, {cut_z},
  /// {safe_z} and {top_z} replaced (kEntityPlaceholders).
  std::optional<std::vector<std::string>> before, after;
  /// Part cutting (curve entities).
  std::optional<CutSide> side;
  std::optional<double> tool_diameter, stock_to_leave, step_down;
  std::optional<CutDirection> direction;
  std::optional<Lead> lead;
  std::optional<Tabs> tabs;
  std::optional<bool> controller_compensation;  ///< `compensation`: "controller" (true) or "cam"
  std::optional<ToleranceSide> tolerance_side;
  PocketKeys pocket;
  DrillKeys drill;
  /// Values set here win; the rest come from `base`.
  JobParams over(const JobParams& base) const;
};

/// Where a surface entity's passes go (docs/job-format.md, `toolpath`).
struct ToolpathSpec {
  std::string pattern = "zigzag";  ///< zigzag | raster | boundary
  char direction = 'u';            ///< parameter that varies along a pass
  std::optional<double> stepover;
};

struct Entity {
  std::string id;    ///< may be empty
  size_t index = 0;  ///< position in the job's `entities`
  /// Position in the file's `entities` when it differs from `index`: the
  /// glyphs of a `text` entity (job/text.hpp) all come from one.
  std::optional<size_t> file_index;
  std::string type;  ///< JSON type
  /// A `text` entity's glyph: the characters it draws (UTF-8).
  std::string glyph;
  JobParams params;     ///< this entity's overrides
  CurveGeometry curve;  ///< for curve entities (bezier, bspline, interpolate, path)
  /// A `point` entity: where the hole is (z 0); it has no curve.
  std::optional<Vec3> point;
  /// bezier_patch, coons_patch: the surface; curve_on_surface: the surface
  /// it lies on (shared with the patch entity it names, if any).
  std::shared_ptr<const SurfaceGeometry> surface;
  ToolpathSpec toolpath;   ///< bezier_patch, coons_patch
  CurveGeometry uv_curve;  ///< curve_on_surface: the 2D curve in the (u, v) square
  /// An entity read from a drawing: where it is in the drawing, for
  /// messages (`layer "OUTLINE", LINE (handle 2F) and 7 more joined, from
  /// (0, 0)`); empty for a job file's entity.
  std::string origin;

  /// The id, or `entities[i]` when there is none.
  std::string label() const { return id.empty() ? json_path() : id; }
  std::string json_path() const { return "entities[" + std::to_string(file_index.value_or(index)) + "]"; }
};

/// The placeholders a `before` / `after` line may use.
inline constexpr std::string_view kEntityPlaceholders[] = {"entity",      "tool",  "rpm",    "feed",
                                                           "plunge_feed", "cut_z", "safe_z", "top_z"};

struct Job {
  int version = 1;
  /// The program number (key `program_number`, 1 to 99999999): Fanuc's
  /// `O` number (the profile's {program}), a comment elsewhere.
  std::optional<long> program_number;
  Units units = Units::mm;
  double tolerance = kDefaultToleranceMm;
  std::optional<std::string> machine;
  JobParams params;
  std::vector<Entity> entities;
  /// `tools`: the tool table, lengths in the job's units; empty when the
  /// job has none (each entity's tool is then what its keys say).
  ToolTable tools;
  /// The tool table in millimetres.
  ToolTable tools_mm() const { return tools.scaled(mm_per_unit(units)); }
  /// `order`: "shortest" (true, default): nested contours first, one tool
  /// at a time where the nesting allows, then the order and start points
  /// that shorten the rapids; "as-written" (false).
  bool order_shortest = true;
  std::vector<std::string> warnings;  ///< unknown keys and other non-fatal findings
  std::string source;                 ///< file name, for messages
};

}  // namespace bezcam
