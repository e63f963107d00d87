// The tool path in a view of the preview: feeds (in one colour, by
// deviation or by the speed reached) and rapids, the tool's swept width,
// holding tabs and material left.
#include <algorithm>
#include <cmath>
#include <map>

#include "bezcam/error.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/report/report.hpp"
#include "preview_draw.hpp"

namespace bezcam::preview {

double feed_scale_top(const MotionPlan& plan) {
  double top = 0;
  for (const PlannedBlock& b : plan.blocks)
    if (b.kind != BlockKind::rapid) top = std::max(top, b.programmed_feed);
  return top > 0 ? top : 1;
}

namespace {

// The cutting moves as executed, coloured by the speed reached: each
// segment of the plan cut into short stretches, neighbours of one colour
// joined in one path; starved blocks get a dashed red overlay.
void svg_feed_path(std::string& o, const View& v, const PreviewInput& in, const std::string& unit) {
  const MotionPlan& plan = *in.plan;
  std::string coloured;
  const double top = feed_scale_top(plan);
  constexpr int kSteps = 24;  // colour steps
  std::string cur_colour, cur_d;
  int cur_step = -1;
  P2 last{};
  auto flush = [&] {
    if (!cur_d.empty())
      coloured += "<path class=\"feed feed-speed\" data-feed-step=\"" + std::to_string(cur_step) + "\" d=\"" + cur_d +
                  "\" fill=\"none\" stroke=\"" + cur_colour +
                  "\" stroke-width=\"3\" stroke-linecap=\"round\" stroke-linejoin=\"round\"/>\n";
    cur_d.clear();
  };
  std::string starved_d;
  for (const PlanSegment& sg : plan.segments) {
    if (sg.rapid || sg.length <= 0) continue;
    const bool starved = sg.block >= 0 && plan.blocks[static_cast<size_t>(sg.block)].starved;
    // Stretches: up to 8 per segment, each at least a pixel or two long.
    const double px = sg.length * v.s;
    const int n = std::clamp(static_cast<int>(px / 3), 1, 8);
    std::string seg_d;
    for (int k = 0; k < n; ++k) {
      const double s0 = sg.length * k / n, s1 = sg.length * (k + 1) / n, sm = 0.5 * (s0 + s1);
      // Speed at distance sm: the trapezoid's, by distance.
      const double a = sg.accel;
      double sp = std::min(
          {sg.vpeak, std::sqrt(sg.v0 * sg.v0 + 2 * a * sm), std::sqrt(sg.v1 * sg.v1 + 2 * a * (sg.length - sm))});
      const int step = std::clamp(static_cast<int>(std::lround(sp * 60 / top * kSteps)), 0, kSteps);
      const P2 p0 = v.screen(sg.point_at(s0, plan.motion)), p1 = v.screen(sg.point_at(s1, plan.motion));
      if (step != cur_step || cur_d.empty() || std::hypot(p0.x - last.x, p0.y - last.y) > 1e-6) {
        if (step != cur_step || cur_d.empty()) {
          flush();
          cur_step = step;
          cur_colour = preview_feed_colour(double(step) / kSteps * top, top);
        }
        cur_d += (cur_d.empty() ? "M" : " M") + n3(p0.x) + " " + n3(p0.y);
      }
      cur_d += " L" + n3(p1.x) + " " + n3(p1.y);
      last = p1;
      if (starved)
        seg_d += (seg_d.empty() ? "M" + n3(p0.x) + " " + n3(p0.y) : std::string()) + " L" + n3(p1.x) + " " + n3(p1.y);
    }
    if (!seg_d.empty()) starved_d += (starved_d.empty() ? "" : " ") + seg_d;
  }
  flush();
  // Starved stretches: a red halo under the coloured path, so that the
  // speed stays readable on top of it.
  if (!starved_d.empty())
    o += "<path class=\"starved\" d=\"" + starved_d + "\" fill=\"none\" stroke=\"" + std::string(kOverColour) +
         "\" stroke-opacity=\"0.45\" stroke-width=\"9\" stroke-linecap=\"round\" "
         "stroke-linejoin=\"round\"><title>starved: "
         "the controller could not feed these blocks fast enough (block rate, minimum segment time or look-ahead)"
         "</title></path>\n";
  o += coloured;
  (void)unit;
}

}  // namespace

// The tool path of one view, under the curves: the path is wide and light,
// the true curve thin and dark on top, so both stay visible where they agree.
// `msamples` are the blocks' points, `dev_of` their deviations (-1: not measured).
void svg_toolpath(std::string& o, const View& v, const PreviewInput& in, const std::vector<std::vector<Vec3>>& msamples,
                  const std::vector<double>& dev_of, const std::string& unit) {
  o += "<g class=\"toolpath\">\n";
  std::string rapid_d;
  // Without colours, a run of feed blocks of one entity is one path (a
  // smaller file, and no darker dots where translucent blocks overlap).
  std::string run_d, run_attrs;
  Vec3 run_end;
  auto flush_run = [&] {
    if (!run_d.empty())
      o += "<path " + run_attrs + " d=\"" + run_d + "\" fill=\"none\" stroke=\"" + kFeedColour +
           "\" stroke-width=\"3\" stroke-linecap=\"round\" stroke-linejoin=\"round\" stroke-opacity=\"0.75\"/>\n";
    run_d.clear();
  };
  // Part cutting: the tool's swept width along each entity's deepest pass
  // (its lowest feed moves), under everything else; marks where a pass
  // rises onto a holding tab.
  if (!v.iso) {
    std::map<int, double> deepest;
    for (const auto& m : in.motion)
      if (m.kind != BlockKind::rapid && m.entity >= 0 && static_cast<size_t>(m.entity) < in.entity_tool_radius.size() &&
          in.entity_tool_radius[static_cast<size_t>(m.entity)] > 0) {
        auto [it, fresh] = deepest.emplace(m.entity, m.to.z);
        if (!fresh) it->second = std::min(it->second, m.to.z);
      }
    for (const auto& [entity, z] : deepest) {
      std::string d, marks;
      for (size_t i = 0; i < in.motion.size(); ++i) {
        const auto& m = in.motion[i];
        if (m.entity != entity || m.kind == BlockKind::rapid) continue;
        const auto& s = msamples[i];
        const bool vertical = s.size() == 2 && s.front().x == s.back().x && s.front().y == s.back().y;
        if (vertical) {
          // Rising from the deepest pass but not to a retract: onto a tab.
          if (m.from.z == z && m.to.z > z && i + 1 < in.motion.size() && in.motion[i + 1].kind != BlockKind::rapid) {
            const P2 q = v.screen(m.to);
            marks += "<rect class=\"tab\" x=\"" + n3(q.x - 4) + "\" y=\"" + n3(q.y - 4) +
                     "\" width=\"8\" height=\"8\" fill=\"#ff9f1c\" stroke=\"#7a4a00\"><title>holding tab: the pass "
                     "rises to z " +
                     fmt_num(m.to.z) + "</title></rect>\n";
          }
          continue;
        }
        if (m.from.z != z && m.to.z != z) continue;
        d += (d.empty() ? "" : " ") + path_d(v, s);
      }
      const double w = 2 * in.entity_tool_radius[static_cast<size_t>(entity)] * v.s;
      if (!d.empty())
        o += "<path class=\"swept\" data-entity=\"" + std::to_string(entity) + "\" d=\"" + d +
             "\" fill=\"none\" stroke=\"#9ecae1\" stroke-opacity=\"0.45\" stroke-width=\"" + n3(w) +
             "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"><title>the tool's width on its deepest pass "
             "(diameter " +
             fmt_num(2 * in.entity_tool_radius[static_cast<size_t>(entity)]) + " " + unit + ")</title></path>\n";
      o += marks;
    }
    for (size_t e = 0; e < in.entity_left.size(); ++e)
      for (const MaterialLeft& l : in.entity_left[e]) {
        const std::vector<Vec3> pts = l.points.empty() ? std::vector<Vec3>{l.from, l.to} : l.points;
        o += "<path class=\"material-left\" data-entity=\"" + std::to_string(e) + "\" d=\"" + path_d(v, pts) +
             "\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"7\" stroke-opacity=\"0.8\" "
             "stroke-linecap=\"round\"><title>material left: the tool cannot reach " +
             fmt_num(std::round(l.length * 1000) / 1000) + " " + unit + " of the curve here (" +
             fmt_num(std::round(l.depth * 1000) / 1000) + " " + unit + " deep)</title></path>\n";
      }
  }
  const bool by_feed = in.plan != nullptr;
  if (by_feed) svg_feed_path(o, v, in, unit);
  for (size_t i = 0; i < in.motion.size(); ++i) {
    const auto& m = in.motion[i];
    const auto& s = msamples[i];
    if (by_feed && m.kind != BlockKind::rapid) continue;
    const P2 a = v.screen(s.front()), b = v.screen(s.back());
    const bool zero = s.size() == 2 && std::hypot(a.x - b.x, a.y - b.y) < 1e-6;
    if (m.kind == BlockKind::rapid) {
      if (!zero) rapid_d += (rapid_d.empty() ? "" : " ") + path_d(v, s);
      continue;
    }
    if (zero) continue;  // a plunge seen from above
    std::string attrs = "class=\"feed\"";
    if (m.entity >= 0) attrs += " data-entity=\"" + std::to_string(m.entity) + "\"";
    if (dev_of[i] < 0) {
      if (run_d.empty() || attrs != run_attrs || !(s.front() == run_end)) {
        flush_run();
        run_attrs = attrs;
        run_d = path_d(v, s);
      } else {
        run_d += " " + path_d(v, std::span<const Vec3>(s).subspan(1)).replace(0, 1, "L");
      }
      run_end = s.back();
      continue;
    }
    flush_run();
    // One path per block, coloured by its deviation, with a tooltip.
    const bool over = over_tolerance(dev_of[i], in.tolerance);
    attrs += " data-deviation=\"" + fmt_num(dev_of[i]) + "\"";
    if (over) attrs.replace(0, std::string("class=\"feed\"").size(), "class=\"feed over-tolerance\"");
    const std::string pct = format_significant(100 * dev_of[i] / in.tolerance, 3) + " % of the tolerance";
    o += "<path " + attrs + " d=\"" + path_d(v, s) + "\" fill=\"none\" stroke=\"" +
         deviation_colour(dev_of[i], in.tolerance) + "\" stroke-width=\"" + (over ? "6" : "3") +
         "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"><title>deviation " + format_significant(dev_of[i], 3) +
         " " + unit + " (" + pct + (over ? ": ABOVE THE TOLERANCE" : "") + ")</title></path>\n";
    if (over) {  // a ring around it, visible at any zoom
      const P2 c = v.screen(s[s.size() / 2]);
      o += "<circle class=\"over-tolerance-mark\" cx=\"" + n3(c.x) + "\" cy=\"" + n3(c.y) +
           "\" r=\"9\" fill=\"none\" stroke=\"" + kOverColour + "\" stroke-width=\"2\"/>\n";
    }
  }
  flush_run();
  if (!rapid_d.empty())
    o += "<path class=\"rapid\" d=\"" + rapid_d + "\" fill=\"none\" stroke=\"" + kRapidColour +
         "\" stroke-width=\"1\" stroke-dasharray=\"6 4\"/>\n";
  o += "</g>\n";
}

}  // namespace bezcam::preview
