// Tool tables in JSON: a job's `tools` object and a tools file
// (docs/job-format.md, "Tools").
#include <algorithm>

#include "bezcam/job/keys.hpp"
#include "bezcam/job/tool_table.hpp"
#include "bezcam/limits.hpp"
#include "job_json_detail.hpp"

namespace bezcam {

namespace detail {

namespace {

constexpr std::string_view kEntryKeys[] = {"shape",       "diameter",     "corner_radius", "angle",
                                           "point_angle", "flute_length", "center_cutting"};

// The tool number a key names: decimal digits, no leading zero (one
// spelling per number, so that messages name the entry as it is written).
int tool_number(const JsonCtx& ctx, const std::string& key, const std::string& at) {
  const bool digits = !key.empty() && key.size() <= 9 &&
                      std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || (key.size() > 1 && key[0] == '0'))
    ctx.fail(at, errc::job_tool_table,
             "expected a tool number as the key: a whole number >= 0 written without leading zeros (\"1\", "
             "\"12\"), found the key \"" +
                 key + "\"");
  return std::stoi(key);
}

ToolEntry parse_entry(const JsonCtx& ctx, const json& obj, const std::string& at, int number) {
  if (!obj.is_object()) ctx.expected(at, "a tool object like {\"shape\": \"flat\", \"diameter\": 6}", obj);
  ctx.check_keys(obj, at, std::vector<std::string_view>(std::begin(kEntryKeys), std::end(kEntryKeys)));
  ToolEntry t;
  t.number = number;
  const json& shape = ctx.require(obj, at, "shape");
  const std::optional<ToolType> s = shape.is_string() ? tool_type_from(shape.get<std::string>()) : std::nullopt;
  if (!s)
    ctx.fail(at + ".shape", shape.is_string() ? errc::job_tool_table : errc::job_type,
             "expected one of \"flat\", \"ball\", \"bull\", \"vee\", \"drill\", found " + describe(shape));
  t.shape = *s;
  t.diameter = ctx.number(ctx.require(obj, at, "diameter"), at + ".diameter");
  auto num = [&](const char* key, std::optional<double>& out) {
    if (auto it = obj.find(key); it != obj.end()) out = ctx.number(*it, at + "." + key);
  };
  num("corner_radius", t.corner_radius);
  num("angle", t.angle);
  num("point_angle", t.point_angle);
  num("flute_length", t.flute_length);
  t.center_cutting = t.shape == ToolType::drill;
  if (auto it = obj.find("center_cutting"); it != obj.end())
    t.center_cutting = ctx.boolean(*it, at + ".center_cutting");
  check_tool_entry(t, ctx.source, at);
  return t;
}

}  // namespace

ToolTable parse_tools_object(const JsonCtx& ctx, const json& obj, const std::string& path,
                             std::vector<InputError>& errors) {
  if (!obj.is_object())
    ctx.expected(path.empty() ? "(top level)" : path,
                 "an object of tools by number, like {\"1\": {\"shape\": \"flat\", \"diameter\": 6}}", obj);
  ToolTable table;
  // Entries are independent: a refused one does not hide the next.
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (user_key(it.key())) continue;
    const std::string at = tool_entry_path(path, it.key());
    try {
      table.entries.push_back(parse_entry(ctx, it.value(), at, tool_number(ctx, it.key(), at)));
    } catch (const InputError& e) {
      errors.push_back(e);
    }
  }
  std::sort(table.entries.begin(), table.entries.end(),
            [](const ToolEntry& a, const ToolEntry& b) { return a.number < b.number; });
  return table;
}

}  // namespace detail

ToolTable parse_tool_table(std::string_view text, const std::string& source) {
  if (text.size() > kMaxJobBytes)
    throw InputError(errc::limit_file_size, Place::at_file(source),
                     "the tools file is " + std::to_string(text.size() >> 20) + " MiB, more than bezcam reads (" +
                         std::to_string(kMaxJobBytes >> 20) + " MiB, docs/limits.md)");
  std::vector<InputError> errors;
  detail::JsonCtx ctx{source, nullptr};
  ctx.errors = &errors;
  ToolTable table;
  try {
    table = detail::parse_tools_object(ctx, detail::parse_json_text(text, source), "", errors);
  } catch (const InputError& e) {
    errors.push_back(e);
  }
  if (errors.empty()) return table;
  InputError first = errors.front();
  for (size_t i = 1; i < errors.size(); ++i) first.add_more(errors[i]);
  throw first;
}

ToolTable read_tool_table_file(const std::string& path) {
  return parse_tool_table(read_bounded(path, kMaxJobBytes, "tools file"), path);
}

}  // namespace bezcam
