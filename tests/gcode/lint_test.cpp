// lint_gcode: every finding with its line, all of them (a refused line is
// skipped, recoverable problems are listed and the values kept), the
// machinist's extra checks, and clean programs staying clean.
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/files.hpp"

using namespace bezcam;

namespace {

using bezcam::test::slurp;

// "line:id" of each finding, for compact comparisons.
std::vector<std::string> brief(const std::vector<GcodeFinding>& fs) {
  std::vector<std::string> out;
  for (const auto& f : fs) out.push_back(std::to_string(f.line) + ":" + f.id);
  return out;
}

const MachineProfile& profile(const std::string& name) {
  static std::map<std::string, MachineProfile> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, load_machine_profile(name)).first;
  return it->second;
}

const std::string kHead = "%\nG21 G90 G17\nT1 M06\nS10000 M03\nG00 Z5\nG00 X0 Y0\nG01 Z-1 F300\n";  // 7 lines
const std::string kTail = "G00 Z5\nM05\nM30\n%\n";

}  // namespace

TEST(Lint, CleanProgramHasNoFindings) {
  const std::string prog = kHead + "G01 X10 Y0 F1000\nG03 X0 Y10 I-10 J0\nG02 X10 Y0 R10\n" + kTail;
  EXPECT_EQ(brief(lint_gcode(prog, profile("generic"))), std::vector<std::string>{});
  // A converted sample, for every profile.
  const Job job = load_job(BEZCAM_SOURCE_DIR "/samples/path-closed-teardrop.json");
  for (const char* name : {"generic", "fanuc", "fanuc-g063", "linuxcnc", "grbl", "unisurf"}) {
    const auto r = convert(job, profile(name), ConvertOptions{});
    EXPECT_EQ(brief(lint_gcode(r.gcode, profile(name))), std::vector<std::string>{}) << name;
  }
}

TEST(Lint, SeedsButterflyListsEveryDecreasingKnot) {
  const std::string text = slurp(BEZCAM_SOURCE_DIR "/tests/bad/butterfly-g063.nc");
  const auto fs = lint_gcode(text, profile("fanuc-g063"));
  EXPECT_EQ(brief(fs), (std::vector<std::string>{
                           "1:gcode.repeated-word",     // Z34.400 ... Z0.000
                           "1:gcode.repeated-word",     // R0.000000 ... R1.000
                           "1:gcode.repeated-word",     // P4 ... P900
                           "1:gcode.no-feed",           // no F (P900 was probably F900)
                           "1:gcode.position-unknown",  // nothing positioned the tool
                           "1:gcode.weight",            // R0 (the first R is kept)
                           "1:gcode.knot-missing",      // no K on the first block
                           "1:gcode.modes-unset",
                           "1:gcode.spindle-off",
                           "7:gcode.knot-order",   // K0.03118 after K0.04978
                           "14:gcode.knot-order",  // K0.259080 after K0.343467 (the digest's example)
                           "30:gcode.nurbs-open",  // the listing stops before the knot-only blocks
                           "30:gcode.no-program-end",
                       }));
  EXPECT_EQ(fs[9].message,
            "K0.03118: expected a knot >= 0.04978 (knots must not decrease; the previous knot is on line 6), found "
            "0.03118");
  EXPECT_EQ(fs[10].message,
            "K0.259080: expected a knot >= 0.343467 (knots must not decrease; the previous knot is on line 13), found "
            "0.25908");
  EXPECT_EQ(fs[11].message,
            "the program ends inside the NURBS block opened at line 1: it has 30 control points and 0 of its 4 "
            "knot-only K blocks");
}

TEST(Lint, EveryProblemOnItsLineAndLintGoesOn) {
  const std::string prog = kHead +                    // lines 1-7
                           "G01 X10 Y0 F1000\n"       // 8
                           "G01 X10 Y (broken\n"      // 9: syntax, skipped
                           "G03 X0 Y10.01 I-10 J0\n"  // 10: radius mismatch (kept)
                           "G01 X500\n"               // 11: travel (grbl: 400)
                           "G01 X0 F9000\n"           // 12: feed (grbl: 5000)
                           "G19 G02 Y1 Z1 I1 J0\n"    // 13: I is no centre word in G19
                           "G01 X1 X2\n"              // 14: repeated word, first kept
                           "G38.2 Z-5\n"              // 15: unsupported
                           "G01 Y5\n" +               // 16: fine, from X1
                           kTail;
  const auto fs = lint_gcode(prog, profile("grbl"));
  EXPECT_EQ(brief(fs),
            (std::vector<std::string>{"9:gcode.syntax", "10:gcode.arc-radius", "11:gcode.travel", "12:gcode.feed-limit",
                                      "13:gcode.arc", "14:gcode.repeated-word", "15:gcode.unsupported"}));
  EXPECT_EQ(fs[2].message,
            "the move reaches X = 500 mm, outside the travel of machine \"grbl\" (X from -400 to 400 mm)");
}

TEST(Lint, NurbsBlockRulesAllListed) {
  const std::string prog = kHead +
                           "G06.2 P4 K0 X0 Y0 Z-1 F800\n"  // 8
                           "K0 X10 Y5\n"                   // 9
                           "K0 X20 Y5\n"                   // 10
                           "K0.2 X30 Y0 R0\n"              // 11: clamped start broken, weight 0
                           "K0.5 X40 Y5\n"                 // 12
                           "K0.4 X50 Y5\n"                 // 13: decreasing
                           "K0.3 X60 Y0\n"                 // 14: decreasing again
                           "K1\nK1\nK1\nK2\n"              // 15-18: clamped end broken at 18
                           + kTail;
  const auto fs = lint_gcode(prog, profile("fanuc"));
  EXPECT_EQ(brief(fs), (std::vector<std::string>{"11:gcode.weight", "11:gcode.knot-clamped", "13:gcode.knot-order",
                                                 "14:gcode.knot-order", "18:gcode.knot-clamped"}));
}

TEST(Lint, TooFewControlPointsAndAnInterruptedBlock) {
  // Rank 4 with 3 control points: the clamped ends overlap (every knot would
  // have to be equal), so lint reports the repeat and the count.
  std::string prog = kHead + "G06.2 P4 K0 X0 Y0 Z-1 F800\nK0 X10\nK0 X20\nK1\nK1\nK1\nK1\n" + kTail;
  EXPECT_EQ(brief(lint_gcode(prog, profile("fanuc"))),
            (std::vector<std::string>{"11:gcode.knot-clamped", "14:gcode.knot-count"}));
  // A G01 in the middle of a block: reported, the block dropped, the G01 read.
  prog = kHead + "G06.2 P4 K0 X0 Y0 Z-1 F800\nK0 X10\nG01 X5 Y5\nK0 X7\n" + kTail;
  EXPECT_EQ(brief(lint_gcode(prog, profile("fanuc"))),
            (std::vector<std::string>{"10:gcode.nurbs-open", "11:gcode.nurbs-start"}));
}

TEST(Lint, JumpAtAnInteriorKnotOfFullMultiplicity) {
  // Rank 2 (lines): knot 1 repeated twice inside lets the curve jump from
  // (10,0) to (20,5); the dialect allows it, a machinist wants to know.
  const std::string prog = kHead + "G06.2 P2 K0 X0 Y0 Z-1 F800\nK0 X10 Y0\nK1 X20 Y5\nK1 X30 Y5\nK2\nK2\n" + kTail;
  const auto fs = lint_gcode(prog, profile("fanuc"));
  ASSERT_EQ(brief(fs), (std::vector<std::string>{"13:gcode.nurbs-jump"}));
  EXPECT_EQ(fs[0].message,
            "knot 1 repeats 2 times inside the NURBS block of line 8: the curve jumps from (10, 0, -1) to (20, 5, -1)");
}

TEST(Lint, MachinistChecks) {
  const std::string prog =
      "N10 G00 X0 Y0 Z5\n"  // 1: modes unset
      "N20 X10 Y10 Z-2\n"   // 2: rapid plunging while moving in X/Y
      "N15 G01 X20 F100\n"  // 3: N decreasing, spindle off (position is known by now)
      "N30 M06\n"           // 4: M06 without T
      "N40 M03 S1000\n"     // 5
      "N50 G01 X30\n";      // 6: no program end
  const auto fs = lint_gcode(prog, profile("generic"));
  EXPECT_EQ(brief(fs),
            (std::vector<std::string>{"1:gcode.modes-unset", "2:gcode.rapid-plunge", "3:gcode.line-number-order",
                                      "3:gcode.spindle-off", "4:gcode.tool-unset", "6:gcode.no-program-end"}));
  EXPECT_EQ(fs[0].message,
            "the first move comes before G21/G20 (units), G90 (absolute) and G17 (XY plane) are set: the machine "
            "would use whatever the last program left; start with a safety line such as G21 G90 G17");
  // Cutting from a position the program never set.
  const auto p = lint_gcode("G21 G90 G17\nS1000 M03\nG01 X5 F100\nM30\n", profile("generic"));
  EXPECT_EQ(brief(p), (std::vector<std::string>{"3:gcode.position-unknown"}));
}

TEST(Lint, LinuxCncBlocksAgainstTheProfile) {
  const std::string prog = kHead +
                           "G5.2 P1 L5\n"  // 8: order 5 > the profile's 4
                           "X10 Y10 P1\nX20 Y10 P1\nX30 Y0 P1\nX40 Y0 P1\n"
                           "G5.3\n"                        // 13
                           "G5 I5 J0 P-5 Q0 X50 Y0 Z-1\n"  // 14: Z refused
                           + kTail;
  EXPECT_EQ(brief(lint_gcode(prog, profile("linuxcnc"))),
            (std::vector<std::string>{"8:gcode.rank", "14:gcode.bezier"}));
  // The same words on a Fanuc are a dialect error, each line on its own.
  const auto f = lint_gcode(kHead + "G5.1 X10 Y0 I5 J5\n" + kTail, profile("fanuc"));
  EXPECT_EQ(brief(f), (std::vector<std::string>{"8:gcode.dialect"}));
}

TEST(Lint, SeededGarbageNeverCrashesTheReaderOrLint) {
  // Random lines over the G-code alphabet (and valid fragments): the reader
  // refuses with an InputError or reads, lint reports; nothing else escapes.
  std::mt19937 rng(1234);
  const std::string alphabet = "GXYZIJKRPQLFSTMNO0123456789.-+ ()%;/";
  const std::vector<std::string> frags = {
      "G06.2 P4 K0 X0 Y0 Z0", "K0 X1",       "K1",           "G5.2 P1", "X1 Y1 P1", "G5.3",
      "G02 X1 Y1 I1 J0",      "G01 X5 F100", "G03 X0 Y0 R5", "M30",     "G5 P1 Q1"};
  for (int trial = 0; trial < 400; ++trial) {
    std::string prog = "G21 G90 G17\nG00 X0 Y0 Z0\nF100\n";
    const int lines = 1 + static_cast<int>(rng() % 12);
    for (int l = 0; l < lines; ++l) {
      if (rng() % 2) {
        prog += frags[rng() % frags.size()];
      } else {
        const int len = static_cast<int>(rng() % 24);
        for (int c = 0; c < len; ++c) prog += alphabet[rng() % alphabet.size()];
      }
      prog += "\n";
    }
    try {
      read_gcode(prog, &profile("fanuc"));
      read_gcode(prog);
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected " << e.what() << " for\n" << prog;
    }
    for (const char* m : {"fanuc", "linuxcnc", "grbl"}) {
      std::vector<GcodeFinding> fs;
      EXPECT_NO_THROW(fs = lint_gcode(prog, profile(m))) << prog;
      for (const auto& f : fs) {
        EXPECT_GE(f.line, 1);
        EXPECT_EQ(f.id.rfind("gcode.", 0), 0u) << f.id;
        EXPECT_FALSE(f.message.empty());
      }
    }
  }
}
