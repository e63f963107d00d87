#pragma once
/// The whole post-processing step: job + profile -> validated program ->
/// text. What `bezcam convert` runs.
#include <string>

#include "bezcam/gcode/writer.hpp"
#include "bezcam/cam/validate.hpp"

namespace bezcam {

struct ConvertResult {
  Program program;
  std::string gcode;
};

/// Throws InputError (bad job, limits) before producing any text.
ConvertResult convert(const Job& job, const MachineProfile& m, const ConvertOptions& opt);

}  // namespace bezcam
