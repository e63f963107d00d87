// The preview's scales: coordinate ticks and the origin, the scale bar and
// axis triad of each view, and the legend below the views (line styles,
// the feed or deviation colour scale).
#include <algorithm>
#include <cmath>
#include <functional>

#include "bezcam/error.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/report/report.hpp"
#include "preview_draw.hpp"

namespace bezcam::preview {

// The top view's coordinates: ticks with their values along the bottom and
// the left of the drawing, and the origin (0, 0) marked where it is in view
// (said in a corner where it is not).
void svg_axes(std::string& o, const View& v) {
  if (v.iso) return;
  const double w = v.maxx - v.minx, h = v.maxy - v.miny;
  const double step = nice_below(std::max(w, h) / 4);
  const double bottom = v.oy + h * v.s, left = v.ox;
  o += "<g class=\"axis-ticks\" fill=\"#666666\" font-size=\"10\">\n";
  std::string d;
  for (double k = std::ceil(v.minx / step); k * step <= v.maxx + 1e-9 * step; ++k) {
    const double x = v.ox + (k * step - v.minx) * v.s;
    d += "M" + n3(x) + " " + n3(bottom + 8) + " L" + n3(x) + " " + n3(bottom + 13) + " ";
    o += "<text x=\"" + n3(x) + "\" y=\"" + n3(bottom + 24) + "\" text-anchor=\"middle\">" +
         format_significant(k * step == 0 ? 0.0 : k * step, 6) + "</text>\n";
  }
  for (double k = std::ceil(v.miny / step); k * step <= v.maxy + 1e-9 * step; ++k) {
    const double y = v.oy + (v.maxy - k * step) * v.s;
    d += "M" + n3(left - 13) + " " + n3(y) + " L" + n3(left - 8) + " " + n3(y) + " ";
    o += "<text x=\"" + n3(left - 15) + "\" y=\"" + n3(y + 3) + "\" text-anchor=\"end\">" +
         format_significant(k * step == 0 ? 0.0 : k * step, 6) + "</text>\n";
  }
  o += "<path d=\"" + d + "\" stroke=\"#666666\" stroke-width=\"1\" fill=\"none\"/>\n</g>\n";
  const double slack = 0.02 * std::max(w, h);
  if (v.minx - slack <= 0 && 0 <= v.maxx + slack && v.miny - slack <= 0 && 0 <= v.maxy + slack) {
    const P2 c = v.screen(Vec3{0, 0, 0});
    o += "<g class=\"origin\" stroke=\"#000000\" stroke-width=\"1.2\">"
         "<circle cx=\"" +
         n3(c.x) + "\" cy=\"" + n3(c.y) +
         "\" r=\"5\" fill=\"none\"/>"
         "<path d=\"M" +
         n3(c.x) + " " + n3(c.y) + " L" + n3(c.x + 24) + " " + n3(c.y) + " M" + n3(c.x) + " " + n3(c.y) + " L" +
         n3(c.x) + " " + n3(c.y - 24) +
         "\"/>"
         "<path d=\"" +
         arrow_d({c.x + 28, c.y}, {1, 0}, 7, 3) + " " + arrow_d({c.x, c.y - 28}, {0, -1}, 7, 3) +
         "\" fill=\"#000000\" stroke=\"none\"/>"
         "<text x=\"" +
         n3(c.x + 31) + "\" y=\"" + n3(c.y + 4) +
         "\" stroke=\"none\" font-size=\"10\">X</text>"
         "<text x=\"" +
         n3(c.x - 3) + "\" y=\"" + n3(c.y - 32) +
         "\" stroke=\"none\" font-size=\"10\">Y</text>"
         "<text x=\"" +
         n3(c.x - 8) + "\" y=\"" + n3(c.y + 16) +
         "\" stroke=\"none\" font-size=\"10\" "
         "text-anchor=\"end\">0, 0</text></g>\n";
  } else {
    o += "<text class=\"origin-off-view\" x=\"" + n3(v.px + v.pw - 8) + "\" y=\"" + n3(v.py + 16) +
         "\" text-anchor=\"end\" fill=\"#666666\">program zero (0, 0) lies outside this view</text>\n";
  }
}

// The scale bar of one view, bottom left; an isometric view's axis triad.
void svg_scale_bar(std::string& o, const View& v, double pad, const std::string& unit) {
  const double avail = (v.pw - 2 * pad) * 0.3 / v.s;
  const double L = nice_below(avail);
  const double bx = v.px + pad, by = v.py + v.ph - 14, bw = L * v.s;
  o += "<g class=\"scale-bar\" data-length=\"" + fmt_num(L) + "\">\n";
  o += "<path d=\"M" + n3(bx) + " " + n3(by - 5) + " L" + n3(bx) + " " + n3(by) + " L" + n3(bx + bw) + " " + n3(by) +
       " L" + n3(bx + bw) + " " + n3(by - 5) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
  o += "<text x=\"" + n3(bx + bw + 6) + "\" y=\"" + n3(by) + "\">" + format_significant(L, 6) + " " + unit +
       (v.iso ? " (along the axes)" : "") + "</text>\n";
  o += "</g>\n";
  if (v.iso) {
    // Axis triad, bottom right.
    const double cx = v.px + v.pw - 60, cy = v.py + v.ph - 24;
    o += "<g class=\"axes\">\n";
    const char* names[3] = {"X", "Y", "Z"};
    const Vec3 dirs[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a) {
      const P2 d = v.screen_dir(Vec3{}, dirs[a]);
      o += "<path d=\"M" + n3(cx) + " " + n3(cy) + " L" + n3(cx + d.x * 22) + " " + n3(cy + d.y * 22) +
           "\" stroke=\"#555555\" stroke-width=\"1\"/>";
      o += "<text x=\"" + n3(cx + d.x * 30 - 4) + "\" y=\"" + n3(cy + d.y * 30 + 4) + "\" font-size=\"10\">" +
           names[a] + "</text>\n";
    }
    o += "</g>\n";
  }
}

namespace {

// A legend key's sample, drawn with its left end at (x, y).
using Sample = std::function<std::string(double x, double y)>;

Sample line_sample(const std::string& colour, double width, const char* dash) {
  return [=](double x, double y) {
    return "<path d=\"M" + n3(x) + " " + n3(y) + " L" + n3(x + 28) + " " + n3(y) + "\" stroke=\"" + colour +
           "\" stroke-width=\"" + n3(width) + "\"" + (*dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "") +
           " fill=\"none\"/>";
  };
}

// The line styles, as many rows as the width needs; returns the last row's
// baseline.
double svg_legend_keys(std::string& o, const PreviewInput& in, const PreviewOptions& opt,
                       const std::vector<double>& dev_of, bool tabs, double right, double margin, double top) {
  double lx = margin, ly = top + 12;
  auto key = [&](const std::string& cls, const Sample& sample, const std::string& label) {
    const double w = 34 + text_width(label, 12);
    if (lx > margin && lx + w > right) lx = margin, ly += 20;  // a new row
    o += "<g class=\"legend-key " + cls + "\">" + sample(lx, ly) + "<text x=\"" + n3(lx + 34) + "\" y=\"" + n3(ly + 4) +
         "\">" + esc(label) + "</text></g>\n";
    lx += w + 16;
  };
  key("key-curve", line_sample(kCurveColour, 1.2, ""), "true curve (surfaces: iso lines)");
  if (opt.control) key("key-control", line_sample(kControlColour, 0.8, ""), "control polygon");
  if (in.plan) {
    key("key-feed", line_sample(preview_feed_colour(1, 1), 3, ""), "feed, coloured by the speed reached");
    key(
        "key-starved",
        [](double x, double y) {
          return "<path d=\"M" + n3(x) + " " + n3(y) + " L" + n3(x + 28) + " " + n3(y) + "\" stroke=\"" + kOverColour +
                 "\" stroke-opacity=\"0.45\" stroke-width=\"9\" fill=\"none\"/>";
        },
        "starved blocks (red halo)");
  } else if (opt.deviation) {
    key("key-feed", line_sample(deviation_colour(0, 1), 3, ""), "feed, coloured by deviation");
    bool unmeasured = false;
    for (size_t i = 0; i < in.motion.size(); ++i)
      unmeasured = unmeasured || (is_feed(in.motion[i]) && !is_plunge(in.motion, i) && dev_of[i] < 0);
    if (unmeasured)
      key("key-feed-unmeasured", line_sample(kFeedColour, 3, ""),
          in.program_measured >= 0 ? "leads, pockets, surfaces: measured when built"
                                   : "leads, pockets, surfaces: not measured");
  } else {
    key("key-feed", line_sample(kFeedColour, 3, ""), "feed (cutting)");
  }
  key("key-rapid", line_sample(kRapidColour, 1, "6 4"), "rapid");
  // Part cutting, when the drawing has it.
  bool swept = false, left = false;
  for (double r : in.entity_tool_radius) swept = swept || r > 0;
  for (const auto& l : in.entity_left) left = left || !l.empty();
  if (swept) key("key-swept", line_sample("#9ecae1", 9, ""), "tool's width");
  if (swept && tabs)
    key(
        "key-tab",
        [](double x, double y) {
          return "<rect x=\"" + n3(x + 10) + "\" y=\"" + n3(y - 4) +
                 "\" width=\"8\" height=\"8\" fill=\"#ff9f1c\" stroke=\"#7a4a00\"/>";
        },
        "holding tab");
  if (left) key("key-material-left", line_sample("#d62728", 7, ""), "material left");
  key(
      "key-start",
      [](double x, double y) {
        return "<circle cx=\"" + n3(x + 6) + "\" cy=\"" + n3(y) + "\" r=\"3.5\" fill=\"" + kCurveColour +
               "\"/><path d=\"" + arrow_d({x + 26, y}, {1, 0}, 9, 4) + "\" fill=\"" + kCurveColour + "\"/>";
      },
      "start and direction");
  return ly;
}

// A colour scale: its caption (wrapped to the width), the gradient `gw`
// wide with its ticks, and a count beside it (below it when the row is too
// narrow; `mark`: a sample drawn before the count). Returns its bottom.
struct Scale {
  std::string cls, data_max, caption, gradient;
  std::vector<std::pair<double, std::string>> ticks;  // (fraction, label)
  double gw = 240, gap = 60;
  std::string count_cls, count, count_style, mark_colour;
};

double svg_scale(std::string& o, const Scale& sc, double right, double margin, double top) {
  const double gx = margin;
  double y = top + 12;
  o += "<g class=\"" + sc.cls + "\" data-max=\"" + sc.data_max + "\">\n";
  for (const auto& l : wrap(sc.caption, right - margin, 12)) {
    o += "<text x=\"" + n3(gx) + "\" y=\"" + n3(y) + "\">" + esc(l) + "</text>\n";
    y += 16;
  }
  const double gy = y - 6;
  o += "<rect x=\"" + n3(gx) + "\" y=\"" + n3(gy) + "\" width=\"" + n3(sc.gw) + "\" height=\"12\" fill=\"url(#" +
       sc.gradient + ")\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
  for (const auto& [f, label] : sc.ticks) {
    const double x = gx + f * sc.gw;
    o += "<path d=\"M" + n3(x) + " " + n3(gy + 12) + " L" + n3(x) + " " + n3(gy + 16) +
         "\" stroke=\"#000000\" stroke-width=\"1\"/>";
    // The end labels stay inside the page: anchored at their inner side.
    const double w = text_width(label, 11);
    const char* anchor = x - w / 2 < 0 ? "start" : x + w / 2 > right + margin ? "end" : "middle";
    o += "<text x=\"" + n3(x) + "\" y=\"" + n3(gy + 28) + "\" text-anchor=\"" + anchor + "\" font-size=\"11\">" +
         esc(label) + "</text>\n";
  }
  double bottom = gy + 32;
  const double mark = sc.mark_colour.empty() ? 0 : 30;
  double sx = gx + sc.gw + sc.gap, sy = gy + 10;
  if (sx + mark + text_width(sc.count, 12, !sc.count_style.empty()) > right) sx = gx, sy = gy + 48, bottom = sy + 6;
  if (!sc.mark_colour.empty())
    o += "<rect x=\"" + n3(sx) + "\" y=\"" + n3(sy - 12) + "\" width=\"24\" height=\"16\" fill=\"" + sc.mark_colour +
         "\"/>";
  o += "<text class=\"" + sc.count_cls + "\" x=\"" + n3(sx + mark) + "\" y=\"" + n3(sy) + "\"" + sc.count_style + ">" +
       esc(sc.count) + "</text>\n";
  o += "</g>\n";
  return bottom;
}

}  // namespace

double svg_legend(std::string& o, const PreviewInput& in, const PreviewOptions& opt, const std::vector<double>& dev_of,
                  double dev_max, bool tabs, double width, double margin, double legend_y) {
  const std::string unit = to_string(in.units);
  const double right = width - margin;
  o += "<g class=\"legend\">\n";
  double bottom = svg_legend_keys(o, in, opt, dev_of, tabs, right, margin, legend_y) + 8;
  Scale sc;
  if (in.plan) {
    const MotionPlan& plan = *in.plan;
    const double top = feed_scale_top(plan);
    sc.cls = "feed-scale";
    sc.data_max = fmt_num(top);
    sc.caption = "feed reached on machine " + in.machine + ", " + unit + "/min (estimated cycle time " +
                 format_clock(plan.cycle_time_s) + ", mean " + format_significant(100 * plan.mean_feed_ratio, 3) +
                 " % of the programmed feed)";
    sc.gradient = "feed-gradient";
    sc.gw = 320;
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) sc.ticks.push_back({f, format_significant(f * top, 4)});
    sc.count_cls = "starved-count";
    sc.count = "starved blocks (red halo): " +
               (plan.starved_blocks ? std::to_string(plan.starved_blocks) + " of " + std::to_string(plan.blocks.size())
                                    : std::string("none"));
    if (plan.starved_blocks) sc.count_style = " fill=\"" + std::string(kOverColour) + "\" font-weight=\"bold\"";
    bottom = svg_scale(o, sc, right, margin, bottom);
  } else if (opt.deviation) {
    size_t measured = 0, over = 0;
    for (double d : dev_of)
      if (d >= 0) ++measured, over += over_tolerance(d, in.tolerance);
    std::string largest;
    if (measured > 0)
      largest = "largest " + format_significant(dev_max, 3) + " " + unit + ", " +
                format_significant(100 * dev_max / in.tolerance, 3) + " % of the tolerance";
    else if (in.program_measured >= 0)
      largest = "no curve block to measure here; the program's own check measured " +
                format_significant(in.program_measured, 3) + " " + unit;
    else
      largest = "no curve block to measure";
    sc.cls = "deviation-scale";
    sc.data_max = fmt_num(in.tolerance);
    sc.caption =
        "deviation of each cutting block from the true curve (beside a part: from its exact offset at the "
        "tool's distance), relative to the tolerance " +
        format_significant(in.tolerance, 4) + " " + unit + " (" + largest + ")";
    sc.gradient = "deviation-gradient";
    sc.gap = 90;
    sc.ticks = {{0.0, "0"}, {0.5, "50 %"}, {1.0, "100 % = " + format_significant(in.tolerance, 4)}};
    sc.count_cls = "over-tolerance-count";
    sc.count = "above the tolerance (ringed): " +
               (over ? std::to_string(over) + " block" + (over == 1 ? "" : "s") : std::string("none"));
    if (over) sc.count_style = " fill=\"" + std::string(kOverColour) + "\" font-weight=\"bold\"";
    sc.mark_colour = kOverColour;
    bottom = svg_scale(o, sc, right, margin, bottom);
  }
  o += "</g>\n";
  return bottom;
}

}  // namespace bezcam::preview
