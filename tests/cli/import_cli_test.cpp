// End to end through the executable: `bezcam import` writes the job a
// drawing is read as (the golden of tests/import), importing then
// converting is converting the drawing, `--set` reaches the program,
// `--layer` keeps layers, `check` lists what each layer held; `--set` takes
// dotted keys and JSON values and refuses a key the job does not have.
#include <fstream>
#include <gtest/gtest.h>

#include "in_process.hpp"
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
  // 6 contours, and the note "PART 1" in 8 glyph contours.
  EXPECT_EQ(r.err_first_line(), "bezcam: wrote " + job.string() + ": 14 entities from samples/part.dxf");
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
  EXPECT_NE(c.out.find("layer \"NOTES\": read 1 TEXT\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("layer \"OUTLINE\": read 4 ARC, 4 LINE\n"), std::string::npos) << c.out;
}

// The part from the drawing in one command line: the small holes on a
// second tool picked by id glob, tabs on the outline by layer; importing
// with the same options then converting cuts the same program.
TEST(ImportCommand, PerEntitySettingsFromTheCommandLine) {
  testproc::TempDir dir;
  const std::vector<std::string> options = {"--set",  "feed=600",
                                            "--set",  "plunge_feed=200",
                                            "--set",  "safe_z=5",
                                            "--set",  "cut_z=-1",
                                            "--set",  "side=outside",
                                            "--set",  "tool=1",
                                            "--set",  "tool_diameter=6",
                                            "--set",  "HOLES:3[7-9A]:tool=2",
                                            "--set",  "HOLES:3[7-9A]:tool_diameter=2",
                                            "--set",  R"(OUTLINE:tabs={"count":4,"width":5,"height":0.5})",
                                            "--skip", "NOTES"};
  const fs::path direct = dir / "direct.nc", job = dir / "part.json", imported = dir / "imported.nc";
  std::vector<std::string> args = {"convert", "samples/part.dxf", "--output", "arcs", "-q", "-o", direct.string()};
  args.insert(args.end(), options.begin(), options.end());
  auto r = bezcam(args);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string g = testproc::slurp(direct);
  // The small holes first (tool 2, inside the outline), then the slot and
  // the outline with tool 1: one tool change.
  EXPECT_NE(g.find("(T2: 2 mm flat end mill: HOLES:37, HOLES:3A, HOLES:39, HOLES:38)\n"
                   "(T1: 6 mm flat end mill: HOLES:3B, OUTLINE:2F+7)"),
            std::string::npos)
      << g;
  // The tabs lift the outline's cut from Z-1 to Z-0.5, and only its cut.
  const size_t outline = g.find("(entity OUTLINE:2F+7");
  ASSERT_NE(outline, std::string::npos);
  EXPECT_EQ(g.substr(0, outline).find("Z-0.5"), std::string::npos);
  EXPECT_NE(g.find("Z-0.5", outline), std::string::npos);
  args = {"import", "samples/part.dxf", "-q", "-o", job.string()};
  args.insert(args.end(), options.begin(), options.end());
  r = bezcam(args);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(bezcam({"convert", job.string(), "--output", "arcs", "-q", "-o", imported.string()}).status, 0);
  const auto body = [](std::string s) { return s.substr(s.find('\n', s.find('\n') + 1)); };
  EXPECT_EQ(body(testproc::slurp(imported)), body(g));
  // A selector that matches nothing names what the drawing has; --only
  // and --skip apply to drawings.
  r = bezcam({"convert", "samples/part.dxf", "--skip", "HOLE", "-o", direct.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err_first_line(),
            "bezcam: error: --skip: samples/part.dxf has no layer and no entity matching \"HOLE\"; its layers are "
            "\"HOLES\", \"NOTES\", \"OUTLINE\", its entities \"OUTLINE:2F+7\", \"HOLES:37\", \"HOLES:38\", "
            "\"HOLES:39\", \"HOLES:3A\", \"HOLES:3B\", \"NOTES:3C\"; its circles' diameters are 5");
  r = bezcam({"convert", "samples/curve-semicircle.json", "--only", "x", "-o", direct.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err_first_line().rfind("bezcam: error: --only: ", 0), 0u) << r.err;
  r = bezcam({"import", "samples/part.dxf", "--only", "OUTLINE", "--skip", "*:2F*"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("found none"), std::string::npos) << r.err;
}

// A 10 mm square whose last corner is 0.01 mm open: check says where,
// --join-tolerance closes it and says so, --scale multiplies the drawing.
TEST(ImportCommand, JoinToleranceAndScale) {
  testproc::TempDir dir;
  const fs::path dxf = dir / "gap.dxf", nc = dir / "gap.nc";
  {
    std::ofstream f(dxf);
    f << "0\nSECTION\n2\nENTITIES\n"
         "0\nLINE\n5\nA1\n8\nOUT\n10\n0\n20\n0\n11\n10\n21\n0\n"
         "0\nLINE\n5\nA2\n8\nOUT\n10\n10\n20\n0\n11\n10\n21\n10\n"
         "0\nLINE\n5\nA3\n8\nOUT\n10\n10\n20\n10\n11\n0\n21\n10\n"
         "0\nLINE\n5\nA4\n8\nOUT\n10\n0.01\n20\n10\n11\n0\n21\n0\n"
         "0\nENDSEC\n0\nEOF\n";
  }
  auto r = bezcam({"check", dxf.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  nearly closed: \"OUT:A1+3\", its ends 0.01 mm apart at (0.005, 10); --join-tolerance 0.01 "
                       "closes it\n"),
            std::string::npos)
      << r.out;
  r = bezcam({"check", dxf.string(), "--join-tolerance", "0.01"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("nearly closed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bounds (0, 0) to (10, 10), closed\n"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("bezcam: warning: contour \"OUT:A1+3\": a gap of 0.01 mm at (0.005, 10) closed by the join "
                       "tolerance (the ends moved to meet)"),
            std::string::npos)
      << r.err;
  r = bezcam({"convert", dxf.string(), "--scale", "2.5", "--join-tolerance", "0.03", "--set", "feed=100", "--set",
              "cut_z=-1", "-o", nc.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("a gap of 0.025 mm at (0.0125, 25)"), std::string::npos) << r.err;
  EXPECT_NE(testproc::slurp(nc).find("X25."), std::string::npos);
  r = bezcam({"check", dxf.string(), "--scale", "0"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err_first_line(), "bezcam: error: --scale: expected a number > 0, found 0");
}

const char* kSquare = R"(<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="60mm" viewBox="0 0 60 60">
  <rect id="part" x="10" y="10" width="40" height="40"/>
</svg>
)";

TEST(ImportCommand, SetTakesDottedKeysAndJsonValues) {
  // Tabs given key by key and a lead given as a JSON object reach the
  // program: the last passes rise to cut_z + 1.5 over the tabs.
  testproc::TempDir dir;
  const fs::path svg = dir / "square.svg", nc = dir / "square.nc", plain = dir / "plain.nc";
  testproc::write_file(svg, kSquare);
  const std::vector<std::string> part = {"--set", "side=outside", "--set", "tool_diameter=6", "--set", "cut_z=-6",
                                         "--set", "step_down=2",  "-q"};
  std::vector<std::string> args = {"convert", svg.string(),      "-o",    nc.string(),
                                   "--set",   "tabs.count=4",    "--set", "tabs.width=5",
                                   "--set",   "tabs.height=1.5", "--set", R"(lead={"radius":4,"length":2})"};
  args.insert(args.end(), part.begin(), part.end());
  const auto r = bezcam(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // nothing ignored, nothing to warn about
  std::vector<std::string> no_tabs = {"convert", svg.string(), "-o", plain.string()};
  no_tabs.insert(no_tabs.end(), part.begin(), part.end());
  ASSERT_EQ(bezcam(no_tabs).status, 0);
  EXPECT_NE(testproc::slurp(nc).find("Z-4.5"), std::string::npos);  // over a tab: -6 + 1.5
  EXPECT_EQ(testproc::slurp(plain).find("Z-4.5"), std::string::npos);
  // The job import writes holds them as the job file does.
  const auto j = bezcam({"import", svg.string(), "--set", "tabs.count=4", "--set", "tabs.width=5", "--set",
                         "tabs.height=1.5", "--set", R"(lead={"radius":4,"length":2})"});
  ASSERT_EQ(j.status, 0) << j.err;
  EXPECT_NE(j.out.find(R"("tabs": {"count":4,"width":5,"height":1.5})"), std::string::npos) << j.out;
  EXPECT_NE(j.out.find(R"("lead": {"radius":4,"length":2})"), std::string::npos) << j.out;
}

TEST(ImportCommand, SetRefusesAKeyTheJobDoesNotHave) {
  testproc::TempDir dir;
  const fs::path svg = dir / "square.svg", nc = dir / "square.nc";
  testproc::write_file(svg, kSquare);
  for (const auto& [set, first] : std::vector<std::pair<std::string, std::string>>{
           {"depth=-6", "bezcam: error: --set depth: unknown key \"depth\": did you mean \"cut_z\"?"},
           {"colour=red", "bezcam: error: --set colour: unknown key \"colour\" ("},
           {"tabs.cont=4",
            "bezcam: error: --set tabs.cont: unknown key \"tabs.cont\": did you mean \"tabs.count\"?"}}) {
    for (const char* command : {"convert", "check", "import"}) {
      std::vector<std::string> args = {command, svg.string(), "--set", set};
      if (std::string(command) != "check") args.insert(args.end(), {"-o", nc.string()});
      const auto r = bezcam::test::run_cli(args);  // a refusal: no process needed
      EXPECT_EQ(r.status, 2) << command << " " << set;
      EXPECT_EQ(r.err_first_line().rfind(first, 0), 0u) << command << ": " << r.err;
      EXPECT_NE(r.err.find("(error id: usage.setting)"), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(nc));
    }
  }
}

TEST(ToolHeader, EachToolWithItsDiameterAndShape) {
  // The operator loads the tools from the header: each number with the
  // diameter and shape the job cuts for, in the profile's dialect.
  const auto g = bezcam({"convert", "samples/part-flange.json", "-q"});
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_NE(g.out.find("\n(T2: 3 mm flat end mill: bolt-1, bolt-2, bolt-3, bolt-4)\n(T1: 6 mm flat end mill: bore, "
                       "outline)\n"),
            std::string::npos)
      << g.out.substr(0, 400);
  const auto f = bezcam({"convert", "samples/part-flange.json", "--machine", "fanuc", "-q"});
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_NE(f.out.find("\nN30 (T2: 3 mm flat end mill: bolt-1, "), std::string::npos) << f.out.substr(0, 400);
  const auto b = bezcam({"convert", "samples/patch-coons-curved.json", "-q"});
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_NE(b.out.find("\n(T2: 8 mm ball end mill: coons-panel)\n"), std::string::npos) << b.out.substr(0, 400);
  // An inch job in inches; a job that gives no diameter names none.
  testproc::TempDir dir;
  const fs::path job = dir / "inch.json";
  testproc::write_file(job, R"({"bezcam": 1, "units": "inch", "job": {"tool": 3, "cut_z": -0.1, "safe_z": 0.2},
      "entities": [{"id": "sq", "type": "path", "closed": true, "side": "outside", "tool_diameter": 0.25,
                    "segments": [{"type": "bezier", "points": [[0,0],[2,0]]}, {"type": "bezier", "points": [[2,0],[2,2]]},
                                 {"type": "bezier", "points": [[2,2],[0,2]]}, {"type": "bezier", "points": [[0,2],[0,0]]}]},
                   {"id": "line", "type": "bezier", "tool": 4, "points": [[3,0],[4,0]]}]})");
  const auto i = bezcam({"convert", job.string(), "-q"});
  ASSERT_EQ(i.status, 0) << i.err;
  EXPECT_NE(i.out.find("\n(T3: 0.25 in flat end mill: sq)\n(T4: line)\n"), std::string::npos) << i.out.substr(0, 400);
}

// A job file's entities take --set ID:KEY=VALUE: the serial number of a
// name plate replaced from the command line; the program engraves the new
// one and the file is not touched.
TEST(ImportCommand, AJobsTextIsReplacedFromTheCommandLine) {
  testproc::TempDir dir;
  const fs::path a = dir / "a.nc", b = dir / "b.nc";
  const std::string before = testproc::slurp(fs::path(BEZCAM_SOURCE_DIR) / "samples/part-nameplate.json");
  ASSERT_EQ(bezcam({"convert", "samples/part-nameplate.json", "-o", a.string(), "-q"}).status, 0);
  const auto r =
      bezcam({"convert", "samples/part-nameplate.json", "--set", "serial:text=No. 43", "-o", b.string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(testproc::slurp(a), testproc::slurp(b));
  EXPECT_EQ(testproc::slurp(fs::path(BEZCAM_SOURCE_DIR) / "samples/part-nameplate.json"), before);
  const auto c = bezcam({"check", "samples/part-nameplate.json", "--set", "serial:text=No. 43"});
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("\"serial/3\": text \"4\""), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("\"serial/4\": text \"3\""), std::string::npos) << c.out;
  // The selector must match an entity, and the job's own settings stay
  // the file's.
  const auto n = bezcam({"convert", "samples/part-nameplate.json", "--set", "serail:text=1", "-o", b.string()});
  EXPECT_EQ(n.status, 2);
  EXPECT_EQ(n.err_first_line().rfind("bezcam: error: --set serail:text: ", 0), 0u) << n.err;
  EXPECT_NE(n.err.find("\"serial\""), std::string::npos) << n.err;
}

}  // namespace
