// Tool tables: the shapes, an entry's checks and description (the JSON
// reading is job_json_tools.cpp's).
#include "bezcam/job/tool_table.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {
constexpr ToolType kShapes[] = {ToolType::flat, ToolType::ball, ToolType::bull, ToolType::vee, ToolType::drill};
}  // namespace

const char* to_string(ToolType s) {
  switch (s) {
    case ToolType::flat: return "flat end mill";
    case ToolType::ball: return "ball end mill";
    case ToolType::bull: return "bull nose end mill";
    case ToolType::vee: return "V-bit";
    case ToolType::drill: return "drill";
  }
  return "flat end mill";
}

const char* table_name(ToolType s) {
  switch (s) {
    case ToolType::flat: return "flat";
    case ToolType::ball: return "ball";
    case ToolType::bull: return "bull";
    case ToolType::vee: return "vee";
    case ToolType::drill: return "drill";
  }
  return "flat";
}

std::optional<ToolType> tool_type_from(std::string_view name) {
  for (ToolType s : kShapes)
    if (name == table_name(s)) return s;
  return std::nullopt;
}

std::string ToolEntry::description() const {
  std::string d = std::string(table_name(shape)) + " D" + fmt_num(diameter);
  if (shape == ToolType::bull && corner_radius) d += " r" + fmt_num(*corner_radius);
  if (shape == ToolType::vee && angle) d += " " + fmt_num(*angle) + "deg";
  if (shape == ToolType::drill && point_angle) d += " " + fmt_num(*point_angle) + "deg";
  if (flute_length) d += " flutes " + fmt_num(*flute_length);
  return d;
}

const ToolEntry* ToolTable::find(int number) const {
  auto it =
      std::lower_bound(entries.begin(), entries.end(), number, [](const ToolEntry& t, int n) { return t.number < n; });
  return it != entries.end() && it->number == number ? &*it : nullptr;
}

std::string ToolTable::numbers() const {
  std::string s;
  for (const ToolEntry& t : entries) s += (s.empty() ? "" : ", ") + std::to_string(t.number);
  return s;
}

ToolTable ToolTable::scaled(double factor) const {
  ToolTable t = *this;
  for (ToolEntry& e : t.entries) {
    e.diameter *= factor;
    for (auto* v : {&e.corner_radius, &e.flute_length})
      if (*v) **v *= factor;
  }
  return t;
}

std::string tool_entry_path(const std::string& parent, const std::string& key) {
  return (parent.empty() ? "" : parent + ".") + "\"" + key + "\"";
}

void check_tool_entry(const ToolEntry& t, const std::string& file, const std::string& path) {
  const auto place = [&](const char* key) { return Place::in_json(file, path + "." + key); };
  const std::string shape = std::string("a \"") + table_name(t.shape) + "\" tool";
  if (t.number < 0)
    throw InputError(errc::job_tool_table, Place::in_json(file, path),
                     "expected a tool number >= 0, found " + std::to_string(t.number));
  if (!std::isfinite(t.diameter) || !(t.diameter > 0))
    throw InputError(errc::job_not_positive, place("diameter"),
                     "expected a tool diameter > 0, found " + fmt_num(t.diameter));
  // Each value belongs to one shape: on another it would be ignored.
  const auto belongs = [&](const std::optional<double>& v, ToolType owner, const char* key, const char* what) {
    if (v && t.shape != owner)
      throw InputError(errc::job_tool_table, place(key),
                       shape + " has no " + what + ": remove \"" + key + "\", or make the tool's shape \"" +
                           table_name(owner) + "\"");
    if (!v && t.shape == owner)
      throw InputError(errc::job_missing, place(key), shape + " needs \"" + key + "\" (its " + what + "); add it");
  };
  belongs(t.corner_radius, ToolType::bull, "corner_radius", "corner radius");
  belongs(t.angle, ToolType::vee, "angle", "included angle (degrees)");
  belongs(t.point_angle, ToolType::drill, "point_angle", "point angle (degrees)");
  if (t.corner_radius) {
    const double rc = *t.corner_radius, r = t.diameter / 2;
    if (!std::isfinite(rc) || !(rc > 0) || rc > r * (1 + 1e-12))
      throw InputError(errc::job_range, place("corner_radius"),
                       "expected a corner radius above 0 and at most the tool's radius (" + fmt_num(r) + "), found " +
                           fmt_num(rc) + (rc > r ? "; the corner cannot be wider than the tool" : ""));
  }
  for (const auto& [v, key] : {std::pair{&t.angle, "angle"}, std::pair{&t.point_angle, "point_angle"}})
    if (*v && (!std::isfinite(**v) || !(**v > 0) || !(**v < 180)))
      throw InputError(errc::job_range, place(key),
                       "expected an angle above 0 and below 180 degrees, found " + fmt_num(**v));
  if (t.flute_length && (!std::isfinite(*t.flute_length) || !(*t.flute_length > 0)))
    throw InputError(errc::job_not_positive, place("flute_length"),
                     "expected a flute length > 0, found " + fmt_num(*t.flute_length));
  if (t.shape == ToolType::drill && !t.center_cutting)
    throw InputError(errc::job_tool_table, place("center_cutting"),
                     "a drill always cuts at its centre: \"center_cutting\" cannot be false for a \"drill\"; "
                     "remove it");
}

}  // namespace bezcam
