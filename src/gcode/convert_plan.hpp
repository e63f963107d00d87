#pragma once
// Internal to gcode/: where a built program's plan comes from.
#include "bezcam/cam/program.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam::detail {

/// Whether the program's moves are the printed program's motion (then
/// convert_program() plans them), or not: where the profile's tool change
/// position lines (e.g. G53 G00 Z0.) run after the program has moved, a
/// motion the moves do not hold, the report plans the text read back.
bool plans_from_moves(const Program& p, const MachineProfile& m);

}  // namespace bezcam::detail
