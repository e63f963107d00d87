// DXF in, exactly, against files nobody here wrote: ezdxf (python3-ezdxf)
// writes an R2010 drawing (rational SPLINE, partial ELLIPSE, bulged
// LWPOLYLINE, INSERTs rotated, mirrored and scaled unevenly) and evaluates
// points on each entity itself; the imported curves pass through them to
// 1e-9 mm, and convert in every output mode stays within the tolerance.
#include "bezcam/import/dxf_reader.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <map>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "support/files.hpp"

namespace bezcam::import {
namespace {

namespace fs = std::filesystem;

struct RefPoint {
  std::string layer;
  Vec3 p;
};

// The drawing and ezdxf's reference points, made once per test binary.
const std::pair<fs::path, std::vector<RefPoint>>& ezdxf_part() {
  static const test::TempDir dir;  // removed when the test program ends
  static const auto made = [] {
    const fs::path dxf = dir / "part.dxf", ref = dir / "part.ref";
    const std::string cmd = "/usr/bin/python3 " + std::string(BEZCAM_SOURCE_DIR) + "/tests/import/data/ezdxf_part.py " +
                            dxf.string() + " " + ref.string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::vector<RefPoint> pts;
    std::ifstream in(ref);
    RefPoint r;
    while (in >> r.layer >> r.p.x >> r.p.y) pts.push_back(r);
    return std::make_pair(dxf, pts);
  }();
  return made;
}

// Distance from q to a piece: dense samples, then golden-section refinement.
double distance(const Piece& pc, const Vec3& q) {
  std::function<Vec3(double)> f;
  double a = 0, b = 1;
  if (pc.bspline) {
    const NurbsCurve c = NurbsCurve::make(pc.degree, pc.points, pc.knots, pc.weights);
    a = c.domain_start(), b = c.domain_end();
    f = [c](double u) { return evaluate(c, u); };
  } else {
    const Bezier bz = Bezier::make(pc.points, pc.weights);
    f = [bz](double t) { return evaluate(bz, t); };
  }
  const int n = 400;
  int best = 0;
  double bd = 1e300;
  for (int i = 0; i <= n; ++i) {
    const double d = dist(f(a + (b - a) * i / n), q);
    if (d < bd) bd = d, best = i;
  }
  double lo = a + (b - a) * std::max(0, best - 1) / n, hi = a + (b - a) * std::min(n, best + 1) / n;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 200; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (dist(f(m1), q) < dist(f(m2), q))
      hi = m2;
    else
      lo = m1;
  }
  return std::min(bd, dist(f((lo + hi) / 2), q));
}

TEST(DxfReader, EzdxfEntitiesPassThroughEzdxfsOwnPoints) {
  const auto& [file, ref] = ezdxf_part();
  ASSERT_GT(ref.size(), 150u);
  const Drawing d = read_drawing(file);
  for (const char* layer : {"SPLINE", "FIT", "ELLIPSE", "POLY", "OCS", "POLY2D", "INS", "INS2"})
    EXPECT_TRUE(d.layers.count(layer)) << layer;
  for (const RefPoint& r : ref) {
    double best = 1e300;
    for (const Contour& c : d.contours)
      if (c.layer == r.layer)
        for (const Piece& p : c.pieces) best = std::min(best, distance(p, r.p));
    EXPECT_LT(best, 1e-9) << r.layer << " (" << r.p.x << ", " << r.p.y << ")";
  }
  // The bulged polyline is one closed contour; the spline stays a NURBS.
  for (const Contour& c : d.contours) {
    if (c.layer == "POLY") EXPECT_TRUE(c.closed);
    if (c.layer == "FIT") {  // fit points and end tangents: the CAD program's exact B-spline
      ASSERT_EQ(c.pieces.size(), 1u);
      EXPECT_TRUE(c.pieces[0].bspline);
      EXPECT_FALSE(c.is_interpolation);
    }
    if (c.layer == "SPLINE") {
      ASSERT_EQ(c.pieces.size(), 1u);
      EXPECT_TRUE(c.pieces[0].bspline);
      EXPECT_EQ(c.pieces[0].weights.size(), 5u);
    }
  }
}

TEST(DxfReader, EveryOutputModeWithinTolerance) {
  const Drawing d = read_drawing(ezdxf_part().first);
  ImportOptions opt;
  opt.settings = {{"tolerance", "0.005"}};
  const Job job = to_job(d, opt);
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    ConvertOptions co;
    co.output = mode;
    const ConvertResult r = convert(job, load_machine_profile(mode == OutputMode::nurbs ? "fanuc" : "generic"), co);
    EXPECT_LE(r.program.max_measured, 0.005);
  }
}

TEST(DxfReader, LinesAndArcsMeetingEndToEndAreOneClosedContour) {
  const std::string dxf =
      "0\nSECTION\n2\nENTITIES\n"
      "0\nLINE\n5\nA1\n8\nOUT\n10\n0\n20\n0\n11\n10\n21\n0\n"
      "0\nARC\n5\nA2\n8\nOUT\n10\n10\n20\n5\n40\n5\n50\n270\n51\n90\n"
      "0\nLINE\n5\nA3\n8\nOUT\n10\n0\n20\n10\n11\n10.0000000001\n21\n10\n"
      "0\nLINE\n5\nA4\n8\nOUT\n10\n0\n20\n10\n11\n0\n21\n0\n"
      "0\nHATCH\n5\nA5\n8\nOUT\n10\n0\n20\n0\n"
      "0\nENDSEC\n0\nEOF\n";
  Drawing d = read_dxf(dxf, "j.dxf");
  join_contours(d);
  ASSERT_EQ(d.contours.size(), 1u);
  EXPECT_TRUE(d.contours[0].closed);
  EXPECT_EQ(d.layers["OUT"].skipped["HATCH"], 1u);
  EXPECT_EQ(d.layers["OUT"].read["LINE"], 3u);
  const Job job = to_job(d);
  EXPECT_TRUE(job.entities.at(0).curve.closed);
}

TEST(DxfReader, Refusals) {
  const auto id_of = [](const std::string& text) {
    try {
      read_dxf(text, "bad.dxf");
    } catch (const Error& e) {
      EXPECT_NE(e.where().find("bad.dxf"), std::string::npos) << e.what();
      return e.id();
    }
    return std::string("none");
  };
  const std::string head = "0\nSECTION\n2\nENTITIES\n";
  const std::string tail = "0\nENDSEC\n0\nEOF\n";
  EXPECT_EQ(id_of("hello"), "import.not-a-drawing");
  EXPECT_EQ(id_of(std::string("AutoCAD Binary DXF\r\n\x1a") + std::string(10, '\0')), "import.dxf-binary");
  EXPECT_EQ(id_of(head + "0\nLINE\n10\n0\n20\n"), "import.dxf-syntax");  // truncated
  EXPECT_EQ(id_of(head + "0\nHATCH\n10\n0\n20\n0\n" + tail), "import.empty");
  EXPECT_EQ(id_of(head + "0\nLINE\n5\n1F\n10\nnan\n20\n0\n11\n1\n21\n1\n" + tail), "import.not-finite");
  EXPECT_EQ(id_of("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n99\n0\nENDSEC\n" + head +
                  "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n" + tail),
            "import.units");
  EXPECT_EQ(id_of("0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nB\n10\n0\n20\n0\n0\nINSERT\n5\n2A\n2\nB\n10\n0\n20\n0\n0\nENDBLK"
                  "\n0\nENDSEC\n" +
                  head + "0\nINSERT\n5\n2B\n2\nB\n10\n0\n20\n0\n" + tail),
            "import.block-recursion");
  EXPECT_EQ(
      id_of(head + "0\nSPLINE\n5\n3C\n71\n1\n72\n4\n73\n2\n40\n0\n40\n1\n40\n0.5\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n" +
            tail),
      "import.knots");
  // Hostile numbers: a degree far out of range, an ellipse swept 1e300
  // radians (no endless loop), an insert scaled by 0 (nothing to cut).
  EXPECT_EQ(id_of(head + "0\nSPLINE\n5\n3D\n71\n1e300\n10\n0\n20\n0\n" + tail), "import.dxf-syntax");
  EXPECT_EQ(id_of(head + "0\nELLIPSE\n10\n0\n20\n0\n11\n5\n21\n0\n40\n0.5\n41\n0\n42\n1e300\n210\n0\n220\n0\n230\n0\n" +
                  tail),
            "none");
  EXPECT_EQ(id_of("0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nB\n10\n0\n20\n0\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n0\nENDBLK"
                  "\n0\nENDSEC\n" +
                  head + "0\nINSERT\n5\n2B\n2\nB\n10\n0\n20\n0\n41\n0\n42\n0\n" + tail),
            "import.empty");
}

// LibreCAD's part library (librecad-data, in .ci/packages): DXF files
// written by dxflib and libdxfrw, read here and by ezdxf independently. Every
// point ezdxf evaluates on a curve entity (inserts, polylines with bulges,
// OCS included) lies on the imported geometry within 1e-9 of the drawing's
// size, and each file converts in every output mode within the tolerance.
TEST(DxfReader, LibreCadLibraryMatchesEzdxfsReading) {
  std::vector<fs::path> all;
  if (fs::exists("/usr/share/librecad/library"))
    for (const auto& e : fs::recursive_directory_iterator("/usr/share/librecad/library"))
      if (e.path().extension() == ".dxf") all.push_back(e.path());
  if (all.empty()) GTEST_SKIP() << "librecad-data is not installed";
  std::sort(all.begin(), all.end());
  std::vector<fs::path> files;
  for (size_t i = 0; i < all.size(); i += 40) files.push_back(all[i]);
  const test::TempDir dir;
  {
    std::ofstream list(dir / "list.txt");
    for (const auto& f : files) list << f.string() << "\n";
  }
  const std::string cmd = "/usr/bin/python3 " + std::string(BEZCAM_SOURCE_DIR) + "/tests/import/data/ezdxf_points.py " +
                          (dir / "list.txt").string() + " " + dir.path().string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  // mm per drawing unit, $INSUNITS (the DXF reference's table).
  const std::map<int, double> mm = {{0, 1}, {1, 25.4}, {2, 304.8}, {4, 1}, {5, 10}, {6, 1000}};
  size_t compared = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    SCOPED_TRACE(files[i].string());
    std::ifstream in(dir / (std::to_string(i) + ".ref"));
    std::string tag;
    int units = 0;
    in >> tag >> units;
    ASSERT_TRUE(mm.count(units)) << units;
    std::vector<Vec3> ref;
    for (Vec3 p; in >> p.x >> p.y;) ref.push_back(p * mm.at(units));
    // Compared before joining: joining moves ends that nearly meet (within
    // 1e-6 of the size) onto each other, as it should.
    Drawing d;
    try {
      std::ifstream f(files[i], std::ios::binary);
      std::ostringstream text;
      text << f.rdbuf();
      d = read_dxf(text.str(), files[i].string());
    } catch (const Error& e) {
      EXPECT_TRUE(ref.empty()) << e.what();  // refused: only when ezdxf found no curve either
      continue;
    }
    const double tol = 1e-9 * std::max(1.0, d.size());
    struct Cand {
      const Piece* p;
      Vec3 lo, hi;
    };
    std::vector<Cand> cands;
    for (const Contour& c : d.contours)
      for (const Piece& p : c.pieces) {
        Cand k{&p, p.points[0], p.points[0]};
        for (const Vec3& q : p.points)
          k.lo = {std::min(k.lo.x, q.x), std::min(k.lo.y, q.y)}, k.hi = {std::max(k.hi.x, q.x), std::max(k.hi.y, q.y)};
        cands.push_back(k);
      }
    // At most about 150 points a file, spread over it (time).
    const size_t step = std::max<size_t>(1, ref.size() / 150);
    for (size_t j = 0; j < ref.size(); j += step) {
      const Vec3& r = ref[j];
      double best = 1e300;
      for (const Cand& k : cands) {
        const double dx = std::max({k.lo.x - r.x, 0.0, r.x - k.hi.x}), dy = std::max({k.lo.y - r.y, 0.0, r.y - k.hi.y});
        if (std::hypot(dx, dy) > std::min(best, 1e-6 * std::max(1.0, d.size()))) continue;
        best = std::min(best, distance(*k.p, r));
        if (best <= tol) break;
      }
      EXPECT_LE(best, tol) << "(" << r.x << ", " << r.y << ")";
      ++compared;
    }
    join_contours(d);
    d.texts.clear();  // the curves are compared here; texts: dxf_text_test.cpp
    const Job job = to_job(d);
    for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
      ConvertOptions co;
      co.output = mode;
      const ConvertResult r =
          convert(job, load_machine_profile(mode == OutputMode::nurbs ? "linuxcnc" : "generic"), co);
      EXPECT_LE(r.program.max_measured, job.tolerance);
    }
  }
  EXPECT_GT(compared, 500u);
  RecordProperty("points", static_cast<int>(compared));
}

}  // namespace
}  // namespace bezcam::import
