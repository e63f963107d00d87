#pragma once
// Shared by the job_json*.cpp files: reading typed values with errors that
// name the JSON path, expected and found. Only the kernel's job_json files
// know JSON.
#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/tool_table.hpp"

namespace bezcam::detail {

using json = nlohmann::json;

/// The cutting parameters, at job and entity level (docs/job-format.md);
/// the last, `order`, is the job's only.
inline constexpr std::array<std::string_view, 37> kParamKeys = {
    "feed", "plunge_feed", "safe_z", "cut_z", "spindle_rpm", "tool", "tool_radius", "gouge", "coolant", "clearance",
    "top_z", "before", "after", "side", "tool_diameter", "stock_to_leave", "step_down", "direction", "lead", "tabs",
    "compensation", "tolerance_side",
    // Pocket clearing (job_json_pocket.cpp).
    "operation", "region", "pattern", "angle", "stepover", "finish", "entry", "rest_from", "load",
    // Drilling (job_json_pocket.cpp).
    "to", "peck", "chip_break", "dwell", "retract_z", "order"};
/// The keys of `lead` and `tabs`.
inline constexpr std::array<std::string_view, 2> kLeadKeys = {"radius", "length"};
inline constexpr std::array<std::string_view, 3> kTabsKeys = {"count", "width", "height"};

struct JsonCtx {
  std::string source;
  std::vector<std::string>* warnings = nullptr;
  /// Refusals recorded without stopping the reading (unknown keys), so
  /// that each is reported; parse_job throws them together.
  std::vector<InputError>* errors = nullptr;
  // Limits (bezcam/limits.hpp): points written in the entity being read,
  // and points of the exact Bézier form of the whole job so far.
  mutable std::size_t entity_points = 0, job_points = 0;
  /// How the file is read (a text's outliner and folder); the job's own
  /// cutting parameters, read before the entities (a text's `side`).
  const JobReadOptions* options = nullptr;
  const JobParams* job_params = nullptr;

  [[noreturn]] void fail(const std::string& path, const std::string& id, const std::string& what) const;
  [[noreturn]] void expected(const std::string& path, const std::string& what, const json& found) const;
  void warn(const std::string& path, const std::string& what) const;
  /// Keys of `obj` neither in `known` nor the user's own ("x-..."): each
  /// refused (recorded in `errors`), naming the known key it resembles or
  /// stands for.
  void check_keys(const json& obj, const std::string& path, std::initializer_list<const char*> known) const;
  void check_keys(const json& obj, const std::string& path, const std::vector<std::string_view>& known) const;

  const json& require(const json& obj, const std::string& path, const char* key) const;
  double number(const json& v, const std::string& path) const;
  double positive(const json& v, const std::string& path) const;
  int integer(const json& v, const std::string& path) const;
  std::string string(const json& v, const std::string& path) const;
  bool boolean(const json& v, const std::string& path) const;
  const json& array(const json& v, const std::string& path, size_t min_size = 0) const;
  /// A point [x, y] or [x, y, z]; *dim is set by the first point and every
  /// later point must match it.
  Vec3 point(const json& v, const std::string& path, int* dim) const;
  std::vector<Vec3> points(const json& v, const std::string& path, int* dim, size_t min_size) const;
  std::vector<double> numbers(const json& v, const std::string& path) const;
  /// Counts `n` points written at `path` (an array of points) against
  /// kMaxEntityPoints for the entity being read; fails naming the path.
  void count_points(std::size_t n, const std::string& path) const;
  /// Counts `n` control points of the exact Bézier form against
  /// kMaxJobPoints, before that form is built; fails naming the path.
  void count_bezier_points(std::size_t n, const std::string& path) const;
  /// Runs f, re-throwing a kernel InputError with `path` prefixed to its place.
  template <class F>
  auto at(const std::string& path, F&& f) const -> decltype(f()) {
    try {
      return f();
    } catch (const InputError& e) {
      throw InputError(e.id(), Place::in_json(source, path, e.place().relative_path()), e.message());
    }
  }
};

/// Parses JSON text; InputError at `source` and the line and column
/// (job.syntax), or the JSON path of a number too large for a double.
json parse_json_text(std::string_view text, const std::string& source);

/// A tool table object (a job's `tools` at `path`, or a tools file's top
/// level where `path` is empty): each entry read and checked, a refused
/// entry recorded in `errors` without hiding the next.
ToolTable parse_tools_object(const JsonCtx& ctx, const json& obj, const std::string& path,
                             std::vector<InputError>& errors);

/// The pocket keys of an entity or the job (job_json_pocket.cpp).
PocketKeys parse_pocket_keys(const JsonCtx& ctx, const json& obj, const std::string& path);
/// The drilling keys of an entity or the job (job_json_pocket.cpp).
DrillKeys parse_drill_keys(const JsonCtx& ctx, const json& obj, const std::string& path);

/// Describes a JSON value for "found ..." in messages.
std::string describe(const json& v);

/// A curve object ({"type": "bezier" | "bspline", ...}) as a segment with
/// its Bézier pieces, appended to `pieces`. `in_path`: objects inside a
/// path's segments (no id allowed).
CurveSegment parse_curve_object(const JsonCtx& ctx, const json& obj, const std::string& path, int* dim,
                                std::vector<Bezier>& pieces, bool in_path);

// Entity parsers by type (each file of the job_json family adds its own).
void parse_bspline_segment(const JsonCtx& ctx, const json& obj, const std::string& path, int* dim,
                           std::vector<Bezier>& pieces, CurveSegment& seg);
void parse_interpolate_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e);
// Surfaces (job_json_surfaces.cpp).
void parse_bezier_patch_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e);
void parse_coons_patch_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e);
void parse_curve_on_surface_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e);
// Text (job_json_text.cpp): `e` holds the entity's id and parameters; its
// glyph contours are appended to `out`.
void parse_text_entity(const JsonCtx& ctx, const json& obj, const std::string& path, const Entity& e,
                       std::vector<Entity>& out);
/// The options' entity_settings written into `ents` (the file's entity
/// objects, job_json_set.cpp); returns, for each entity index and top key
/// given, the setting's name (`settings.SELECTOR:KEY`). Throws InputError
/// at the setting.
std::map<std::pair<size_t, std::string>, std::string> apply_entity_settings(const JsonCtx& ctx, json& ents);
/// `e`, a refusal of entity `index`, named at the setting that gave the
/// refused key (`given`: apply_entity_settings()'s answer); `e` itself
/// when the file gave it.
InputError at_entity_setting(const InputError& e, size_t index,
                             const std::map<std::pair<size_t, std::string>, std::string>& given,
                             const std::string& source);
/// After all entities are read: a curve_on_surface whose `surface` is a
/// string gets the surface of the patch entity with that id.
void resolve_surface_references(const JsonCtx& ctx, const json& entities, Job& job);

}  // namespace bezcam::detail
