#pragma once
// Internal to the report: the lines and the JSON of the output modes
// weighed per entity (ProgramReport::choice, gcode/best_output.hpp) and of
// the same job in each mode (ProgramReport::alternatives).
#include <nlohmann/json.hpp>
#include <string>

#include "bezcam/report/report.hpp"

namespace bezcam::detail {

/// For the summary: what `--output best` chose and the cycles it is
/// weighed against; with `--compare-outputs` each entity's planned time per
/// mode (at most `max_entities` rows); the note on NURBS; the modes left
/// out. Empty without a choice.
std::string output_choice_text(const ProgramReport& r, size_t max_entities);

/// The table of the same job in each output mode, the shortest marked.
std::string alternatives_text(const ProgramReport& r);

/// The report's "output_choice" object.
nlohmann::ordered_json output_choice_json(const ProgramReport& r);

}  // namespace bezcam::detail
