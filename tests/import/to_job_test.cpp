// A drawing's job, built in memory (to_job), is the job its file
// (job_json, what `bezcam import` writes) reads as: the same entities, the
// same doubles to the bit (a zero written as -0 reads back as +0), the same
// G-code, and the same refusals of the stated limits, word for word.
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/conic.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam::import {
namespace {

Contour contour(std::string id, std::vector<Piece> pieces, bool closed) {
  Contour c;
  c.id = std::move(id);
  c.element = "test";
  c.pieces = std::move(pieces);
  c.closed = closed;
  return c;
}

// A clamped uniform B-spline piece through `n` control points on a wave.
Piece bspline(int degree, size_t n, double y0) {
  Piece p;
  p.bspline = true;
  p.degree = degree;
  for (size_t i = 0; i < n; ++i) p.points.push_back({double(i), y0 + std::sin(double(i)), 0});
  const auto q = static_cast<size_t>(degree);
  p.knots.assign(q + 1, 0);
  for (size_t k = 1; k + q < n; ++k) p.knots.push_back(double(k));
  p.knots.insert(p.knots.end(), q + 1, double(n - q));
  return p;
}

Drawing sample() {
  Drawing d;
  d.source = "sample.dxf";
  d.format = "dxf";
  // A closed outline of lines and a rational arc, a corner at x = -0.
  std::vector<Piece> outline = {line_piece({-0.0, 0, 0}, {40, 0, 0}), line_piece({40, 0, 0}, {40, 20, 0})};
  for (Piece& p : ellipse_arc({20, 20, 0}, {20, 0, 0}, {0, 20, 0}, 0, std::acos(-1.0))) outline.push_back(p);
  outline.push_back(line_piece({0, 20, 0}, {-0.0, 0, 0}));
  outline.back().points.back() = {-0.0, 0, 0};
  d.contours.push_back(contour("0:1A", outline, true));
  d.contours.back().layer = "0";
  // A hole: a circle of rational pieces inside it.
  d.contours.push_back(contour("0:1B", ellipse_arc({20, 10, 0}, {4, 0, 0}, {0, 4, 0}, 0, 2 * std::acos(-1.0)), true));
  d.contours.back().layer = "0";
  // An open rational B-spline (weights not all equal).
  Piece spline = bspline(3, 7, 30);
  spline.weights = {1, 2, 1, 0.5, 1, 2, 1};
  d.contours.push_back(contour("0:1C", {spline}, false));
  d.contours.back().layer = "curves";
  // A closed curve through fit points.
  Contour fit;
  fit.id = "0:1D";
  fit.is_interpolation = true;
  fit.interpolation.through = {{60, 0, 0}, {70, 10, 0}, {60, 20, 0}, {50, 10, 0}};
  fit.interpolation.closed = true;
  fit.layer = "0";
  d.contours.push_back(fit);
  d.layers["0"].read["LINE"] = 4;
  d.layers["curves"].read["SPLINE"] = 1;
  return d;
}

ImportOptions part_in_inches() {
  ImportOptions o;
  o.settings = {{"units", "inch"}, {"feed", "20"}, {"cut_z", "-0.05"}, {"side", "outside"}, {"tool_diameter", "0.05"}};
  o.layers = {"0"};  // the closed contours
  return o;
}

// Settings of single entities picked by layer and id globs, one layer
// left out.
ImportOptions per_entity() {
  ImportOptions o;
  o.settings = {{"feed", "600"}, {"cut_z", "-1"}, {"side", "outside"}, {"tool", "1"}, {"tool_diameter", "3"}};
  o.scoped = {{"0:1B", "tool", "2"},       {"0:1B", "tool_diameter", "1"}, {"0:1A", "tabs.count", "2"},
              {"0:1A", "tabs.width", "3"}, {"0:1A", "tabs.height", "0.5"}, {"0", "feed", "500"},
              {"0:1[BC]", "feed", "300"},  {"0:1D", "side", "inside"}};
  o.skip = {"curves"};
  return o;
}

// Bit for bit: the sign of a zero counts.
bool same(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

TEST(ToJob, IsTheJobItsFileReadsAs) {
  const Drawing d = sample();
  for (const ImportOptions& opt : {ImportOptions{}, part_in_inches(), per_entity()}) {
    const Job file = parse_job(job_json(d, opt), d.source);
    const Job built = to_job(d, opt);
    EXPECT_EQ(built.units, file.units);
    EXPECT_EQ(built.tolerance, file.tolerance);
    ASSERT_EQ(built.entities.size(), file.entities.size());
    for (size_t k = 0; k < file.entities.size(); ++k) {
      const Entity &a = file.entities[k], &b = built.entities[k];
      EXPECT_EQ(b.id, a.id);
      EXPECT_EQ(b.type, a.type);
      EXPECT_EQ(b.params.side, a.params.side) << a.id;
      EXPECT_EQ(b.params.tool, a.params.tool) << a.id;
      EXPECT_EQ(b.params.feed, a.params.feed) << a.id;
      EXPECT_EQ(b.params.tabs.has_value(), a.params.tabs.has_value()) << a.id;
      EXPECT_EQ(b.curve.closed, a.curve.closed);
      ASSERT_EQ(b.curve.pieces.size(), a.curve.pieces.size()) << a.id;
      for (size_t i = 0; i < a.curve.pieces.size(); ++i) {
        const Bezier &pa = a.curve.pieces[i], &pb = b.curve.pieces[i];
        ASSERT_EQ(pb.points.size(), pa.points.size());
        for (size_t j = 0; j < pa.points.size(); ++j)
          EXPECT_TRUE(same(pb.points[j].x, pa.points[j].x) && same(pb.points[j].y, pa.points[j].y) &&
                      same(pb.points[j].z, pa.points[j].z))
              << a.id << " piece " << i << " point " << j;
        EXPECT_EQ(pb.weights, pa.weights);
      }
    }
    for (const char* machine : {"generic", "linuxcnc"}) {
      const MachineProfile m = load_machine_profile(machine);
      for (OutputMode mode : {OutputMode::lines, OutputMode::nurbs}) {
        ConvertOptions co;
        co.output = mode;
        EXPECT_EQ(convert(built, m, co).gcode, convert(file, m, co).gcode) << machine << " " << to_string(mode);
      }
    }
  }
}

// The refusal of to_job and of the file's reader, as printed with the
// further refusals.
std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    std::string s = e.what();
    for (const Error& m : e.more()) s += "\n" + std::string(m.what());
    return s;
  }
  return "accepted";
}

void expect_refused_alike(const Drawing& d, const std::string& id) {
  const std::string file = refusal([&] { (void)parse_job(job_json(d), d.source); });
  const std::string built = refusal([&] { (void)to_job(d); });
  EXPECT_NE(file.find(id), std::string::npos) << file;
  EXPECT_EQ(built, file);
}

TEST(ToJob, RefusesTheStatedLimitsAsTheFilesReaderDoes) {
  {  // more points in one entity than kMaxEntityPoints: a polyline
    Drawing d;
    d.source = "long.dxf";
    std::vector<Piece> lines;
    for (size_t i = 0; i < kMaxEntityPoints / 2 + 1; ++i)
      lines.push_back(line_piece({double(i), 0, 0}, {double(i + 1), double(i % 2), 0}));
    d.contours.push_back(contour("0:1", lines, false));
    expect_refused_alike(d, "points in one entity");
  }
  {  // more Bézier points in the job than kMaxJobPoints: two B-splines
    Drawing d;
    d.source = "dense.dxf";
    const size_t n = kMaxEntityPoints / 2;  // each spline's Bézier form: (n - 5) x 6 points
    for (int k = 0; k < 4; ++k)
      d.contours.push_back(contour("0:" + std::to_string(k), {bspline(5, n, 3.0 * k)}, false));
    expect_refused_alike(d, "control points in their exact Bézier form");
  }
  {  // more entities than kMaxEntities
    Drawing d;
    d.source = "many.dxf";
    for (size_t i = 0; i <= kMaxEntities; ++i)
      d.contours.push_back(
          contour("0:" + std::to_string(i), {line_piece({double(i), 0, 0}, {double(i), 1, 0})}, false));
    expect_refused_alike(d, "entities in one job");
  }
}

}  // namespace
}  // namespace bezcam::import
