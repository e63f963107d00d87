// A drawing's text laid out as a job's text entity: the drawing gives the
// capitals' height and an alignment point, the job an em size and the
// baseline's point; the font's measures turn one into the other.
#include "drawing_text.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/format.hpp"
#include "bezcam/warnings.hpp"
#include "selection.hpp"

namespace bezcam::import {

namespace {

std::string where(const DrawingText& t) {
  return "layer \"" + t.layer + "\", " + t.element + " at (" + format_significant(t.at.x, 6) + ", " +
         format_significant(t.at.y, 6) + ")";
}

}  // namespace

std::vector<const DrawingText*> kept_texts(const Drawing& d, const std::set<std::string>& keep,
                                           const ImportOptions& opt) {
  const auto any = [](const std::vector<std::string>& sels, const DrawingText& t) {
    return std::any_of(sels.begin(), sels.end(), [&](const std::string& s) { return selects(s, t.layer, t.id); });
  };
  std::vector<const DrawingText*> out;
  for (const DrawingText& t : d.texts)
    if ((keep.empty() || keep.count(t.layer)) && (opt.only.empty() || any(opt.only, t)) && !any(opt.skip, t))
      out.push_back(&t);
  return out;
}

TextSpec text_spec(const DrawingText& t, const ImportOptions& opt, const std::string& source,
                   std::vector<std::string>* warnings) {
  // The text's own keys from scoped settings: the last that picks it wins.
  const ScopedSetting* font_set = nullptr;
  TextSpec spec;
  spec.text = t.text;
  for (const ScopedSetting& s : opt.scoped)
    if (is_text_key(s.key) && selects(s.selector, t.layer, t.id)) {
      if (s.key == "font") font_set = &s;
      if (s.key == "text") spec.text = s.value;
    }
  if (!opt.fonts || !opt.outline)
    throw InputError(errc::text_unavailable, Place::at_file(source),
                     where(t) + ": this program reads no fonts, so the drawing's text cannot be cut; skip " + t.id +
                         " or read the drawing with the bezcam program");
  if (!font_set && t.stroke_font)
    throw InputError(errc::import_text, Place::at_file(source),
                     where(t) + ": its style \"" + t.style + "\" names the stroke font \"" + t.font +
                         "\" (SHX), which has no outlines to cut; set a TrueType or OpenType font for its layer, "
                         "for example set '" +
                         t.layer + ":font=DejaVu Sans' (for this text alone: set '" + t.id +
                         ":font=DejaVu Sans'), or skip " + t.id);
  FontMeasures m;
  try {
    m = font_set ? opt.fonts(font_set->value, false, spec.text) : opt.fonts(t.font, true, spec.text);
  } catch (const InputError& e) {
    if (!font_set) throw;
    Place p = Place::at_setting("settings." + font_set->selector + ":font");
    p.file = source;
    throw InputError(e.id(), p, e.message());
  }
  if (!m.substitute.empty() && warnings)
    warnings->push_back(tagged_warning(
        "text \"" + t.id + "\" (" + where(t) + "): its style \"" + t.style + "\" names " +
            (t.font.empty() ? std::string("no font") : "the font \"" + t.font + "\", which is not installed") +
            "; it is cut in \"" + m.substitute + "\" instead (set '" + t.layer + ":font=FAMILY' names another)",
        "font-substituted"));
  if (!(m.units_per_em > 0) || !(m.cap_height > 0))
    throw InputError(errc::import_text, Place::at_file(source),
                     where(t) + ": the font \"" + m.font +
                         "\" gives no height of its capitals, so the drawing's text height cannot be met; set "
                         "another: '" +
                         t.layer + ":font=FAMILY'");
  spec.font = m.font;
  if (t.to) {
    // Aligned: the line's advance spans the two points.
    const Vec3 d = *t.to - t.at;
    if (!(m.advance > 0))
      throw InputError(errc::import_text, Place::at_file(source),
                       where(t) + ": an aligned text needs letters with an advance, found none");
    spec.size = std::hypot(d.x, d.y) * m.units_per_em / m.advance;
    spec.angle = std::atan2(d.y, d.x) * 180 / std::numbers::pi;
    spec.at = t.at;
    spec.align = TextAlign::left;
    return spec;
  }
  // The capitals are `height` high: the em is height * units_per_em / cap_height.
  spec.size = t.height * m.units_per_em / m.cap_height;
  spec.angle = t.angle;
  spec.align = t.along == 0 ? TextAlign::left : t.along == 1 ? TextAlign::right : TextAlign::center;
  // The baseline below the alignment point, across the line.
  double up = 0;
  switch (t.vertical) {
    case DrawingText::Vertical::baseline: break;
    case DrawingText::Vertical::bottom: up = -m.descender * spec.size / m.units_per_em; break;
    case DrawingText::Vertical::middle: up = -t.height / 2; break;
    case DrawingText::Vertical::top: up = -t.height; break;
  }
  const double a = t.angle * std::numbers::pi / 180;
  spec.at = {t.at.x - std::sin(a) * up, t.at.y + std::cos(a) * up, 0};
  return spec;
}

}  // namespace bezcam::import
