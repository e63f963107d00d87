#pragma once
/// The setup sheet: one self-contained HTML page (inline style, the
/// picture inline as SVG, no script, nothing fetched) that the operator
/// sets the machine up from: the part's picture, the stock and the origin,
/// the tools, the operations in order, the cycle time and the guarantees.
/// Every figure is the program's own (the one its header prints):
/// the sheet is made from the same Program, plan and report.
///
/// Element ids and classes (stable, for tests and for styling): sections
/// `picture`, `stock`, `tools`, `operations`, `times`, `guarantees`,
/// `header`; the tool rows `tr.tool` (data-tool = the T number), the
/// operation rows `tr.operation` (data-entity = the job's index); the
/// cycle time `cycle-time`, the chord error line `chord-error`.
#include <string>
#include <vector>

#include "bezcam/cam/program.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/planner.hpp"
#include "bezcam/report/report.hpp"

namespace bezcam {

struct SetupSheetInput {
  const Job* job = nullptr;
  const Program* program = nullptr;  ///< built from `job` for `machine`, validated
  const MachineProfile* machine = nullptr;
  const ProgramReport* report = nullptr;  ///< the program's (make_report(), write_and_report())
  /// The program's moves planned on the machine's motion model with
  /// per-block figures (plan_motion(program_timeline(p), model,
  /// PlanDetail::full)): the header's cycle time and each tool's time;
  /// null without a motion model.
  const MotionPlan* plan = nullptr;
  std::string picture_svg;          ///< the preview (preview_svg()), inlined
  std::vector<std::string> header;  ///< the program's header comment lines, as printed
  std::string title;                ///< what the sheet is for (the job's file)
};

/// One tool as the sheet lists it.
struct SheetTool {
  int number = -1;    ///< -1: the machine's default tool, unnumbered
  std::string shape;  ///< "flat end mill", ...
  std::optional<double> diameter, corner_radius, angle, flute_length;
  std::vector<std::string> entities;  ///< the labels of the entities it cuts, in cutting order
  double top_z = 0, deepest_z = 0;    ///< the stock top its entities start from, its deepest cutting point
  double time_s = 0;                  ///< its entities' moves (motion model, else programmed feeds)
};

/// The tools of the program in the order they are loaded.
std::vector<SheetTool> sheet_tools(const SetupSheetInput& in);

/// The estimated cycle time in seconds, as the program's header plans it:
/// the program's moves on the machine's motion model, else feeds as
/// programmed and rapids at the maximum feed.
double sheet_cycle_seconds(const SetupSheetInput& in);

/// The estimated cycle time as the program's header says it: "1 min 05 s
/// on the motion model of machine fanuc", or without a motion model "..:
/// feeds as programmed, rapids at ...".
std::string sheet_cycle_time(const SetupSheetInput& in);

/// The chord error as the header states it: "tolerance 0.01 mm; largest
/// deviation measured 0.0093 mm, proven bound 0.0098 mm, rounding
/// included".
std::string sheet_chord_error(const Program& p);

/// The page. Throws std::invalid_argument when job, program, machine or
/// report is missing.
std::string setup_sheet_html(const SetupSheetInput& in);

}  // namespace bezcam
