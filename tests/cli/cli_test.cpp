// The bezcam executable as a user meets it: exit codes (docs/cli.md), messages
// that name the place, and no output file created or truncated on refusal.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/run_process.hpp"

namespace fs = std::filesystem;

namespace {

using Result = testproc::Result;  // stdout and stderr together in `out`

Result run(const std::string& args) { return testproc::shell(std::string(BEZCAM_EXE) + " " + args + " 2>&1"); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("bezcam-cli-" + std::to_string(::getpid()) + "-" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return path / name;
  }
};

const std::string kSrc = BEZCAM_SOURCE_DIR;

}  // namespace

TEST(Cli, HelpListsTheSubcommands) {
  const Result r = run("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* c : {"convert", "check"}) EXPECT_NE(r.out.find(c), std::string::npos) << r.out;
  EXPECT_EQ(run("convert --help").status, 0);
  EXPECT_EQ(run("").status, 2);                // no subcommand
  EXPECT_EQ(run("convert").status, 2);         // missing JOB
  EXPECT_EQ(run("frobnicate x").status, 2);    // unknown subcommand
}

TEST(Cli, ConvertWritesTheSameProgramAsTheLibrary) {
  TempDir t;
  const fs::path out = t.path / "semi.nc";
  const Result r2 = run("convert " + kSrc + "/samples/curve-semicircle.json --machine fanuc -o " + out.string() + " -q");
  EXPECT_EQ(r2.status, 0) << r2.out;
  EXPECT_EQ(r2.out, "");
  const auto job = bezcam::load_job(kSrc + "/samples/curve-semicircle.json");
  EXPECT_EQ(slurp(out), bezcam::convert(job, bezcam::load_machine_profile("fanuc"), {}).gcode);
}

TEST(Cli, ConvertToStdoutAndSummaryOnStderr) {
  const Result r = run("convert " + kSrc + "/samples/curve-exercise-4.json");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("G21 G90 G17"), std::string::npos);
  EXPECT_NE(r.out.find("largest deviation measured"), std::string::npos);
}

TEST(Cli, InvalidJsonIsRefusedWithItsPlaceAndNoFileIsTouched) {
  TempDir t;
  const fs::path out = t.write("keep.nc", "previous program\n");
  const fs::path bad = t.write("bad.json", "{\"bezcam\": 1,\n \"entities\": [ {\"type\": \"bezier\", \"points\": [[0,0],[1,\"a\"]]} ]}");
  Result r = run("convert " + bad.string() + " -o " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("entities[0].points[1][1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("expected a number"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(out), "previous program\n");

  const fs::path syntax = t.write("syntax.json", "{\"bezcam\": 1,\n  \"entities\": [\n  }");
  r = run("convert " + syntax.string() + " -o " + (t.path / "new.nc").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("line 3"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t.path / "new.nc"));
  // No temporary file is left behind either.
  int files = 0;
  for (const auto& e : fs::directory_iterator(t.path)) files += e.is_regular_file();
  EXPECT_EQ(files, 3);
}

TEST(Cli, PathJointThatDoesNotMeetIsNamed) {
  TempDir t;
  const fs::path bad = t.write("gap.json", R"({"bezcam": 1, "entities": [{"id": "p", "type": "path", "segments": [
      {"type": "bezier", "points": [[0,0],[1,1],[2,0]]},
      {"type": "bezier", "points": [[2.5,0],[3,1]]}]}]})");
  const Result r = run("check " + bad.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("entities[0].segments[1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("segments[0] ends"), std::string::npos) << r.out;
}

TEST(Cli, MissingFileIsAnIoError) {
  const Result r = run("convert /nonexistent/job.json");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("/nonexistent/job.json"), std::string::npos);
}

TEST(Cli, UnknownMachineListsTheKnownOnes) {
  const Result r = run("convert " + kSrc + "/samples/curve-exercise-4.json --machine nosuch");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("fanuc"), std::string::npos) << r.out;
}

TEST(Cli, TravelLimitsAndMaximumFeedAreEnforcedBeforeWriting) {
  TempDir t;
  // 1 m wide: beyond unisurf's +/-750 mm in X.
  const fs::path big = t.write("big.json", R"({"bezcam": 1, "machine": "unisurf", "entities": [
      {"id": "wing", "type": "bezier", "points": [[-800,0],[0,300],[800,0]]}]})");
  Result r = run("convert " + big.string() + " -o " + (t.path / "o.nc").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("travel"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wing"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t.path / "o.nc"));
  const fs::path fast = t.write("fast.json", R"({"bezcam": 1, "machine": "unisurf", "job": {"feed": 3000},
      "entities": [{"type": "bezier", "points": [[0,0],[10,10],[20,0]]}]})");
  r = run("convert " + fast.string() + " -o " + (t.path / "o.nc").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("maximum feed"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t.path / "o.nc"));
}

TEST(Cli, CheckReportsEntitiesAndJointContinuity) {
  const Result r = run("check " + kSrc + "/samples/path-closed-teardrop.json");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("degree 3"), std::string::npos);
  EXPECT_NE(r.out.find("joint segments[0] -> segments[1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(closing)"), std::string::npos) << r.out;
}

TEST(Cli, ToleranceOverrideChangesTheProgram) {
  const Result coarse = run("convert -q " + kSrc + "/samples/curve-semicircle.json --tolerance 0.1");
  const Result fine = run("convert -q " + kSrc + "/samples/curve-semicircle.json --tolerance 0.002");
  EXPECT_EQ(coarse.status, 0);
  EXPECT_EQ(fine.status, 0);
  EXPECT_LT(std::count(coarse.out.begin(), coarse.out.end(), '\n'), std::count(fine.out.begin(), fine.out.end(), '\n'));
  EXPECT_EQ(run("convert -q " + kSrc + "/samples/curve-semicircle.json --tolerance -1").status, 2);
}

// Messages a machinist can act on (issue "Safe on the shop floor",
// "Messages and help").
TEST(Cli, MessagesSayWhatWasMeant) {
  const std::string job = kSrc + "/samples/curve-semicircle.json";
  Result r = run("convert " + job + " --tolerance -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--tolerance: expected a number > 0, found -1"), std::string::npos) << r.out;
  EXPECT_LT(r.out.size(), 300u) << r.out;  // no range up to the largest double
  r = run("convert " + job + " --tol 0.1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("convert has no option --tol: did you mean --tolerance?"), std::string::npos) << r.out;
  r = run("stream x.nc --to 127.0.0.1:1 --retrys 3");
  EXPECT_NE(r.out.find("did you mean --retries?"), std::string::npos) << r.out;
  r = run("convert " + job + " --output out.nc");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("to name the program file, use -o out.nc"), std::string::npos) << r.out;
  r = run("convert " + kSrc + "/samples");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.out.find("is a directory"), std::string::npos) << r.out;
  r = run("convert " + kSrc + "/no-such-job.json");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.out.find("No such file or directory"), std::string::npos) << r.out;
  // --help shows the defaults.
  r = run("stream --help");
  EXPECT_NE(r.out.find("=30"), std::string::npos) << r.out;  // --retries
  EXPECT_NE(r.out.find("Examples:"), std::string::npos) << r.out;
}
