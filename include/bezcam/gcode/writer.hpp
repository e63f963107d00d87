#pragma once
/// Canonical moves to G-code text in the profile's dialect: words, decimals,
/// line numbers, header and footer all come from the profile.
#include <string>

#include "bezcam/cam/program.hpp"

namespace bezcam {

/// Prints a validated program. Coordinates are printed with the profile's
/// decimals for the program's units; axis words and feeds are modal (only
/// printed when their printed value changes), as are motion words.
std::string write_gcode(const Program& p, const MachineProfile& m);

}  // namespace bezcam
