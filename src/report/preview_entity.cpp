// An entity in a view of the preview: its true curve, control polygon,
// start point, direction arrows and label.
#include <algorithm>

#include "bezcam/error.hpp"
#include "bezcam/kernel/surface.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/report/report.hpp"
#include "preview_draw.hpp"

namespace bezcam::preview {

// One entity in one view: its true curve (`pts`, one polyline per chain),
// control polygon (with `control`), start, direction and label.
void svg_entity(std::string& o, const View& v, const PreviewInput& in, const Entity& e, const Shape& sh,
                const std::vector<std::vector<Vec3>>& pts, const std::vector<std::vector<Vec3>>& msamples,
                bool control) {
  o += "<g class=\"entity\" data-entity=\"" + std::to_string(e.index) + "\" data-id=\"" + esc(e.id) + "\">\n";
  std::string what = e.label() + ": " + e.type;
  if (sh.surface) {
    what += ", degree " + std::to_string(e.surface->degree_u()) + " x " + std::to_string(e.surface->degree_v()) +
            (e.surface->rational() ? ", rational" : "") + ", surface";
  } else {
    int deg = 0;
    bool rat = false;
    for (const auto& pc : sh.measure) deg = std::max(deg, pc.degree()), rat = rat || pc.rational();
    what += ", degree " + std::to_string(deg) + (rat ? ", rational" : "") + (sh.dim == 3 ? ", 3D" : ", 2D");
  }
  o += "<title>" + esc(what) + "</title>\n";
  if (control && !sh.polygons.empty()) {
    std::string d;
    for (const auto& poly : sh.polygons) d += (d.empty() ? "" : " ") + path_d(v, poly);
    o += "<path class=\"control-polygon\" d=\"" + d + "\" fill=\"none\" stroke=\"" + kControlColour +
         "\" stroke-width=\"0.8\"/>\n";
    for (const auto& p : sh.control_points) {
      const P2 q = v.screen(p);
      o += "<circle class=\"control-point\" cx=\"" + n3(q.x) + "\" cy=\"" + n3(q.y) +
           "\" r=\"2.5\" fill=\"#ffffff\" stroke=\"" + kControlColour + "\" stroke-width=\"1\"/>\n";
    }
  }
  for (size_t c = 0; c < pts.size(); ++c) {
    // A surface's border lines (the first and last of each direction)
    // are drawn heavier than its inner iso lines.
    const bool border = !sh.surface || c < 2 || c + 2 >= pts.size();
    o += "<path class=\"curve" + std::string(sh.surface ? " iso-line" : "") + "\" d=\"" + path_d(v, pts[c]) +
         "\" fill=\"none\" stroke=\"" + kCurveColour + "\" stroke-width=\"" + (border ? "1.2" : "0.6") +
         "\" stroke-linejoin=\"round\"" + (border ? "" : " stroke-opacity=\"0.6\"") + "/>\n";
  }
  // Start point and direction: an arrow leaving the start, another at
  // the middle of the curve. A surface's are those of its first cut.
  Vec3 start, start_dir, mid_pt, mid_dir;
  bool have_start = false, have_mid = false;
  if (!sh.surface) {
    const auto& ch = sh.chains.front();
    start = ch.front().front();
    start_dir = tangent(ch.front(), 0);
    const Bezier& mid = ch[ch.size() / 2];
    const double tm = ch.size() % 2 == 1 ? 0.5 : 0.0;
    mid_pt = evaluate(mid, tm);
    mid_dir = tangent(mid, tm);
    have_start = have_mid = true;
  } else {
    for (size_t i = 0; i < in.motion.size() && !have_start; ++i) {
      const auto& b = in.motion[i];
      if (in.motion[i].entity != static_cast<int>(e.index) || !is_feed(b) || is_plunge(in.motion, i) || b.from == b.to)
        continue;
      start = b.from;
      start_dir = msamples[i][1] - msamples[i][0];
      have_start = true;
    }
    if (!have_start) start = evaluate(*e.surface, 0, 0);
  }
  const P2 s0 = v.screen(start);
  const P2 d0 = have_start ? v.screen_dir(start, start_dir) : P2{1, 0};
  if (have_start) {
    o += "<circle class=\"start-point\" cx=\"" + n3(s0.x) + "\" cy=\"" + n3(s0.y) + "\" r=\"3.5\" fill=\"" +
         kCurveColour + "\"/>\n";
    o += "<path class=\"direction-arrow\" d=\"" + arrow_d({s0.x + d0.x * 18, s0.y + d0.y * 18}, d0, 10, 4.5) +
         "\" fill=\"" + kCurveColour + "\"/>\n";
  }
  if (have_mid) {
    const P2 sm = v.screen(mid_pt), dm = v.screen_dir(mid_pt, mid_dir);
    o += "<path class=\"direction-arrow\" d=\"" + arrow_d({sm.x + dm.x * 5, sm.y + dm.y * 5}, dm, 10, 4.5) +
         "\" fill=\"" + kCurveColour + "\"/>\n";
  }
  // The label sits beside the start, on the side away from the path: the
  // id, the tool and the depth the tool path cuts it at.
  std::string cut;
  const int entity = static_cast<int>(e.index);
  if (entity < static_cast<int>(in.entity_tool.size()) && in.entity_tool[e.index] >= 0)
    cut = "T" + std::to_string(in.entity_tool[e.index]);
  double zlo = HUGE_VAL, zhi = -HUGE_VAL;
  for (size_t i = 0; i < in.motion.size(); ++i) {
    const auto& b = in.motion[i];
    if (in.motion[i].entity != entity || !is_feed(b) || is_plunge(in.motion, i)) continue;
    zlo = std::min({zlo, b.from.z, b.to.z});
    zhi = std::max({zhi, b.from.z, b.to.z});
  }
  if (zlo <= zhi)
    cut += (cut.empty() ? "" : " ") + std::string("Z") + format_significant(zlo, 6) +
           (zhi - zlo > 1e-9 ? " to " + format_significant(zhi, 6) : "");
  const double lx = s0.x - d0.y * 10 + (d0.y > 0 ? 0 : 2), ly = s0.y + d0.x * 10 + (d0.x > 0 ? 10 : -4);
  const std::string anchor = d0.y > 0 ? " text-anchor=\"end\"" : "";
  o += "<text class=\"entity-label\" x=\"" + n3(lx) + "\" y=\"" + n3(ly) + "\" fill=\"" + kCurveColour +
       "\" font-size=\"11\"" + anchor + ">" + esc(e.label()) + "</text>\n";
  // Under it: the tool and the depth the tool path cuts it at.
  if (!cut.empty())
    o += "<text class=\"entity-cut\" x=\"" + n3(lx) + "\" y=\"" + n3(ly + 12) + "\" fill=\"#555555\" font-size=\"10\"" +
         anchor + ">" + esc(cut) + "</text>\n";
  o += "</g>\n";
}

}  // namespace bezcam::preview
