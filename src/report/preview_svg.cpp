// The preview's page (preview_svg.hpp): its views and their layout, the
// document's head and header, each view's frame and contents in order.
#include "bezcam/report/preview_svg.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/report/report.hpp"
#include "preview_draw.hpp"

namespace bezcam {

namespace preview {
namespace {

// The views of the page: the top view always, an isometric view beside it
// when an entity is 3D or the tool path cuts in 3D.
std::vector<View> page_views(const std::vector<Shape>& shapes, std::span<const MotionBlock> motion) {
  bool three_d = false;
  for (const auto& sh : shapes) three_d = three_d || (!sh.chains.empty() && sh.dim == 3);
  for (size_t i = 0; i < motion.size() && !three_d; ++i) {
    const auto& b = motion[i];
    if (!is_feed(b) || is_plunge(motion, i)) continue;
    three_d = b.from.z != b.to.z;
    for (const auto& c : b.ctrl) three_d = three_d || c.z != b.from.z;
  }

  std::vector<View> views(1);
  views[0].id = "top-view";
  views[0].title = "Top view (XY)";
  if (three_d) {
    views.emplace_back();
    views[1].id = "iso-view";
    views[1].title = "Isometric view";
    views[1].iso = true;
  }
  return views;
}

// The tool path's blocks as points (a fraction of the drawing's size apart
// along curved blocks), and each view fitted to what it shows: tight curve
// boxes, control points (with `control`), those points.
std::vector<std::vector<Vec3>> fit_views(std::vector<View>& views, const std::vector<Shape>& shapes,
                                         std::span<const MotionBlock> motion, bool control) {
  Box3 all;
  for (const auto& sh : shapes) {
    for (const auto& ch : sh.chains)
      for (const auto& pc : ch) all.add(bounds(pc));
    if (control)
      for (const auto& p : sh.control_points) all.add(p);
  }
  for (const auto& m : motion) {
    all.add(m.from);
    all.add(m.to);
  }
  const double size0 = all.empty() ? 1.0 : std::max(norm(all.hi - all.lo), 1e-9);
  std::vector<std::vector<Vec3>> msamples(motion.size());
  for (size_t i = 0; i < motion.size(); ++i) msamples[i] = sample_block(motion[i], size0 * 2e-4);
  for (auto& v : views) {
    for (const auto& sh : shapes) {
      for (const auto& ch : sh.chains)
        for (const auto& pc : ch) v.fit(bounds(pc));
      if (control)
        for (const auto& p : sh.control_points) v.fit(p);
    }
    for (const auto& s : msamples)
      for (const auto& p : s) v.fit(p);
    if (v.empty()) v.fit(Vec3{0, 0, 0});
  }
  return msamples;
}

// The page's layout: the header (title, notes, wrapped warnings), the
// views side by side, the legend below them.
struct Page {
  static constexpr double margin = 20, pad = 36, bar_room = 34;
  double W = 0, H = 0, legend_y = 0;
  std::vector<std::string> title_lines, note_lines, warn_lines;
};

// Lays out the page `W` wide: scales and places every view.
Page lay_out(std::vector<View>& views, const PreviewInput& in, double W) {
  Page pg;
  pg.W = W;
  const double margin = Page::margin, pad = Page::pad, bar_room = Page::bar_room;
  // The title leaves room for the units at its right.
  const std::string title = in.title.empty() ? "bezcam preview" : in.title;
  pg.title_lines = wrap(title, W - 2 * margin - text_width("units: " + std::string(to_string(in.units)), 12) - 12,
                        16 * 1.12);  // bold
  for (const auto& nline : in.notes)
    for (auto& l : wrap(nline, W - 2 * margin, 12)) pg.note_lines.push_back(l);
  for (const auto& w : in.warnings)
    for (auto& l : wrap(w, W - 2 * margin, 12 * 1.12)) pg.warn_lines.push_back(l);  // bold
  const double header_h = 30 + 20.0 * double(pg.title_lines.size() - 1) + 17.0 * double(pg.note_lines.size()) +
                          17.0 * double(pg.warn_lines.size()) + 8;
  const double nv = double(views.size());
  const double pw = (W - margin * (nv + 1)) / nv;
  const double max_inner_h = (views.size() == 1 ? 0.62 * W : 1.05 * pw) - 2 * pad - bar_room;
  double ph = 0;
  for (auto& v : views) {
    double wx = v.maxx - v.minx, wy = v.maxy - v.miny;
    const double big = std::max({wx, wy, 1e-9});
    // A straight line along an axis still gets a sensible scale.
    if (wx < 1e-3 * big) v.minx -= 0.5e-3 * big, v.maxx += 0.5e-3 * big, wx = v.maxx - v.minx;
    if (wy < 1e-3 * big) v.miny -= 0.5e-3 * big, v.maxy += 0.5e-3 * big, wy = v.maxy - v.miny;
    v.s = std::min((pw - 2 * pad) / wx, max_inner_h / wy);
    ph = std::max(ph, wy * v.s + 2 * pad + bar_room);
  }
  for (size_t k = 0; k < views.size(); ++k) {
    View& v = views[k];
    v.px = margin + double(k) * (pw + margin);
    v.py = header_h;
    v.pw = pw;
    v.ph = ph;
    v.ox = v.px + (pw - (v.maxx - v.minx) * v.s) / 2;
    v.oy = v.py + pad + (ph - 2 * pad - bar_room - (v.maxy - v.miny) * v.s) / 2;
  }
  pg.legend_y = header_h + ph + 14;
  return pg;
}

// The true curves, sampled finely: a fifth of a pixel, and never coarser
// than a twentieth of the tolerance, so the tool path's deviation shows
// when zoomed in. One polyline per chain of each shape.
std::vector<std::vector<std::vector<Vec3>>> sample_curves(const std::vector<Shape>& shapes,
                                                          const std::vector<View>& views, double tolerance) {
  double smax = 0;
  for (const auto& v : views) smax = std::max(smax, v.s);
  double draw_tol = 0.2 / smax;
  if (tolerance > 0) draw_tol = std::min(draw_tol, tolerance / 20);
  auto sample_chain = [&](const std::vector<Bezier>& chain) {
    try {
      return flatten(chain, FlattenOptions{.tolerance = draw_tol, .decimals = -1, .on_curve = true}).points;
    } catch (const InputError&) {  // finer than double precision allows
      return flatten(chain, FlattenOptions{.tolerance = 0.2 / smax, .decimals = -1, .on_curve = true}).points;
    }
  };
  std::vector<std::vector<std::vector<Vec3>>> chain_pts(shapes.size());
  for (size_t k = 0; k < shapes.size(); ++k)
    for (const auto& ch : shapes[k].chains) chain_pts[k].push_back(sample_chain(ch));
  return chain_pts;
}

// The document's opening: the svg element, its title and description, the
// colour gradients the legend uses, the white background.
void svg_document_head(std::string& o, const Page& pg, const PreviewInput& in, const PreviewOptions& opt,
                       const std::string& unit) {
  const double W = pg.W, H = pg.H;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + n3(W) + "\" height=\"" + n3(H) +
       "\" viewBox=\"0 0 " + n3(W) + " " + n3(H) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o += "<title>" + esc(in.title.empty() ? "bezcam preview" : in.title) + "</title>\n";
  o += "<desc>Drawn by bezcam: true curves from their exact Bézier pieces, control polygons, the tool path (feeds "
       "solid, rapids dashed). Units: " +
       unit + ".</desc>\n";
  if (in.plan) {
    o += "<defs><linearGradient id=\"feed-gradient\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0})
      o += "<stop offset=\"" + fmt_num(f) + "\" stop-color=\"" + preview_feed_colour(f, 1) + "\"/>";
    o += "</linearGradient></defs>\n";
  }
  if (opt.deviation)
    o += "<defs><linearGradient id=\"deviation-gradient\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">"
         "<stop offset=\"0\" stop-color=\"" +
         deviation_colour(0, 1) + "\"/><stop offset=\"0.5\" stop-color=\"" + deviation_colour(0.5, 1) +
         "\"/><stop offset=\"1\" stop-color=\"" + deviation_colour(1, 1) + "\"/></linearGradient></defs>\n";
  o += "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" + n3(W) + "\" height=\"" + n3(H) +
       "\" fill=\"#ffffff\"/>\n";
}

// The header: the title, the units, the notes, the warnings in red.
void svg_header(std::string& o, const Page& pg, const std::string& unit) {
  const double margin = Page::margin;
  o += "<g class=\"header\">\n";
  double ty = 24;
  o += "<text class=\"units\" x=\"" + n3(pg.W - margin) + "\" y=\"" + n3(ty) + "\" text-anchor=\"end\">units: " + unit +
       "</text>\n";
  for (size_t k = 0; k < pg.title_lines.size(); ++k) {
    if (k > 0) ty += 20;
    o += "<text class=\"title\" x=\"" + n3(margin) + "\" y=\"" + n3(ty) + "\" font-size=\"16\" font-weight=\"bold\">" +
         esc(pg.title_lines[k]) + "</text>\n";
  }
  for (const auto& nline : pg.note_lines) {
    ty += 17;
    o += "<text class=\"note\" x=\"" + n3(margin) + "\" y=\"" + n3(ty) + "\" fill=\"#333333\">" + esc(nline) +
         "</text>\n";
  }
  for (const auto& w : pg.warn_lines) {
    ty += 17;
    o += "<text class=\"warning\" x=\"" + n3(margin) + "\" y=\"" + n3(ty) +
         "\" fill=\"#b00000\" font-weight=\"bold\">" + esc(w) + "</text>\n";
  }
  o += "</g>\n";
}

// What every view draws: the shapes of the job's entities with their
// sampled curves, the tool path's points and deviations.
struct Drawn {
  std::vector<Shape> shapes;
  std::vector<std::vector<std::vector<Vec3>>> curve_pts;
  std::vector<std::vector<Vec3>> msamples;
  std::vector<double> dev_of;
};

// One view: its frame and title, the tool path, the entities, the axes and
// the scale bar.
void svg_view(std::string& o, const View& v, const PreviewInput& in, const PreviewOptions& opt, const Drawn& dr,
              const std::string& unit) {
  o += "<g class=\"view\" id=\"" + v.id + "\">\n";
  o += "<rect class=\"frame\" x=\"" + n3(v.px) + "\" y=\"" + n3(v.py) + "\" width=\"" + n3(v.pw) + "\" height=\"" +
       n3(v.ph) + "\" fill=\"#fbfbfb\" stroke=\"#cccccc\"/>\n";
  o += "<text class=\"view-title\" x=\"" + n3(v.px + 8) + "\" y=\"" + n3(v.py + 16) + "\" font-weight=\"bold\">" +
       v.title + "</text>\n";

  svg_toolpath(o, v, in, dr.msamples, dr.dev_of, unit);

  // Entities.
  if (in.job) {
    o += "<g class=\"entities\">\n";
    for (size_t k = 0; k < in.job->entities.size(); ++k) {
      const Entity& e = in.job->entities[k];
      const Shape& sh = dr.shapes[k];
      if (sh.chains.empty()) continue;
      svg_entity(o, v, in, e, sh, dr.curve_pts[k], dr.msamples, opt.control);
    }
    o += "</g>\n";
  }

  svg_axes(o, v);
  svg_scale_bar(o, v, Page::pad, unit);
  o += "</g>\n";
}

}  // namespace
}  // namespace preview

std::string preview_svg(const PreviewInput& in, const PreviewOptions& opt) {
  using namespace preview;
  const Job* job = in.job;
  const bool has_entities = job && !job->entities.empty();
  if (!has_entities && in.motion.empty())
    throw InputError(errc::preview_empty, Place{},
                     "nothing to draw: the job has no entities and there is no tool path");
  if (opt.deviation && in.plan)
    throw InputError(errc::preview_deviation, Place::at_setting("deviation"),
                     "a preview is coloured by deviation or by feed, not both: choose one");
  if (opt.deviation && (!job || !(in.tolerance > 0)))
    throw InputError(errc::preview_deviation, Place::at_setting("deviation"),
                     "colouring by deviation needs the job's true curves and a tolerance; give the job file");
  const std::string unit = to_string(in.units);

  // Deviation first: it is the slow part and reports progress.
  Drawn dr;
  dr.dev_of.assign(in.motion.size(), -1);
  double dev_max = 0;
  if (opt.deviation)
    for (const auto& d : block_deviations(*job, in.motion, in.tolerance, opt.on_entity, in.parts))
      dr.dev_of[d.block] = d.deviation, dev_max = std::max(dev_max, d.deviation);

  if (job)
    for (const auto& e : job->entities) dr.shapes.push_back(entity_shape(e));
  std::vector<View> views = page_views(dr.shapes, in.motion);
  dr.msamples = fit_views(views, dr.shapes, in.motion, opt.control);
  Page pg = lay_out(views, in, std::max(400.0, opt.width));
  dr.curve_pts = sample_curves(dr.shapes, views, in.tolerance);

  // The views and the legend first: the page's height is the legend's
  // bottom.
  std::string body;
  body.reserve(1 << 16);
  for (const View& v : views) svg_view(body, v, in, opt, dr, unit);
  const bool tabs = body.find("class=\"tab\"") != std::string::npos;
  pg.H = svg_legend(body, in, opt, dr.dev_of, dev_max, tabs, pg.W, Page::margin, pg.legend_y) + 10;
  std::string o;
  o.reserve(body.size() + 4096);
  svg_document_head(o, pg, in, opt, unit);
  svg_header(o, pg, unit);
  o += body;
  o += "</svg>\n";
  return o;
}

void add_part_cutting(PreviewInput& in, const Program& p, size_t entities) {
  in.entity_tool_radius.assign(entities, 0);
  in.entity_left.assign(entities, {});
  in.parts.offset.assign(entities, 0);
  std::vector<char> lead_move(p.moves.size(), 0);
  for (const auto& r : p.entities) {
    if (r.entity >= 0 && static_cast<size_t>(r.entity) < entities) {
      in.entity_tool_radius[static_cast<size_t>(r.entity)] = r.tool_width / 2;
      in.entity_left[static_cast<size_t>(r.entity)] = r.left;
      in.parts.offset[static_cast<size_t>(r.entity)] = r.offset;
    }
    for (const auto& [first, end] : r.lead_moves)
      for (size_t i = first; i < end && i < lead_move.size(); ++i) lead_move[i] = 1;
  }
  in.parts.lead.clear();
  for_each_motion_block(p, [&](MotionBlock&, size_t source) { in.parts.lead.push_back(lead_move[source]); });
  if (in.parts.lead.size() != in.motion.size())
    throw std::logic_error("add_part_cutting: the preview's motion is not the program's");
}

}  // namespace bezcam
