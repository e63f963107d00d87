#pragma once
/// A machine profile: everything that differs between controllers, as data
/// (machines/NAME.json; docs/machines.md documents every key).
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bezcam/kernel/job.hpp"

namespace bezcam {

/// Which exact-curve words a controller understands (gcode-dialects.md).
enum class NurbsDialect {
  none,      ///< lines and arcs only
  fanuc,     ///< G06.2-style block (start word configurable: G06.2 / G06.3)
  linuxcnc,  ///< G5 / G5.1 Bézier moves and G5.2 / G5.3 NURBS
};

struct MachineProfile {
  std::string name;
  std::string description;
  std::vector<std::string> header;   ///< raw lines before the program
  std::vector<std::string> footer;   ///< raw lines after the final retract
  bool line_numbers = false;
  int line_start = 10, line_step = 10;
  int decimals_mm = 3, decimals_inch = 4;
  int feed_decimals = 1;
  std::string word_rapid = "G00", word_feed = "G01", word_cw = "G02", word_ccw = "G03";
  std::string tool_change = "T{tool} M06";  ///< {tool} is replaced
  std::string spindle_on = "S{rpm} M03";    ///< {rpm} is replaced
  std::string spindle_off = "M05";
  bool arcs = true;
  double arc_tolerance_mm = 0.002;  ///< allowed radius mismatch of a printed arc
  NurbsDialect nurbs = NurbsDialect::none;
  std::string nurbs_start_word = "G06.2";
  int nurbs_max_rank = 4;
  int knot_decimals = 4, weight_decimals = 4;
  /// NURBS block numbers printed with all their decimals (`K0.000000
  /// X55.507 Y52.139 Z0.000 R1.000`, the seeds' listing) instead of with
  /// trailing zeros trimmed (`K0. X55.507 ... R1.`).
  bool nurbs_fixed_decimals = false;
  /// Travel in program coordinates, mm: {min, max} per axis.
  std::array<std::array<double, 2>, 3> travel_mm{{{-1e4, 1e4}, {-1e4, 1e4}, {-1e4, 1e4}}};
  double max_feed_mm_min = 1e5;
  JobParams defaults;  ///< feed, plunge_feed, safe_z, cut_z, spindle_rpm, tool (mm)

  int decimals(Units u) const { return u == Units::mm ? decimals_mm : decimals_inch; }
};

/// Parses a profile document; `source` names it in messages.
MachineProfile parse_machine_profile(const std::string& text, const std::string& source);
/// `name_or_file`: a path to a .json file, or a name looked up in the
/// machines directory (BEZCAM_MACHINES, then the one beside the executable,
/// then the source tree's). Throws InputError for an unknown name.
MachineProfile load_machine_profile(const std::string& name_or_file);
/// Names of the profiles in the machines directory.
std::vector<std::string> machine_profile_names();
/// The machines directory in use.
std::filesystem::path machines_dir();

}  // namespace bezcam
