// Jobs from in-memory curves: the same invariants as the JSON reader's.
#include "bezcam/job/job_builder.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "bezcam/error.hpp"
#include "bezcam/job/keys.hpp"
#include "bezcam/job/tools.hpp"
#include "bezcam/kernel/spline_interp.hpp"
#include "bezcam/limits.hpp"

namespace bezcam {

namespace {

// The checks the JSON reader makes of a number that must be positive.
double positive(double v, const std::string& source, const std::string& key) {
  if (!std::isfinite(v) || v <= 0)
    throw InputError(errc::job_not_positive, Place::in_json(source, key),
                     "expected a finite number > 0, found " + fmt_num(v));
  return v;
}

double finite(double v, const std::string& source, const std::string& key) {
  if (!std::isfinite(v))
    throw InputError(errc::job_not_finite, Place::in_json(source, key),
                     "expected a finite number, found " + fmt_num(v));
  return v;
}

void check_params(const JobParams& p, const std::string& source, const std::string& path) {
  const std::string at = path.empty() ? "" : path + ".";
  if (p.feed) positive(*p.feed, source, at + "feed");
  if (p.plunge_feed) positive(*p.plunge_feed, source, at + "plunge_feed");
  if (p.spindle_rpm && (!std::isfinite(*p.spindle_rpm) || *p.spindle_rpm < 0))
    throw InputError(errc::job_not_positive, Place::in_json(source, at + "spindle_rpm"),
                     "expected a finite number >= 0, found " + fmt_num(*p.spindle_rpm));
  if (p.safe_z) finite(*p.safe_z, source, at + "safe_z");
  if (p.cut_z) finite(*p.cut_z, source, at + "cut_z");
  if (p.tool_radius && (!std::isfinite(*p.tool_radius) || *p.tool_radius < 0))
    throw InputError(errc::job_not_positive, Place::in_json(source, at + "tool_radius"),
                     "expected a finite number >= 0, found " + fmt_num(*p.tool_radius));
  if (p.top_z) finite(*p.top_z, source, at + "top_z");
  if (p.clearance && (!std::isfinite(*p.clearance) || *p.clearance < 0))
    throw InputError(errc::job_range, Place::in_json(source, at + "clearance"),
                     "expected a height >= 0 above top_z, found " + fmt_num(*p.clearance));
  for (const auto* seq : {&p.before, &p.after}) {
    if (!*seq) continue;
    const std::string key = at + (seq == &p.before ? "before" : "after");
    for (size_t i = 0; i < (*seq)->size(); ++i)
      if (auto why = template_problem((**seq)[i], kEntityPlaceholders))
        throw InputError(errc::job_template, Place::in_json(source, key + "[" + std::to_string(i) + "]"), *why);
  }
  if (p.tool && *p.tool < 0)
    throw InputError(errc::job_not_positive, Place::in_json(source, at + "tool"),
                     "expected a tool number >= 0, found " + std::to_string(*p.tool));
}

}  // namespace

JobBuilder::JobBuilder(std::string name) { job_.source = std::move(name); }

JobBuilder& JobBuilder::tools(ToolTable t) {
  job_.tools = std::move(t);
  return *this;
}

JobBuilder& JobBuilder::units(Units u) {
  // The default tolerance is kDefaultToleranceMm in the job's units, as in a file.
  if (job_.tolerance == kDefaultToleranceMm / mm_per_unit(job_.units))
    job_.tolerance = kDefaultToleranceMm / mm_per_unit(u);
  job_.units = u;
  return *this;
}
JobBuilder& JobBuilder::tolerance(double t) {
  job_.tolerance = positive(t, job_.source, "tolerance");
  return *this;
}
JobBuilder& JobBuilder::machine(std::string name) { return set(job_.machine, std::move(name)); }
JobBuilder& JobBuilder::feed(double v) { return set(job_.params.feed, v); }
JobBuilder& JobBuilder::plunge_feed(double v) { return set(job_.params.plunge_feed, v); }
JobBuilder& JobBuilder::safe_z(double v) { return set(job_.params.safe_z, v); }
JobBuilder& JobBuilder::cut_z(double v) { return set(job_.params.cut_z, v); }
JobBuilder& JobBuilder::spindle_rpm(double v) { return set(job_.params.spindle_rpm, v); }
JobBuilder& JobBuilder::tool(int t) { return set(job_.params.tool, t); }
JobBuilder& JobBuilder::params(const JobParams& p) {
  job_.params = p.over(job_.params);
  return *this;
}

JobBuilder& JobBuilder::entity(std::string id, std::string type, CurveGeometry g, JobParams params) {
  if (job_.entities.size() >= kMaxEntities)
    throw InputError(errc::limit_entities, Place::in_json(job_.source, "entities"),
                     "expected at most " + std::to_string(kMaxEntities) + " entities in one job (docs/limits.md)");
  Entity e;
  e.id = std::move(id);
  e.index = job_.entities.size();
  e.type = std::move(type);
  e.params = std::move(params);
  e.curve = std::move(g);
  if (e.index != file_entities_) e.file_index = file_entities_;
  job_.entities.push_back(std::move(e));
  ++file_entities_;
  return *this;
}

JobBuilder& JobBuilder::text(std::string id, const std::vector<Glyph>& glyphs, JobParams params) {
  const std::string at = "entities[" + std::to_string(file_entities_) + "]";
  if (glyphs.empty())
    throw InputError(errc::text_empty, Place::in_json(job_.source, at, "text"),
                     "expected letters to cut, found only spaces (no glyph with an outline)");
  const std::optional<CutSide> side = params.side ? params.side : job_.params.side;
  const size_t file_index = file_entities_;
  for (size_t g = 0; g < glyphs.size(); ++g)
    for (const GlyphContour& c : glyphs[g].contours) {
      JobParams p = params;
      if (c.hole && (side == CutSide::inside || side == CutSide::outside)) p.side = hole_side(side);
      CurveGeometry geometry;
      try {
        geometry = make_path(glyph_segments(c), c.pieces, true, 2);
      } catch (const InputError& e) {
        throw InputError(e.id(), Place::in_json(job_.source, at, e.place().relative_path()), e.message());
      }
      file_entities_ = file_index;
      entity(id + "/" + std::to_string(g), "text", std::move(geometry), std::move(p));
      job_.entities.back().glyph = glyphs[g].characters;
    }
  file_entities_ = file_index + 1;
  return *this;
}

JobBuilder& JobBuilder::bezier(std::string id, Bezier curve, JobParams params) {
  CurveSegment seg;
  seg.kind = "bezier";
  seg.degree = curve.degree();
  seg.rational = curve.rational();
  seg.piece_count = 1;
  const int dim = curve.dim;
  return entity(std::move(id), "bezier", make_single(seg, {std::move(curve)}, dim), std::move(params));
}

JobBuilder& JobBuilder::nurbs(std::string id, NurbsCurve curve, JobParams params) {
  std::vector<Bezier> pieces = to_bezier(curve);
  CurveSegment seg;
  seg.kind = "bspline";
  seg.degree = curve.degree;
  seg.rational = !curve.weights.empty();
  seg.piece_count = pieces.size();
  const int dim = curve.dim;
  seg.nurbs = std::make_shared<const NurbsCurve>(std::move(curve));
  return entity(std::move(id), "bspline", make_single(seg, std::move(pieces), dim), std::move(params));
}

JobBuilder& JobBuilder::path(std::string id, std::vector<Bezier> segments, bool closed, JobParams params) {
  if (segments.empty())
    throw InputError(errc::job_missing,
                     Place::in_json(job_.source, "entities[" + std::to_string(job_.entities.size()) + "].segments"),
                     "a path needs at least one segment");
  std::vector<CurveSegment> segs;
  int dim = 2;
  for (size_t i = 0; i < segments.size(); ++i) {
    CurveSegment s;
    s.kind = "bezier";
    s.degree = segments[i].degree();
    s.rational = segments[i].rational();
    s.first_piece = i;
    s.piece_count = 1;
    dim = std::max(dim, segments[i].dim);
    segs.push_back(std::move(s));
  }
  const std::string at = "entities[" + std::to_string(job_.entities.size()) + "]";
  CurveGeometry g;
  try {
    g = make_path(std::move(segs), std::move(segments), closed, dim);
  } catch (const InputError& e) {
    throw InputError(e.id(), Place::in_json(job_.source, at, e.place().relative_path()), e.message());
  }
  return entity(std::move(id), "path", std::move(g), std::move(params));
}

JobBuilder& JobBuilder::path_segments(std::string id, std::vector<PathSegment> segments, bool closed,
                                      JobParams params) {
  const std::string at = "entities[" + std::to_string(job_.entities.size()) + "]";
  if (segments.empty())
    throw InputError(errc::job_missing, Place::in_json(job_.source, at, "segments"),
                     "a path needs at least one segment");
  std::vector<CurveSegment> segs;
  std::vector<Bezier> pieces;
  int dim = 2;
  for (PathSegment& sg : segments) {
    CurveSegment s;
    s.first_piece = pieces.size();
    if (Bezier* b = std::get_if<Bezier>(&sg)) {
      s.kind = "bezier";
      s.degree = b->degree();
      s.rational = b->rational();
      dim = std::max(dim, b->dim);
      pieces.push_back(std::move(*b));
    } else {
      NurbsCurve c = std::get<NurbsCurve>(std::move(sg));
      // Equal weights cancel out: the curve is polynomial, and exactly so.
      if (c.rational() && std::all_of(c.weights.begin(), c.weights.end(), [&](double w) { return w == c.weights[0]; }))
        c.weights.clear();
      const std::vector<Bezier> bez = to_bezier(c);
      pieces.insert(pieces.end(), bez.begin(), bez.end());
      s.kind = "bspline";
      s.degree = c.degree;
      s.rational = c.rational();
      dim = std::max(dim, c.dim);
      s.nurbs = std::make_shared<const NurbsCurve>(std::move(c));
    }
    s.piece_count = pieces.size() - s.first_piece;
    segs.push_back(std::move(s));
  }
  CurveGeometry g;
  try {
    g = make_path(std::move(segs), std::move(pieces), closed, dim);
  } catch (const InputError& e) {
    throw InputError(e.id(), Place::in_json(job_.source, at, e.place().relative_path()), e.message());
  }
  return entity(std::move(id), "path", std::move(g), std::move(params));
}

JobBuilder& JobBuilder::interpolate(std::string id, std::vector<Vec3> through, bool closed, JobParams params) {
  const std::string at = "entities[" + std::to_string(job_.entities.size()) + "]";
  const int dim = std::any_of(through.begin(), through.end(), [](const Vec3& p) { return p.z != 0; }) ? 3 : 2;
  NurbsCurve c;
  try {
    c = closed ? periodic_cubic_spline(through, dim) : natural_cubic_spline(through, dim);
  } catch (const InputError& e) {
    throw InputError(e.id(), Place::in_json(job_.source, at, e.place().relative_path()), e.message());
  }
  CurveSegment seg;
  seg.kind = "interpolate";
  seg.degree = 3;
  std::vector<Bezier> pieces = to_bezier(c);
  seg.nurbs = std::make_shared<const NurbsCurve>(std::move(c));
  CurveGeometry g = make_single(seg, std::move(pieces), dim);
  g.closed = closed;
  return entity(std::move(id), "interpolate", std::move(g), std::move(params));
}

Job JobBuilder::build() const {
  if (job_.entities.empty())
    throw InputError(errc::job_missing, Place::in_json(job_.source, "entities"), "expected at least one entity");
  check_params(job_.params, job_.source, "job");
  for (const Entity& e : job_.entities) check_params(e.params, job_.source, e.json_path());
  Job job = job_;
  std::sort(job.tools.entries.begin(), job.tools.entries.end(),
            [](const ToolEntry& a, const ToolEntry& b) { return a.number < b.number; });
  for (size_t i = 0; i < job.tools.entries.size(); ++i) {
    const ToolEntry& t = job.tools.entries[i];
    const std::string at = tool_entry_path("tools", std::to_string(t.number));
    check_tool_entry(t, job.source, at);
    if (i > 0 && job.tools.entries[i - 1].number == t.number)
      throw InputError(errc::job_tool_table, Place::in_json(job.source, at),
                       "tool " + std::to_string(t.number) + " is given twice; one tool number is one tool");
  }
  (void)job_tools(job);  // one diameter and shape per tool number; the table's tools
  return job;
}

}  // namespace bezcam
