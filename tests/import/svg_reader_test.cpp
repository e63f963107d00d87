// SVG in, exactly: shapes and arcs checked against points computed here
// from the SVG specification's own formulas (appendix F.6), transforms and
// units against hand-computed coordinates, every output mode measured.
#include "bezcam/import/svg_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "support/files.hpp"

namespace bezcam::import {
namespace {

Bezier bez(const Piece& p) { return Bezier::make(p.points, p.weights); }

// Distance from q to the curve b.
double nearest(const Bezier& b, const Vec3& q) {
  const int n = 200;
  int k = 0;
  for (int i = 1; i <= n; ++i)
    if (dist(evaluate(b, i / double(n)), q) < dist(evaluate(b, k / double(n)), q)) k = i;
  double lo = std::max(0, k - 1) / double(n), hi = std::min(n, k + 1) / double(n);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 200; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (dist(evaluate(b, m1), q) < dist(evaluate(b, m2), q))
      hi = m2;
    else
      lo = m1;
  }
  return dist(evaluate(b, (lo + hi) / 2), q);
}

std::string svg(const std::string& body, const std::string& root = R"~(width="200" height="100")~") {
  return R"~(<svg xmlns="http://www.w3.org/2000/svg" )~" + root + ">" + body + "</svg>";
}

// SVG 1.1 F.6.5, computed independently of the reader: the centre and the
// angles of an endpoint arc (radii large enough).
struct CenterArc {
  double cx, cy, rx, ry, phi, t1, dt;
  Vec3 at(double t) const {
    return {cx + rx * std::cos(phi) * std::cos(t) - ry * std::sin(phi) * std::sin(t),
            cy + rx * std::sin(phi) * std::cos(t) + ry * std::cos(phi) * std::sin(t)};
  }
};
CenterArc to_center(double x1, double y1, double rx, double ry, double phi_deg, bool fa, bool fs, double x2,
                    double y2) {
  const double phi = phi_deg * std::numbers::pi / 180;
  const double xp = std::cos(phi) * (x1 - x2) / 2 + std::sin(phi) * (y1 - y2) / 2;
  const double yp = -std::sin(phi) * (x1 - x2) / 2 + std::cos(phi) * (y1 - y2) / 2;
  // F.6.6: radii too small for the ends are scaled up.
  const double lambda = xp * xp / (rx * rx) + yp * yp / (ry * ry);
  if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  double sq = (rx * rx * ry * ry - rx * rx * yp * yp - ry * ry * xp * xp) / (rx * rx * yp * yp + ry * ry * xp * xp);
  double k = std::sqrt(std::max(0.0, sq)) * (fa == fs ? -1 : 1);
  const double cxp = k * rx * yp / ry, cyp = -k * ry * xp / rx;
  const double cx = std::cos(phi) * cxp - std::sin(phi) * cyp + (x1 + x2) / 2;
  const double cy = std::sin(phi) * cxp + std::cos(phi) * cyp + (y1 + y2) / 2;
  const auto angle = [](double ux, double uy, double vx, double vy) {
    const double a = std::acos(std::clamp((ux * vx + uy * vy) / (std::hypot(ux, uy) * std::hypot(vx, vy)), -1.0, 1.0));
    return ux * vy - uy * vx < 0 ? -a : a;
  };
  const double t1 = angle(1, 0, (xp - cxp) / rx, (yp - cyp) / ry);
  double dt =
      std::fmod(angle((xp - cxp) / rx, (yp - cyp) / ry, (-xp - cxp) / rx, (-yp - cyp) / ry), 2 * std::numbers::pi);
  if (!fs && dt > 0) dt -= 2 * std::numbers::pi;
  if (fs && dt < 0) dt += 2 * std::numbers::pi;
  return {cx, cy, rx, ry, phi, t1, dt};
}

// Page 200 x 100 user units, unitless: 1 unit = 25.4 / 96 mm, y up.
Vec3 page(double x, double y) { return {x * 25.4 / 96, (100 - y) * 25.4 / 96}; }
// Equal up to the rounding of the unit conversion.
void expect_at(const Vec3& got, const Vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12);
  EXPECT_NEAR(got.y, want.y, 1e-12);
}

TEST(SvgReader, EllipticalArcIsTheSpecsArcExactly) {
  // Rotated ellipse, large arc, sweep flag 0: the hardest case of F.6.5.
  const Drawing d = read_svg(svg(R"~(<path id="a" d="M 40 60 A 30 15 25 1 0 90 40"/>)~"), "a.svg");
  ASSERT_EQ(d.contours.size(), 1u);
  const CenterArc ref = to_center(40, 60, 30, 15, 25, true, false, 90, 40);
  const auto& ps = d.contours[0].pieces;
  EXPECT_EQ(ps.size(), static_cast<size_t>(std::ceil(std::abs(ref.dt) / (std::numbers::pi / 2) - 1e-12)));
  for (const Piece& p : ps) {
    ASSERT_EQ(p.points.size(), 3u);  // rational quadratics
    ASSERT_EQ(p.weights.size(), 3u);
  }
  // Points of the reference arc at equal angles, from the spec's centre
  // parameterisation, lie on the pieces to 1e-9 mm (nearest point found by
  // dense sampling, then golden-section refinement).
  for (int i = 0; i <= 40; ++i) {
    const double t = ref.t1 + ref.dt * i / 40.0;
    const Vec3 want = page(ref.at(t).x, ref.at(t).y);
    double best = 1e300;
    for (const Piece& p : ps) best = std::min(best, nearest(bez(p), want));
    EXPECT_LT(best, 1e-9) << i;
  }
  // Exact: every point of every piece satisfies the ellipse's equation.
  for (const Piece& p : ps) {
    const Bezier b = bez(p);
    for (int j = 0; j <= 50; ++j) {
      const Vec3 q = evaluate(b, j / 50.0);
      const double ux = q.x * 96 / 25.4 - ref.cx, uy = 100 - q.y * 96 / 25.4 - ref.cy;
      const double xr = std::cos(ref.phi) * ux + std::sin(ref.phi) * uy,
                   yr = -std::sin(ref.phi) * ux + std::cos(ref.phi) * uy;
      EXPECT_NEAR(xr * xr / (ref.rx * ref.rx) + yr * yr / (ref.ry * ref.ry), 1.0, 1e-12);
    }
  }
  expect_at(ps.front().points.front(), page(40, 60));
  expect_at(ps.back().points.back(), page(90, 40));
  // The arc passes through the reference midpoint (the sweep's direction).
  const Vec3 mid = page(ref.at(ref.t1 + ref.dt / 2).x, ref.at(ref.t1 + ref.dt / 2).y);
  double best = 1e9;
  for (const Piece& p : ps)
    for (int j = 0; j <= 2000; ++j) best = std::min(best, dist(evaluate(bez(p), j / 2000.0), mid));
  EXPECT_LT(best, 0.01);
}

TEST(SvgReader, RelativeCommandsShorthandsAndClose) {
  const Drawing d = read_svg(
      svg(R"~(<path id="logo" d="m 10 10 h 20 v 10 c 0 5 -5 10 -10 10 s -10 -5 -10 -10 z M 50 50 q 10 -10 20 0 t 20 0 L 50 50 Z"/>)~"),
      "r.svg");
  ASSERT_EQ(d.contours.size(), 2u);
  EXPECT_EQ(d.contours[0].id, "logo");
  EXPECT_EQ(d.contours[1].id, "logo.2");
  EXPECT_TRUE(d.contours[0].closed);
  const auto& a = d.contours[0].pieces;
  ASSERT_EQ(a.size(), 5u);  // h, v, c, s, and the closing line
  expect_at(a[2].points[1], page(30, 25));
  expect_at(a[2].points[3], page(20, 30));
  expect_at(a[3].points[1], page(15, 30));  // reflection of (25, 30) about (20, 30)
  expect_at(a[3].points[3], page(10, 20));
  expect_at(a[4].points.back(), page(10, 10));
  const auto& b = d.contours[1].pieces;
  ASSERT_EQ(b.size(), 3u);
  expect_at(b[1].points[1], page(80, 60));  // T reflects (60, 40) about (70, 50)
  expect_at(b[1].points[2], page(90, 50));
  // After a line, S has no control point to reflect: its first is the current point.
  const Drawing l = read_svg(
      svg(R"~(<path d="M 0 0 C 10 0 20 10 20 20 L 30 30 S 40 40 50 50 M 0 50 Q 5 40 10 50 H 20 T 30 50"/>)~"), "l.svg");
  expect_at(l.contours[0].pieces[2].points[1], page(30, 30));
  expect_at(l.contours[1].pieces[2].points[1], page(20, 50));
}

TEST(SvgReader, ShapesRoundedRectCircleEllipseLinePolyline) {
  const Drawing d = read_svg(svg(R"~(<rect id="r" x="10" y="10" width="40" height="20" rx="5"/>
      <circle id="c" cx="100" cy="50" r="20"/><ellipse id="e" cx="150" cy="50" rx="20" ry="10"/>
      <line id="l" x1="0" y1="0" x2="10" y2="5"/><polyline id="p" points="0,90 10,80 20,90"/>
      <polygon id="g" points="30 90 40 80 50 90"/>)~"),
                             "s.svg");
  ASSERT_EQ(d.contours.size(), 6u);
  // Circle: every point at radius 20 (user units) from the centre.
  for (const Piece& p : d.contours[1].pieces)
    for (int j = 0; j <= 20; ++j) EXPECT_NEAR(dist(evaluate(bez(p), j / 20.0), page(100, 50)), 20 * 25.4 / 96, 1e-12);
  EXPECT_TRUE(d.contours[1].closed);
  EXPECT_EQ(d.contours[1].pieces.size(), 4u);
  // Rounded rect: 4 lines and 4 quarter arcs of radius 5.
  EXPECT_EQ(d.contours[0].pieces.size(), 8u);
  EXPECT_TRUE(d.contours[0].closed);
  // Ellipse equation.
  for (const Piece& p : d.contours[2].pieces)
    for (int j = 0; j <= 20; ++j) {
      const Vec3 q = evaluate(bez(p), j / 20.0), c = page(150, 50);
      const double k = 25.4 / 96;
      EXPECT_NEAR(std::pow((q.x - c.x) / (20 * k), 2) + std::pow((q.y - c.y) / (10 * k), 2), 1.0, 1e-12);
    }
  EXPECT_FALSE(d.contours[3].closed);
  EXPECT_EQ(d.contours[4].pieces.size(), 2u);
  EXPECT_FALSE(d.contours[4].closed);
  EXPECT_EQ(d.contours[5].pieces.size(), 3u);
  EXPECT_TRUE(d.contours[5].closed);
}

TEST(SvgReader, NestedTransformsAndUnits) {
  // 100 mm wide page of 200 user units: 1 unit = 0.5 mm; page height 50 mm.
  const Drawing d = read_svg(svg(R"~(<g transform="translate(10,20)"><g transform="scale(2) rotate(90)">
      <line x1="0" y1="0" x2="5" y2="0"/></g></g>)~",
                                 R"~(width="100mm" height="50mm" viewBox="0 0 200 100")~"),
                             "t.svg");
  ASSERT_EQ(d.contours.size(), 1u);
  const auto& p = d.contours[0].pieces[0].points;
  // (5, 0) -> rotate 90 -> (0, 5) -> scale 2 -> (0, 10) -> translate -> (10, 30) user units.
  EXPECT_NEAR(p[0].x, 5, 1e-12);
  EXPECT_NEAR(p[0].y, 50 - 10, 1e-12);
  EXPECT_NEAR(p[1].x, 5, 1e-12);
  EXPECT_NEAR(p[1].y, 50 - 15, 1e-12);
  // Inches: 1in page, 96 units.
  const Drawing in = read_svg(
      svg(R"~(<line x1="0" y1="0" x2="96" y2="0"/>)~", R"~(width="1in" height="1in" viewBox="0 0 96 96")~"), "i.svg");
  EXPECT_NEAR(in.contours[0].pieces[0].points[1].x, 25.4, 1e-12);
  EXPECT_NEAR(in.contours[0].pieces[0].points[1].y, 25.4, 1e-12);
}

TEST(SvgReader, Refusals) {
  const auto id_of = [](const std::string& text) {
    try {
      read_svg(text, "bad.svg");
    } catch (const Error& e) {
      EXPECT_NE(e.where().find("bad.svg"), std::string::npos) << e.what();
      return e.id();
    }
    return std::string("none");
  };
  EXPECT_EQ(id_of("{ \"bezcam\": 1 }"), "import.not-a-drawing");
  EXPECT_EQ(id_of(svg("<path d=\"M 0 0 L 1 1\"/>").substr(0, 60)), "import.not-a-drawing");  // truncated
  EXPECT_EQ(id_of(svg("<text>hi</text>")), "import.empty");
  EXPECT_EQ(id_of(svg("<path id=\"n\" d=\"M 0 0 L nan 1\"/>")).substr(0, 7), "import.");
  EXPECT_EQ(id_of(svg("<line x2=\"1\" y2=\"1\"/>", R"~(width="10furlong" height="10mm")~")).substr(0, 7), "import.");
}

TEST(SvgReader, EveryOutputModeWithinTolerance) {
  const Drawing d = read_svg(svg(R"~(<path id="a" d="M 40 60 A 30 15 25 1 0 90 40 C 120 10 150 90 180 50"/>
      <circle cx="100" cy="50" r="20"/><rect x="5" y="5" width="30" height="20" rx="4" ry="8"/>)~"),
                             "m.svg");
  ImportOptions opt;
  opt.settings = {{"tolerance", "0.005"}};
  const Job job = to_job(d, opt);
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    ConvertOptions co;
    co.output = mode;
    const ConvertResult r = convert(job, load_machine_profile(mode == OutputMode::nurbs ? "fanuc" : "generic"), co);
    EXPECT_LE(r.program.max_measured, 0.005);
    EXPECT_GT(r.program.entities.size(), 2u);
  }
}

// `use` (SVG 1.1, 5.6): the referenced element drawn as a child of a group
// with the use's transform, then translate(x, y); through other uses, inside
// transformed groups, a used group's children with transforms of their own.
// Coordinates computed by hand.
TEST(SvgReader, UseNestedAndInsideTransformedGroups) {
  const Drawing d = read_svg(svg(R"~(<defs><line id="l" x1="0" y1="0" x2="10" y2="0" transform="rotate(90)"/></defs>
      <g id="grp" transform="translate(5 5)"><line id="m" x1="0" y1="0" x2="4" y2="4" transform="skewX(45)"/></g>
      <use id="a" xlink:href="#l" x="20" y="30"/>
      <use id="b" href="#a" transform="scale(-1 1)" x="-100"/>
      <g transform="translate(0 40) scale(1 -1) translate(0 -40)"><use id="c" href="#grp" x="50" transform="skewX(-20)"/></g>)~",
                                 R"~(xmlns:xlink="http://www.w3.org/1999/xlink" width="200" height="100")~"),
                             "use.svg");
  std::map<std::string, const Contour*> by_id;
  for (const Contour& c : d.contours) by_id[c.id] = &c;
  ASSERT_EQ(by_id.size(), 4u);  // m, a/l, b/a/l, c/m: nothing from defs by itself
  const auto line_is = [&](const std::string& id, Vec3 a, Vec3 b) {
    SCOPED_TRACE(id);
    ASSERT_TRUE(by_id.count(id));
    const auto& p = by_id[id]->pieces;
    ASSERT_EQ(p.size(), 1u);
    expect_at(p[0].points.front(), page(a.x, a.y));
    expect_at(p[0].points.back(), page(b.x, b.y));
  };
  line_is("m", {5, 5}, {13, 9});
  line_is("a/l", {20, 30}, {20, 40});
  line_is("b/a/l", {80, 30}, {80, 40});
  const double t = std::tan(20 * std::numbers::pi / 180);
  line_is("c/m", {55 - 5 * t, 75}, {63 - 9 * t, 71});
  EXPECT_EQ(d.layers.at("").read.at("line"), 4u);
  EXPECT_NE(by_id["b/a/l"]->element.find("through <use id=\"b\">"), std::string::npos) << by_id["b/a/l"]->element;

  // A use of a symbol draws nothing bezcam reads: counted as skipped.
  const Drawing s = read_svg(
      svg(R"~(<symbol id="s"><rect width="5" height="5"/></symbol><use href="#s"/><line x2="1" y2="1"/>)~"), "s.svg");
  EXPECT_EQ(s.contours.size(), 1u);
  EXPECT_EQ(s.layers.at("").skipped.at("use"), 1u);

  const auto refusal = [](const std::string& body) {
    try {
      read_svg(svg(body), "bad.svg");
    } catch (const InputError& e) {
      return e.id() + ": " + e.what();
    }
    return std::string("none");
  };
  EXPECT_EQ(refusal(R"~(<g id="g1"><line x2="1" y2="1"/><use id="loop" href="#g1"/></g>)~").substr(0, 53),
            "import.block-recursion: bad.svg: <use id=\"loop\"> on l");
  EXPECT_EQ(refusal(R"~(<use id="x" href="#y"/><use id="y" href="#x"/><line x2="1" y2="1"/>)~").substr(0, 22),
            "import.block-recursion");
  const std::string missing = refusal(R"~(<use id="u" href="#nope"/><line x2="1" y2="1"/>)~");
  EXPECT_EQ(missing.substr(0, 17), "import.svg-syntax") << missing;
  EXPECT_NE(missing.find("<use id=\"u\"> on line 1: href \"#nope\": no element has the id \"nope\""), std::string::npos)
      << missing;
}

// Transforms on the elements themselves (before or after their geometry in
// the tag), on every kind of element, of every kind (translate, rotate about
// a point, mirrors, skews, matrix() with a negative determinant, lists),
// elliptical arcs with every flag combination under each, inside
// transformed groups, through `use` (x, y, transform, nested uses), and
// the viewBox / preserveAspectRatio chain (meet, slice, none, a nested svg,
// no width and height): svgelements (python3-svgelements) reads the same
// files independently. Every point it evaluates on a shape (nine per
// segment) lies on bezcam's contour of that id within 1e-9 of the drawing's
// size, the contours start and end where its subpaths do, have their
// lengths, are closed alike, and neither reader has a subpath the other
// lacks.
TEST(SvgReader, ElementTransformsUseAndViewportsMatchSvgelements) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(BEZCAM_SOURCE_DIR) / "tests/import/data/svg"))
    if (e.path().extension() == ".svg") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 6u);
  const test::TempDir dir;
  {
    std::ofstream list(dir / "list.txt");
    for (const auto& f : files) list << f.string() << "\n";
  }
  const std::string cmd = "/usr/bin/python3 " + std::string(BEZCAM_SOURCE_DIR) +
                          "/tests/import/data/svgelements_points.py " + (dir / "list.txt").string() + " " +
                          dir.path().string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const double k = 25.4 / 96;  // mm per px
  size_t points = 0, subpaths = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    SCOPED_TRACE(files[i].filename().string());
    const Drawing d = read_drawing(files[i]);
    std::map<std::string, const Contour*> by_id;
    for (const Contour& c : d.contours) by_id[c.id] = &c;
    const double tol = 1e-9 * std::max(1.0, d.size());
    std::ifstream in(dir / (std::to_string(i) + ".ref"));
    std::string word;
    double page_h = 0;
    ASSERT_TRUE(in >> word >> page_h);
    ASSERT_EQ(word, "page");
    std::string line;
    std::getline(in, line);
    std::map<std::string, bool> seen;
    std::string id, closed;
    double length = 0;
    std::vector<Vec3> ref;
    const auto compare = [&] {
      if (id.empty()) return;
      SCOPED_TRACE(id);
      ++subpaths;
      seen[id] = true;
      const auto it = by_id.find(id);
      ASSERT_NE(it, by_id.end()) << "bezcam has no contour " << id;
      const Contour& c = *it->second;
      EXPECT_EQ(c.closed, closed == "closed");
      ASSERT_GE(ref.size(), 2u);
      EXPECT_LT(dist(c.pieces.front().points.front(), ref.front()), tol);
      EXPECT_LT(dist(c.pieces.back().points.back(), ref.back()), tol);
      double len = 0;
      for (const Piece& p : c.pieces) len += bezcam::length(bez(p));
      EXPECT_NEAR(len, length * k, 1e-7 * length * k);
      for (const Vec3& q : ref) {
        double best = 1e300;
        for (const Piece& p : c.pieces) best = std::min(best, nearest(bez(p), q));
        EXPECT_LT(best, tol) << "(" << q.x << ", " << q.y << ")";
        ++points;
      }
    };
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      if (line.rfind("subpath ", 0) == 0) {
        compare();
        ls >> word >> id >> closed >> length;
        ref.clear();
      } else {
        double x = 0, y = 0;
        ASSERT_TRUE(ls >> x >> y) << line;
        ref.push_back({x * k, (page_h - y) * k});
      }
    }
    compare();
    for (const Contour& c : d.contours) EXPECT_TRUE(seen.count(c.id)) << "svgelements has no subpath " << c.id;
  }
  EXPECT_GT(subpaths, 60u);
  EXPECT_GT(points, 1500u);
  RecordProperty("points", static_cast<int>(points));
}

// Drawings nobody here wrote, from Debian packages (linuxcnc-uspace, in
// .ci/packages): Inkscape files with namespaced metadata, CSS, text,
// markers, nested groups with transforms. Each is read and converted in
// every output mode within the tolerance, measured on the printed path.
TEST(SvgReader, DrawingsFromDebianPackagesConvertInEveryMode) {
  const char* files[] = {
      "/usr/share/doc/linuxcnc/examples/sample-configs/sim/qtvcp_screens/qtvcp_experimental/LatheMacro.svg",
      "/usr/share/icons/hicolor/scalable/apps/linuxcncicon.svg", "/usr/share/qtvcp/images/qtplasmac/keyboard.svg"};
  int read = 0;
  for (const char* f : files) {
    if (!std::filesystem::exists(f)) continue;
    SCOPED_TRACE(f);
    ++read;
    const Drawing d = read_drawing(f);
    EXPECT_GT(d.contours.size(), 10u);
    const Job job = to_job(d);
    for (const auto& [machine, mode] :
         {std::pair{"generic", OutputMode::lines}, std::pair{"generic", OutputMode::arcs},
          std::pair{"fanuc", OutputMode::nurbs}, std::pair{"linuxcnc", OutputMode::nurbs}}) {
      ConvertOptions co;
      co.output = mode;
      const ConvertResult r = convert(job, load_machine_profile(machine), co);
      EXPECT_LE(r.program.max_measured, job.tolerance);
      EXPECT_EQ(r.program.entities.size(), job.entities.size());
    }
  }
  if (read == 0) GTEST_SKIP() << "linuxcnc-uspace's drawings are not installed";
}

}  // namespace
}  // namespace bezcam::import
