// A DXF with text through the program: convert and import-then-convert
// cut the same program; check lists the glyphs; a stroke font is refused
// with exit 2, naming where the text is, and nothing is written; a font
// given with --set replaces it; --units says what a unitless drawing's
// unit is.
#include <filesystem>
#include <gtest/gtest.h>

#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

const std::string kData = "tests/import/data/text/";

TEST(DxfTextCommand, ConvertingTheDrawingIsImportingThenConverting) {
  testproc::TempDir dir;
  const fs::path direct = dir / "direct.nc", job = dir / "text.json", imported = dir / "imported.nc";
  for (const char* mode : {"lines", "arcs", "nurbs"}) {
    SCOPED_TRACE(mode);
    const std::vector<std::string> common = {"--machine", "linuxcnc", "--output", mode, "-q"};
    std::vector<std::string> a = {"convert", kData + "text.dxf", "-o", direct.string()};
    a.insert(a.end(), common.begin(), common.end());
    ASSERT_EQ(bezcam(a).status, 0);
    ASSERT_EQ(bezcam({"import", kData + "text.dxf", "-q", "-o", job.string()}).status, 0);
    std::vector<std::string> b = {"convert", job.string(), "-o", imported.string()};
    b.insert(b.end(), common.begin(), common.end());
    ASSERT_EQ(bezcam(b).status, 0);
    const auto body = [](std::string s) { return s.substr(s.find('\n', s.find('\n') + 1)); };
    EXPECT_EQ(body(testproc::slurp(direct)), body(testproc::slurp(imported)));
  }
  const std::string j = testproc::slurp(job);
  EXPECT_NE(j.find("{ \"id\": \"NOTES:31\", \"type\": \"text\", \"text\": \"HELLO\", \"font\": \""), std::string::npos)
      << j;
}

TEST(DxfTextCommand, CheckListsTheGlyphs) {
  const auto r = bezcam({"check", kData + "text.dxf"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("DXF drawing, 1 contour after joining, 6 texts\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("layer \"NOTES\": read 5 TEXT\n"), std::string::npos) << r.out;
  // HELLO's H: left on the baseline at (10, 10), capitals 5 high.
  EXPECT_NE(r.out.find("\"NOTES:31/0\": text \"H\", 2D, degree 1, 12 Bézier pieces, length 26.4836 mm, bounds "
                       "(10.6731, 10) to (14.4843, 15), closed"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"MARKS:36/5\": text \"\u00B1\""), std::string::npos) << r.out;
}

TEST(DxfTextCommand, AStrokeFontIsRefusedAndNothingIsWritten) {
  testproc::TempDir dir;
  const fs::path nc = dir / "part.nc", job = dir / "part.json";
  for (const char* cmd : {"convert", "import"}) {
    const auto r = bezcam({cmd, kData + "text-shx.dxf", "-o", (std::string(cmd) == "import" ? job : nc).string()});
    EXPECT_EQ(r.status, 2) << cmd;
    EXPECT_EQ(r.err_first_line(),
              "bezcam: error: " + kData +
                  "text-shx.dxf: layer \"NOTES\", TEXT (handle 32) at (20, 25): its style \"ROMANS\" names the stroke "
                  "font \"romans.shx\" (SHX), which has no outlines to cut; set a TrueType or OpenType font for its "
                  "layer, for example set 'NOTES:font=DejaVu Sans' (for this text alone: set 'NOTES:32:font=DejaVu "
                  "Sans'), or skip NOTES:32");
    EXPECT_NE(r.err.find("(error id: import.text)"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(nc));
  EXPECT_FALSE(fs::exists(job));
  auto r = bezcam({"convert", kData + "text-shx.dxf", "--set", "NOTES:font=DejaVu Sans", "-o", nc.string(), "-q"});
  EXPECT_EQ(r.status, 0) << r.err;
  r = bezcam({"convert", kData + "text-shx.dxf", "--skip", "NOTES", "-o", nc.string(), "-q"});
  EXPECT_EQ(r.status, 0) << r.err;
  r = bezcam({"convert", kData + "text-lines.dxf", "-o", (dir / "lines.nc").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err_first_line().find("layer \"NOTES\", MTEXT (handle 31) at (10, 40): expected one line of text"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "lines.nc"));
}

TEST(DxfTextCommand, AMissingFontIsWarnedAboutByKind) {
  testproc::TempDir dir;
  const fs::path nc = dir / "t.nc";
  auto r = bezcam({"convert", kData + "text-missing-font.dxf", "-o", nc.string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("bezcam: warning: text \"NOTES:32\" (layer \"NOTES\", TEXT (handle 32) at (20, 25)): its style "
                       "\"GONE\" names the font \"no-such-font-bezcam.ttf\", which is not installed; it is cut in"),
            std::string::npos)
      << r.err;
  r = bezcam({"convert", kData + "text-missing-font.dxf", "--no-warn", "font-substituted", "-o", nc.string()});
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  r = bezcam({"convert", kData + "text-missing-font.dxf", "--strict", "-o", (dir / "strict.nc").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(dir / "strict.nc"));
}

TEST(DxfTextCommand, UnitsSayWhatAUnitlessDrawingsUnitIs) {
  // A 4 x 2 plate drawn in inches without $INSUNITS, a text 0.5 high.
  auto r = bezcam({"check", kData + "text-unitless.dxf", "--units", "inch"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("bounds (0, 0) to (101.6, 50.8), closed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"NOTES:31/0\": text \"H\", 2D, degree 1, 12 Bézier pieces, length 67.2683 mm, bounds "
                       "(27.1098, 25.4) to (36.79, 38.1)"),
            std::string::npos)
      << r.out;
  r = bezcam({"check", kData + "text-unitless.dxf"});
  EXPECT_NE(r.out.find("bounds (0, 0) to (4, 2), closed"), std::string::npos) << r.out;
  // A drawing that says its unit: the same is accepted, another refused.
  EXPECT_EQ(bezcam({"check", kData + "text.dxf", "--units", "mm"}).status, 0);
  r = bezcam({"convert", kData + "text.dxf", "--units", "inch", "-o", "/dev/null"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err_first_line(), "bezcam: error: --units: " + kData +
                                    "text.dxf says its unit is mm ($INSUNITS 4), not inch; leave the units out to "
                                    "read it in its own, or scale it");
  EXPECT_EQ(bezcam({"check", kData + "text-unitless.dxf", "--units", "furlong"}).status, 2);
  // A job file states its own units.
  r = bezcam({"check", "samples/curve-semicircle.json", "--units", "inch"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err_first_line().rfind("bezcam: error: --units: ", 0), 0u) << r.err;
}

}  // namespace
