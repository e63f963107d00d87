#pragma once
/// A drawing read from an SVG or DXF file (bezcam::import): exact curves,
/// grouped in contours, with what was read and skipped, before it becomes a
/// job. Nothing here is flattened: lines, Béziers and conic arcs are Bézier
/// pieces (conics rational), splines keep their knots and weights.
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bezcam/job/job.hpp"
#include "bezcam/job/text.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam::import {

/// One exact curve of a contour: a Bézier (polynomial, or rational when
/// `weights` is not empty) or a B-spline/NURBS (`degree`, `knots`).
struct Piece {
  bool bspline = false;
  int degree = 0;               ///< bspline only (a Bézier's is points - 1)
  std::vector<Vec3> points;     ///< control points, millimetres (or the job's units)
  std::vector<double> weights;  ///< empty: polynomial
  std::vector<double> knots;    ///< bspline only
  Vec3 start() const { return points.front(); }
  Vec3 end() const;  ///< the end point (a clamped B-spline's last point)
};

/// A curve through points (a DXF spline given by fit points only): the
/// job's `interpolate` entity.
struct Interpolation {
  std::vector<Vec3> through;
  bool closed = false;
};

/// One entity of the job to be: pieces end to end (a `path`), or an
/// interpolation.
struct Contour {
  std::string id;       ///< from the drawing: SVG id (`logo`, `logo.2`), DXF layer and handle
  std::string layer;    ///< SVG: empty; DXF: the layer's name
  std::string element;  ///< where it came from, for messages (`<path id="logo"> line 4`, `handle 2A`)
  std::vector<Piece> pieces;
  bool closed = false;
  bool is_interpolation = false;
  Interpolation interpolation;
};

/// A line of text of a drawing (DXF TEXT, MTEXT), as the drawing gives
/// it: the job's `text` entity it becomes is laid out with its font's
/// measures when the job is made (to_job(), job_json()).
struct DrawingText {
  std::string id, layer, element;  ///< as a Contour's (`NOTES:3C`, `TEXT (handle 3C)`)
  std::string text;                ///< UTF-8, one line, formatting codes resolved
  /// The font its style names: a family (the style's extended data), or a
  /// font file's name (`DejaVuSans.ttf`); empty when the style names none.
  std::string font;
  std::string style;  ///< the style's name, for messages
  /// The style's font is a stroke font (AutoCAD SHX, LibreCAD LFF, or a
  /// name without extension such as `txt`): it has no outlines to read.
  bool stroke_font = false;
  double height = 0;  ///< the capitals' height, millimetres
  Vec3 at;            ///< the alignment point, millimetres
  double angle = 0;   ///< degrees, counter-clockwise
  /// Where `at` lies along the line's advance: 0 its start, 0.5 its middle,
  /// 1 its end.
  double along = 0;
  /// Where `at` lies across the line: the baseline, the descender's depth
  /// (bottom), half the capitals' height (middle) or their top.
  enum class Vertical { baseline, bottom, middle, top } vertical = Vertical::baseline;
  /// DXF "aligned": the line runs from `at` to `to`, its size such that
  /// its advance is their distance (the height follows).
  std::optional<Vec3> to;
};

/// What a font gives the layout of a drawing's text: the job's `font`,
/// and the measures of the text in it (text/font_text.hpp's TextMeasures,
/// font units).
struct FontMeasures {
  std::string font;        ///< the job's `font`: a family or a file
  std::string substitute;  ///< not empty: the style's font is not installed, and this is used instead
  double units_per_em = 0, cap_height = 0, descender = 0, advance = 0;
};

/// Finds the font named `font` (a family or a font file's name; empty: the
/// stand-in) and measures `text` in it. With `substitute`, a font that is
/// not installed gives the stand-in, said in FontMeasures::substitute;
/// without, it is refused (InputError at `font`). The CLI gives
/// bezcam::text's fonts.
using FontMeasurer = std::function<FontMeasures(const std::string& font, bool substitute, const std::string& text)>;

/// What one layer held: elements read, and elements skipped by kind (TEXT,
/// HATCH, DIMENSION, image ...).
struct LayerSummary {
  std::map<std::string, std::size_t> read, skipped;
};

/// A gap between two ends of a contour: its size and where it is (the
/// midpoint of the two ends).
struct Gap {
  std::string id;  ///< the contour's id
  double size = 0;
  Vec3 at;
};

struct Drawing {
  std::string source;  ///< the file name, for messages
  std::string format;  ///< "svg" or "dxf"
  std::vector<Contour> contours;
  std::vector<DrawingText> texts;
  std::map<std::string, LayerSummary> layers;  ///< by layer name ("" for SVG)
  /// Gaps wider than the default join distance that join_contours() closed
  /// with a larger tolerance (the ends moved to meet).
  std::vector<Gap> closed_gaps;
  /// The unit the file says a drawing unit is (DXF `$INSUNITS`, the SVG
  /// root's `width` and `height` with a unit): its name and millimetres;
  /// empty and 0 when it says none (DXF `$INSUNITS` 0 or absent, SVG
  /// lengths without a unit).
  std::string declared_units;
  double declared_mm = 0;
  /// Millimetres per drawing unit as read (a unitless DXF: 1; a unitless
  /// SVG: 25.4 / 96, CSS pixels).
  double mm_per_unit = 1;
  /// Largest extent of the control points (mm), the scale of "meet".
  double size() const;
};

/// How a drawing becomes a job: `--set KEY=VALUE` settings (top-level
/// `tolerance`, `units`, `machine`; every other key goes to the `job`
/// object and is validated as the job file's keys are) and the layers to
/// keep (empty: all).
/// A setting of the contours a selector picks (`--set SELECTOR:KEY=VALUE`).
struct ScopedSetting {
  std::string selector, key, value;
};

/// A selector picks a contour when it matches, as a shell glob (`*`, `?`,
/// `[...]`), the contour's layer or its id (selects()).
struct ImportOptions {
  std::vector<std::pair<std::string, std::string>> settings;
  std::vector<std::string> layers;
  /// Settings of single entities, applied in the order given (a later
  /// value of a key wins), over the job-wide `settings`: the keys an
  /// entity of a job file takes (not tolerance, units, machine, order,
  /// program_number).
  std::vector<ScopedSetting> scoped;
  /// The contours to cut: those `only` selects (all when empty) that
  /// `skip` does not select.
  std::vector<std::string> only, skip;
  /// The fonts of the drawing's texts (their measures) and their outlines;
  /// without them a drawing's text is refused (text.unavailable).
  FontMeasurer fonts;
  TextOutliner outline;
};

/// True when `selector` matches, as a shell glob, the contour's (or the
/// text's) layer or its id.
bool selects(const std::string& selector, const std::string& layer, const std::string& id);
/// For a contour, also `circle<D` and `circle>D`: a closed contour that is
/// a circle of diameter below (above) D. (No DXF layer name or SVG id holds
/// `<` or `>`.) `nesting_side` is the side its nesting gives it
/// ("outside", "inside", or empty), which `<outside>` and `<inside>` pick.
bool selects(const std::string& selector, const Contour& c, const std::string& nesting_side = "");

/// Checks the options before a drawing is read: each scoped setting's key
/// is a key an entity takes (settings_json()'s checks), refused at the
/// setting `settings.SELECTOR:KEY` otherwise.
void check_options(const ImportOptions& opt);

/// Joins contours of the same layer that meet end to end within
/// 1e-6 x size(), or within `tolerance` when that is larger, into one
/// (reversing a contour where that makes it meet), closing those that
/// close; ends that are apart are moved to meet exactly (an unclamped
/// B-spline's by a bridging line). Gaps wider than 1e-6 x size() so
/// closed are recorded in d.closed_gaps. Contours already closed stay as
/// they are.
void join_contours(Drawing& d, double tolerance = 0);

/// Multiplies every coordinate of the drawing by `s` (> 0).
void scale_drawing(Drawing& d, double s);

/// The open contours whose two ends are at most `within` apart, with the
/// gap between them.
std::vector<Gap> nearly_closed(const Drawing& d, double within);

/// The job file (docs/job-format.md) the drawing is read as: every number
/// written to full double precision (shortest text that reads back
/// exactly). With the setting `side` "outside" (or "inside"), each closed
/// contour's entity gets its own side by its even-odd depth among the kept
/// closed contours (flatten/nesting.hpp): even the side asked for, odd the
/// other (docs/import.md, "Sides of a part"); each entity's scoped
/// settings are written on it (a `side` given there wins over nesting).
/// Throws InputError when a layer named in `opt` is not in the drawing, a
/// selector matches no layer and no id of it (naming those it has), or
/// nothing is left to cut.
std::string job_json(const Drawing& d, const ImportOptions& opt = {});

/// The job, built in memory (JobBuilder) from what job_json() writes: the
/// same entities, ids, sides, settings, limits and refusals as the job
/// reader gives that text, so that `import` then `convert` and `convert
/// DRAWING` are the same job. A setting refused is named as `--set KEY`.
/// `warnings` gets one for each gap of d.closed_gaps (its size and place)
/// and, with a side inside or outside, one for each pair of
/// contours that cross (none when the job is refused).
Job to_job(const Drawing& d, const ImportOptions& opt = {}, std::vector<std::string>* warnings = nullptr);

}  // namespace bezcam::import
