#pragma once
/// What a program does, in numbers: per entity what was asked for and
/// achieved (kind, degree, length, blocks, deviation measured and proven),
/// and for the whole program the path lengths at feed and at rapid and the
/// estimated run time. Written by `bezcam convert --report FILE.json` and,
/// in short human form, to stderr.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/gcode/best_output.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/gcode/writer.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam {

// MotionTotals and motion_totals(): machine/motion.hpp.

struct EntitySummary {
  EntityReport report;  ///< kind (type), degree, length, blocks, measured, bound
  MotionTotals motion;  ///< this entity's blocks (approach, plunge, cut, retract)
};

struct ProgramReport {
  std::string job, machine;
  Units units = Units::mm;
  OutputMode output = OutputMode::lines;
  std::string output_name = "lines";  ///< output_name(): "best" for a program convert_best() composed
  double tolerance = 0;
  int decimals = 3;
  double max_measured = 0, max_bound = 0;
  /// What the independent measurement can resolve (kMeasureResolution of
  /// the tolerance): a measured deviation above the proven bound by less
  /// than this is the measurement's own error (exact NURBS output, whose
  /// bound is often 0, measures about 1e-5 of the tolerance).
  double measurement_resolution = 0;
  /// Rate assumed for rapids (units/min) and where it comes from.
  double rapid_rate = 0;
  std::string rapid_rate_basis;
  std::vector<EntitySummary> entities;
  MotionTotals total;
  size_t gcode_lines = 0, gcode_bytes = 0;  ///< of the printed program (0 when not given)
  /// The program planned on the machine's motion model (docs/motion.md),
  /// when the profile has one: the estimated cycle time and what limits it.
  struct Planned {
    double cycle_time_s = 0, cutting_time_s = 0, rapid_time_s = 0, pause_time_s = 0;
    double programmed_feed_time_s = 0, mean_feed_ratio = 1, max_path_deviation = 0;
    size_t starved_blocks = 0, clamped_blocks = 0;
    /// The time of the cuts along curves with a time-optimal bound
    /// (MotionPlan::path_time_s; 0 when the plan has none).
    double path_time_s = 0;
  };
  std::optional<Planned> planned;
  /// The time-optimal bound of those cuts' exact paths on the machine
  /// (exact_path_bound_s(); 0: none): the same in every output mode.
  double path_bound_s = 0;
  /// The same job in the other output modes the machine takes
  /// (ConvertOptions / `compare_outputs`): output, cutting blocks, plan.
  struct Alternative {
    OutputMode output = OutputMode::lines;
    size_t blocks = 0, gcode_bytes = 0;
    Planned planned;
    bool best = false;  ///< the program convert_best() composed (`output` is not its mode)
  };
  std::vector<Alternative> alternatives;
  /// The output modes weighed per entity (gcode/best_output.hpp): what
  /// convert_best() chose for this program, or, with `compare_outputs`,
  /// what it would choose; each entity's planned time and blocks per mode.
  std::optional<OutputChoice> choice;
  /// What the cut order saved (Program::order), when it was planned.
  std::optional<OrderFigures> order;
  std::vector<std::string> warnings;
};

/// Builds the report of a program built for `m` (the rapid rate is the
/// profile's maximum feed, in the program's units). `gcode`: the printed
/// text, for its line and byte counts (may be empty).
ProgramReport make_report(const Program& p, const MachineProfile& m, std::string_view gcode = {},
                          const MotionPlan* plan = nullptr);

/// A printed program's size, counted piece by piece as it is written.
struct GcodeCounts {
  size_t bytes = 0, newlines = 0;
  char last = '\n';  ///< the last character so far ('\n' before any)
  void add(std::string_view piece);
  /// Lines: a last line without its newline counts too.
  size_t lines() const { return newlines + (last != '\n'); }
};

/// The same report from what a streamed program leaves: its counts and,
/// where the plan cannot come from the moves (a machine with a motion
/// model and no `plan`), its text read back (`read_back`; null: the
/// program's moves are planned).
ProgramReport make_report(const Program& p, const MachineProfile& m, const GcodeCounts& text, const MotionPlan* plan,
                          const Timeline* read_back);

/// What `bezcam convert` does once the program is validated and planned
/// (convert_program()): prints it to `sink` in pieces (write_gcode()),
/// never holding its text, and reports it (make_report() above, the text
/// read back as it goes where the report plans the text).
ProgramReport write_and_report(const Program& p, const MachineProfile& m, const MotionPlan* plan,
                               const GcodeSink& sink);

/// The figures of a plan that a report keeps.
ProgramReport::Planned planned_summary(const MotionPlan& plan);

/// The report as a JSON document (`"bezcam_report": 1`; lengths in program
/// units, times in seconds, deviations in units), ending with a newline.
std::string report_json(const ProgramReport& r);

/// A short human summary, a few lines for stderr: one line per entity (at
/// most `max_entities`, then a count of the rest) and one for the program.
/// Every line starts with "bezcam: " or two spaces.
std::string report_text(const ProgramReport& r, size_t max_entities = 10);

}  // namespace bezcam
