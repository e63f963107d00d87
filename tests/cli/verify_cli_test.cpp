// `bezcam verify PROGRAM --machine M ...` as a user meets it (in-process):
// the machined result, gouges against a design (exit 5), the files it
// writes, and refusals (exit 2, the option named, nothing written).
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>

#include "in_process.hpp"
#include "support/files.hpp"

namespace fs = std::filesystem;
using bezcam::test::run_cli;
using bezcam::test::slurp;

namespace {

// A 20 x 20 mm square cut outside with a 4 mm flat end mill, and the
// program of its exact offset.
const char* kJob = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
  "job": {"feed": 500, "plunge_feed": 100, "safe_z": 5, "top_z": 0, "cut_z": -2, "spindle_rpm": 10000,
          "tool": 1, "tool_diameter": 4, "side": "outside"},
  "entities": [{"id": "square", "type": "path", "closed": true, "segments": [
    {"type": "bezier", "points": [[-10, -10], [10, -10]]}, {"type": "bezier", "points": [[10, -10], [10, 10]]},
    {"type": "bezier", "points": [[10, 10], [-10, 10]]}, {"type": "bezier", "points": [[-10, 10], [-10, -10]]}]}]})";
const std::string kProgram =
    "G21 G90 G17\nT1 M6\nG0 X-10 Y-12 Z5\nG1 Z-2 F100\nG1 X10 Y-12 F500\nG3 X12 Y-10 I0 J2\nG1 X12 Y10\n"
    "G3 X10 Y12 I-2 J0\nG1 X-10 Y12\nG3 X-12 Y10 I0 J-2\nG1 X-12 Y-10\nG3 X-10 Y-12 I2 J0\nG0 Z5\n";

struct Files {
  bezcam::test::TempDir dir;
  std::string job = write("square.json", kJob);
  std::string write(const std::string& name, const std::string& text) const {
    bezcam::test::write_file(dir / name, text);
    return (dir / name).string();
  }
  std::string at(const std::string& name) const { return (dir / name).string(); }
};

}  // namespace

TEST(VerifyCli, TheExactProgramPassesAndItsFilesAreWritten) {
  Files f;
  const std::string nc = f.write("square.nc", kProgram + "M30\n");
  const auto r = run_cli({"verify", nc, "--design", f.job, "--cell", "0.1", "--report", f.at("r.json"), "--image",
                          f.at("i.png"), "--heightmap", f.at("h.npy")});
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("square: largest gouge 0 mm, largest excess 0 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no gouge beyond the tolerance 0.01 mm"), std::string::npos) << r.out;
  const std::string report = slurp(f.at("r.json"));
  EXPECT_NE(report.find("\"removed_volume\""), std::string::npos);
  EXPECT_NE(report.find("\"gouged\": false"), std::string::npos) << report;
  EXPECT_EQ(slurp(f.at("i.png")).substr(1, 3), "PNG");
  EXPECT_EQ(slurp(f.at("h.npy")).substr(0, 6), "\x93NUMPY");
}

TEST(VerifyCli, AGougeBeyondTheToleranceExitsFive) {
  Files f;
  const std::string nc = f.write("gouge.nc", kProgram + "G0 X11.7 Y-5\nG1 Z-2 F100\nG1 Y5 F500\nG0 Z5\nM30\n");
  const auto r = run_cli({"verify", nc, "--design", f.job, "--cell", "0.1", "--report", f.at("r.json")});
  EXPECT_EQ(r.status, 5) << r.out << r.err;
  EXPECT_NE(r.out.find("GOUGED"), std::string::npos) << r.out;
  EXPECT_NE(slurp(f.at("r.json")).find("\"gouged\": true"), std::string::npos);
}

TEST(VerifyCli, HashPrintsTheHashAlone) {
  Files f;
  const std::string nc = f.write("square.nc", kProgram + "M30\n");
  const auto a = run_cli({"verify", nc, "--design", f.job, "--cell", "0.1", "--hash"});
  EXPECT_EQ(a.status, 0) << a.err;
  EXPECT_TRUE(std::regex_match(a.out, std::regex("[0-9a-f]{16}\n"))) << a.out;
  // One thread or two: the same part.
  const auto b = run_cli({"verify", nc, "--design", f.job, "--cell", "0.1", "--hash", "--threads", "1"});
  EXPECT_EQ(a.out, b.out);
  // A program that differs by 0.05 mm in one word machines another part.
  const std::string moved = std::regex_replace(kProgram, std::regex("G1 X12 Y10"), "G1 X12.05 Y10");
  const auto c =
      run_cli({"verify", f.write("moved.nc", moved + "M30\n"), "--design", f.job, "--cell", "0.1", "--hash"});
  EXPECT_NE(a.out, c.out);
}

TEST(VerifyCli, RefusalsNameTheOptionAndWriteNothing) {
  Files f;
  const std::string nc = f.write("square.nc", kProgram + "M30\n");
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"--stock", "1,2,3"}, "--stock: expected six numbers"},
      {{"--stock", "50,50,-5,80,80,0"}, "no cutting move of the program reaches the stock"},
      {{"--stock", "0,0,0,0,10,10"}, "--stock"},
      {{"--cell", "0.0005", "--memory-limit", "64MiB"}, "--cell"},
      {{"--memory-limit", "lots"}, "--memory-limit: expected a size"},
      {{"--image", f.at("i.jpg")}, "--image: expected a file name ending in .png or .svg"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"verify", nc, "--design", f.job, "--report", f.at("r.json")};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 2) << c.says << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(f.at("r.json"))) << c.says;
  }
  // An unreadable line, as lint says it; a tool the design lacks.
  const auto bad = run_cli({"verify", f.write("bad.nc", "G21 G90\nG1 X1 Y1 Q?\n"), "--design", f.job});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("line 2"), std::string::npos) << bad.err;
  const auto t2 =
      run_cli({"verify", f.write("t2.nc", "G21 G90\nT2 M6\nG0 X0 Y0 Z5\nG1 Z-1 F100\nM30\n"), "--design", f.job});
  EXPECT_EQ(t2.status, 2);
  EXPECT_NE(t2.err.find("line 4"), std::string::npos) << t2.err;  // its first cut
  EXPECT_NE(t2.err.find("T1 (flat D4)"), std::string::npos) << t2.err;
}

TEST(VerifyCli, AToolsFileCutsAnInchProgramInMillimetres) {
  Files f;
  const std::string tools = f.write("tools.json", R"({"4": {"shape": "ball", "diameter": 6.35}})");
  const std::string inch = "G20 G90 G17\nT4 M6\nG0 X0 Y0 Z0.2\nG1 Z-0.05 F4\nG1 X1 F20\nG0 Z0.2\nM30\n";
  const std::string mm = "G21 G90 G17\nT4 M6\nG0 X0 Y0 Z5.08\nG1 Z-1.27 F100\nG1 X25.4 F500\nG0 Z5.08\nM30\n";
  const std::vector<std::string> common{"--tools", tools, "--stock", "-5,-5,-3,30,5,0", "--cell", "0.05"};
  std::vector<std::string> a{"verify", f.write("in.nc", inch), "--report", f.at("r.json")};
  a.insert(a.end(), common.begin(), common.end());
  const auto ri = run_cli(a);
  EXPECT_EQ(ri.status, 0) << ri.err;
  std::vector<std::string> b{"verify", f.write("mm.nc", mm), "--hash"};
  b.insert(b.end(), common.begin(), common.end());
  const auto rm = run_cli(b);
  EXPECT_NE(ri.out.find("hash " + rm.out.substr(0, 16)), std::string::npos) << ri.out << rm.out;
  // The report is in millimetres: the ball's floor 1.27 mm deep.
  const std::string report = slurp(f.at("r.json"));
  EXPECT_NE(report.find("\"program_units\": \"inch\""), std::string::npos);
  // The ball 1.27 mm deep, its floor at the column nearest the path
  // 0.025 mm aside.
  const auto z_at = report.find("\"z\": ", report.find("deepest_floor"));
  ASSERT_NE(z_at, std::string::npos) << report;
  EXPECT_NEAR(std::stod(report.substr(z_at + 5)), -1.27 + 3.175 - std::sqrt(3.175 * 3.175 - 0.025 * 0.025), 1e-9);
  EXPECT_NE(report.find("\"shape\": \"ball\""), std::string::npos);
  // A bad tools file is refused at its JSON path.
  const auto bad =
      run_cli({"verify", f.at("in.nc"), "--tools", f.write("bad.json", R"({"4": {"shape": "bull", "diameter": 6}})")});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad.json: \"4\""), std::string::npos) << bad.err;
}

TEST(VerifyCli, APocketRegionIsComparedWhole) {
  // The plate: a recess cleared round two bosses (one region by the
  // even-odd rule), the outline on tabs.
  Files f;
  const std::string nc = f.at("plate.nc");
  const auto conv = run_cli({"convert", "samples/part-plate.json", "--machine", "linuxcnc", "-o", nc, "-q"});
  ASSERT_EQ(conv.status, 0) << conv.err;
  const auto r =
      run_cli({"verify", nc, "--machine", "linuxcnc", "--design", "samples/part-plate.json", "--cell", "0.1"});
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("boss-1: not compared: compared with its pocket region \"recess\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("recess: largest gouge 0 mm"), std::string::npos) << r.out;
  // The same program without the recess's passes leaves it standing: 4 mm.
  const std::string text = slurp(nc);
  const auto from = text.find("(pocket: 3 curves from recess)"), to = text.find("(entity outline", from);
  ASSERT_NE(from, std::string::npos);
  const std::string uncut = text.substr(0, from) + text.substr(to);
  const auto u = run_cli({"verify", f.write("uncut.nc", uncut), "--machine", "linuxcnc", "--design",
                          "samples/part-plate.json", "--cell", "0.1", "--report", f.at("r.json")});
  EXPECT_EQ(u.status, 0) << u.err;
  EXPECT_NE(u.out.find("recess: largest gouge 0 mm, largest excess 4 mm"), std::string::npos) << u.out;
}
