#pragma once
// The fonts a drawing's texts are read with, as the bezcam program gives
// them (src/cli/job_input.cpp): bezcam::text finds and measures the
// style's font (its family, or its file's name among the installed fonts;
// fontconfig's sans-serif when it is not installed) and outlines the text.
#include "bezcam/import/drawing.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam::test {

inline import::ImportOptions with_fonts(import::ImportOptions o = {}) {
  o.fonts = [](const std::string& font, bool substitute, const std::string& letters) {
    TextSpec spec;
    spec.text = letters;
    spec.font = font;
    std::string instead;
    if (substitute) {
      if (const auto f = text::installed_font(font)) {
        if (text::names_a_file(font)) spec.font = f->file.string();
      } else {
        spec.font = instead = text::default_font().family;
      }
    }
    const text::TextMeasures m = text::measure_text(spec);
    return import::FontMeasures{spec.font, instead, m.units_per_em, m.cap_height, m.descender, m.advance};
  };
  o.outline = text::font_outliner();
  return o;
}

}  // namespace bezcam::test
