#pragma once
// The job a command reads: a job file, or a drawing (.svg, .dxf) read as
// the job it stands for with the --set settings and --layer layers; its
// warnings.
#include <string>
#include <vector>

#include "bezcam/import/drawing.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "conversion_options.hpp"

namespace bezcam::cli {

/// Reads a job file, with `settings` given to the entities their selectors
/// match. When the job is refused, the warnings found before are printed
/// first: a refusal never hides a warning.
Job read_job(const std::string& path, std::vector<EntitySetting> settings = {});
/// Reads a job file, or a drawing (.svg, .dxf) as the job it stands for,
/// with the options' --set settings and --layer layers (which apply to
/// drawings only: a job file states its own settings, but takes --set
/// ID:KEY=VALUE for its entities).
/// `drawing`, when given, receives the drawing read (check lists it).
Job read_job(const std::string& path, const ConversionOptions& o, import::Drawing* drawing = nullptr);
/// The --set and --layer options as import options (KEY=VALUE checked).
import::ImportOptions import_options(const ConversionOptions& o);
/// The --scale and --join-tolerance options as read options.
import::ReadOptions read_options(const ConversionOptions& o);
/// Prints warnings (of reading a job, of converting it) on stderr as
/// `bezcam: warning: ...`.
void print_warnings(const std::vector<std::string>& warnings);
/// The warnings as shown: those of a kind --no-warn names left out, the
/// warnings of one kind on one entity grouped into one line.
std::vector<std::string> shown_warnings(const std::vector<std::string>& warnings, const ConversionOptions& o);
/// With --strict, warnings shown are a refusal (usage.strict, exit 2,
/// nothing written), one line each.
void refuse_warnings_if_strict(const std::vector<std::string>& shown, const ConversionOptions& o);

}  // namespace bezcam::cli
