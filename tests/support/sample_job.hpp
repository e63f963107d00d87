#pragma once
// A sample's job as the bezcam program reads it: its text entities
// outlined from fonts (bezcam::text), which a bare load_job() refuses.
#include <filesystem>

#include "bezcam/job/job_json.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam::test {

inline Job load_sample(const std::filesystem::path& file) {
  JobReadOptions o;
  o.text = text::font_outliner();
  return load_job(file, o);
}

}  // namespace bezcam::test
