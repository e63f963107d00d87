// job_json family: surface entities (`bezier_patch`, `coons_patch`,
// `curve_on_surface`) and their `toolpath` object (docs/job-format.md).
#include <algorithm>
#include <cmath>

#include "job_json_detail.hpp"

namespace bezcam::detail {

namespace {

std::string idx(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

// Every point of a patch is [x, y, z].
std::vector<Vec3> points3(const JsonCtx& ctx, const json& v, const std::string& path, size_t min_size) {
  int dim = 0;
  std::vector<Vec3> pts = ctx.points(v, path, &dim, min_size);
  if (dim != 3)
    ctx.fail(path, errc::job_dimension,
             "expected 3D points [x, y, z] (a patch lives in space), found " + std::to_string(dim) + "D points");
  return pts;
}

ToolpathSpec parse_toolpath(const JsonCtx& ctx, const json& obj, const std::string& path) {
  ToolpathSpec t;
  auto it = obj.find("toolpath");
  if (it == obj.end()) return t;
  const std::string tp = path + ".toolpath";
  if (!it->is_object()) ctx.expected(tp, "an object with \"pattern\", \"direction\" and \"stepover\"", *it);
  ctx.check_keys(*it, tp, {"pattern", "direction", "stepover"});
  if (auto p = it->find("pattern"); p != it->end()) {
    t.pattern = ctx.string(*p, tp + ".pattern");
    if (t.pattern != "zigzag" && t.pattern != "raster" && t.pattern != "boundary")
      ctx.fail(tp + ".pattern", errc::job_toolpath,
               "expected \"zigzag\", \"raster\" or \"boundary\", found " + describe(*p));
  }
  if (auto d = it->find("direction"); d != it->end()) {
    const std::string s = ctx.string(*d, tp + ".direction");
    if (s != "u" && s != "v")
      ctx.fail(tp + ".direction", errc::job_toolpath,
               "expected \"u\" or \"v\" (the parameter that varies along a pass), found " + describe(*d));
    t.direction = s[0];
  }
  if (auto s = it->find("stepover"); s != it->end()) t.stepover = ctx.positive(*s, tp + ".stepover");
  return t;
}

// Knot spans of a B-spline object as a partition of [0,1]: the distinct
// knots inside the valid domain [knots[p], knots[len-p-1]], normalised.
std::vector<double> bspline_breaks(const json& obj) {
  const int p = obj["degree"].get<int>();
  std::vector<double> k;
  for (const auto& x : obj["knots"]) k.push_back(x.get<double>());
  const size_t hi = k.size() - size_t(p) - 1;
  const double a = k[size_t(p)], b = k[hi];
  std::vector<double> br;
  for (size_t i = size_t(p); i <= hi; ++i)
    if (br.empty() || (k[i] - a) / (b - a) > br.back()) br.push_back((k[i] - a) / (b - a));
  return br;
}

BoundaryCurve parse_boundary(const JsonCtx& ctx, const json& obj, const std::string& path) {
  if (!obj.is_object()) ctx.expected(path, "a curve object ({\"type\": \"bezier\" or \"bspline\", ...})", obj);
  ctx.check_keys(obj, path, {"type", "points", "weights", "degree", "knots"});
  int dim = 0;
  std::vector<Bezier> pieces;
  const CurveSegment seg = parse_curve_object(ctx, obj, path, &dim, pieces, false);
  if (dim != 3)
    ctx.fail(path + ".points", errc::job_dimension,
             "expected 3D points [x, y, z] for a Coons boundary, found " + std::to_string(dim) + "D points");
  if (seg.kind == "bspline" && pieces.size() > 1) {
    // The Coons formula uses the curve's own parameter: its knot spans.
    std::vector<double> br = bspline_breaks(obj);
    if (br.size() == pieces.size() + 1) {
      br.back() = 1;
      return ctx.at(path, [&] { return BoundaryCurve::make(std::move(pieces), std::move(br)); });
    }
    ctx.warn(path, "its Bézier pieces do not match its knot spans; using a uniform parametrisation");
  }
  return ctx.at(path, [&] { return BoundaryCurve::make(std::move(pieces)); });
}

std::shared_ptr<const SurfaceGeometry> parse_bezier_patch(const JsonCtx& ctx, const json& obj,
                                                          const std::string& path) {
  const json& pts = ctx.array(ctx.require(obj, path, "points"), path + ".points", 2);
  std::vector<std::vector<Vec3>> rows;
  for (size_t i = 0; i < pts.size(); ++i) rows.push_back(points3(ctx, pts[i], idx(path + ".points", i), 2));
  ctx.count_bezier_points(pts.size() * rows.front().size(), path + ".points");
  std::vector<std::vector<double>> weights;
  if (auto it = obj.find("weights"); it != obj.end()) {
    ctx.array(*it, path + ".weights");
    for (size_t i = 0; i < it->size(); ++i) weights.push_back(ctx.numbers((*it)[i], idx(path + ".weights", i)));
  }
  return ctx.at(path, [&] { return SurfaceGeometry::make(BezierPatch::make(rows, weights)); });
}

std::shared_ptr<const SurfaceGeometry> parse_coons_patch(const JsonCtx& ctx, const json& obj, const std::string& path) {
  const std::string bp = path + ".boundaries";
  const json& b = ctx.require(obj, path, "boundaries");
  if (!b.is_object()) ctx.expected(bp, "an object with the curves \"v0\", \"v1\", \"u0\" and \"u1\"", b);
  ctx.check_keys(b, bp, {"v0", "v1", "u0", "u1"});
  BoundaryCurve c[4];
  const char* names[4] = {"v0", "v1", "u0", "u1"};
  for (int k = 0; k < 4; ++k) c[k] = parse_boundary(ctx, ctx.require(b, bp, names[k]), bp + "." + names[k]);
  CoonsBlend blend = CoonsBlend::cubic;
  if (auto it = obj.find("blend"); it != obj.end()) {
    const std::string s = ctx.string(*it, path + ".blend");
    if (s == "linear")
      blend = CoonsBlend::linear;
    else if (s == "cubic")
      blend = CoonsBlend::cubic;
    else if (s == "quintic")
      blend = CoonsBlend::quintic;
    else
      ctx.fail(path + ".blend", errc::job_blend,
               "expected \"linear\", \"cubic\" or \"quintic\", found " + describe(*it));
  }
  return ctx.at(path, [&] {
    return SurfaceGeometry::make(
        CoonsPatch::make(std::move(c[0]), std::move(c[1]), std::move(c[2]), std::move(c[3]), blend));
  });
}

// A curve in the parameter square: its Bézier pieces' control points must
// lie in [0,1]^2 (so the curve does, and the exact composition with the
// patch has positive weights). Points a hair outside are clamped.
void check_unit_square(const JsonCtx& ctx, CurveGeometry& g, const std::string& path) {
  constexpr double slack = 1e-12;
  for (size_t s = 0; s < g.segments.size(); ++s) {
    const std::string sp = g.kind == "path" ? idx(path + ".segments", s) : path;
    const CurveSegment& seg = g.segments[s];
    for (size_t k = seg.first_piece; k < seg.first_piece + seg.piece_count; ++k)
      for (auto& p : g.pieces[k].points) {
        if (p.x < -slack || p.x > 1 + slack || p.y < -slack || p.y > 1 + slack)
          ctx.fail(sp, errc::job_uv_range,
                   "expected a curve in the patch's parameter square [0,1]^2 (u, v), found a control point (" +
                       fmt_num(p.x) + ", " + fmt_num(p.y) + ") of its Bézier form outside it");
        p = {std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0)};
      }
  }
}

}  // namespace

void parse_bezier_patch_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e) {
  e.surface = parse_bezier_patch(ctx, obj, path);
  e.toolpath = parse_toolpath(ctx, obj, path);
}

void parse_coons_patch_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e) {
  e.surface = parse_coons_patch(ctx, obj, path);
  e.toolpath = parse_toolpath(ctx, obj, path);
}

void parse_curve_on_surface_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e) {
  const std::string sp = path + ".surface";
  const json& s = ctx.require(obj, path, "surface");
  if (s.is_object()) {
    const std::string type = ctx.string(ctx.require(s, sp, "type"), sp + ".type");
    if (type == "bezier_patch") {
      ctx.check_keys(s, sp, {"type", "id", "points", "weights"});
      e.surface = parse_bezier_patch(ctx, s, sp);
    } else if (type == "coons_patch") {
      ctx.check_keys(s, sp, {"type", "id", "boundaries", "blend"});
      e.surface = parse_coons_patch(ctx, s, sp);
    } else {
      ctx.fail(sp + ".type", errc::job_surface_type,
               "expected \"bezier_patch\" or \"coons_patch\", found " + describe(s["type"]));
    }
  } else if (!s.is_string()) {
    ctx.expected(sp, "a patch object or the id of a patch entity", s);
  }  // a string is resolved once every entity is read
  const std::string cp = path + ".curve";
  const json& c = ctx.require(obj, path, "curve");
  if (!c.is_object()) ctx.expected(cp, "a 2D curve object (\"bezier\", \"bspline\" or \"path\")", c);
  const std::string type = ctx.string(ctx.require(c, cp, "type"), cp + ".type");
  int dim = 0;
  std::vector<Bezier> pieces;
  if (type == "path") {
    ctx.check_keys(c, cp, {"type", "segments", "closed"});
    const json& segs = ctx.array(ctx.require(c, cp, "segments"), cp + ".segments", 1);
    std::vector<CurveSegment> ss;
    for (size_t i = 0; i < segs.size(); ++i)
      ss.push_back(parse_curve_object(ctx, segs[i], idx(cp + ".segments", i), &dim, pieces, true));
    bool closed = false;
    if (c.contains("closed")) closed = ctx.boolean(c["closed"], cp + ".closed");
    e.uv_curve = ctx.at(cp, [&] { return make_path(std::move(ss), std::move(pieces), closed, dim); });
  } else {
    ctx.check_keys(c, cp, {"type", "points", "weights", "degree", "knots"});
    CurveSegment seg = parse_curve_object(ctx, c, cp, &dim, pieces, false);
    e.uv_curve = make_single(seg, std::move(pieces), dim);
  }
  if (dim != 2)
    ctx.fail(cp, errc::job_dimension,
             "expected a 2D curve of (u, v) parameters, found " + std::to_string(dim) + "D points");
  check_unit_square(ctx, e.uv_curve, cp);
}

void resolve_surface_references(const JsonCtx& ctx, const json& entities, Job& job) {
  for (size_t i = 0; i < job.entities.size(); ++i) {
    Entity& e = job.entities[i];
    const json& given = entities[e.file_index.value_or(i)];
    if (e.type != "curve_on_surface" || !given["surface"].is_string()) continue;
    const std::string name = given["surface"].get<std::string>();
    const std::string sp = e.json_path() + ".surface";
    const Entity* found = nullptr;
    for (const Entity& o : job.entities) {
      if (o.id != name) continue;
      if (found)
        ctx.fail(sp, errc::job_surface_ref,
                 "the id \"" + name + "\" names more than one entity; give the patch a unique id");
      found = &o;
    }
    if (!found)
      ctx.fail(sp, errc::job_surface_ref,
               "expected the id of a bezier_patch or coons_patch entity, found \"" + name + "\", which no entity has");
    if (!found->surface || found->type == "curve_on_surface")
      ctx.fail(sp, errc::job_surface_ref,
               "expected the id of a bezier_patch or coons_patch entity, found \"" + name + "\", a " + found->type);
    e.surface = found->surface;
  }
}

}  // namespace bezcam::detail
