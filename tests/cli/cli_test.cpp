// bezcam as a user meets it: exit codes (docs/cli.md), messages that name
// the place, and no output file created or truncated on refusal. What
// writes files runs the executable; the rest runs in-process.
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "in_process.hpp"
#include "support/files.hpp"
#include "support/run_process.hpp"

namespace fs = std::filesystem;

namespace {

using bezcam::test::slurp;
using bezcam::test::TempDir;

// The executable, stdout and stderr together in `out`.
testproc::Result run(const std::string& args) {
  return testproc::shell(std::string(BEZCAM_EXE) + " " + args + " 2>&1");
}

// In-process, stdout and stderr together in `out` (the order of lines
// between the two is not kept: the tests look for one or the other).
testproc::Result run_here(const std::string& args) {
  std::istringstream in(args);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  testproc::Result r = bezcam::test::run_cli(words);
  r.out += r.err;
  return r;
}

fs::path write(const TempDir& t, const std::string& name, const std::string& text) {
  bezcam::test::write_file(t / name, text);
  return t / name;
}

const std::string kSrc = BEZCAM_SOURCE_DIR;

}  // namespace

TEST(Cli, HelpListsTheSubcommands) {
  const auto r = run_here("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* c : {"convert", "check"}) EXPECT_NE(r.out.find(c), std::string::npos) << r.out;
  EXPECT_EQ(run_here("convert --help").status, 0);
  EXPECT_EQ(run_here("").status, 2);              // no subcommand
  EXPECT_EQ(run_here("convert").status, 2);       // missing JOB
  EXPECT_EQ(run_here("frobnicate x").status, 2);  // unknown subcommand
}

TEST(Cli, ConvertWritesTheSameProgramAsTheLibrary) {
  TempDir t;
  const fs::path out = t / "semi.nc";
  const auto r2 = run("convert " + kSrc + "/samples/curve-semicircle.json --machine fanuc -o " + out.string() + " -q");
  EXPECT_EQ(r2.status, 0) << r2.out;
  EXPECT_EQ(r2.out, "");
  const auto job = bezcam::load_job(kSrc + "/samples/curve-semicircle.json");
  EXPECT_EQ(slurp(out), bezcam::convert(job, bezcam::load_machine_profile("fanuc"), {}).gcode);
}

TEST(Cli, ConvertToStdoutAndSummaryOnStderr) {
  const auto r = run_here("convert " + kSrc + "/samples/curve-exercise-4.json");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("G21 G90 G17"), std::string::npos);
  EXPECT_NE(r.out.find("largest deviation measured"), std::string::npos);
}

TEST(Cli, InvalidJsonIsRefusedWithItsPlaceAndNoFileIsTouched) {
  TempDir t;
  const fs::path out = write(t, "keep.nc", "previous program\n");
  const fs::path bad = write(
      t, "bad.json", "{\"bezcam\": 1,\n \"entities\": [ {\"type\": \"bezier\", \"points\": [[0,0],[1,\"a\"]]} ]}");
  auto r = run("convert " + bad.string() + " -o " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("entities[0].points[1][1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("expected a number"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(out), "previous program\n");

  const fs::path syntax = write(t, "syntax.json", "{\"bezcam\": 1,\n  \"entities\": [\n  }");
  r = run("convert " + syntax.string() + " -o " + (t / "new.nc").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("line 3"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t / "new.nc"));
  // No temporary file is left behind either.
  EXPECT_EQ(t.files(), (std::vector<std::string>{"bad.json", "keep.nc", "syntax.json"}));
}

TEST(Cli, PathJointThatDoesNotMeetIsNamed) {
  TempDir t;
  const fs::path bad = write(t, "gap.json", R"({"bezcam": 1, "entities": [{"id": "p", "type": "path", "segments": [
      {"type": "bezier", "points": [[0,0],[1,1],[2,0]]},
      {"type": "bezier", "points": [[2.5,0],[3,1]]}]}]})");
  const auto r = run_here("check " + bad.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("entities[0].segments[1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("segments[0] ends"), std::string::npos) << r.out;
}

TEST(Cli, MissingFileIsAnIoError) {
  const auto r = run_here("convert /nonexistent/job.json");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("/nonexistent/job.json"), std::string::npos);
}

TEST(Cli, UnknownMachineListsTheKnownOnes) {
  const auto r = run_here("convert " + kSrc + "/samples/curve-exercise-4.json --machine nosuch");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("fanuc"), std::string::npos) << r.out;
}

TEST(Cli, TravelLimitsAndMaximumFeedAreEnforcedBeforeWriting) {
  TempDir t;
  // 1 m wide: beyond unisurf's +/-750 mm in X.
  const fs::path big = write(t, "big.json", R"({"bezcam": 1, "machine": "unisurf", "entities": [
      {"id": "wing", "type": "bezier", "points": [[-800,0],[0,300],[800,0]]}]})");
  auto r = run("convert " + big.string() + " -o " + (t / "o.nc").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("travel"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wing"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t / "o.nc"));
  const fs::path fast = write(t, "fast.json", R"({"bezcam": 1, "machine": "unisurf", "job": {"feed": 3000},
      "entities": [{"type": "bezier", "points": [[0,0],[10,10],[20,0]]}]})");
  r = run("convert " + fast.string() + " -o " + (t / "o.nc").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("maximum feed"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t / "o.nc"));
}

TEST(Cli, CheckReportsEntitiesAndJointContinuity) {
  const auto r = run_here("check " + kSrc + "/samples/path-closed-teardrop.json");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("degree 3"), std::string::npos);
  EXPECT_NE(r.out.find("joint segments[0] -> segments[1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(closing)"), std::string::npos) << r.out;
}

TEST(Cli, ToleranceOverrideChangesTheProgram) {
  const auto coarse = run_here("convert -q " + kSrc + "/samples/curve-semicircle.json --tolerance 0.1");
  const auto fine = run_here("convert -q " + kSrc + "/samples/curve-semicircle.json --tolerance 0.002");
  EXPECT_EQ(coarse.status, 0);
  EXPECT_EQ(fine.status, 0);
  EXPECT_LT(std::count(coarse.out.begin(), coarse.out.end(), '\n'), std::count(fine.out.begin(), fine.out.end(), '\n'));
  EXPECT_EQ(run_here("convert -q " + kSrc + "/samples/curve-semicircle.json --tolerance -1").status, 2);
}

// Messages a machinist can act on (issue "Safe on the shop floor",
// "Messages and help").
TEST(Cli, MessagesSayWhatWasMeant) {
  const std::string job = kSrc + "/samples/curve-semicircle.json";
  auto r = run_here("convert " + job + " --tolerance -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--tolerance: expected a number > 0, found -1"), std::string::npos) << r.out;
  EXPECT_LT(r.out.size(), 300u) << r.out;  // no range up to the largest double
  r = run_here("convert " + job + " --tol 0.1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("convert has no option --tol: did you mean --tolerance?"), std::string::npos) << r.out;
  r = run_here("stream x.nc --to 127.0.0.1:1 --retrys 3");
  EXPECT_NE(r.out.find("did you mean --retries?"), std::string::npos) << r.out;
  r = run_here("convert " + job + " --output out.nc");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("to name the program file, use -o out.nc"), std::string::npos) << r.out;
  r = run_here("convert " + kSrc + "/samples");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.out.find("is a directory"), std::string::npos) << r.out;
  r = run_here("convert " + kSrc + "/no-such-job.json");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.out.find("No such file or directory"), std::string::npos) << r.out;
  // --help shows the defaults.
  r = run_here("stream --help");
  EXPECT_NE(r.out.find("=30"), std::string::npos) << r.out;  // --retries
  EXPECT_NE(r.out.find("Examples:"), std::string::npos) << r.out;
}
