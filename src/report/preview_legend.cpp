// The preview's scales: coordinate ticks and the origin, the scale bar and
// axis triad of each view, and the legend below the views (line styles,
// the feed or deviation colour scale).
#include <algorithm>
#include <cmath>

#include "bezcam/error.hpp"
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

// The legend below the views: the line styles, and the deviation scale
// when coloured.
void svg_legend(std::string& o, const PreviewInput& in, const PreviewOptions& opt, const std::vector<double>& dev_of,
                double dev_max, double margin, double legend_y) {
  const std::string unit = to_string(in.units);
  o += "<g class=\"legend\">\n";
  double lx = margin;
  const double ly = legend_y + 12;
  auto key = [&](const std::string& cls, const std::string& sample, const std::string& label) {
    o += "<g class=\"legend-key " + cls + "\">" + sample + "<text x=\"" + n3(lx + 34) + "\" y=\"" + n3(ly + 4) + "\">" +
         esc(label) + "</text></g>\n";
    lx += 44 + 6.8 * double(label.size());
  };
  auto line = [&](const std::string& colour, double width, const char* dash) {
    return "<path d=\"M" + n3(lx) + " " + n3(ly) + " L" + n3(lx + 28) + " " + n3(ly) + "\" stroke=\"" + colour +
           "\" stroke-width=\"" + n3(width) + "\"" + (*dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "") +
           " fill=\"none\"/>";
  };
  key("key-curve", line(kCurveColour, 1.2, ""), "true curve (surfaces: iso lines)");
  if (opt.control) key("key-control", line(kControlColour, 0.8, ""), "control polygon");
  if (in.plan) {
    key("key-feed", line(preview_feed_colour(1, 1), 3, ""), "feed, coloured by the speed reached");
    key("key-starved",
        "<path d=\"M" + n3(lx) + " " + n3(ly) + " L" + n3(lx + 28) + " " + n3(ly) + "\" stroke=\"" + kOverColour +
            "\" stroke-opacity=\"0.45\" stroke-width=\"9\" fill=\"none\"/>",
        "starved blocks (red halo)");
  } else if (opt.deviation) {
    key("key-feed", line(deviation_colour(0, 1), 3, ""), "feed, coloured by deviation");
    bool unmeasured = false;
    for (size_t i = 0; i < in.motion.size(); ++i)
      unmeasured = unmeasured || (is_feed(in.motion[i]) && !is_plunge(in.motion, i) && dev_of[i] < 0);
    if (unmeasured)
      key("key-feed-unmeasured", line(kFeedColour, 3, ""),
          in.program_measured >= 0 ? "surfaces, parts: measured when built" : "surfaces, parts: not measured");
  } else {
    key("key-feed", line(kFeedColour, 3, ""), "feed (cutting)");
  }
  key("key-rapid", line(kRapidColour, 1, "6 4"), "rapid");
  // Part cutting, when the drawing has it.
  bool swept = false, left = false;
  for (double r : in.entity_tool_radius) swept = swept || r > 0;
  for (const auto& l : in.entity_left) left = left || !l.empty();
  // (Only as many as the row holds; every mark has its own tooltip.)
  auto fits = [&](const std::string& label) { return lx + 44 + 6.8 * double(label.size()) <= opt.width - margin; };
  if (swept && fits("tool's width")) key("key-swept", line("#9ecae1", 9, ""), "tool's width");
  if (swept && o.find("class=\"tab\"") != std::string::npos && fits("holding tab"))
    key("key-tab",
        "<rect x=\"" + n3(lx + 10) + "\" y=\"" + n3(ly - 4) +
            "\" width=\"8\" height=\"8\" fill=\"#ff9f1c\" stroke=\"#7a4a00\"/>",
        "holding tab");
  if (left && fits("material left")) key("key-material-left", line("#d62728", 7, ""), "material left");
  key("key-start",
      "<circle cx=\"" + n3(lx + 6) + "\" cy=\"" + n3(ly) + "\" r=\"3.5\" fill=\"" + kCurveColour + "\"/><path d=\"" +
          arrow_d({lx + 26, ly}, {1, 0}, 9, 4) + "\" fill=\"" + kCurveColour + "\"/>",
      "start and direction");
  if (in.plan) {
    const MotionPlan& plan = *in.plan;
    const double top = feed_scale_top(plan);
    const double gy = ly + 30, gx = margin, gw = 320;
    o += "<g class=\"feed-scale\" data-max=\"" + fmt_num(top) + "\">\n";
    o += "<text x=\"" + n3(gx) + "\" y=\"" + n3(gy - 6) + "\">feed reached on machine " + esc(in.machine) + ", " +
         unit + "/min (cycle " + esc(format_seconds(plan.cycle_time_s)) + ", mean " +
         format_significant(100 * plan.mean_feed_ratio, 3) + " % of the programmed feed)</text>\n";
    o += "<rect x=\"" + n3(gx) + "\" y=\"" + n3(gy) + "\" width=\"" + n3(gw) +
         "\" height=\"12\" fill=\"url(#feed-gradient)\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const double x = gx + f * gw;
      o += "<path d=\"M" + n3(x) + " " + n3(gy + 12) + " L" + n3(x) + " " + n3(gy + 16) +
           "\" stroke=\"#000000\" stroke-width=\"1\"/>";
      o += "<text x=\"" + n3(x) + "\" y=\"" + n3(gy + 28) + "\" text-anchor=\"middle\" font-size=\"11\">" +
           format_significant(f * top, 4) + "</text>\n";
    }
    const double sx = gx + gw + 60;
    o += "<text class=\"starved-count\" x=\"" + n3(sx) + "\" y=\"" + n3(gy + 10) + "\"" +
         (plan.starved_blocks ? " fill=\"" + std::string(kOverColour) + "\" font-weight=\"bold\"" : "") +
         ">starved blocks (red halo): " +
         (plan.starved_blocks ? std::to_string(plan.starved_blocks) + " of " + std::to_string(plan.blocks.size())
                              : std::string("none")) +
         "</text>\n";
    o += "</g>\n";
  } else if (opt.deviation) {
    const double gy = ly + 30, gx = margin, gw = 240;
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
    o += "<g class=\"deviation-scale\" data-max=\"" + fmt_num(in.tolerance) + "\">\n";
    o += "<text x=\"" + n3(gx) + "\" y=\"" + n3(gy - 6) + "\">deviation of each cutting block from the true curve, " +
         "relative to the tolerance " + format_significant(in.tolerance, 4) + " " + unit + " (" + esc(largest) +
         ")</text>\n";
    o += "<rect x=\"" + n3(gx) + "\" y=\"" + n3(gy) + "\" width=\"" + n3(gw) +
         "\" height=\"12\" fill=\"url(#deviation-gradient)\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
    for (double f : {0.0, 0.5, 1.0}) {
      const double x = gx + f * gw;
      o += "<path d=\"M" + n3(x) + " " + n3(gy + 12) + " L" + n3(x) + " " + n3(gy + 16) +
           "\" stroke=\"#000000\" stroke-width=\"1\"/>";
      o += "<text x=\"" + n3(x) + "\" y=\"" + n3(gy + 28) + "\" text-anchor=\"middle\" font-size=\"11\">" +
           (f == 0     ? std::string("0")
            : f == 0.5 ? std::string("50 %")
                       : "100 % = " + format_significant(in.tolerance, 4)) +
           "</text>\n";
    }
    const double sx = gx + gw + 90;
    o += "<rect x=\"" + n3(sx) + "\" y=\"" + n3(gy - 2) + "\" width=\"24\" height=\"16\" fill=\"" + kOverColour +
         "\"/><text class=\"over-tolerance-count\" x=\"" + n3(sx + 30) + "\" y=\"" + n3(gy + 10) + "\"" +
         (over ? " fill=\"" + std::string(kOverColour) + "\" font-weight=\"bold\"" : "") +
         ">above the tolerance (ringed): " +
         (over ? std::to_string(over) + " block" + (over == 1 ? "" : "s") : std::string("none")) + "</text>\n";
    o += "</g>\n";
  }
  o += "</g>\n";
}

}  // namespace bezcam::preview
