#pragma once
/// The whole program is checked against the profile before one character
/// is written: travel limits (arcs by their full extent), maximum feed,
/// rapids only at or above safe Z.
#include "bezcam/cam/program.hpp"

namespace bezcam {

/// Throws InputError naming the entity and the axis or feed at fault.
void validate_program(const Program& p, const MachineProfile& m);

}  // namespace bezcam
