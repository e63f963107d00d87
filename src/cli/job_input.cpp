// Reading the job of convert, check, preview and import: a job file or a
// drawing with the --set and --layer options.
#include "job_input.hpp"

#include <algorithm>
#include <iostream>

#include "bezcam/error.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/settings.hpp"
#include "bezcam/text/font_text.hpp"
#include "bezcam/warnings.hpp"

namespace bezcam::cli {

std::vector<std::string> shown_warnings(const std::vector<std::string>& warnings, const ConversionOptions& o) {
  std::vector<std::string> kept;
  for (const auto& w : warnings) {
    const std::string kind = warning_kind(w);
    if (kind.empty() || std::find(o.no_warn.begin(), o.no_warn.end(), kind) == o.no_warn.end()) kept.push_back(w);
  }
  return grouped_warnings(kept);
}

void refuse_warnings_if_strict(const std::vector<std::string>& shown, const ConversionOptions& o) {
  if (!o.strict || shown.empty()) return;
  const auto refusal = [](const std::string& w) {
    return InputError(errc::usage_strict, Place::at_option("--strict"), "warning taken as an error: " + w);
  };
  InputError first = refusal(shown.front());
  for (size_t i = 1; i < shown.size(); ++i) first.add_more(refusal(shown[i]));
  throw first;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) std::cerr << "bezcam: warning: " << w << "\n";
}

Job read_job(const std::string& path, std::vector<EntitySetting> settings) {
  std::vector<std::string> warnings;
  JobReadOptions ro;
  ro.entity_settings = std::move(settings);
  ro.warnings = &warnings;
  ro.text = text::font_outliner();
  try {
    return load_job(path, ro);
  } catch (const Error&) {
    print_warnings(warnings);
    throw;
  }
}

namespace {
// A drawing's text font (import::FontMeasurer) found and measured by
// bezcam::text: a style's family or font file's name among the installed
// fonts, else (with `substitute`) fontconfig's sans-serif.
import::FontMeasures measure_font(const std::string& font, bool substitute, const std::string& letters){TextSpec spec;
spec.text = letters;
spec.font = font;
std::string used_instead;
if (substitute) {
  if (const std::optional<text::FontFace> f = text::installed_font(font)) {
    if (text::names_a_file(font)) spec.font = f->file.string();
  } else {
    spec.font = text::default_font().family;
    used_instead = spec.font;
  }
}
const text::TextMeasures m = text::measure_text(spec);
return {spec.font, used_instead, m.units_per_em, m.cap_height, m.descender, m.advance};
}  // namespace

// KEY=VALUE of --set.
std::pair<std::string, std::string> split_setting(const std::string& kv) {
  const size_t eq = kv.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(errc::import_setting, Place::at_option("--set"),
                     "expected KEY=VALUE (for example --set feed=600), found \"" + kv + "\"");
  return {kv.substr(0, eq), kv.substr(eq + 1)};
}
}  // namespace bezcam::cli

import::ImportOptions import_options(const ConversionOptions& o){import::ImportOptions io;
for (const auto& kv : o.sets) {
  auto [key, value] = split_setting(kv);
  // SELECTOR:KEY: keys have no colon, selectors (DXF ids) may.
  if (const size_t colon = key.rfind(':'); colon != std::string::npos)
    io.scoped.push_back({key.substr(0, colon), key.substr(colon + 1), value});
  else
    io.settings.emplace_back(std::move(key), std::move(value));
}
// Keys and values checked before the drawing is read: an unknown key is
// a mistake on the command line, whatever the drawing holds.
(void)settings_json(io.settings);
import::check_options(io);
io.layers = o.layers;
io.only = o.only;
io.skip = o.skip;
io.fonts = measure_font;
io.outline = text::font_outliner();
return io;
}  // namespace bezcam::cli

import::ReadOptions read_options(const ConversionOptions& o){import::ReadOptions ro;
ro.scale = o.scale;
ro.join_tolerance = o.join_tolerance;
ro.units = o.units;
return ro;
}

Job read_job(const std::string& path, const ConversionOptions& o, import::Drawing* drawing) {
  if (!import::is_drawing(path)) {
    // SELECTOR:KEY=VALUE settings the job's entities; the rest is the
    // file's to say.
    std::vector<EntitySetting> entity_settings;
    bool unscoped = false;
    for (const auto& kv : o.sets) {
      auto [key, value] = split_setting(kv);
      if (const size_t colon = key.rfind(':'); colon != std::string::npos)
        entity_settings.push_back({key.substr(0, colon), key.substr(colon + 1), value});
      else
        unscoped = true;
    }
    const char* option = unscoped               ? "--set"
                         : !o.layers.empty()    ? "--layer"
                         : !o.only.empty()      ? "--only"
                         : !o.skip.empty()      ? "--skip"
                         : o.join_tolerance > 0 ? "--join-tolerance"
                         : o.scale != 1         ? "--scale"
                         : !o.units.empty()     ? "--units"
                                                : nullptr;
    if (option)
      throw InputError(errc::import_setting, Place::at_option(option),
                       path +
                           " is a job file, which states its own settings and has no layers; --set KEY=VALUE, "
                           "--layer, --only, --skip, --scale and --units apply to drawings (.svg, .dxf); --set "
                           "ID:KEY=VALUE sets a key "
                           "of the job's entities whose id ID matches");
    Job job = read_job(path, std::move(entity_settings));
    job.warnings = shown_warnings(job.warnings, o);
    return job;
  }
  const import::ImportOptions io = import_options(o);
  import::Drawing d = import::read_drawing(path, read_options(o));
  if (drawing) *drawing = d;
  std::vector<std::string> warnings;
  try {
    Job job = import::to_job(d, io, &warnings);
    // Printed with the job's own warnings, as a job file's are.
    job.warnings.insert(job.warnings.begin(), warnings.begin(), warnings.end());
    job.warnings = shown_warnings(job.warnings, o);
    return job;
  } catch (const Error&) {
    print_warnings(shown_warnings(warnings, o));
    throw;
  }
}

}  // namespace bezcam::cli
