// A drawing as LibreCAD saves it (samples/plate-layer0.dxf: everything on
// layer 0) cut as a part from one command line, no JSON: the holes before
// the outline that holds them, the small holes with a second tool picked
// by their diameter, tabs on the outline only (picked by its side), the
// same program through `import`, and a program lint finds nothing in.
#include <gtest/gtest.h>

#include "in_process.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

const std::vector<std::string> kPart = {"--set", "side=outside",
                                        "--set", "tool=1",
                                        "--set", "tool_diameter=6",
                                        "--set", "cut_z=-6",
                                        "--set", "step_down=2",
                                        "--set", "feed=800",
                                        "--set", "plunge_feed=200",
                                        "--set", "circle<4:tool=2",
                                        "--set", "circle<4:tool_diameter=2",
                                        "--set", R"(<outside>:tabs={"count": 4, "width": 5, "height": 1.5})"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(PlateLayer0, IsCutFromOneCommandLine) {
  testproc::TempDir dir;
  const fs::path nc = dir / "plate.ngc";
  const auto r =
      bezcam(with({"convert", "samples/plate-layer0.dxf", "--machine", "linuxcnc", "-o", nc.string(), "-q"}, kPart));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string g = testproc::slurp(nc);
  // The dowel holes (3 mm) with T2, the rest with T1.
  EXPECT_NE(g.find("(T2: 2 mm flat end mill: 0:10E, 0:10F)"), std::string::npos) << g.substr(0, 600);
  EXPECT_NE(g.find("(T1: 6 mm flat end mill: "), std::string::npos);
  // Every hole is cut before the outline, and only the outline has tabs
  // (passes at -6 that rise to -4.5 over the tabs).
  const size_t outline = g.find("(entity 0:101+7");
  ASSERT_NE(outline, std::string::npos);
  for (const char* hole : {"0:109", "0:10A", "0:10B", "0:10C", "0:10D", "0:10E", "0:10F"}) {
    const size_t at = g.find(std::string("(entity ") + hole);
    ASSERT_NE(at, std::string::npos) << hole;
    EXPECT_LT(at, outline) << hole;
  }
  EXPECT_EQ(g.find("Z-4.5"), g.find("Z-4.5", outline));
  size_t tabs = 0;
  for (size_t at = g.find("Z-4.5", outline); at != std::string::npos; at = g.find("Z-4.5", at + 1)) ++tabs;
  EXPECT_EQ(tabs, 4u);
  // Through `import`: the same program.
  const fs::path job = dir / "plate.json", nc2 = dir / "imported.ngc";
  ASSERT_EQ(bezcam(with({"import", "samples/plate-layer0.dxf", "-o", job.string()}, kPart)).status, 0);
  ASSERT_EQ(bezcam({"convert", job.string(), "--machine", "linuxcnc", "-o", nc2.string(), "-q"}).status, 0);
  const auto body = [](std::string s) { return s.substr(s.find('\n', s.find('\n') + 1)); };
  EXPECT_EQ(body(testproc::slurp(nc2)), body(g));
  // What lint reads in it: nothing to say.
  const auto l = bezcam({"lint", nc.string()});
  EXPECT_EQ(l.status, 0) << l.out << l.err;
}

}  // namespace
