// A line of text measured in its font: the units per em, the capitals'
// height, the descender and the shaped line's advance, in font units.
#include <ft2build.h>
#include FT_TRUETYPE_TABLES_H

#include "bezcam/error.hpp"
#include "bezcam/text/font_text.hpp"
#include "font_cache.hpp"

namespace bezcam::text {

namespace {

// The top of the outline of the glyph of `c` (font units), or nothing when
// the font has no such glyph or it has no ink.
std::optional<double> glyph_top(const detail::OpenFont& font, char32_t c) {
  const FT_UInt g = FT_Get_Char_Index(font.ft, c);
  if (g == 0) return std::nullopt;
  const std::vector<std::vector<Bezier>> contours = detail::glyph_contours(font, g);
  std::optional<double> top;
  // The highest control point: the top of "H" is a straight edge.
  for (const auto& contour : contours)
    for (const Bezier& b : contour)
      for (const Vec3& p : b.points)
        if (!top || p.y > *top) top = p.y;
  return top;
}

}  // namespace

TextMeasures measure_text(const TextSpec& spec) {
  const FontFace face = find_font(spec.font, spec.folder);
  const std::lock_guard<std::mutex> lock(detail::font_lock());
  const detail::OpenFont& font = detail::open_font(face);
  TextMeasures m;
  m.face = font.face;
  m.units_per_em = font.units_per_em;
  m.descender = font.ft->descender;
  if (const std::optional<double> h = glyph_top(font, U'H')) {
    m.cap_height = *h;
  } else if (const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(font.ft, FT_SFNT_OS2));
             os2 && os2->version != 0xFFFF && os2->version >= 2 && os2->sCapHeight > 0) {
    m.cap_height = os2->sCapHeight;
  } else {
    m.cap_height = font.ft->ascender;
  }
  hb_buffer_t* buf = hb_buffer_create();
  hb_buffer_add_utf8(buf, spec.text.data(), static_cast<int>(spec.text.size()), 0, -1);
  hb_buffer_guess_segment_properties(buf);
  hb_shape(font.hb, buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
  for (unsigned i = 0; i < n; ++i) m.advance += pos[i].x_advance;
  hb_buffer_destroy(buf);
  return m;
}

}  // namespace bezcam::text
