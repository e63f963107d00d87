// `bezcam check` (in-process) on the B-spline, interpolation and
// mixed-path samples: it reports what they hold; a bad bspline exits 2
// naming the JSON path; the Lagrange overshoot warning reaches stderr.
#include <filesystem>
#include <gtest/gtest.h>

#include "in_process.hpp"
#include "support/files.hpp"

namespace fs = std::filesystem;

namespace {

// stdout and stderr together in `out`.
testproc::Result check(const std::string& file) {
  testproc::Result r = bezcam::test::run_cli({"check", file});
  r.out += r.err;
  return r;
}

std::string sample(const char* name) { return std::string(BEZCAM_SOURCE_DIR "/samples/") + name; }

struct Expect {
  const char* file;
  std::vector<std::string> lines;  // substrings that must appear
};

}  // namespace

TEST(CheckNurbsCli, ReportsTheNurbsAndInterpolationSamples) {
  const std::vector<Expect> cases = {
      {"curve-nurbs-circle.json",
       {"\"circle-d80\": bspline, 2D, degree 2, rational, 4 Bézier pieces, length 251.327 mm, bounds (20, 10) to (100, "
        "90)"}},
      {"curve-bspline-wave.json", {"\"wave\": bspline, 2D, degree 3, 5 Bézier pieces"}},
      {"curve-bspline-unclamped.json", {"\"uniform-cubic\": bspline, 2D, degree 3, 4 Bézier pieces"}},
      {"curve-bspline-3d-ramp.json", {"\"ramp\": bspline, 3D, degree 3, rational, 4 Bézier pieces"}},
      {"curve-interpolate-airfoil.json", {"\"upper-surface\": interpolate, 2D, degree 3, 8 Bézier pieces"}},
      {"curve-interpolate-closed-cam.json", {"\"cam\": interpolate, 2D, degree 3, 8 Bézier pieces", ", closed"}},
      {"curve-interpolate-lagrange.json", {"\"arch\": interpolate, 2D, degree 4, 1 Bézier piece,"}},
      {"path-mixed-bezier-bspline.json",
       {"path, 2D, degree 3, 5 Bézier pieces", "segments[1]: bspline, degree 3", "joint segments[0] -> segments[1]: G1",
        "joint segments[1] -> segments[2]: C1"}},
      {"path-mixed-closed-keyhole.json",
       {"path, 2D, degree 2, rational, 6 Bézier pieces", ", closed", "segments[0]: bspline, degree 2, rational",
        "joint segments[3] -> segments[0] (closing): G1"}},
  };
  for (const auto& c : cases) {
    const auto r = check(sample(c.file));
    EXPECT_EQ(r.status, 0) << c.file << "\n" << r.out;
    for (const auto& l : c.lines)
      EXPECT_NE(r.out.find(l), std::string::npos) << c.file << ": no \"" << l << "\" in\n" << r.out;
    EXPECT_NE(r.out.find("ok: 1 entity valid"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  }
}

TEST(CheckNurbsCli, BadBsplineExitsTwoNamingThePath) {
  bezcam::test::TempDir dir;
  bezcam::test::write_file(dir / "bad.json", R"({"bezcam": 1, "entities": [
      {"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0],[3,1],[4,0],[5,1],[6,0],[7,1]],
       "knots": [0,0,0,0.1,0.2,0.3,0.5,0.25,1,1,1]}]})");
  auto r = check((dir / "bad.json").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("entities[0].knots[7]: expected a knot >= 0.5 (knots must not decrease), found 0.25"),
            std::string::npos)
      << r.out;
  bezcam::test::write_file(dir / "step.json",
                           R"({"bezcam": 1, "entities": [{"type": "interpolate", "method": "lagrange",
       "through": [[0,0],[10,0],[20,0],[30,0],[40,0],[50,20],[60,20],[70,20],[80,20],[90,20],[100,20]]}]})");
  r = check((dir / "step.json").string());
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("bezcam: warning: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the Lagrange polynomial through these 11 points leaves their bounding box by "),
            std::string::npos)
      << r.out;
}
