#pragma once
/// A machine profile: everything that differs between controllers, as data
/// (machines/NAME.json; docs/machines.md documents every key).
#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bezcam/flatten/exact_blocks.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/kernel/units.hpp"

namespace bezcam {

/// The travel of a profile that states none.
inline constexpr double kNoTravelLimit = std::numeric_limits<double>::infinity();

/// How the controller moves (key `motion`, docs/machines.md): the limits
/// and timing its trajectory planner works with. The simulated controller
/// and the cycle-time estimate plan with them (machine/planner.hpp).
struct MotionModel {
  std::array<double, 3> max_velocity_mm_min{};  ///< per axis x, y, z
  std::array<double, 3> max_acceleration_mm_s2{};
  /// Per axis; absent for an acceleration-limited (trapezoidal) planner.
  std::optional<std::array<double, 3>> max_jerk_mm_s3;
  double period_s = 0.001;  ///< trajectory period
  /// A block of length L runs at most at L / (this x period_s); 0: no cap.
  double min_segment_periods = 0;
  double block_rate_hz = 0;   ///< most blocks started per second; 0: no cap
  int lookahead_blocks = 50;  ///< blocks the planner sees ahead
  /// Largest distance the executed path may leave the programmed one at a
  /// corner (the controller's default path mode); 0: exact stop.
  double blend_tolerance_mm = 0;
  double tool_change_s = 0, spindle_start_s = 0;
  /// Which planner the controller has (key `planner`): `generic` (a
  /// look-ahead planner with blend arcs; the analytic cases hold exactly)
  /// or `linuxcnc` (LinuxCNC 2.9's trajectory planner: half acceleration on
  /// arcs and on moves whose end is not blended, tangent kinks, rapids
  /// blended with feeds, blends at arcs between secants; docs/motion.md).
  enum class Planner { generic, linuxcnc };
  Planner planner = Planner::generic;
};

/// The canned drilling cycles G81, G82, G83 and G73 the controller runs
/// (key `canned_cycles`, docs/machines.md; docs/gcode-dialects.md says
/// how the dialects differ).
struct CannedCycles {
  /// `none`: no canned cycles (Grbl); `linuxcnc`: LinuxCNC 2.9's
  /// interpreter; `fanuc`: Fanuc's (ISO) cycles.
  enum class Dialect { none, linuxcnc, fanuc };
  Dialect dialect = Dialect::linuxcnc;
  /// G73: how far the drill backs off after each peck (mm).
  double g73_retract_mm = 0.254;
  /// G83: how far above the last depth the rapid back into the hole
  /// stops (mm).
  double g83_clearance_mm = 0.254;
};

/// LinuxCNC 2.9 (G83_RAPID_DELTA: 0.010 inch for both).
inline constexpr double kLinuxcncPeckClearanceMm = 0.254;
/// The `fanuc` dialect's defaults (Fanuc parameters 5114 and 5115).
inline constexpr double kFanucPeckClearanceMm = 1.0;

struct MachineProfile {
  std::string name;
  std::string description;
  std::vector<std::string> header;  ///< raw lines before the program
  std::vector<std::string> footer;  ///< raw lines after the final retract
  bool line_numbers = false;
  int line_start = 10, line_step = 10;
  int decimals_mm = 3, decimals_inch = 4;
  /// The most coordinate decimals the controller accepts (key
  /// `max_decimals`): a tolerance the default decimals cannot hold gets as
  /// many as it needs, up to these (default: the decimals themselves).
  int max_decimals_mm = -1, max_decimals_inch = -1;
  int feed_decimals = 1;
  std::string word_rapid = "G00", word_feed = "G01", word_cw = "G02", word_ccw = "G03";
  std::string tool_change = "T{tool} M06";  ///< {tool} is replaced
  std::string spindle_on = "S{rpm} M03";    ///< {rpm} is replaced
  std::string spindle_off = "M05";
  /// Lines after the units line (`G21 G90 G17`): the safety line and the
  /// work offset a machinist's post writes (`G40 G49 G80 G94`, `G54`).
  std::vector<std::string> preamble;
  /// After each tool change: tool length compensation (`G43 H{tool}`),
  /// empty for none.
  std::string tool_length;
  /// False for a machine without an automatic tool changer (Grbl): a tool
  /// change becomes spindle off, retract, `M0` naming the tool.
  bool tool_changer = true;
  /// Lines before each tool change (and before the M00 of a manual one):
  /// the move to the tool-change position (`G53 G00 Z0.`: machine Z zero,
  /// the top of travel). After them the tool's position is unknown: the
  /// next approach rapids Z to safe Z first.
  std::vector<std::string> tool_change_position;
  /// Seconds to dwell (`G4 P-`) after the spindle starts, for a controller
  /// that does not wait for the spindle's speed itself; 0 for none.
  double spindle_dwell_s = 0;
  /// Comments in the program (header, entities, notes); false for a
  /// controller or a shop that wants none (`--no-comments`). M00's
  /// message to the operator stays.
  bool comments = true;
  /// No repeated words inside exact-curve blocks: a Fanuc G06.2 point
  /// omits Z and R equal to the previous point's (`--modal`).
  bool modal = false;
  /// The program number when the job gives none: {program} in the header
  /// (Fanuc `O{program}`, printed with at least 4 digits).
  long program_number = 1000;
  bool arcs = true;
  /// Cutter radius compensation (G41/G42 D-, G40) is available (Grbl: no).
  bool cutter_compensation = true;
  /// The controller's tool table as far as compensation needs it: the
  /// diameter (mm) each D register holds (`tool_diameters_mm`, or
  /// `--tool-diameter T=D` on the command line). A program that asks for
  /// G41/G42 with a D not listed is refused by the reader.
  std::map<int, double> tool_diameters_mm;
  double arc_tolerance_mm = 0.002;  ///< allowed radius mismatch of a printed arc
  NurbsDialect nurbs = NurbsDialect::none;
  std::string nurbs_start_word = "G06.2";
  int nurbs_max_rank = 4;
  /// Key `canned_cycles`; without it the dialect follows `nurbs` (a
  /// LinuxCNC profile: LinuxCNC's, any other: Fanuc's).
  CannedCycles cycles;
  int knot_decimals = 4, weight_decimals = 4;
  /// NURBS block numbers printed with all their decimals (`K0.000000
  /// X55.507 Y52.139 Z0.000 R1.000`, the seeds' listing) instead of with
  /// trailing zeros trimmed (`K0. X55.507 ... R1.`).
  bool nurbs_fixed_decimals = false;
  /// Travel in program coordinates, mm: {min, max} per axis; none (the
  /// whole line) unless the profile gives it: `generic` is not a machine.
  std::array<std::array<double, 2>, 3> travel_mm{
      {{-kNoTravelLimit, kNoTravelLimit}, {-kNoTravelLimit, kNoTravelLimit}, {-kNoTravelLimit, kNoTravelLimit}}};
  double max_feed_mm_min = 1e5;
  /// The motion model (key `motion`); every shipped profile has one. A
  /// user's profile without it can still convert and be checked, but has
  /// no planned cycle time.
  std::optional<MotionModel> motion;
  JobParams defaults;  ///< feed, plunge_feed, safe_z, cut_z, spindle_rpm, tool (mm)

  int decimals(Units u) const { return u == Units::mm ? decimals_mm : decimals_inch; }
  int max_decimals(Units u) const {
    const int m = u == Units::mm ? max_decimals_mm : max_decimals_inch;
    return std::max(m, decimals(u));
  }
};

/// Parses a profile document; `source` names it in messages.
MachineProfile parse_machine_profile(const std::string& text, const std::string& source);
/// The folders searched for a profile given by name, in order: each entry
/// of the BEZCAM_MACHINES environment variable (':'-separated), then
/// `extra`. The library holds no source path: a program that links bezcam
/// passes its own folders (the CLI adds ../machines beside its executable,
/// the build tree's, and ../share/bezcam/machines, where `cmake --install`
/// puts the shipped profiles; the CMake package names that folder in
/// `bezcam_MACHINES_DIR`).
std::vector<std::filesystem::path> machine_search_path(const std::vector<std::filesystem::path>& extra = {});

/// `name_or_file`: a path to a .json file, or a name looked up in `dirs`
/// (the first folder that holds NAME.json wins). Throws InputError
/// (machine.unknown) for an unknown or invalid name, listing the known ones.
MachineProfile load_machine_profile(const std::string& name_or_file,
                                    const std::vector<std::filesystem::path>& dirs = machine_search_path());
/// Names of the profiles found in `dirs`, sorted, without duplicates.
std::vector<std::string> machine_profile_names(const std::vector<std::filesystem::path>& dirs = machine_search_path());

}  // namespace bezcam
