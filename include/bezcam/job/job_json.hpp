#pragma once
/// The job file's JSON reader (docs/job-format.md, version 1): parses,
/// validates, and names the JSON path of every refusal.
#include <filesystem>
#include <string>
#include <string_view>

#include "bezcam/job/job.hpp"

namespace bezcam {

/// Parses and validates a job. `source` names the file in messages.
/// Throws InputError whose place is `SOURCE: json.path`.
Job parse_job(std::string_view text, const std::string& source);
/// Reads a file and parses it; IoError when it cannot be read.
Job load_job(const std::filesystem::path& file);

}  // namespace bezcam
