#pragma once
/// A tool table: per tool number (the `T` word), the cutter loaded for it
/// (docs/job-format.md, "Tools"). A job carries one under `tools`, in the
/// job's units; a tools file (`{"1": {...}, ...}` at its top level) holds
/// one in millimetres, for programs bezcam did not write.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bezcam {

/// The shape of a tool's end.
enum class ToolType { flat, ball, bull, vee, drill };
/// "flat end mill", "ball end mill", "bull nose end mill", "V-bit" or "drill".
const char* to_string(ToolType s);
/// The shape a table names "flat", "ball", "bull", "vee" or "drill";
/// nothing for any other text.
std::optional<ToolType> tool_type_from(std::string_view name);
/// The name a table gives the shape: "flat", "ball", "bull", "vee", "drill".
const char* table_name(ToolType s);

/// One tool of a table. Lengths in the table's units (a job's: its units;
/// a tools file's: mm); angles in degrees.
struct ToolEntry {
  int number = 0;  ///< the T number, >= 0
  ToolType shape = ToolType::flat;
  double diameter = 0;                  ///< > 0
  std::optional<double> corner_radius;  ///< bull only (required): 0 < rc <= diameter / 2
  std::optional<double> angle;          ///< vee only (required): included angle, 0 < a < 180
  std::optional<double> point_angle;    ///< drill only (required): 0 < a < 180
  std::optional<double> flute_length;   ///< > 0: the deepest one pass may cut
  bool center_cutting = false;          ///< may plunge straight down; always true for a drill

  /// `ball D6`, `bull D10 r1`, `vee D6 60deg`, `drill D5 118deg`, `flat
  /// D6`, then ` flutes 20` where the flute length is given (numbers as
  /// fmt_num prints them, in the table's units).
  std::string description() const;
};

/// A tool table: its entries in ascending tool number, each number once.
struct ToolTable {
  std::vector<ToolEntry> entries;

  bool empty() const { return entries.empty(); }
  /// The entry for tool `number`; nullptr when the table has none.
  const ToolEntry* find(int number) const;
  /// The numbers the table has, for messages: `1, 2, 5`.
  std::string numbers() const;
  /// The same table with every length multiplied by `factor` (25.4 turns
  /// an inch table into millimetres).
  ToolTable scaled(double factor) const;
};

/// Checks one entry as a job file's or a tools file's entry is checked:
/// diameter finite > 0; a bull's corner radius 0 < rc <= diameter / 2; a
/// vee's angle and a drill's point angle 0 < a < 180; a flute length
/// finite > 0; no value the shape does not take (a corner radius on a
/// flat tool); a drill cuts at its centre. Throws InputError placed at
/// `file` and `path.key` (`tools."3".corner_radius`).
void check_tool_entry(const ToolEntry& t, const std::string& file, const std::string& path);

/// The JSON path of tool `number`'s entry under `parent` (`tools."3"`, or
/// `"3"` at a tools file's top level, where `parent` is empty).
std::string tool_entry_path(const std::string& parent, const std::string& key);

/// Parses a tools file's text: `{"1": {"shape": "flat", "diameter": 6},
/// ...}` at the top level, lengths in millimetres. `source` names the file
/// in messages. Throws InputError placed at `source` and the JSON path of
/// each refusal (`"3".corner_radius`), independent refusals (two bad
/// entries) together in Error::more().
ToolTable parse_tool_table(std::string_view text, const std::string& source);
/// Reads a tools file (parse_tool_table()); IoError when it cannot be read.
ToolTable read_tool_table_file(const std::string& path);

}  // namespace bezcam
