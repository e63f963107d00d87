#pragma once
/// The job file's JSON reader (docs/job-format.md, version 1): parses,
/// validates, and names the JSON path of every refusal.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/job/job.hpp"
#include "bezcam/job/text.hpp"

namespace bezcam {

/// A value given on the command line for the entities of a job file whose
/// `id` the selector matches as a shell glob (`--set SELECTOR:KEY=VALUE`):
/// the entity reads as if the file held KEY with that value.
struct EntitySetting {
  std::string selector, key, value;
};

/// How a job file is read.
struct JobReadOptions {
  /// Receives the job's warnings also when the job is refused, so that a
  /// program can print them beside the refusal.
  std::vector<std::string>* warnings = nullptr;
  /// Outlines the `text` entities (bezcam::text's font_outliner()); a job
  /// with text is refused when it is empty.
  TextOutliner text;
  /// Where a text's relative font file is found; load_job() gives the job
  /// file's folder when this is empty, parse_job() the working directory.
  std::filesystem::path folder;
  /// Applied to the entities' objects before they are read, in order (a
  /// later value of a key wins). `text`, `font` and `align` take VALUE as
  /// the text itself (a quoted JSON string as that string); every other
  /// key reads VALUE as settings_json() does. Refused at the setting
  /// `settings.SELECTOR:KEY` (errc::usage_setting): a selector that
  /// matches no entity's id (naming the ids), `id` or `type`, a job-wide
  /// key, a key a job file does not have, a text's key for an entity that
  /// is not a text; a value the reader refuses is named at the setting too.
  std::vector<EntitySetting> entity_settings;
};

/// Parses and validates a job. `source` names the file in messages.
/// Throws InputError whose place is `SOURCE: json.path`; independent
/// refusals (two bad entities, a misspelt key and a bad value) come as
/// one InputError with the others in Error::more().
Job parse_job(std::string_view text, const std::string& source, const JobReadOptions& opt = {});
/// Reads a file and parses it; IoError when it cannot be read.
Job load_job(const std::filesystem::path& file, const JobReadOptions& opt = {});

}  // namespace bezcam
