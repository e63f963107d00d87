#pragma once
/// Canonical moves to G-code text in the profile's dialect: words, decimals,
/// line numbers, header and footer all come from the profile.
#include <functional>
#include <string>
#include <string_view>

#include "bezcam/cam/program.hpp"
#include "bezcam/cam/program_motion.hpp"

namespace bezcam {

/// Prints a validated program. Coordinates are printed with the profile's
/// decimals for the program's units; axis words and feeds are modal (only
/// printed when their printed value changes), as are motion words.
std::string write_gcode(const Program& p, const MachineProfile& m);

struct MotionPlan;
/// The same, with the program's plan on the machine's motion model already
/// made (plan_motion(program_timeline(p), *m.motion), any PlanDetail): the
/// header's cycle time is its, not a second plan's. Null: as above.
std::string write_gcode(const Program& p, const MachineProfile& m, const MotionPlan* plan);

/// The header's words for a cycle time of `seconds`: on the machine's
/// motion model when `m` has one, else feeds as programmed and rapids at
/// the machine's maximum feed (in `units` per minute). The sheet and the
/// preview say it in the same words.
std::string cycle_time_words(const MachineProfile& m, double seconds, Units units);

/// Receives the program's text in order, in pieces of about 64 KiB.
using GcodeSink = std::function<void(std::string_view)>;
/// The same text, streamed: never held whole in memory.
void write_gcode(const Program& p, const MachineProfile& m, const GcodeSink& sink);
/// Streamed, with the program's plan (as above; null: none).
void write_gcode(const Program& p, const MachineProfile& m, const MotionPlan* plan, const GcodeSink& sink);

}  // namespace bezcam
