// End to end through the executable: `bezcam import` writes the job a
// drawing is read as (the golden of tests/import), importing then
// converting is converting the drawing, `--set` reaches the program,
// `--layer` keeps layers, `check` lists what each layer held.
#include <gtest/gtest.h>

#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

TEST(ImportCommand, WritesTheJobTheDrawingIsReadAs) {
  testproc::TempDir dir;
  const fs::path job = dir / "part.json";
  const auto r = bezcam({"import", "samples/part.dxf", "-o", job.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err_first_line(), "bezcam: wrote " + job.string() + ": 6 entities from samples/part.dxf");
  EXPECT_EQ(testproc::slurp(job), testproc::slurp(fs::path(BEZCAM_SOURCE_DIR) / "tests/golden/import/part.json"));
  // Converting the imported job and converting the drawing cut the same
  // moves (only the file name in the header differs).
  const fs::path a = dir / "a.nc", b = dir / "b.nc";
  ASSERT_EQ(bezcam({"convert", job.string(), "-o", a.string(), "--output", "arcs", "-q"}).status, 0);
  ASSERT_EQ(bezcam({"convert", "samples/part.dxf", "-o", b.string(), "--output", "arcs", "-q"}).status, 0);
  const auto body = [](std::string s) { return s.substr(s.find('\n', s.find('\n') + 1)); };
  EXPECT_EQ(body(testproc::slurp(a)), body(testproc::slurp(b)));
}

TEST(ImportCommand, SettingsAndLayersOfADrawing) {
  testproc::TempDir dir;
  const fs::path nc = dir / "holes.nc";
  const auto r = bezcam({"convert", "samples/part.dxf", "--layer", "HOLES", "--set", "feed=432", "--set", "cut_z=-1.5",
                         "-o", nc.string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string g = testproc::slurp(nc);
  EXPECT_NE(g.find("F432"), std::string::npos);
  EXPECT_NE(g.find("Z-1.5"), std::string::npos);
  EXPECT_EQ(g.find("OUTLINE"), std::string::npos);
  EXPECT_NE(g.find("HOLES:"), std::string::npos);
  // A job file states its own settings.
  const auto j = bezcam({"convert", "samples/curve-semicircle.json", "--set", "feed=432", "-o", nc.string()});
  EXPECT_EQ(j.status, 2);
  EXPECT_EQ(j.err_first_line().rfind("bezcam: error: --set: ", 0), 0u) << j.err;
  const auto c = bezcam({"check", "samples/part.dxf"});
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("layer \"HOLES\": read 4 CIRCLE, 1 LWPOLYLINE\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("layer \"NOTES\": read nothing; skipped 1 TEXT\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("layer \"OUTLINE\": read 4 ARC, 4 LINE\n"), std::string::npos) << c.out;
}

}  // namespace
