// A drawing's refusals and warnings: every independent error on its own
// line, located in the drawing; warnings by kind, silenced with --no-warn,
// refusals with --strict.
#include <filesystem>
#include <gtest/gtest.h>

#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(DrawingMessages, EveryIndependentErrorIsReportedWhereItIsInTheDrawing) {
  // A 12 mm tool fits none of the five holes of the part: five refusals,
  // each naming its layer, DXF entity type, handle and coordinates (the
  // note's letters left out).
  testproc::TempDir dir;
  const fs::path nc = dir / "part.nc";
  const auto r = bezcam({"convert", "samples/part.dxf", "--set", "side=outside", "--set", "tool_diameter=12", "--skip",
                         "NOTES", "-o", nc.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(nc));
  EXPECT_EQ(count(r.err, "bezcam: error: "), 5u) << r.err;
  EXPECT_NE(r.err.find("for entity HOLES:37: a tool of diameter 12 does not fit"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[layer \"HOLES\", CIRCLE (handle 37), from (12.5, 10)]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[layer \"HOLES\", LWPOLYLINE (handle 3B), from (30, 20)]"), std::string::npos) << r.err;
}

TEST(DrawingMessages, WarningsHaveAKindThatNoWarnSilencesAndStrictRefuses) {
  testproc::TempDir dir;
  const fs::path nc = dir / "logo.nc";
  const std::vector<std::string> base = {"convert", "samples/logo.svg", "--set", "side=left",
                                         "--set",   "tool_diameter=2",  "-o",    nc.string()};
  const auto plain = bezcam(base);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.err.find("bezcam: warning: z: the tool (offset 1) cannot reach "), std::string::npos) << plain.err;
  EXPECT_NE(plain.err.find(" [material-left]\n"), std::string::npos) << plain.err;

  auto quiet = base;
  quiet.insert(quiet.end(), {"--no-warn", "material-left"});
  const auto silenced = bezcam(quiet);
  ASSERT_EQ(silenced.status, 0) << silenced.err;
  EXPECT_EQ(silenced.err.find("warning"), std::string::npos) << silenced.err;

  fs::remove(nc);
  auto strict = base;
  strict.push_back("--strict");
  const auto refused = bezcam(strict);
  EXPECT_EQ(refused.status, 2);
  EXPECT_FALSE(fs::exists(nc));
  EXPECT_NE(refused.err.find("bezcam: error: --strict: warning taken as an error: z: the tool (offset 1) cannot reach"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("(error id: usage.strict)"), std::string::npos);

  // A silenced kind is no refusal under --strict either.
  quiet.push_back("--strict");
  EXPECT_EQ(bezcam(quiet).status, 0);

  const auto bad = bezcam({"check", "samples/logo.svg", "--no-warn", "material"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--no-warn: expected a warning kind (material-left, "), std::string::npos) << bad.err;
}

}  // namespace
