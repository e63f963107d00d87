// A drawing as a job: built in memory through JobBuilder (to_job(), what
// convert, check and preview cut), and written as the job file's text
// (job_json(), what `bezcam import` writes). Both keep the same contours
// with the same ids, sides, settings and refusals.
#include <charconv>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/flatten/nesting.hpp"
#include "bezcam/format.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/job/job_builder.hpp"
#include "bezcam/job/settings.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/warnings.hpp"
#include "drawing_text.hpp"
#include "selection.hpp"

namespace bezcam::import {
namespace {

// ---- What becomes the job ---------------------------------------------------

std::string quoted(const std::string& s) {
  std::string o = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      o += '\\';
      o += ch;
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
    } else {
      o += ch;
    }
  }
  return o + "\"";
}

// The layers to keep (empty: all); each must be in the drawing.
std::set<std::string> kept_layers(const Drawing& d, const ImportOptions& opt) {
  std::set<std::string> keep(opt.layers.begin(), opt.layers.end());
  for (const std::string& l : keep)
    if (!d.layers.count(l)) {
      std::string known;
      for (const auto& [name, s] : d.layers)
        if (!name.empty()) known += (known.empty() ? "" : ", ") + quoted(name);
      throw InputError(errc::import_layer, Place::at_setting("layers"),
                       d.source + " has no layer " + quoted(l) + "; " +
                           (known.empty() ? "it has no named layers (everything is on one unnamed layer: select none)"
                                          : "its layers are " + known));
    }
  return keep;
}

// The contours and texts of the kept layers that --only and --skip keep,
// in the drawing's order; refused when there are none.
struct Kept {
  std::vector<const Contour*> contours;
  std::vector<const DrawingText*> texts;
};
Kept kept_entities(const Drawing& d, const std::set<std::string>& keep, const ImportOptions& opt) {
  check_selectors(d, opt);
  std::vector<const Contour*> layers;
  for (const Contour& c : d.contours)
    if (keep.empty() || keep.count(c.layer)) layers.push_back(&c);
  Kept out{select_contours(layers, opt), kept_texts(d, keep, opt)};
  if (out.contours.empty() && out.texts.empty())
    throw InputError(errc::import_empty, Place::at_file(d.source),
                     keep.empty() && opt.only.empty() && opt.skip.empty()
                         ? std::string("expected geometry to cut, found none")
                         : "expected geometry to cut among the layers and entities asked for, found none");
  return out;
}

// Drawing millimetres in the job's units: 1 / 25.4 when `units` is "inch".
double units_scale(const SettingsJson& settings) {
  for (const auto& [k, v] : settings.top)
    if (k == "units") return v == "\"inch\"" ? 1 / 25.4 : 1;
  return 1;
}

// ---- The job in memory ------------------------------------------------------

// The limits a job file's reader applies (bezcam/limits.hpp), counted as
// it counts them and refused with its words, at the JSON path the entity's
// text would have.
struct PointLimits {
  const std::string& source;
  std::size_t entity_points = 0, job_points = 0;

  void count_points(std::size_t n, const std::string& path) {
    entity_points += n;
    if (entity_points > kMaxEntityPoints)
      throw InputError(errc::limit_points, Place::in_json(source, path),
                       "expected at most " + std::to_string(kMaxEntityPoints) +
                           " points in one entity (docs/limits.md), found " +
                           (entity_points == n ? std::to_string(n) : std::to_string(entity_points) + " with these") +
                           "; split the geometry into several entities");
  }
  void count_bezier_points(std::size_t n, const std::string& path) {
    job_points += n;
    if (job_points > kMaxJobPoints)
      throw InputError(errc::limit_points, Place::in_json(source, path),
                       "the job's curves and patches need " + std::to_string(job_points) +
                           " control points in their exact Bézier form with this one, more than the limit of " +
                           std::to_string(kMaxJobPoints) + " (docs/limits.md); split the job into several files");
  }
};

// Runs f, naming a kernel refusal at `path` of the entity's text.
template <class F>
auto at_path(const std::string& source, const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(e.id(), Place::in_json(source, path, e.place().relative_path()), e.message());
  }
}

// A drawing's point in the job: in the job's units, in the XY plane, and
// with a zero that is +0 (as a number written and read back is).
std::vector<Vec3> job_points(const std::vector<Vec3>& ps, double scale) {
  std::vector<Vec3> out;
  out.reserve(ps.size());
  for (const Vec3& p : ps) out.push_back({p.x * scale + 0.0, p.y * scale + 0.0, 0});
  return out;
}

// One contour as entity `index` of the job: a path of its pieces, or an
// interpolation through its points.
void add_contour(JobBuilder& b, const Contour& c, std::size_t index, double scale, const JobParams& params,
                 PointLimits& limits, const std::string& source);

// add_contour(), its refusals named at entity `index` (the builder names
// an entity by how many it holds, fewer than `index` once one is refused).
void add_entity(JobBuilder& b, const Contour& c, std::size_t index, double scale, const JobParams& params,
                PointLimits& limits, const std::string& source) {
  try {
    add_contour(b, c, index, scale, params, limits, source);
  } catch (const InputError& e) {
    const std::string path = e.place().json_path.value_or("");
    if (!path.starts_with("entities[")) throw;
    const std::size_t dot = path.find('.', std::string("entities[").size());
    throw InputError(e.id(),
                     Place::in_json(source, "entities[" + std::to_string(index) + "]",
                                    dot == std::string::npos ? std::string() : path.substr(dot + 1)),
                     e.message());
  }
}

void add_contour(JobBuilder& b, const Contour& c, std::size_t index, double scale, const JobParams& params,
                 PointLimits& limits, const std::string& source) {
  const std::string at = "entities[" + std::to_string(index) + "]";
  limits.entity_points = 0;
  if (c.is_interpolation) {
    limits.count_points(c.interpolation.through.size(), at + ".through");
    limits.count_bezier_points(4 * c.interpolation.through.size(), at + ".through");
    b.interpolate(c.id, job_points(c.interpolation.through, scale), c.interpolation.closed, params);
    return;
  }
  std::vector<JobBuilder::PathSegment> segments;
  for (std::size_t j = 0; j < c.pieces.size(); ++j) {
    const Piece& p = c.pieces[j];
    const std::string sp = at + ".segments[" + std::to_string(j) + "]";
    limits.count_points(p.points.size(), sp + ".points");
    std::vector<Vec3> pts = job_points(p.points, scale);
    if (!p.bspline) {
      limits.count_bezier_points(pts.size(), sp + ".points");
      segments.emplace_back(at_path(source, sp, [&] { return Bezier::make(std::move(pts), p.weights, 2); }));
      continue;
    }
    // Its Bézier form has at most one piece of degree + 1 points per span.
    const auto degree = static_cast<std::size_t>(p.degree);
    if (p.degree >= 1 && p.degree <= kMaxBezierDegree && pts.size() > degree)
      limits.count_bezier_points((pts.size() - degree) * (degree + 1), sp + ".points");
    segments.emplace_back(
        at_path(source, sp, [&] { return NurbsCurve::make(p.degree, std::move(pts), p.knots, p.weights, 2); }));
  }
  b.path_segments(c.id, std::move(segments), c.closed, params);
}

// A kept text as the job's text entity: its spec (millimetres) and its
// cutting parameters.
struct TextEntity {
  const DrawingText* text = nullptr;
  TextSpec spec;
  JobParams params;
};

// The text entity at `index` of the job, outlined by `outline` (the spec
// in the job's units), its refusals named at `entities[index]`.
void add_text(JobBuilder& b, const TextEntity& t, std::size_t index, double scale, const TextOutliner& outline,
              PointLimits& limits, const std::string& source) {
  const std::string at = "entities[" + std::to_string(index) + "]";
  TextSpec spec = t.spec;
  spec.size *= scale;
  spec.at = {spec.at.x * scale + 0.0, spec.at.y * scale + 0.0, 0};
  const std::vector<Glyph> glyphs = at_path(source, at, [&] { return outline(spec); });
  std::size_t points = 0;
  for (const Glyph& g : glyphs)
    for (const GlyphContour& c : g.contours)
      for (const Bezier& p : c.pieces) points += p.points.size();
  limits.count_bezier_points(points, at + ".text");
  b.text(t.text->id, glyphs, t.params);
}

// The kept contours as the builder's entities (`params`: each one's
// settings, or empty), then the texts. Each entity is refused on its own,
// as a file's are: the first refusal is thrown with the others in
// Error::more().
void add_geometry(JobBuilder& b, const std::vector<const Contour*>& kept, double scale,
                  const std::vector<JobParams>& params, const std::string& source,
                  const std::vector<TextEntity>& texts = {}, const TextOutliner& outline = {}) {
  if (kept.size() + texts.size() > kMaxEntities)
    throw InputError(errc::limit_entities, Place::in_json(source, "entities"),
                     "expected at most " + std::to_string(kMaxEntities) +
                         " entities in one job (docs/limits.md), found " + std::to_string(kept.size() + texts.size()) +
                         "; split the job into several files");
  PointLimits limits{source};
  std::vector<InputError> errors;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    try {
      add_entity(b, *kept[k], k, scale, k < params.size() ? params[k] : JobParams(), limits, source);
    } catch (const InputError& e) {
      errors.push_back(e);
    }
  }
  for (std::size_t k = 0; k < texts.size(); ++k) {
    try {
      add_text(b, texts[k], kept.size() + k, scale, outline, limits, source);
    } catch (const InputError& e) {
      errors.push_back(e);
    }
  }
  if (errors.empty()) return;
  InputError first = errors.front();
  for (std::size_t i = 1; i < errors.size(); ++i) first.add_more(errors[i]);
  throw first;
}

// Where each entity of the job comes from in the drawing, for messages:
// the layer, the element (entity type and handle), where it starts (a
// text's glyph: where the text is).
void locate_entities(Job& job, const Kept& kept) {
  std::map<std::string, const Contour*> by_id;
  std::map<std::string, const DrawingText*> texts;
  for (const Contour* c : kept.contours) by_id.emplace(c->id, c);
  for (const DrawingText* t : kept.texts) texts.emplace(t->id, t);
  for (Entity& e : job.entities) {
    if (const auto t = texts.find(e.id.substr(0, e.id.rfind('/'))); e.type == "text" && t != texts.end()) {
      const DrawingText& dt = *t->second;
      e.origin = "layer " + quoted(dt.layer) + ", " + dt.element + ", at (" + format_significant(dt.at.x, 6) + ", " +
                 format_significant(dt.at.y, 6) + ")";
      continue;
    }
    const auto it = by_id.find(e.id);
    if (it == by_id.end()) continue;
    const Contour& c = *it->second;
    const bool any = c.is_interpolation ? !c.interpolation.through.empty() : !c.pieces.empty();
    const Vec3 at = !any ? Vec3{} : c.is_interpolation ? c.interpolation.through.front() : c.pieces.front().start();
    const size_t joined = c.is_interpolation ? 1 : c.pieces.size();
    e.origin = (c.layer.empty() ? std::string() : "layer " + quoted(c.layer) + ", ") + c.element +
               (joined > 1 && c.id.find('+') != std::string::npos ? " and the elements joined to it" : "") +
               (any ? ", from (" + format_significant(at.x, 6) + ", " + format_significant(at.y, 6) + ")" : "");
  }
}

// A drawing's `side` "outside" is the part's outside, "inside" the
// outline's inside (docs/import.md, "Sides of a part"): each kept closed
// contour gets the side of its even-odd depth among the others (even: the
// side asked for; odd: the other one). Empty: the setting is not one of
// those two, every entity keeps the job's side. Contours that cross each
// other are warned about.
std::vector<std::string> sides_by_nesting(const Drawing& d, const std::vector<const Contour*>& kept,
                                          const SettingsJson& settings, std::vector<std::string>* warnings) {
  std::string side;  // the value as JSON text
  for (const auto& [k, v] : settings.job)
    if (k == "side") side = v;
  if (side != "\"outside\"" && side != "\"inside\"") return {};
  side = side.substr(1, side.size() - 2);
  // The curves as the job has them (B-splines and interpolations
  // included), from the geometry alone.
  JobBuilder geometry(d.source);
  add_geometry(geometry, kept, 1, {}, d.source);
  const Job job = geometry.build();
  std::vector<size_t> closed;
  std::vector<std::vector<Bezier>> curves;
  for (size_t k = 0; k < job.entities.size(); ++k)
    if (job.entities[k].curve.closed && !job.entities[k].curve.pieces.empty()) {
      closed.push_back(k);
      curves.push_back(job.entities[k].curve.pieces);
    }
  const Nesting nest = nest_closed_curves(curves);
  const std::string other = side == "outside" ? "inside" : "outside";
  std::vector<std::string> out(job.entities.size());
  for (size_t i = 0; i < closed.size(); ++i) out[closed[i]] = nest.depth[i] % 2 == 0 ? side : other;
  if (warnings)
    for (const auto& [a, b] : nest.crossing)
      warnings->push_back(tagged_warning("side \"" + side + "\": contours " + quoted(job.entities[closed[a]].id) +
                                             " and " + quoted(job.entities[closed[b]].id) +
                                             " cross each other, so neither is inside the other: each is cut on the "
                                             "side its nesting among the rest gives it, and the tool runs through "
                                             "the other's region",
                                         "contours-cross"));
  return out;
}

// A refused setting is named by the option that gave it: the names the
// refused path and the setting's key have in common (`--set lead` for
// job.lead.lenght given whole, `--set tabs` for job.tabs.width missing
// beside --set tabs.count). Empty when no setting is named.
std::string refused_setting(const InputError& e, const ImportOptions& opt) {
  const std::string path = e.place().json_path.value_or("");
  const auto names = [](const std::string& p) {
    std::vector<std::string> out(1);
    for (const char c : p) {
      if (c == '.' || c == '[')
        out.emplace_back();
      else
        out.back() += c;
    }
    return out;
  };
  const std::vector<std::string> at = names(path.starts_with("job.") ? path.substr(4) : path);
  std::string best;
  for (const auto& [k, v] : opt.settings) {
    const std::vector<std::string> key = names(k);
    std::string common;
    for (size_t i = 0; i < key.size() && i < at.size() && key[i] == at[i]; ++i) common += (i ? "." : "") + key[i];
    if (common.empty() && path == "job" && e.message().find(quoted(k)) != std::string::npos) common = k;
    if (common.size() > best.size()) best = common;
  }
  return best;
}

// ---- The job file's text ----------------------------------------------------

// Every number at full double precision (format_exact: messages round, a
// job file must not).
std::string num(double v, double scale) { return format_exact(v * scale); }
std::string point(const Vec3& p, double scale) { return "[" + num(p.x, scale) + ", " + num(p.y, scale) + "]"; }
std::string points(const std::vector<Vec3>& ps, double scale) {
  std::string o = "[";
  for (size_t i = 0; i < ps.size(); ++i) o += (i ? ", " : "") + point(ps[i], scale);
  return o + "]";
}
std::string numbers(const std::vector<double>& vs) {
  std::string o = "[";
  for (size_t i = 0; i < vs.size(); ++i) o += (i ? ", " : "") + format_exact(vs[i]);
  return o + "]";
}

// One kept contour as an entity of the job file, with its settings
// (`members`: keys and values as JSON text).
void write_contour(std::ostream& o, const Contour& c, const std::vector<std::pair<std::string, std::string>>& members,
                   double scale) {
  o << "    { \"id\": " << quoted(c.id) << ", ";
  for (const auto& [k, v] : members) o << quoted(k) << ": " << v << ", ";
  if (c.is_interpolation) {
    o << "\"type\": \"interpolate\", " << (c.interpolation.closed ? "\"closed\": true, " : "")
      << "\"through\": " << points(c.interpolation.through, scale) << " }";
    return;
  }
  o << "\"type\": \"path\", " << (c.closed ? "\"closed\": true, " : "") << "\"segments\": [";
  for (size_t i = 0; i < c.pieces.size(); ++i) {
    const Piece& p = c.pieces[i];
    o << (i ? ",\n" : "\n") << "        { \"type\": \"" << (p.bspline ? "bspline" : "bezier") << "\", ";
    if (p.bspline) o << "\"degree\": " << p.degree << ", ";
    o << "\"points\": " << points(p.points, scale);
    if (!p.weights.empty()) o << ", \"weights\": " << numbers(p.weights);
    if (p.bspline) o << ", \"knots\": " << numbers(p.knots);
    o << " }";
  }
  o << " ] }";
}

// One kept text as an entity of the job file.
void write_text(std::ostream& o, const DrawingText& t, const TextSpec& spec,
                const std::vector<std::pair<std::string, std::string>>& members, double scale) {
  o << "    { \"id\": " << quoted(t.id) << ", ";
  for (const auto& [k, v] : members) o << quoted(k) << ": " << v << ", ";
  o << "\"type\": \"text\", \"text\": " << quoted(spec.text) << ", \"font\": " << quoted(spec.font)
    << ", \"size\": " << num(spec.size, scale) << ", \"at\": " << point(spec.at, scale) << ", \"align\": \""
    << (spec.align == TextAlign::left     ? "left"
        : spec.align == TextAlign::center ? "center"
                                          : "right")
    << "\", \"angle\": " << format_exact(spec.angle) << " }";
}

}  // namespace

std::string job_json(const Drawing& d, const ImportOptions& opt) {
  check_options(opt);
  const std::set<std::string> keep = kept_layers(d, opt);
  const SettingsJson settings = settings_json(opt.settings);
  const Kept all = kept_entities(d, keep, opt);
  const std::vector<const Contour*>& kept = all.contours;
  const double scale = units_scale(settings);
  std::string top, job;
  bool units = false;
  for (const auto& [k, v] : settings.top) {
    units = units || k == "units";
    top += (top.empty() ? "" : ",\n  ") + quoted(k) + ": " + v;
  }
  for (const auto& [k, v] : settings.job) job += (job.empty() ? "" : ",\n    ") + quoted(k) + ": " + v;
  std::ostringstream o;
  o << "{\n  \"bezcam\": 1,\n";
  if (!units) o << "  \"units\": \"mm\",\n";
  if (!top.empty()) o << "  " << top << ",\n";  // top-level settings, one per line
  if (!job.empty()) o << "  \"job\": {\n    " << job << "\n  },\n";
  const std::vector<std::string> sides = sides_by_nesting(d, kept, settings, nullptr);
  check_nesting_selectors(opt, sides, d.source);
  o << "  \"entities\": [";
  for (size_t k = 0; k < kept.size(); ++k) {
    o << (k ? ",\n" : "\n");
    write_contour(o, *kept[k], entity_members(*kept[k], opt, k < sides.size() ? sides[k] : std::string()), scale);
  }
  for (size_t k = 0; k < all.texts.size(); ++k) {
    const DrawingText& t = *all.texts[k];
    o << (k + kept.size() ? ",\n" : "\n");
    write_text(o, t, text_spec(t, opt, d.source, nullptr), entity_members(t.layer, t.id, opt, ""), scale);
  }
  o << "\n  ]\n}\n";
  return o.str();
}

Job to_job(const Drawing& d, const ImportOptions& opt, std::vector<std::string>* warnings) {
  check_options(opt);
  const std::set<std::string> keep = kept_layers(d, opt);
  const SettingsJson settings = settings_json(opt.settings);
  const Kept all = kept_entities(d, keep, opt);
  const std::vector<const Contour*>& kept = all.contours;
  if (warnings)
    for (const Gap& g : d.closed_gaps)
      warnings->push_back(tagged_warning("contour " + quoted(g.id) + ": a gap of " + format_significant(g.size, 3) +
                                             " mm at (" + format_significant(g.at.x, 6) + ", " +
                                             format_significant(g.at.y, 6) +
                                             ") closed by the join tolerance (the ends moved to meet)",
                                         "gap-closed"));
  const std::vector<std::string> sides = sides_by_nesting(d, kept, settings, warnings);
  check_nesting_selectors(opt, sides, d.source);
  std::vector<JobParams> params;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    try {
      params.push_back(entity_params(entity_members(*kept[k], opt, k < sides.size() ? sides[k] : std::string()),
                                     d.source, "entities[" + std::to_string(k) + "]"));
    } catch (const InputError& e) {
      if (warnings) warnings->clear();
      throw at_scoped_setting(e, *kept[k], opt, d.source);
    }
  }
  std::vector<TextEntity> texts;
  for (std::size_t k = 0; k < all.texts.size(); ++k) {
    const DrawingText& t = *all.texts[k];
    try {
      texts.push_back({&t, text_spec(t, opt, d.source, warnings),
                       entity_params(entity_members(t.layer, t.id, opt, ""), d.source,
                                     "entities[" + std::to_string(kept.size() + k) + "]")});
    } catch (const InputError& e) {
      if (warnings) warnings->clear();
      throw at_scoped_setting(e, t.layer, t.id, opt, d.source);
    }
  }
  JobBuilder b(d.source);
  try {
    b.settings(opt.settings);
    add_geometry(b, kept, units_scale(settings), params, d.source, texts, opt.outline);
    Job job = b.build();
    locate_entities(job, all);
    return job;
  } catch (const InputError& e) {
    // The refusal stands alone: what the sides of a refused job would
    // have been is not said.
    if (warnings) warnings->clear();
    const std::string best = refused_setting(e, opt);
    if (best.empty()) throw;
    Place where = Place::at_setting("settings." + best);
    where.file = d.source;
    throw InputError(e.id(), where, e.message());
  }
}

}  // namespace bezcam::import
