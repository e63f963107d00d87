#pragma once
// What convert and sheet do first: read the job (or drawing), pick its
// machine profile, build the program with the command's options, showing
// progress; a refusal prints the job's warnings before it (a refusal never
// hides a warning) and nothing is written.
#include <string>

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
};

/// `command` names the progress line ("convert", "sheet").
JobConversion convert_job_file(const std::string& path, const ConversionOptions& conv, const PostOptions& post,
                               bool quiet, const char* command);

}  // namespace bezcam::cli
