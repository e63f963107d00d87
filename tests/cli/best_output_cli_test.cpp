// `--output best` on the command line: convert's summary says what each
// entity got and the cycle against each mode's, the program's header says
// best, `--compare-outputs` marks the shortest row and shows each entity's
// time per mode, and the figures agree with the same job converted in each
// mode; check, sheet and preview take it.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <unistd.h>

#include "cli/in_process.hpp"

namespace {

namespace fs = std::filesystem;
using bezcam::test::run_cli;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("bezcam-best-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

class BestOutputCli : public testing::TestWithParam<std::string> {};

TEST_P(BestOutputCli, NoModeIsShorterAndTheSummarySaysWhatEachEntityGot) {
  const std::string machine = GetParam();
  Scratch s;
  const std::string nc = (s.dir / "best.nc").string(), json = (s.dir / "best.json").string();
  const auto r = run_cli({"convert", "samples/part-flange.json", "--machine", machine, "--output", "best",
                          "--compare-outputs", "-o", nc, "--report", json});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(read(json));
  EXPECT_EQ(j["output"], "best");
  // Each mode converted on its own, as `convert --output MODE` does.
  double best = -1;
  std::map<std::string, double> modes;
  for (const auto& a : j["compare_outputs"]) {
    const double cycle = a["planned"]["cycle_time_s"].get<double>();
    if (a["output"] == "best")
      best = cycle;
    else
      modes[a["output"].get<std::string>()] = cycle;
  }
  ASSERT_GE(best, 0) << r.err;
  EXPECT_EQ(best, j["program"]["planned"]["cycle_time_s"].get<double>());
  ASSERT_GE(modes.size(), 2u);
  EXPECT_EQ(modes.count("nurbs"), machine == "grbl" ? 0u : 1u);
  for (const auto& [mode, cycle] : modes) {
    EXPECT_LE(best, cycle) << mode;
    const auto again = run_cli({"convert", "samples/part-flange.json", "--machine", machine, "--output", mode, "-o",
                                (s.dir / (mode + ".nc")).string(), "--report", (s.dir / (mode + ".json")).string()});
    ASSERT_EQ(again.status, 0) << again.err;
    const auto one = nlohmann::json::parse(read(s.dir / (mode + ".json")));
    EXPECT_EQ(one["program"]["planned"]["cycle_time_s"].get<double>(), cycle) << mode;
  }
  // The weighing's figures are the same programs'.
  for (const auto& m : j["output_choice"]["modes"])
    EXPECT_NEAR(m["cycle_time_s"].get<double>(), modes.at(m["output"].get<std::string>()), 1e-6);
  // Per entity: the program's mode is the one weighed shortest.
  std::map<std::string, int> got;
  for (const auto& e : j["output_choice"]["entities"]) {
    EXPECT_EQ(e["output"], e["shortest"]);
    double shortest = 1e300;
    for (const auto& [mode, t] : e["time_s"].items()) shortest = std::min(shortest, t.get<double>());
    EXPECT_LE(e["time_s"][e["output"].get<std::string>()].get<double>(),
              shortest + j["output_choice"]["tie_s"].get<double>());
    ++got[e["output"].get<std::string>()];
  }
  for (const auto& e : j["entities"])
    for (const auto& c : j["output_choice"]["entities"])
      if (c["index"] == e["index"]) EXPECT_EQ(e["output"], c["output"]);
  // The summary: each mode's count and the cycles.
  std::smatch m;
  ASSERT_TRUE(
      std::regex_search(r.err, m, std::regex("bezcam: output best: ([^\n]*) \\(cycle ([^\n]*) against ([^\n]*)\\)\n")))
      << r.err;
  for (const auto& [mode, n] : got) EXPECT_NE(m[1].str().find(mode + " for " + std::to_string(n)), std::string::npos);
  for (const auto& [mode, cycle] : modes) EXPECT_NE(m[3].str().find(" in " + mode), std::string::npos) << m[3];
  EXPECT_NE(r.err.find("(this program, the shortest)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("per entity, the planned time of its moves in each output mode"), std::string::npos);
  const std::string program = read(nc);
  EXPECT_NE(program.find(", output best)"), std::string::npos);
  EXPECT_NE(program.find("(output best, per entity the mode with the shortest planned time: "), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Machines, BestOutputCli, testing::Values("fanuc", "linuxcnc", "grbl"));

TEST(BestOutputCliNotes, NurbsOnOffsetPartsIsExplainedInTheComparison) {
  Scratch s;
  const auto lcnc = run_cli({"convert", "samples/part-flange.json", "--machine", "linuxcnc", "--output", "nurbs",
                             "--compare-outputs", "-o", (s.dir / "l.nc").string()});
  ASSERT_EQ(lcnc.status, 0) << lcnc.err;
  EXPECT_NE(lcnc.err.find("are cut in arcs in nurbs output too"), std::string::npos) << lcnc.err;
  const auto fanuc = run_cli({"convert", "samples/part-flange.json", "--machine", "fanuc", "--output", "nurbs",
                              "--compare-outputs", "-o", (s.dir / "f.nc").string()});
  ASSERT_EQ(fanuc.status, 0) << fanuc.err;
  EXPECT_NE(fanuc.err.find("nurbs loses on the"), std::string::npos) << fanuc.err;
  // The shortest mode's row is marked, this program's too.
  EXPECT_NE(fanuc.err.find("(the shortest)"), std::string::npos) << fanuc.err;
  EXPECT_NE(fanuc.err.find("(this program)"), std::string::npos) << fanuc.err;
}

TEST(BestOutputCliNotes, CheckSheetAndPreviewTakeIt) {
  Scratch s;
  const auto check = run_cli({"check", "samples/part-flange.json", "--machine", "grbl", "--output", "best"});
  ASSERT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find("output best, per entity the mode with the shortest planned time: "), std::string::npos)
      << check.out;
  const std::string html = (s.dir / "sheet.html").string();
  const auto sheet =
      run_cli({"sheet", "samples/part-flange.json", "--machine", "grbl", "--output", "best", "-o", html, "-q"});
  ASSERT_EQ(sheet.status, 0) << sheet.err;
  EXPECT_NE(read(html).find("output best"), std::string::npos);
  const auto preview = run_cli({"preview", "samples/part-flange.json", "--machine", "grbl", "--output", "best", "-o",
                                (s.dir / "p.svg").string()});
  ASSERT_EQ(preview.status, 0) << preview.err;
  EXPECT_NE(read((s.dir / "p.svg").string()).find("output best"), std::string::npos);
  // The same cycle time as the program convert writes.
  const std::string nc = (s.dir / "p.nc").string();
  ASSERT_EQ(
      run_cli({"convert", "samples/part-flange.json", "--machine", "grbl", "--output", "best", "-o", nc, "-q"}).status,
      0);
  const std::string prog = read(nc);
  const size_t at = prog.find("(estimated cycle time ");
  ASSERT_NE(at, std::string::npos);
  const size_t from = at + std::string("(estimated cycle time ").size();
  const std::string figure = "cycle time " + prog.substr(from, prog.find(" on the motion model", from) - from) + " on";
  EXPECT_NE(read((s.dir / "p.svg").string()).find(figure), std::string::npos) << figure;
}

}  // namespace
