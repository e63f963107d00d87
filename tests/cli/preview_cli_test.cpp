// End to end through the executable: `preview` writes a well-formed SVG
// atomically (also for a G-code file, against a job), draws a program that
// convert would refuse with the refusal in red; `convert --report` writes
// the JSON report beside an unchanged program and a short summary on
// stderr; progress appears as plain lines or as a bar when asked for; an
// output file named for another format than SVG is refused.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/mini_xml.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;
using testproc::run;

const std::map<std::string, std::string> kQuietProgress{{"BEZCAM_PROGRESS", "off"}};

testproc::Result bezcam(const std::vector<std::string>& args,
                        const std::map<std::string, std::string>& env = kQuietProgress) {
  return run(BEZCAM_EXE, args, env, BEZCAM_SOURCE_DIR);
}

TEST(PreviewCommand, WritesAWellFormedSvgReplacingTheOldFileWhole) {
  testproc::TempDir dir;
  const fs::path svg = dir / "teardrop.svg";
  testproc::write_file(svg, "old contents");
  const auto r = bezcam({"preview", "samples/path-closed-teardrop.json", "-o", svg.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string said = r.err_first_line();
  EXPECT_EQ(said.rfind("bezcam: wrote " + svg.string() + ": 1 entity, ", 0), 0u) << said;
  EXPECT_TRUE(said.ends_with(" cutting blocks for machine generic")) << said;
  const auto root = testxml::parse(testproc::slurp(svg));
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.by_class("entity").size(), 1u);
  EXPECT_FALSE(root.by_class("control-point").empty());
  EXPECT_EQ(dir.files(), std::vector<std::string>{"teardrop.svg"});  // no temporary left behind

  const auto nc = bezcam({"preview", "samples/path-closed-teardrop.json", "-o", svg.string(), "--no-control", "-q"});
  ASSERT_EQ(nc.status, 0);
  EXPECT_EQ(nc.err, "");
  EXPECT_TRUE(testxml::parse(testproc::slurp(svg)).by_class("control-point").empty());
}

TEST(PreviewCommand, ThreeDimensionalJobsGetAnIsometricView) {
  testproc::TempDir dir;
  const auto r = bezcam({"preview", "samples/curve-cube-3d.json", "-o", (dir / "c.svg").string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto root = testxml::parse(testproc::slurp(dir / "c.svg"));
  EXPECT_NE(root.by_id("iso-view"), nullptr);
  EXPECT_NE(root.by_id("top-view"), nullptr);
}

TEST(PreviewCommand, DrawsAGcodeProgramAgainstItsJobWithDeviations) {
  testproc::TempDir dir;
  const fs::path nc = dir / "t.nc", svg = dir / "t.svg";
  ASSERT_EQ(bezcam({"convert", "samples/job-exercises-all.json", "-o", nc.string(), "-q"}).status, 0);
  const auto r = bezcam(
      {"preview", "samples/job-exercises-all.json", "--program", nc.string(), "-o", svg.string(), "--deviation"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto root = testxml::parse(testproc::slurp(svg));
  EXPECT_EQ(root.by_class("entity").size(), 9u);
  size_t coloured = 0;
  for (const auto* f : root.by_class("feed"))
    if (f->has("data-deviation")) {
      ++coloured;
      EXPECT_LE(std::stod(f->attr("data-deviation")), 0.01);
    }
  // Every cutting block of the program (the job's 87 or so) is measured.
  EXPECT_GT(coloured, 60u);
  EXPECT_NE(root.by_class("title").at(0)->text.find("against samples/job-exercises-all.json"), std::string::npos);
  // Alone, without the job, the program is drawn and deviation is refused.
  EXPECT_EQ(bezcam({"preview", "--program", nc.string(), "-o", svg.string(), "-q"}).status, 0);
  const auto dev = bezcam({"preview", "--program", nc.string(), "-o", svg.string(), "--deviation"});
  EXPECT_EQ(dev.status, 2);
  EXPECT_EQ(dev.err_first_line().rfind("bezcam: error: --deviation: ", 0), 0u) << dev.err;
}

TEST(PreviewCommand, DrawsWhatConvertWouldRefuseWithTheRefusal) {
  testproc::TempDir dir;
  const auto r = bezcam({"preview", "tests/bad/travel-exceeded.json", "-o", (dir / "t.svg").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err_first_line().rfind("bezcam: warning: convert would refuse this program: ", 0), 0u) << r.err;
  const auto root = testxml::parse(testproc::slurp(dir / "t.svg"));
  ASSERT_FALSE(root.by_class("warning").empty());
  EXPECT_NE(root.by_class("warning")[0]->text.find("convert would refuse"), std::string::npos);
}

TEST(ConvertReport, WritesTheReportBesideAnUnchangedProgram) {
  testproc::TempDir dir;
  const fs::path nc = dir / "a.nc", rep = dir / "a.json";
  const auto plain = bezcam({"convert", "samples/job-exercises-all.json", "-q"});
  ASSERT_EQ(plain.status, 0);
  const auto r = bezcam({"convert", "samples/job-exercises-all.json", "-o", nc.string(), "--report", rep.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(testproc::slurp(nc), plain.out);  // the report changes nothing in the program
  const auto j = nlohmann::json::parse(testproc::slurp(rep));
  EXPECT_EQ(j["bezcam_report"], 1);
  ASSERT_EQ(j["entities"].size(), 9u);
  EXPECT_EQ(j["entities"][0]["label"], "seed-ex-1");
  EXPECT_EQ(j["entities"][0]["kind"], "bezier");
  EXPECT_EQ(j["entities"][0]["degree"], 2);
  EXPECT_EQ(j["program"]["gcode_bytes"], plain.out.size());
  EXPECT_GT(j["program"]["estimated_time_s"].get<double>(), 0);
  // The human summary: a headline, one line per entity, the program, the files.
  EXPECT_EQ(r.err_first_line().rfind("bezcam: order shortest: 0 nested contours cut before what encloses them; ", 0),
            0u)
      << r.err;
  EXPECT_NE(r.err.find("\nbezcam: 9 entities, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\n  seed-ex-9: bezier, degree 4, length "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\n  program: "), std::string::npos);
  EXPECT_NE(r.err.find("bezcam: wrote " + nc.string() + " and " + rep.string() + "\n"), std::string::npos);
  // --quiet: nothing on stderr, the report still written.
  fs::remove(rep);
  const auto q =
      bezcam({"convert", "samples/job-exercises-all.json", "-o", nc.string(), "--report", rep.string(), "-q"});
  EXPECT_EQ(q.status, 0);
  EXPECT_EQ(q.err, "");
  EXPECT_TRUE(fs::exists(rep));
}

TEST(Progress, ConvertReportsEntitiesAsPlainLinesOrABar) {
  testproc::TempDir dir;
  const std::string nc = (dir / "p.nc").string();
  const auto lines = bezcam({"convert", "samples/job-exercises-all.json", "-o", nc},
                            {{"BEZCAM_PROGRESS", "lines"}, {"BEZCAM_PROGRESS_DELAY", "0"}});
  ASSERT_EQ(lines.status, 0) << lines.err;
  EXPECT_EQ(lines.err_first_line(), "bezcam: convert: 0/9 entities (0%), now seed-ex-1");
  EXPECT_NE(lines.err.find("\nbezcam: convert: done, 9/9 entities in "), std::string::npos) << lines.err;
  EXPECT_EQ(lines.err.find('\r'), std::string::npos);

  const auto bar = bezcam({"convert", "samples/job-exercises-all.json", "-o", nc},
                          {{"BEZCAM_PROGRESS", "bar"}, {"BEZCAM_PROGRESS_DELAY", "0"}, {"COLUMNS", "100"}});
  ASSERT_EQ(bar.status, 0);
  EXPECT_EQ(bar.err.rfind("\rconvert [", 0), 0u) << bar.err;
  EXPECT_NE(bar.err.find("9/9 entities  100%"), std::string::npos) << bar.err;
  // The bar line is ended before the summary starts.
  EXPECT_NE(bar.err.find("\nbezcam: 9 entities, "), std::string::npos);

  // Quiet and the default one-second delay: no progress at all.
  const auto quiet = bezcam({"convert", "samples/job-exercises-all.json", "-o", nc, "-q"},
                            {{"BEZCAM_PROGRESS", "lines"}, {"BEZCAM_PROGRESS_DELAY", "0"}});
  EXPECT_EQ(quiet.err, "");
}

TEST(Progress, PreviewMeasuringIsASecondPhase) {
  testproc::TempDir dir;
  const auto r = bezcam({"preview", "samples/job-exercises-all.json", "-o", (dir / "p.svg").string(), "--deviation"},
                        {{"BEZCAM_PROGRESS", "lines"}, {"BEZCAM_PROGRESS_DELAY", "0"}});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("bezcam: preview: done, 9/9 entities in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bezcam: preview: measuring deviation: done, 9/9 entities in "), std::string::npos) << r.err;
}

}  // namespace

namespace {

TEST(PreviewCommand, OriginTicksAndEachEntitysToolAndDepth) {
  testproc::TempDir dir;
  const fs::path svg = dir / "two.svg";
  const auto r = bezcam({"preview", "samples/job-two-tools.json", "-o", svg.string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto root = testxml::parse(testproc::slurp(svg));
  const auto* top = root.by_id("top-view");
  ASSERT_NE(top, nullptr);
  // The origin sits on the outline's start: marked, with its X and Y.
  ASSERT_EQ(top->by_class("origin").size(), 1u);
  // Ticks along both axes, 0 among them.
  const auto ticks = top->by_class("axis-ticks");
  ASSERT_EQ(ticks.size(), 1u);
  std::vector<std::string> labels;
  for (const auto* t : ticks[0]->by_name("text")) labels.push_back(t->text);
  EXPECT_GE(labels.size(), 6u);
  EXPECT_NE(std::find(labels.begin(), labels.end(), "0"), labels.end());
  // Per entity its tool and depth.
  std::vector<std::string> cuts;
  for (const auto* t : top->by_class("entity-cut")) cuts.push_back(t->text);
  EXPECT_EQ(cuts, (std::vector<std::string>{"T1 Z-1", "T2 Z-0.2"}));
}

TEST(PreviewCommand, AProgramFarFromItsJobIsSaid) {
  testproc::TempDir dir;
  const fs::path nc = dir / "moved.nc", svg = dir / "moved.svg";
  ASSERT_EQ(bezcam({"convert", "samples/job-two-tools.json", "-o", nc.string(), "--offset", "300,0", "-q"}).status, 0);
  const auto far = bezcam({"preview", "--program", nc.string(), "samples/job-two-tools.json", "-o", svg.string()});
  ASSERT_EQ(far.status, 0) << far.err;
  EXPECT_NE(far.err.find("warning: the program's cutting moves lie "), std::string::npos) << far.err;
  EXPECT_NE(testproc::slurp(svg).find("warning: the program&apos;s cutting moves lie"), std::string::npos);
  // The same program unmoved: no such warning.
  ASSERT_EQ(bezcam({"convert", "samples/job-two-tools.json", "-o", nc.string(), "-q"}).status, 0);
  const auto near = bezcam({"preview", "--program", nc.string(), "samples/job-two-tools.json", "-o", svg.string()});
  ASSERT_EQ(near.status, 0) << near.err;
  EXPECT_EQ(near.err.find("cutting moves lie"), std::string::npos) << near.err;
}

TEST(PreviewCommand, RefusesAnOutputFileNamedForAnotherFormat) {
  testproc::TempDir dir;
  // preview writes SVG, sheet HTML: a .png or .pdf name is refused before
  // anything is written, naming the option and the extensions written.
  const fs::path png = dir / "flange.png";
  testproc::write_file(png, "old picture");
  const auto p = bezcam({"preview", "samples/part-flange.json", "-o", png.string()});
  EXPECT_EQ(p.status, 2);
  EXPECT_EQ(p.err_first_line().rfind("bezcam: error: -o: preview writes SVG only", 0), 0u) << p.err;
  EXPECT_NE(p.err_first_line().find("ending in .svg"), std::string::npos) << p.err;
  EXPECT_EQ(testproc::slurp(png), "old picture");
  const auto g =
      bezcam({"preview", "--program", "tests/golden/curve-bspline-wave.generic.nc", "-o", (dir / "g.PNG").string()});
  EXPECT_EQ(g.status, 2) << g.err;
  const auto s = bezcam({"sheet", "samples/part-flange.json", "-o", (dir / "sheet.pdf").string()});
  EXPECT_EQ(s.status, 2);
  EXPECT_EQ(s.err_first_line().rfind("bezcam: error: -o: sheet writes one HTML page", 0), 0u) << s.err;
  EXPECT_NE(s.err_first_line().find("ending in .html or .htm"), std::string::npos) << s.err;
  EXPECT_EQ(dir.files(), std::vector<std::string>{"flange.png"});
  // The format's own extension, in any case, or none, is written.
  for (const char* name : {"a.svg", "b.SVG", "c"})
    EXPECT_EQ(bezcam({"preview", "samples/part-flange.json", "-o", (dir / name).string(), "-q"}).status, 0) << name;
  EXPECT_EQ(bezcam({"sheet", "samples/part-flange.json", "-o", (dir / "s.HTML").string(), "-q"}).status, 0);
}

}  // namespace
