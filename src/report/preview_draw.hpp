#pragma once
// Shared by the preview_*.cpp files (preview_svg.hpp): what an entity looks
// like (its Shape), the views the page holds and their projection, the SVG
// text helpers and colours, and the drawing functions of each part of the
// page (tool path, entities, axes and scale bar, legend).
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/job/job.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"
#include "bezcam/report/preview_svg.hpp"

namespace bezcam::preview {

// ---- What is drawn and measured (preview_shape.cpp) ------------------------

// What an entity looks like: the exact curves to draw (a curve entity's
// pieces; a curve on a surface composed with the surface; a surface's
// iso-parameter lines), its control polygons, and the curve its cut is
// measured against (empty for surfaces).
struct Shape {
  std::vector<std::vector<Bezier>> chains;
  std::vector<std::vector<Vec3>> polygons;
  std::vector<Vec3> control_points;
  std::vector<Bezier> measure;
  int dim = 2;
  bool closed = false;
  bool surface = false;
};

Shape entity_shape(const Entity& e);

// A feed straight down after a rapid (or at the start): not a cutting block.
bool is_plunge(std::span<const MotionBlock> m, size_t i);

// ---- SVG text and colours (preview_svg_text.cpp) ---------------------------

std::string esc(std::string_view s);
// Pixel coordinates with 3 decimals (a thousandth of a pixel keeps
// deviations visible when zoomed in), trailing zeros trimmed.
std::string n3(double v);

// Deviation colour, on a scale relative to the tolerance: within it a calm
// sequential scale, dark blue at 0 through teal to green at the tolerance
// (a program that uses 97 % of its tolerance keeps its promise and looks
// like it); above it a saturated red that no colour of the scale comes
// near, drawn wider and marked (a broken promise must stand out).
inline constexpr const char* kOverColour = "#ff0000";
inline bool over_tolerance(double d, double tol) { return d > tol * (1 + 1e-9); }
std::string deviation_colour(double d, double tol);

inline constexpr const char* kCurveColour = "#1f3b73";
inline constexpr const char* kControlColour = "#8c8c8c";
inline constexpr const char* kFeedColour = "#f28e2b";
inline constexpr const char* kRapidColour = "#d62728";

// The largest 1, 2 or 5 times a power of ten not above x.
double nice_below(double x);

struct P2 {
  double x = 0, y = 0;
};

// A view: a projection of model space and its placement on the page.
struct View {
  std::string id, title;
  bool iso = false;
  double minx = HUGE_VAL, maxx = -HUGE_VAL, miny = HUGE_VAL, maxy = -HUGE_VAL;
  double s = 1, ox = 0, oy = 0;           // scale (px per unit) and origin
  double px = 0, py = 0, pw = 0, ph = 0;  // panel rectangle

  // Isometric drawing: the three axes at 120 degrees, lengths along them
  // kept (so one scale bar serves all three).
  P2 project(const Vec3& p) const {
    if (!iso) return {p.x, p.y};
    const double c = std::cos(std::numbers::pi / 6), sn = 0.5;
    return {(p.x - p.y) * c, (p.x + p.y) * sn + p.z};
  }
  void fit(const Vec3& p) {
    const P2 q = project(p);
    minx = std::min(minx, q.x), maxx = std::max(maxx, q.x);
    miny = std::min(miny, q.y), maxy = std::max(maxy, q.y);
  }
  void fit(const Box3& b) {
    if (b.empty()) return;
    for (int k = 0; k < 8; ++k)
      fit(Vec3{(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z});
  }
  bool empty() const { return minx > maxx; }
  P2 screen(const Vec3& p) const {
    const P2 q = project(p);
    return {ox + (q.x - minx) * s, oy + (maxy - q.y) * s};
  }
  // Screen direction of a model direction at p.
  P2 screen_dir(const Vec3& p, const Vec3& d) const {
    const P2 a = screen(p), b = screen(p + d);
    const double l = std::hypot(b.x - a.x, b.y - a.y);
    if (!(l > 0)) return {1, 0};
    return {(b.x - a.x) / l, (b.y - a.y) / l};
  }
};

std::string path_d(const View& v, std::span<const Vec3> pts);
// Arrowhead with its tip at `tip`, pointing along `d`.
std::string arrow_d(P2 tip, P2 d, double len, double half_width);
// Tangent of the curve at t, falling back to a nearby chord where the
// derivative vanishes (repeated control points).
Vec3 tangent(const Bezier& b, double t);
// The width of `s` drawn in a sans-serif font of `font_size` pixels, never
// below what the common sans-serif fonts take (an estimate from above: text
// laid out with it is not clipped).
double text_width(std::string_view s, double font_size, bool bold = false);
// `s` broken at spaces into lines at most `width` pixels wide by
// text_width() (a single word wider than that stays whole).
std::vector<std::string> wrap(const std::string& s, double width, double font_size);

// ---- The parts of the page ------------------------------------------------

// Top of the feed scale: the highest programmed cutting feed.
double feed_scale_top(const MotionPlan& plan);

// The tool path of one view, under the curves (preview_toolpath.cpp).
// `msamples` are the blocks' points, `dev_of` their deviations (-1: not
// measured).
void svg_toolpath(std::string& o, const View& v, const PreviewInput& in, const std::vector<std::vector<Vec3>>& msamples,
                  const std::vector<double>& dev_of, const std::string& unit);

// One entity in one view (preview_entity.cpp): its true curve (`pts`, one
// polyline per chain), control polygon (with `control`), start, direction
// and label.
void svg_entity(std::string& o, const View& v, const PreviewInput& in, const Entity& e, const Shape& sh,
                const std::vector<std::vector<Vec3>>& pts, const std::vector<std::vector<Vec3>>& msamples,
                bool control);

// The top view's coordinate ticks and origin; the scale bar of a view and
// an isometric view's axis triad; the legend below the views
// (preview_legend.cpp).
void svg_axes(std::string& o, const View& v);
void svg_scale_bar(std::string& o, const View& v, double pad, const std::string& unit);
// The legend is laid out in rows across the page `width` wide (`tabs`: the
// views draw holding tabs); returns its bottom.
double svg_legend(std::string& o, const PreviewInput& in, const PreviewOptions& opt, const std::vector<double>& dev_of,
                  double dev_max, bool tabs, double width, double margin, double legend_y);

}  // namespace bezcam::preview
