#pragma once
// What convert and sheet do first: read the job (or drawing), pick its
// machine profile, build the program with the command's options, showing
// progress; a refusal prints the job's warnings before it (a refusal never
// hides a warning) and nothing is written.
#include <optional>
#include <string>

#include "bezcam/gcode/best_output.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "conversion_options.hpp"
#include "post_options.hpp"

namespace bezcam::cli {

struct JobConversion {
  Job job;
  MachineProfile machine;  ///< with the command's post options applied
  ConvertOptions options;  ///< what the program was built with (no progress callback)
  ConvertResult result;
  /// --output best: what each entity got and the modes weighed (the
  /// options' `output` is lines then, `entity_output` the choice).
  std::optional<OutputChoice> best;
};

/// `command` names the progress line ("convert", "sheet"). --output best
/// (convert_best()) needs the machine's motion model: refused at --output
/// without one.
JobConversion convert_job_file(const std::string& path, const ConversionOptions& conv, const PostOptions& post,
                               bool quiet, const char* command);

}  // namespace bezcam::cli
