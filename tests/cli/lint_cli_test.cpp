// `bezcam lint FILE.nc --machine NAME` as a user meets it: exit 0 clean,
// 2 findings, 3 unreadable file; each finding as `FILE:LINE: message [id]`.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "support/run_process.hpp"

namespace fs = std::filesystem;

namespace {

using LintRun = testproc::Result;

LintRun lint(const std::string& args, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  LintRun r = testproc::shell(std::string(BEZCAM_EXE) + " lint " + args + " 2>" + err.string());
  r.err = testproc::slurp(err);
  return r;
}

struct Dir {
  fs::path path = fs::temp_directory_path() / ("bezcam-lint-" + std::to_string(::getpid()) + "-" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Dir() { fs::create_directories(path); }
  ~Dir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return path / name;
  }
};

}  // namespace

TEST(LintCli, CleanProgramExitsZero) {
  Dir d;
  const auto f = d.write("ok.nc", "%\nG21 G90 G17\nT1 M06\nS9000 M03\nG00 Z5\nG00 X0 Y0\nG01 Z-1 F300\n"
                                  "G01 X10 F900\nG03 X0 Y10 I-10 J0\nG00 Z5\nM05\nM30\n%\n");
  const auto r = lint(f.string() + " --machine fanuc", d.path);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("no findings for machine fanuc"), std::string::npos) << r.err;
}

TEST(LintCli, FindingsExitTwoOnePerLine) {
  Dir d;
  const auto f = d.write("bad.nc", "%\nG21 G90 G17\nS9000 M03\nG00 X0 Y0 Z0\nG01 X900 F100\nG01 X0 Y0 Y1\nM30\n");
  const auto r = lint(f.string() + " --machine grbl", d.path);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, f.string() +
                       ":5: the move reaches X = 900 mm, outside the travel of machine \"grbl\" (X from -400 to 400 "
                       "mm) [gcode.travel]\n" +
                       f.string() + ":6: Y appears twice on the line (Y0 and Y1); a block gives each address once "
                                    "[gcode.repeated-word]\n");
  EXPECT_NE(r.err.find("2 findings for machine grbl"), std::string::npos) << r.err;
}

TEST(LintCli, SeedsButterflyListingExitsTwoWithBothDecreasingKnots) {
  Dir d;
  const std::string f = BEZCAM_SOURCE_DIR "/tests/bad/butterfly-g063.nc";
  const auto r = lint(f + " --machine fanuc-g063", d.path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(f + ":7: K0.03118: expected a knot >= 0.04978"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(f + ":14: K0.259080: expected a knot >= 0.343467"), std::string::npos) << r.out;
}

TEST(LintCli, UnreadableFileExitsThree) {
  Dir d;
  auto r = lint((d.path / "missing.nc").string() + " --machine generic", d.path);
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("cannot open the G-code file: No such file or directory"), std::string::npos) << r.err;
  r = lint(d.path.string(), d.path);  // a directory
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

TEST(LintCli, UnknownMachineIsAUsageError) {
  Dir d;
  const auto f = d.write("ok.nc", "G21 G90 G17\nM30\n");
  const auto r = lint(f.string() + " --machine no-such-machine", d.path);
  EXPECT_EQ(r.status, 2);
}
