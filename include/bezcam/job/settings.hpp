#pragma once
/// Job settings given as KEY=VALUE (the CLI's `--set`) for a job that has
/// no file of its own, such as a drawing read as a job: their keys checked
/// against the job file's before anything is read, their values read as
/// JSON, dotted keys made into nested objects.
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "bezcam/job/job.hpp"

namespace bezcam {

/// The settings as members of a job document, each a key and its value as
/// JSON text, in the order the keys were first given: `top` for the top
/// level (`tolerance`, `units`, `machine`), `job` for the `job` object.
struct SettingsJson {
  std::vector<std::pair<std::string, std::string>> top, job;
};

/// Reads settings given as (KEY, VALUE) text:
///  - VALUE is JSON when it reads as JSON (a number, an object, an array,
///    true, false, null, a quoted string) or as a number written the C way
///    (`.5`, `5.`); anything else is the text itself, a string
///    (`units=inch`).
///  - KEY may be dotted (`tabs.count`): each name but the last is an
///    object, created or merged into (`tabs.count=4`, `tabs.width=5` and
///    `tabs.height=1.5` make one `tabs` object). A later value of the same
///    key replaces the earlier one; an object given whole is merged into
///    the one the earlier settings made.
///  - KEY must name a key the job file has (docs/job-format.md): a
///    top-level setting, a key of `job`, a key of `lead` or `tabs` under
///    them, or one of the user's own ("x-..."). Another key is refused
///    (errc::usage_setting, at the setting `settings.KEY`), naming the key
///    it resembles or stands for (`cutz`, `depth`: `cut_z`).
/// A value of the wrong kind (`feed=fast`) is left to the job reader, which
/// refuses it with its JSON path.
SettingsJson settings_json(std::span<const std::pair<std::string, std::string>> settings);

/// The cutting parameters of one entity given as the members of its
/// object (each a key and its value as JSON text, settings_json()'s `job`
/// members), read as a job file's entity keys are read: the same keys
/// (`order` and `program_number` are the job's), the same checks. Throws
/// InputError at `source` and `path.KEY`, with the further refusals in
/// Error::more().
JobParams entity_params(std::span<const std::pair<std::string, std::string>> members, const std::string& source,
                        const std::string& path);

}  // namespace bezcam
