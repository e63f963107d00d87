// Opening fonts with FreeType and HarfBuzz, and reading a glyph's outline
// from FreeType's points and tags.
#include "font_cache.hpp"

#include FT_OUTLINE_H

#include <map>
#include <memory>
#include <utility>

#include "bezcam/error.hpp"

namespace bezcam::text::detail {

namespace {

FT_Library library() {
  static FT_Library lib = [] {
    FT_Library l = nullptr;
    if (FT_Init_FreeType(&l)) l = nullptr;
    return l;
  }();
  return lib;
}

[[noreturn]] void not_a_font(const FontFace& face, const std::string& why) {
  throw InputError(
      errc::text_font_file, Place::at_json("font"),
      face.file.string() + " " + why + "; give a TrueType or OpenType font (.ttf, .otf, .ttc), or a family name");
}

// A font is opened once and kept: a name plate's job reads one or two.
std::map<std::pair<std::string, int>, std::unique_ptr<OpenFont>>& cache() {
  static std::map<std::pair<std::string, int>, std::unique_ptr<OpenFont>> c;
  return c;
}

std::unique_ptr<OpenFont> open_new(const FontFace& face) {
  auto f = std::make_unique<OpenFont>();
  f->face = face;
  if (!library()) not_a_font(face, "cannot be read: FreeType cannot start");
  if (FT_New_Face(library(), face.file.c_str(), face.index, &f->ft) != 0)
    not_a_font(face, "is not a font FreeType reads");
  const auto fail = [&](const std::string& why) {
    FT_Done_Face(f->ft);
    not_a_font(face, why);
  };
  if (!FT_IS_SCALABLE(f->ft)) fail("holds bitmaps, not outlines");
  if (!FT_IS_SFNT(f->ft)) fail("is not a TrueType or OpenType font (HarfBuzz shapes only those)");
  if (f->ft->units_per_EM == 0) fail("gives no units per em");
  hb_blob_t* blob = hb_blob_create_from_file_or_fail(face.file.c_str());
  if (!blob) fail("cannot be read by HarfBuzz");
  hb_face_t* hf = hb_face_create(blob, static_cast<unsigned>(face.index));
  hb_blob_destroy(blob);
  if (hb_face_get_glyph_count(hf) == 0 || hb_face_get_upem(hf) != f->ft->units_per_EM) {
    hb_face_destroy(hf);
    fail("is not a font HarfBuzz reads as FreeType does");
  }
  f->hb = hb_font_create(hf);
  hb_face_destroy(hf);
  f->units_per_em = f->ft->units_per_EM;
  hb_font_set_scale(f->hb, f->units_per_em, f->units_per_em);
  if (face.family.empty() && f->ft->family_name) f->face.family = f->ft->family_name;
  return f;
}

// A point of the outline in font units.
Vec3 at(const FT_Vector& v) { return {static_cast<double>(v.x), static_cast<double>(v.y), 0}; }
Vec3 mid(const Vec3& a, const Vec3& b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2, 0}; }

// The pieces of one contour, points first..last of the outline.
std::vector<Bezier> contour_pieces(const FT_Outline& o, int first, int last) {
  const auto tag = [&](int i) { return FT_CURVE_TAG(o.tags[i]); };
  const auto malformed = [] {
    throw InputError(errc::text_font_file, Place::at_json("font"),
                     "the font's outline of a glyph of this text is malformed (a contour starts with a cubic "
                     "control point or holds a lone one); use another font");
  };
  // Where the contour starts on the curve: its first point, else its last,
  // else the implied point between the two (both quadratic controls).
  Vec3 start;
  int from = first, to = last;
  if (tag(first) == FT_CURVE_TAG_ON) {
    start = at(o.points[first]);
    from = first + 1;
  } else if (tag(first) == FT_CURVE_TAG_CUBIC) {
    malformed();
  } else if (tag(last) == FT_CURVE_TAG_ON) {
    start = at(o.points[last]);
    to = last - 1;
  } else {
    start = mid(at(o.points[first]), at(o.points[last]));
  }
  std::vector<Bezier> out;
  const auto emit = [&](std::vector<Vec3> pts) {
    for (const Vec3& p : pts)
      if (p.x != pts[0].x || p.y != pts[0].y) {
        out.push_back(Bezier::make(std::move(pts)));
        return;
      }
  };
  Vec3 cur = start;
  std::vector<Vec3> pending;  // control points since the last on-curve point
  char pending_tag = FT_CURVE_TAG_ON;
  for (int i = from; i <= to + 1; ++i) {
    const bool closing = i == to + 1;
    const Vec3 p = closing ? start : at(o.points[i]);
    const char t = closing ? static_cast<char>(FT_CURVE_TAG_ON) : static_cast<char>(tag(i));
    if (t == FT_CURVE_TAG_ON) {
      std::vector<Vec3> pts{cur};
      pts.insert(pts.end(), pending.begin(), pending.end());
      pts.push_back(p);
      if (pending_tag == FT_CURVE_TAG_CUBIC && pending.size() != 2) malformed();
      emit(std::move(pts));
      cur = p;
      pending.clear();
      pending_tag = FT_CURVE_TAG_ON;
    } else if (t == FT_CURVE_TAG_CONIC) {
      if (pending_tag == FT_CURVE_TAG_CUBIC) malformed();
      if (!pending.empty()) {  // two quadratic controls: the implied on-curve point between them
        const Vec3 m = mid(pending[0], p);
        emit({cur, pending[0], m});
        cur = m;
        pending.clear();
      }
      pending.push_back(p);
      pending_tag = FT_CURVE_TAG_CONIC;
    } else {
      if (pending_tag == FT_CURVE_TAG_CONIC || pending.size() >= 2) malformed();
      pending.push_back(p);
      pending_tag = FT_CURVE_TAG_CUBIC;
    }
  }
  return out;
}

}  // namespace

std::mutex& font_lock() {
  static std::mutex m;
  return m;
}

const OpenFont& open_font(const FontFace& face) {
  auto& c = cache();
  const auto key = std::make_pair(face.file.string(), face.index);
  auto it = c.find(key);
  if (it == c.end()) it = c.emplace(key, open_new(face)).first;
  return *it->second;
}

std::vector<std::vector<Bezier>> glyph_contours(const OpenFont& font, unsigned glyph) {
  if (FT_Load_Glyph(font.ft, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
      font.ft->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
    throw InputError(errc::text_font_file, Place::at_json("font"),
                     "FreeType cannot read the outline of glyph " + std::to_string(glyph) + " of " +
                         font.face.file.string() + "; use another font");
  const FT_Outline& o = font.ft->glyph->outline;
  std::vector<std::vector<Bezier>> out;
  int first = 0;
  for (int c = 0; c < o.n_contours; ++c) {
    const int last = o.contours[c];
    if (last < first || last >= o.n_points) break;
    std::vector<Bezier> pieces = contour_pieces(o, first, last);
    if (!pieces.empty()) out.push_back(std::move(pieces));
    first = last + 1;
  }
  return out;
}

}  // namespace bezcam::text::detail
