// A line of text as placed glyph outlines: shaped by HarfBuzz in font
// units, each glyph's outline from FreeType moved to its pen position,
// scaled, aligned and turned in one affine map per point.
#include "bezcam/text/font_text.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "bezcam/error.hpp"
#include "bezcam/flatten/nesting.hpp"
#include "font_cache.hpp"

namespace bezcam::text {

namespace {

// The character that starts at byte `at` of UTF-8 `s`, and its length.
std::pair<char32_t, size_t> decode(const std::string& s, size_t at) {
  const auto b = [&](size_t i) { return i < s.size() ? static_cast<unsigned char>(s[i]) : 0u; };
  const unsigned c = b(at);
  if (c < 0x80) return {c, 1};
  if ((c >> 5) == 0x6) return {((c & 0x1f) << 6) | (b(at + 1) & 0x3f), 2};
  if ((c >> 4) == 0xe) return {((c & 0x0f) << 12) | ((b(at + 1) & 0x3f) << 6) | (b(at + 2) & 0x3f), 3};
  return {((c & 0x07) << 18) | ((b(at + 1) & 0x3f) << 12) | ((b(at + 2) & 0x3f) << 6) | (b(at + 3) & 0x3f), 4};
}

std::string code_point(char32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}

// A character as a message shows it: itself and its code point, or the
// code point alone for a control character.
std::string shown(const std::string& text, size_t at) {
  const auto [c, n] = decode(text, at);
  if (c < 0x20 || c == 0x7f) return code_point(c);
  return "\"" + text.substr(at, n) + "\" (" + code_point(c) + ")";
}

// A text is one line: a line break or another control character is refused.
void check_line(const std::string& text) {
  for (size_t i = 0; i < text.size();) {
    const auto [c, n] = decode(text, i);
    if (c < 0x20 || c == 0x7f)
      throw InputError(errc::text_glyph, Place::at_json("text"),
                       "expected one line of text, found the control character " + code_point(c) + " at byte " +
                           std::to_string(i) +
                           (c == '\n' || c == '\r' ? "; write one text entity per line" : "; leave it out"));
    i += n;
  }
}

// Where a point of the font (units) goes in the job: the affine map of
// the spec, the same for every point of the text.
struct Placement {
  double scale, cos_a, sin_a, shift;
  Vec3 at;
  Vec3 operator()(const Vec3& p, double pen_x, double pen_y) const {
    const double x = (pen_x + p.x - shift) * scale, y = (pen_y + p.y) * scale;
    return {at.x + cos_a * x - sin_a * y, at.y + sin_a * x + cos_a * y, 0};
  }
};

}  // namespace

std::vector<Glyph> outline_text(const TextSpec& spec) {
  if (!(spec.size > 0) || !std::isfinite(spec.size))
    throw InputError(errc::job_not_positive, Place::at_json("size"),
                     "expected an em size > 0, found " + fmt_num(spec.size));
  check_line(spec.text);
  const FontFace face = find_font(spec.font, spec.folder);
  const std::lock_guard<std::mutex> lock(detail::font_lock());
  const detail::OpenFont& font = detail::open_font(face);

  hb_buffer_t* buf = hb_buffer_create();
  hb_buffer_add_utf8(buf, spec.text.data(), static_cast<int>(spec.text.size()), 0, -1);
  hb_buffer_guess_segment_properties(buf);
  hb_shape(font.hb, buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
  std::vector<hb_glyph_info_t> infos(info, info + n);
  std::vector<hb_glyph_position_t> positions(pos, pos + n);
  hb_buffer_destroy(buf);

  // A cluster's characters run from its first byte to the next cluster's.
  std::set<size_t> starts{spec.text.size()};
  for (const auto& g : infos) starts.insert(g.cluster);
  double total = 0;
  for (size_t i = 0; i < infos.size(); ++i) {
    if (infos[i].codepoint == 0)
      throw InputError(errc::text_glyph, Place::at_json("text"),
                       "the font \"" + font.face.family + "\" (" + font.face.file.string() + ") has no glyph for " +
                           shown(spec.text, infos[i].cluster) + "; leave the character out, or use a font that has it");
    total += positions[i].x_advance;
  }
  const double shift = spec.align == TextAlign::left ? 0 : spec.align == TextAlign::center ? total / 2 : total;
  const double rad = spec.angle * std::numbers::pi / 180;
  const Placement place{spec.size / font.units_per_em, std::cos(rad), std::sin(rad), shift, spec.at};

  std::vector<Glyph> out;
  double pen_x = 0, pen_y = 0;
  for (size_t i = 0; i < infos.size(); ++i) {
    const double ox = pen_x + positions[i].x_offset, oy = pen_y + positions[i].y_offset;
    pen_x += positions[i].x_advance;
    pen_y += positions[i].y_advance;
    std::vector<std::vector<Bezier>> contours = detail::glyph_contours(font, infos[i].codepoint);
    if (contours.empty()) continue;  // a space
    Glyph g;
    const size_t from = infos[i].cluster, to = *starts.upper_bound(from);
    g.characters = spec.text.substr(from, to - from);
    for (auto& c : contours)
      for (Bezier& b : c)
        for (Vec3& p : b.points) p = place(p, ox, oy);
    const Nesting nest = nest_closed_curves(contours);
    for (size_t k = 0; k < contours.size(); ++k) g.contours.push_back({std::move(contours[k]), nest.depth[k] % 2 == 1});
    out.push_back(std::move(g));
  }
  return out;
}

TextOutliner font_outliner() {
  return [](const TextSpec& s) { return outline_text(s); };
}

}  // namespace bezcam::text
