// job_json family: `bspline` segments (also inside paths) and `interpolate`
// entities (docs/job-format.md). The curves become exact Bézier pieces; the
// B-spline form is kept on the segment for exact NURBS output.
#include <algorithm>
#include <memory>
#include <optional>

#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/kernel/spline_interp.hpp"
#include "job_json_detail.hpp"

namespace bezcam::detail {

void parse_bspline_segment(const JsonCtx& ctx, const json& obj, const std::string& path, int* dim,
                           std::vector<Bezier>& pieces, CurveSegment& seg) {
  const int degree = ctx.integer(ctx.require(obj, path, "degree"), path + ".degree");
  auto pts = ctx.points(ctx.require(obj, path, "points"), path + ".points", dim, 2);
  auto knots = ctx.numbers(ctx.require(obj, path, "knots"), path + ".knots");
  std::vector<double> weights;
  if (obj.contains("weights")) weights = ctx.numbers(obj["weights"], path + ".weights");
  // Its Bézier form has at most one piece of degree + 1 points per span.
  if (degree >= 1 && degree <= kMaxBezierDegree && pts.size() > static_cast<size_t>(degree))
    ctx.count_bezier_points((pts.size() - static_cast<size_t>(degree)) * static_cast<size_t>(degree + 1),
                            path + ".points");
  // Kernel errors name `knots[7]`, `weights[2]`, `degree`...: prefix the path.
  NurbsCurve c = ctx.at(path, [&] { return NurbsCurve::make(degree, pts, knots, weights, *dim); });
  // Equal weights cancel out: the curve is polynomial, and exactly so.
  if (c.rational() && std::all_of(c.weights.begin(), c.weights.end(), [&](double w) { return w == c.weights[0]; }))
    c.weights.clear();
  const auto bez = to_bezier(c);
  pieces.insert(pieces.end(), bez.begin(), bez.end());
  seg.degree = degree;
  seg.rational = c.rational();
  seg.nurbs = std::make_shared<const NurbsCurve>(std::move(c));
}

void parse_interpolate_entity(const JsonCtx& ctx, const json& obj, const std::string& path, Entity& e) {
  int dim = 0;
  const auto through = ctx.points(ctx.require(obj, path, "through"), path + ".through", &dim, 2);
  std::string method = "cubic-spline";
  if (obj.contains("method")) {
    method = ctx.string(obj["method"], path + ".method");
    if (method != "cubic-spline" && method != "lagrange" && method != "hermite")
      ctx.fail(path + ".method", errc::job_method,
               "expected \"cubic-spline\", \"hermite\" or \"lagrange\", found " + describe(obj["method"]));
  }
  // Hermite: a tangent per point; cubic spline: optional end tangents.
  std::vector<Vec3> tangents;
  if (method == "hermite") {
    int tdim = 0;
    tangents = ctx.points(ctx.require(obj, path, "tangents"), path + ".tangents", &tdim, 0);
    if (tdim != dim)
      ctx.fail(path + ".tangents", errc::curve_dimension,
               "expected " + std::to_string(dim) + "D tangents like the points, found " + std::to_string(tdim) + "D");
    if (tangents.size() != through.size())
      ctx.fail(path + ".tangents", errc::curve_tangent_count,
               "expected one tangent per point of \"through\" (" + std::to_string(through.size()) + "), found " +
                   std::to_string(tangents.size()));
  } else if (obj.contains("tangents")) {
    ctx.fail(path + ".tangents", errc::job_method,
             "\"tangents\" belong to method \"hermite\"; add \"method\": \"hermite\"");
  }
  std::optional<std::pair<Vec3, Vec3>> end_tangents;
  if (obj.contains("end_tangents")) {
    if (method != "cubic-spline" || (obj.contains("closed") && obj["closed"] == true))
      ctx.fail(path + ".end_tangents", errc::job_method,
               "\"end_tangents\" clamp an open \"cubic-spline\" (a Hermite curve takes \"tangents\", a closed spline "
               "has no ends)");
    int tdim = 0;
    const auto ends = ctx.points(obj["end_tangents"], path + ".end_tangents", &tdim, 0);
    if (ends.size() != 2 || tdim != dim)
      ctx.fail(path + ".end_tangents", errc::curve_tangent_count,
               "expected [T0, Tn]: two " + std::to_string(dim) + "D tangents, at the first and the last point");
    end_tangents = std::pair{ends[0], ends[1]};
  }
  bool closed = false;
  if (obj.contains("closed")) closed = ctx.boolean(obj["closed"], path + ".closed");
  if (closed && method == "lagrange")
    ctx.fail(path + ".closed", errc::job_method,
             "a closed curve through the points is a periodic spline: use method \"cubic-spline\" with closed, or "
             "leave closed out for \"lagrange\"");

  // Lagrange: one piece through every point; cubic spline: a cubic per gap.
  ctx.count_bezier_points(method == "lagrange" ? through.size() : 4 * through.size(), path + ".through");
  CurveSegment seg;
  seg.kind = "interpolate";
  std::vector<Bezier> pieces;
  if (method == "lagrange") {
    Bezier b = ctx.at(path, [&] { return lagrange_polynomial(through, dim); });
    // The digest (§4): one polynomial through many points oscillates.
    const double over = bounding_box_overshoot(std::span<const Bezier>(&b, 1), through);
    double scale = 1e-300;
    for (const auto& p : through) scale = std::max(scale, max_abs(p));
    if (over > 1e-9 * scale)
      ctx.warn(path, "the Lagrange polynomial through these " + std::to_string(through.size()) +
                         " points leaves their bounding box by " + fmt_num(over) +
                         " (one polynomial through many points oscillates between them); method \"cubic-spline\" "
                         "stays close to the points");
    seg.degree = b.degree();
    pieces.push_back(std::move(b));
  } else if (method == "hermite") {
    pieces = ctx.at(path, [&] { return hermite_pieces(through, tangents, closed, dim); });
    seg.degree = 3;  // Bézier pieces are the exact form (no NURBS kept)
  } else {
    NurbsCurve c = ctx.at(path, [&] {
      if (closed) return periodic_cubic_spline(through, dim);
      if (end_tangents) return clamped_cubic_spline(through, end_tangents->first, end_tangents->second, dim);
      return natural_cubic_spline(through, dim);
    });
    pieces = to_bezier(c);
    seg.degree = 3;
    seg.nurbs = std::make_shared<const NurbsCurve>(std::move(c));
  }
  e.curve = make_single(seg, std::move(pieces), dim);
  e.curve.closed = closed;
}

}  // namespace bezcam::detail
