// A drawing's circles drilled (docs/holes.md): `--set LAYER:operation=drill`
// and the drilling keys reach the program through `convert` and through
// `import`; a contour of that layer that is no circle is refused, exit 2,
// nothing written.
#include <fstream>
#include <gtest/gtest.h>
#include <regex>

#include "in_process.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

const std::vector<std::string> kDrill = {"--set", "feed=600",
                                         "--set", "plunge_feed=100",
                                         "--set", "cut_z=-2",
                                         "--set", "HOLES:operation=drill",
                                         "--set", "HOLES:tool_diameter=5",
                                         "--set", "HOLES:peck=0.5",
                                         "--set", "HOLES:chip_break=true"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(DrillDrawing, TheCirclesOfALayerAreDrilled) {
  testproc::TempDir dir;
  const fs::path nc = dir / "part.nc";
  const auto r = bezcam(with({"convert", "samples/part.dxf", "--machine", "linuxcnc", "--skip", "HOLES:3B", "--skip",
                              "NOTES", "-o", nc.string(), "-q"},
                             kDrill));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string g = testproc::slurp(nc);
  EXPECT_NE(g.find("G98 G73 X10. Y10. Z-2. R5. Q0.5 F100."), std::string::npos) << g;
  for (const char* next : {"\nX70. Y10.\n", "\nX70. Y40.\n", "\nX10. Y40.\n"})
    EXPECT_NE(g.find(next), std::string::npos) << next << g;
  // The job `import` writes holds the same keys and cuts the same program.
  const fs::path job = dir / "part.json", nc2 = dir / "imported.nc";
  ASSERT_EQ(
      bezcam(with({"import", "samples/part.dxf", "--skip", "HOLES:3B", "--skip", "NOTES", "-o", job.string()}, kDrill))
          .status,
      0);
  const std::string j = testproc::slurp(job);
  EXPECT_EQ(std::regex_search(j, std::regex(R"("operation": "drill", .*"peck": 0.5, "chip_break": true)")), true) << j;
  ASSERT_EQ(bezcam({"convert", job.string(), "--machine", "linuxcnc", "-o", nc2.string(), "-q"}).status, 0);
  const auto body = [](std::string s) { return s.substr(s.find('\n', s.find('\n') + 1)); };
  EXPECT_EQ(body(testproc::slurp(nc2)), body(g));
}

TEST(DrillDrawing, AContourThatIsNoCircleIsRefused) {
  testproc::TempDir dir;
  const fs::path nc = dir / "part.nc";
  const auto r = bezcam(with({"convert", "samples/part.dxf", "-o", nc.string()}, kDrill));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(
      r.err_first_line().rfind("bezcam: error: samples/part.dxf: entities[5].operation: \"drill\" makes a hole", 0), 0u)
      << r.err;
  EXPECT_FALSE(fs::exists(nc));
}

// `check` says where a point is.
TEST(DrillDrawing, CheckListsAPointsPlace) {
  const auto r = bezcam({"check", "samples/part-plate-drilled.json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("entities[3] \"hole-1\": point at (8, 8)\n"), std::string::npos) << r.out;
}

// An SVG's circles are holes too.
TEST(DrillDrawing, SvgCirclesAreDrilled) {
  testproc::TempDir dir;
  const fs::path svg = dir / "holes.svg", nc = dir / "holes.nc";
  std::ofstream(svg) << R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">)"
                        R"(<circle id="a" cx="20" cy="20" r="2.5"/><circle id="b" cx="50" cy="20" r="2.5"/></svg>)";
  const auto r =
      bezcam({"convert", svg.string(), "--set", "feed=500", "--set", "plunge_feed=100", "--set", "cut_z=-3", "--set",
              "operation=drill", "--set", "tool_diameter=5", "--machine", "linuxcnc", "-o", nc.string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string g = testproc::slurp(nc);
  EXPECT_NE(g.find("\nG98 G81 X20. Y80. Z-3. R5. F100.\n"), std::string::npos) << g;
  EXPECT_NE(g.find("\nX50. Y80.\nG80\n"), std::string::npos) << g;
}

// The setup sheet says how each hole is cut.
TEST(DrillDrawing, TheSetupSheetSaysHowEachHoleIsDrilled) {
  testproc::TempDir dir;
  const fs::path html = dir / "plate.html";
  const auto r = bezcam({"sheet", "samples/part-plate-drilled.json", "--machine", "fanuc", "-o", html.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string h = testproc::slurp(html);
  size_t n = 0;
  for (size_t at = h.find("drilled, pecks of 3 mm"); at != std::string::npos;
       at = h.find("drilled, pecks of 3 mm", at + 1))
    ++n;
  EXPECT_EQ(n, 4u) << h;
}

}  // namespace
