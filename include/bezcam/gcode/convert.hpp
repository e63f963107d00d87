#pragma once
/// The whole post-processing step: job + profile -> validated program ->
/// text. What `bezcam convert` runs.
#include <optional>
#include <string>

#include "bezcam/cam/validate.hpp"
#include "bezcam/gcode/writer.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam {

struct ConvertResult {
  Program program;
  std::string gcode;
  /// The program planned once on the machine's motion model (summary
  /// only; empty without a model): the header's cycle time and the
  /// report's planned figures are both this plan's.
  std::optional<MotionPlan> plan;
};

/// Throws InputError (bad job, limits) before producing any text.
ConvertResult convert(const Job& job, const MachineProfile& m, const ConvertOptions& opt);

/// convert() up to the text: the program built, validated and planned,
/// `gcode` left empty, for a caller that streams the text
/// (write_gcode() with a sink; report.hpp write_and_report()). Every
/// refusal convert() makes is made here.
ConvertResult convert_program(const Job& job, const MachineProfile& m, const ConvertOptions& opt);

/// The cycle time a program's header gives on a machine with a motion
/// model, `moves` being the plan of its moves (program_timeline()): that
/// plan's, or where the profile's tool change position lines move the
/// machine between tools (in the text only), the text's read back and
/// planned. The summary, the sheet and the preview give the same.
double program_cycle_time_s(const Program& p, const MachineProfile& m, const MotionPlan& moves);
/// The plan whose times the header and the report give: `moves` (the plan
/// of the program's moves), its times replaced by the text's read back
/// where program_cycle_time_s() plans the text (the rest, e.g. the time
/// along the curves and the segments, stays the moves').
MotionPlan program_plan(const Program& p, const MachineProfile& m, MotionPlan moves);

}  // namespace bezcam
