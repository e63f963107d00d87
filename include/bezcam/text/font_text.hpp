#pragma once
/// Text from fonts (docs/text.md): a line of text as its glyphs' own
/// outlines, the TrueType quadratic and CFF cubic Béziers exactly as the
/// font holds them, shaped with the font's kerning and positioning. Fonts
/// are read with FreeType, shaped with HarfBuzz and found with fontconfig,
/// which no header of bezcam includes.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bezcam/job/text.hpp"

namespace bezcam::text {

/// A font face: its file, the face's index in it, its family name.
struct FontFace {
  std::filesystem::path file;
  int index = 0;
  std::string family;
};

/// Whether `font` names a file rather than a family: it holds a slash or
/// ends in a font file's extension (.ttf, .otf, .ttc, .otc, .pfb, .pfa,
/// .t1, .woff, .woff2; any case).
bool names_a_file(const std::string& font);

/// The face `font` names: a file (relative to `folder` unless absolute),
/// or a fontconfig pattern (`DejaVu Sans`, `DejaVu Sans:bold`) whose
/// family is installed. Throws InputError at `font`: errc::text_font when
/// fontconfig has not that family (the message names the nearest installed
/// ones and what fontconfig would have used instead), errc::text_font_file
/// when the file does not exist.
FontFace find_font(const std::string& font, const std::filesystem::path& folder);

/// The glyphs of `spec` (job/text.hpp), in order along the line, placed:
/// font units times size / units per em, the pen from `at` along the
/// baseline with HarfBuzz's advances and offsets, shifted by the
/// alignment, turned by the angle about `at`. Each contour is closed with
/// the pieces the font's outline holds (lines, quadratic or cubic Béziers;
/// TrueType's implied on-curve points at the exact midpoints), with no
/// piece of zero length. Throws InputError at `font` (find_font(), and
/// errc::text_font_file for a file FreeType does not read as a scalable
/// font) or at `text` (errc::text_glyph naming a character the font has no
/// glyph for, with its code point U+XXXX; a line break or another control
/// character).
std::vector<Glyph> outline_text(const TextSpec& spec);

/// A line of text measured in its font, in font units: what lays out a
/// text that a drawing gives by the height of its capitals.
struct TextMeasures {
  FontFace face;
  double units_per_em = 0;
  /// The height of the capitals: the top of the glyph of "H" when the font
  /// has one with ink, else the OS/2 table's sCapHeight, else the ascender.
  double cap_height = 0;
  double descender = 0;  ///< the font's descender (hhea), below the baseline: < 0
  double advance = 0;    ///< the shaped line's total advance (kerning included)
};

/// The measures of `spec.text` in `spec.font` (found as find_font()
/// finds it; `size`, `at`, `align` and `angle` are not used). Throws
/// find_font()'s and open_font()'s refusals at `font`.
TextMeasures measure_text(const TextSpec& spec);

/// The installed font a drawing's text style names: a family (as
/// find_font() takes it), or the name of a font file without its folder
/// (`DejaVuSans.ttf`, `arial.ttf`), found among the files fontconfig
/// lists (case aside). Nothing when no such font is installed.
std::optional<FontFace> installed_font(const std::string& name);

/// The face fontconfig gives for the generic family "sans-serif" (the
/// stand-in for a font that is not installed). Throws InputError at
/// `font` (errc::text_font) when fontconfig gives none.
FontFace default_font();

/// outline_text() as the job reader's TextOutliner (JobReadOptions::text).
TextOutliner font_outliner();

}  // namespace bezcam::text
