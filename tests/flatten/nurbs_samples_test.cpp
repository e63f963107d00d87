// The B-spline, interpolation and mixed-path samples through the flattener:
// the certified bound and the independently measured deviation both stay
// within each job's tolerance, with and without rounding to the printed
// decimals; plus the geometric facts each sample is built on.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/kernel/spline_interp.hpp"
#include "support/sample_job.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> nurbs_samples() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(BEZCAM_SOURCE_DIR "/samples")) {
    const std::string n = e.path().filename().string();
    for (const char* prefix : {"curve-nurbs-", "curve-bspline-", "curve-interpolate-", "path-mixed-"})
      if (n.rfind(prefix, 0) == 0) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(NurbsSamples, FlattenedWithinToleranceWithAndWithoutRounding) {
  const auto files = nurbs_samples();
  ASSERT_GE(files.size(), 9u);
  for (const auto& f : files) {
    const Job job = test::load_sample(f);
    for (const auto& e : job.entities) {
      for (int decimals : {-1, 3, 4}) {
        SCOPED_TRACE(f.filename().string() + " " + e.label() + " decimals " + std::to_string(decimals));
        const FlattenResult r = flatten(e.curve.pieces, {job.tolerance, decimals});
        EXPECT_LE(r.bound, job.tolerance);
        ASSERT_GE(r.points.size(), 2u);
        const Deviation d = measure_deviation(e.curve.pieces, r.points, job.tolerance);
        EXPECT_LE(d.max(), job.tolerance)
            << "curve to path " << d.curve_to_path << ", path to curve " << d.path_to_curve;
        if (decimals < 0) {
          // Vertices lie on the curve; ends exact.
          EXPECT_EQ(r.points.front(), e.curve.pieces.front().front());
          EXPECT_EQ(r.points.back(), e.curve.pieces.back().back());
        }
      }
    }
  }
}

TEST(NurbsSamples, TheCircleIsACircle) {
  const Job job = load_job(BEZCAM_SOURCE_DIR "/samples/curve-nurbs-circle.json");
  const auto& g = job.entities[0].curve;
  const Vec3 c{60, 50};
  for (const auto& b : g.pieces)
    for (int i = 0; i <= 200; ++i) EXPECT_NEAR(dist(evaluate(b, i / 200.0), c), 40, 1e-12 * 100);
  // Unrounded vertices of the flattened circle are on it too, when asked
  // for on the curve.
  for (const auto& p : flatten(g.pieces, {.tolerance = job.tolerance, .decimals = -1, .on_curve = true}).points)
    EXPECT_NEAR(dist(p, c), 40, 1e-12 * 100);
  // The band (default) moves them out, towards the circle's convex side, by
  // at most the tolerance; the piece ends stay on it.
  for (const auto& p : flatten(g.pieces, {job.tolerance, -1}).points) {
    EXPECT_GE(dist(p, c), 40 - 1e-12 * 100);
    EXPECT_LE(dist(p, c), 40 + job.tolerance);
  }
  EXPECT_NEAR(g.length(), 80 * M_PI, 1e-8);
}

TEST(NurbsSamples, InterpolantsPassThroughTheirPoints) {
  for (const char* name : {"curve-interpolate-airfoil.json", "curve-interpolate-closed-cam.json"}) {
    const Job job = load_job(std::string(BEZCAM_SOURCE_DIR "/samples/") + name);
    const auto& g = job.entities[0].curve;
    ASSERT_TRUE(g.segments[0].nurbs) << name;
    // One piece per chord: piece k starts at through[k].
    const NurbsCurve& c = *g.segments[0].nurbs;
    std::vector<double> breaks;
    for (double u : c.knots)
      if (u >= c.domain_start() && u <= c.domain_end() && (breaks.empty() || breaks.back() != u)) breaks.push_back(u);
    ASSERT_EQ(breaks.size(), g.pieces.size() + 1) << name;
    for (size_t k = 0; k < g.pieces.size(); ++k)
      EXPECT_LE(dist(evaluate(c, breaks[k]), g.pieces[k].front()), 1e-10 * 200) << name << " piece " << k;
  }
  const Job cam = load_job(BEZCAM_SOURCE_DIR "/samples/curve-interpolate-closed-cam.json");
  EXPECT_TRUE(cam.entities[0].curve.closed);
  EXPECT_LE(dist(cam.entities[0].curve.pieces.back().back(), Vec3{40, 0}), 1e-12 * 100);
  EXPECT_LE(dist(cam.entities[0].curve.pieces[3].front(), Vec3{-30, 30}), 1e-12 * 100);
  const Job arch = load_job(BEZCAM_SOURCE_DIR "/samples/curve-interpolate-lagrange.json");
  EXPECT_TRUE(arch.warnings.empty());  // five points of a gentle arch: no overshoot
  const auto& a = arch.entities[0].curve.pieces[0];
  EXPECT_EQ(a.degree(), 4);
  EXPECT_NEAR(bounds(a).hi.y, 36, 1e-9);  // the arch's top is its middle point
}
