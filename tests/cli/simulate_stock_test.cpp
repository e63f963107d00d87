// `bezcam simulate --stock BOX`: the real executable cuts the same part as
// `bezcam verify` from the same program, box, cell and tools; with --listen
// the stock is kept from program to program until the server stops; bad
// stock options are refused before anything runs or listens.
#include <gtest/gtest.h>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/verify/machined_program.hpp"
#include "in_process.hpp"
#include "support/files.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;

namespace {

const std::string kSource = BEZCAM_SOURCE_DIR;
const std::string kNotch = kSource + "/tests/golden/part-cam-notch.generic.nc";
const std::string kNotchBox = "-35,-50,-4,160,50,0";

std::string last_line(const std::string& text) {
  const auto end = text.find_last_not_of('\n');
  if (end == std::string::npos) return {};
  const auto nl = text.rfind('\n', end);
  const auto start = nl == std::string::npos ? 0 : nl + 1;
  return text.substr(start, end - start + 1);
}

// The programs cut one after the other into one stock, as verify cuts them.
std::string library_hash(const std::vector<std::string>& programs, const StockBox& box, double cell) {
  const MachineProfile generic = load_machine_profile("generic");
  StockCutter c(box, cell, {{1, ToolShape::flat(3)}});
  for (const std::string& p : programs) cut_timeline(c, read_timeline(p, &generic));
  return c.grid().hash_hex();
}

}  // namespace

TEST(SimulateStock, CutsThePartVerifyCuts) {
  test::TempDir dir;
  const auto trace = dir / "notch.trace";
  const auto sim = test::run_bezcam({"simulate", "--program", kNotch, "--stock", kNotchBox, "--cell", "0.1",
                                     "--tool-diameter", "1=8", "--trace", trace.string(), "-q"},
                                    dir);
  ASSERT_EQ(sim.status, 0) << sim.err;
  // The design's tool is the same 8 mm flat end mill.
  const auto ver = test::run_bezcam({"verify", kNotch, "--design", kSource + "/samples/part-cam-notch.json", "--stock",
                                     kNotchBox, "--cell", "0.1", "--hash"},
                                    dir);
  ASSERT_EQ(ver.status, 0) << ver.err;
  ASSERT_EQ(ver.out.size(), 17u) << ver.out;
  const std::string last = last_line(test::slurp(trace));
  EXPECT_EQ(last.rfind("stock hash " + ver.out.substr(0, 16) + " removed ", 0), 0u) << last;
  EXPECT_NE(last.find(" deepest -3.000000 at "), std::string::npos) << last;
}

TEST(SimulateStock, AToolTheTableLacksIsRefusedAtItsLine) {
  test::TempDir dir;
  const auto r = test::run_bezcam({"simulate", "--program", kNotch, "--stock", kNotchBox, "--cell", "0.5"}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("(error id: verify.tool)"), std::string::npos) << r.err;
  // Line 13 moves from where the tool is not yet known (it sweeps nothing);
  // line 15 is the first move the tool makes.
  EXPECT_NE(r.err.find("line 15: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tool T1"), std::string::npos) << r.err;
}

TEST(SimulateStock, BadStockOptionsAreRefusedBeforeAnythingRuns) {
  test::TempDir dir;
  struct Case {
    std::vector<std::string> opts;
    std::string option, id;
  };
  const std::vector<Case> cases = {
      {{"--stock", "0,0,-5,100,60"}, "--stock", "stock.box"},
      {{"--stock", "0,0,-5,100,sixty,0"}, "--stock", "stock.box"},
      {{"--stock", "0,0,-5,0,60,0"}, "--stock", "stock.box"},
      {{"--stock", "0,0,-5,100,60,0", "--cell", "0.001", "--memory-limit", "8MiB"}, "--cell", "stock.memory"},
      {{"--stock", "0,0,-5,100,60,0", "--memory-limit", "lots"}, "--memory-limit", "usage.option"},
  };
  const auto trace = dir / "refused.trace";
  for (const bool listen : {false, true}) {
    for (const Case& c : cases) {
      std::vector<std::string> args{"simulate"};
      if (listen)
        args.insert(args.end(), {"--listen", "127.0.0.1:0", "--time-scale", "max"});
      else
        args.insert(args.end(), {"--program", kNotch});
      args.insert(args.end(), c.opts.begin(), c.opts.end());
      args.insert(args.end(), {"--tool-diameter", "1=8", "--trace", trace.string()});
      SCOPED_TRACE(testing::PrintToString(args));
      const auto r = test::run_bezcam(args, dir);
      EXPECT_EQ(r.status, 2) << r.err;
      EXPECT_EQ(r.err.rfind("bezcam: error: " + c.option + ": ", 0), 0u) << r.err;
      EXPECT_NE(r.err.find("(error id: " + c.id + ")"), std::string::npos) << r.err;
      EXPECT_EQ(r.out, "");  // never listening
      EXPECT_FALSE(std::filesystem::exists(trace));
    }
  }
}

TEST(SimulateStock, ListenKeepsTheStockFromProgramToProgram) {
  test::TempDir dir;
  const auto trace = dir / "listen.trace";
  const StockBox box{0, 0, -5, 100, 60, 0};
  test::SimProcess sim(
      dir, {"--stock", "0,0,-5,100,60,0", "--cell", "0.25", "--tool-diameter", "1=3", "--trace", trace.string(), "-q"});
  const std::string first = test::zigzag_program(40);
  const std::string second =
      "G21 G90 G17\nT1 M06\nS10000 M03\nG00 Z5.\nX10. Y50.\nG01 Z-3. F300.\nG02 X30. Y50. I10. J0. F800.\nG00 "
      "Z5.\nM30\n";
  const link::Endpoint to{"127.0.0.1", sim.port()};
  ASSERT_EQ(link::stream_program(first, to).lines_executed, test::split_lines(first).size());
  const std::string after_first = last_line(test::slurp(trace));
  EXPECT_EQ(after_first.rfind("stock hash " + library_hash({first}, box, 0.25) + " ", 0), 0u) << after_first;
  link::stream_program(second, to);
  // The second program's trace (the file restarts with each program) ends
  // with the stock both programs cut.
  const std::string text = test::slurp(trace);
  EXPECT_EQ(text.find("X0. Y0."), std::string::npos);
  const std::string after_second = last_line(text);
  EXPECT_EQ(after_second.rfind("stock hash " + library_hash({first, second}, box, 0.25) + " ", 0), 0u) << after_second;
  EXPECT_NE(after_second.find(" deepest -3.000000 "), std::string::npos) << after_second;
  EXPECT_EQ(sim.stop(), 0) << sim.child().stderr_text();
}

TEST(SimulateStock, AToolsFileGivesTheShapeVerifyCutsWith) {
  bezcam::test::TempDir dir;
  const std::string tools = (dir / "tools.json").string();
  bezcam::test::write_file(tools, R"({"2": {"shape": "vee", "diameter": 6, "angle": 90}})");
  const std::string nc = (dir / "v.nc").string();
  bezcam::test::write_file(nc, "G21 G90\nT2 M6\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 F500\nG0 Z5\nM30\n");
  const std::string trace = (dir / "t.trace").string();
  const auto sim = bezcam::test::run_cli({"simulate", "--program", nc, "--stock", "-5,-5,-3,15,5,0", "--cell", "0.05",
                                          "--tools", tools, "--trace", trace});
  ASSERT_EQ(sim.status, 0) << sim.err;
  const auto ver =
      bezcam::test::run_cli({"verify", nc, "--stock", "-5,-5,-3,15,5,0", "--cell", "0.05", "--tools", tools, "--hash"});
  ASSERT_EQ(ver.status, 0) << ver.err;
  EXPECT_NE(bezcam::test::slurp(trace).find("stock hash " + ver.out.substr(0, 16)), std::string::npos)
      << bezcam::test::slurp(trace) << ver.out;
}
