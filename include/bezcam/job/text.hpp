#pragma once
/// A `text` entity (docs/text.md): what a job asks for, and the glyph
/// outlines that stand for it. The job reader knows no font: it hands the
/// request to a TextOutliner given in JobReadOptions (bezcam::text's
/// font_outliner(), text/font_text.hpp, reads fonts with FreeType, HarfBuzz
/// and fontconfig), and makes each glyph contour an entity.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bezcam/job/job.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/curve.hpp"

namespace bezcam {

/// Where `at` lies on the line: its start, the middle or the end of the
/// total advance (not of the ink).
enum class TextAlign { left, center, right };

/// One line of text as a job gives it.
struct TextSpec {
  std::string text;              ///< UTF-8, one line
  std::string font;              ///< a fontconfig family (or pattern) or a font file
  std::filesystem::path folder;  ///< where a relative font file is found (the job file's folder)
  double size = 0;               ///< the em size, job units
  Vec3 at;                       ///< the pen's start on the baseline
  TextAlign align = TextAlign::left;
  double angle = 0;  ///< degrees, counter-clockwise about `at`
};

/// One closed contour of a glyph: Bézier pieces end to end, the last
/// ending where the first starts, in job units and placed.
struct GlyphContour {
  std::vector<Bezier> pieces;
  /// Inside an odd number of the glyph's other contours (the counter of
  /// "B", "8", "@"): a hole in the letter's material.
  bool hole = false;
};

/// One glyph with ink (a space has none and is not listed).
struct Glyph {
  std::string characters;  ///< UTF-8: the characters it draws
  std::vector<GlyphContour> contours;
};

/// Turns a text into its glyphs' outlines, in order along the line. Throws
/// InputError whose place's JSON path is the key at fault, relative to the
/// entity (`font`, `text`, `size`), with what to change.
using TextOutliner = std::function<std::vector<Glyph>(const TextSpec&)>;

/// The side a glyph's hole is cut on when its letter is cut on `side`: the
/// other one (the material of "B" is outside its counters); no side and
/// "on" stay as they are.
std::optional<CutSide> hole_side(std::optional<CutSide> side);

/// A glyph contour's pieces as the segments of its closed path entity: one
/// Bézier segment per piece (make_path() of kernel/curve.hpp).
std::vector<CurveSegment> glyph_segments(const GlyphContour& c);

}  // namespace bezcam
