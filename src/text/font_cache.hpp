#pragma once
// The fonts bezcam has opened (private to bezcam::text): each face once,
// with FreeType (outlines) and HarfBuzz (shaping) over the same file.
#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb.h>
#include <mutex>
#include <vector>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam::text::detail {

struct OpenFont {
  FontFace face;
  FT_Face ft = nullptr;     ///< FreeType's library owns it (it lives until exit)
  hb_font_t* hb = nullptr;  ///< its scale is the units per em: positions in font units
  int units_per_em = 0;
  OpenFont() = default;
  OpenFont(const OpenFont&) = delete;
  OpenFont& operator=(const OpenFont&) = delete;
  ~OpenFont() {
    if (hb) hb_font_destroy(hb);
  }
};

/// The font `face` names, opened once per process (the cache lives until
/// exit). The caller holds font_lock(). Throws InputError at `font`
/// (errc::text_font_file) when FreeType or HarfBuzz does not read it as a
/// scalable TrueType or OpenType font.
const OpenFont& open_font(const FontFace& face);
/// FreeType and the cache are used by one thread at a time.
std::mutex& font_lock();

/// The closed contours of glyph `glyph` in font units, as the outline's
/// points and tags hold them (FreeType loads it unscaled and unhinted):
/// on-curve points, quadratic (TrueType) and cubic (CFF) control points,
/// the implied on-curve point between two quadratic control points at
/// their exact midpoint. Pieces of zero length are left out, and contours
/// with none are. Throws InputError at `text` when the outline is malformed.
std::vector<std::vector<Bezier>> glyph_contours(const OpenFont& font, unsigned glyph);

}  // namespace bezcam::text::detail
