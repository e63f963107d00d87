// job_json family: `bspline` segments (also inside paths) and `interpolate`
// entities (docs/job-format.md). The curves become exact Bézier pieces; the
// B-spline form is kept on the segment for exact NURBS output.
#include <algorithm>
#include <memory>

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
    if (method != "cubic-spline" && method != "lagrange")
      ctx.fail(path + ".method", errc::job_method,
               "expected \"cubic-spline\" or \"lagrange\", found " + describe(obj["method"]));
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
  } else {
    NurbsCurve c = ctx.at(path, [&] { return closed ? periodic_cubic_spline(through, dim) : natural_cubic_spline(through, dim); });
    pieces = to_bezier(c);
    seg.degree = 3;
    seg.nurbs = std::make_shared<const NurbsCurve>(std::move(c));
  }
  e.curve = make_single(seg, std::move(pieces), dim);
  e.curve.closed = closed;
}

}  // namespace bezcam::detail
