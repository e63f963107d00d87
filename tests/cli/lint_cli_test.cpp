// `bezcam lint FILE.nc --machine NAME` as a user meets it (in-process):
// exit 0 clean, 2 findings, 3 unreadable file; each finding as
// `FILE:LINE: message [id]`.
#include <filesystem>
#include <gtest/gtest.h>

#include "in_process.hpp"
#include "support/files.hpp"

namespace fs = std::filesystem;

namespace {

testproc::Result lint(const std::vector<std::string>& args) {
  std::vector<std::string> all{"lint"};
  all.insert(all.end(), args.begin(), args.end());
  return bezcam::test::run_cli(all);
}

struct Dir {
  bezcam::test::TempDir dir;
  fs::path write(const std::string& name, const std::string& text) const {
    bezcam::test::write_file(dir / name, text);
    return dir / name;
  }
};

}  // namespace

TEST(LintCli, CleanProgramExitsZero) {
  Dir d;
  const auto f = d.write("ok.nc",
                         "%\nG21 G90 G17\nT1 M06\nS9000 M03\nG00 Z5\nG00 X0 Y0\nG01 Z-1 F300\n"
                         "G01 X10 F900\nG03 X0 Y10 I-10 J0\nG00 Z5\nM05\nM30\n%\n");
  const auto r = lint({f.string(), "--machine", "fanuc"});
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("no findings for machine fanuc"), std::string::npos) << r.err;
}

TEST(LintCli, FindingsExitTwoOnePerLine) {
  Dir d;
  const auto f = d.write("bad.nc", "%\nG21 G90 G17\nS9000 M03\nG00 X0 Y0 Z0\nG01 X900 F100\nG01 X0 Y0 Y1\nM30\n");
  const auto r = lint({f.string(), "--machine", "grbl"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, f.string() +
                       ":5: the move reaches X = 900 mm, outside the travel of machine \"grbl\" (X from -400 to 400 "
                       "mm) [gcode.travel]\n" +
                       f.string() +
                       ":6: Y appears twice on the line (Y0 and Y1); a block gives each address once "
                       "[gcode.repeated-word]\n");
  EXPECT_NE(r.err.find("2 findings for machine grbl"), std::string::npos) << r.err;
}

TEST(LintCli, SeedsButterflyListingExitsTwoWithBothDecreasingKnots) {
  const std::string f = BEZCAM_SOURCE_DIR "/tests/bad/butterfly-g063.nc";
  const auto r = lint({f, "--machine", "fanuc-g063"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(f + ":7: K0.03118: expected a knot >= 0.04978"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(f + ":14: K0.259080: expected a knot >= 0.343467"), std::string::npos) << r.out;
}

TEST(LintCli, UnreadableFileExitsThree) {
  Dir d;
  auto r = lint({(d.dir / "missing.nc").string(), "--machine", "generic"});
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("cannot open the G-code file: No such file or directory"), std::string::npos) << r.err;
  r = lint({d.dir.path().string()});  // a directory
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

TEST(LintCli, UnknownMachineIsAUsageError) {
  Dir d;
  const auto f = d.write("ok.nc", "G21 G90 G17\nM30\n");
  const auto r = lint({f.string(), "--machine", "no-such-machine"});
  EXPECT_EQ(r.status, 2);
}

TEST(LintCli, WithoutMachineTheProgramsHeaderNamesIt) {
  // A Fanuc program as bezcam writes it: clean for fanuc, full of findings
  // for generic (line numbers, G06.2 blocks).
  Dir d;
  const std::string nc = (d.dir / "part.nc").string();
  const auto conv = bezcam::test::run_cli(
      {"convert", BEZCAM_SOURCE_DIR "/samples/part.dxf", "--machine", "fanuc", "--output", "nurbs", "-o", nc, "-q"});
  ASSERT_EQ(conv.status, 0) << conv.err;
  const auto named = lint({nc});
  EXPECT_EQ(named.status, 0) << named.out << named.err;
  EXPECT_NE(named.err.find("no findings for machine fanuc (named in the program's header)"), std::string::npos)
      << named.err;
  const auto generic = lint({nc, "--machine", "generic", "-q"});
  EXPECT_EQ(generic.status, 2);
  // A program without bezcam's header: generic.
  const auto plain = lint({d.write("plain.nc",
                                   "%\nG21 G90 G17\nT1 M06\nS9000 M03\nG00 Z5\nG00 X0 Y0\nG01 Z-1 F300\n"
                                   "G01 X10 F900\nG00 Z5\nM05\nM30\n%\n")
                               .string()});
  EXPECT_EQ(plain.status, 0) << plain.out;
  EXPECT_NE(plain.err.find("no findings for machine generic\n"), std::string::npos) << plain.err;
}

TEST(LintCli, AMachineNameIgnoresCaseOrIsSuggested) {
  Dir d;
  const auto p = d.write("p.nc",
                         "%\nG21 G90 G17\nT1 M06\nS9000 M03\nG00 Z5\nG00 X0 Y0\nG01 Z-1 F300\n"
                         "G01 X10 F900\nG00 Z5\nM05\nM30\n%\n")
                     .string();
  const auto upper = lint({p, "--machine", "LinuxCNC"});
  EXPECT_EQ(upper.status, 0) << upper.err;
  EXPECT_NE(upper.err.find("for machine linuxcnc"), std::string::npos) << upper.err;
  const auto typo = lint({p, "--machine", "linuxcn"});
  EXPECT_EQ(typo.status, 2);
  EXPECT_NE(typo.err.find("no machine profile named \"linuxcn\" (did you mean \"linuxcnc\"?); known profiles: "),
            std::string::npos)
      << typo.err;
}
