#pragma once
/// The whole post-processing step: job + profile -> validated program ->
/// text. What `bezcam convert` runs.
#include <string>

#include "bezcam/post/gcode_writer.hpp"
#include "bezcam/post/validate.hpp"

namespace bezcam {

struct ConvertResult {
  Program program;
  std::string gcode;
};

/// Throws InputError (bad job, limits) before producing any text.
ConvertResult convert(const Job& job, const MachineProfile& m, const ConvertOptions& opt);

/// Picks the profile: `cli_machine` if set, else the job's, else "generic".
MachineProfile resolve_profile(const Job& job, const std::string& cli_machine);

}  // namespace bezcam
