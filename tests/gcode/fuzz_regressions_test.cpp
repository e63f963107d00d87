// Findings of the G-code reader fuzzer (tests/fuzz/fuzz_gcode_reader.cpp),
// kept as regression tests: each input once crashed, hung or hit undefined
// behaviour; now it is refused with an error naming its line. Whole inputs
// as the fuzzer wrote them are in tests/fuzz/regressions/.
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"

using namespace bezcam;

namespace {

std::string read_file(const std::string& name) {
  std::ifstream in(std::string(BEZCAM_SOURCE_DIR) + "/tests/fuzz/regressions/gcode/" + name, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string refusal(const std::string& text, const MachineProfile* m = nullptr, std::string* where = nullptr) {
  try {
    read_gcode(text, m);
  } catch (const InputError& e) {
    if (where) *where = e.where();
    return e.id();
  }
  return "";
}

bool lint_finds(const std::string& text, const MachineProfile& m, const std::string& id, int line) {
  for (const auto& f : lint_gcode(text, m))
    if (f.id == id && f.line == line) return true;
  return false;
}

}  // namespace

TEST(FuzzRegression, AToolNumberBeyondAnIntIsRefused) {
  // T1e20 was converted to int: undefined behaviour (UBSan: 1e+20 is
  // outside the range of representable values of type 'int').
  const MachineProfile generic = load_machine_profile("generic");
  const std::string whole = read_file("tool-number-overflow.nc");
  ASSERT_FALSE(whole.empty());
  // read_gcode stops at the first garbled line; lint, which the fuzzer ran,
  // goes on to line 18 and reaches the tool number.
  EXPECT_NE(refusal(whole), "");
  EXPECT_TRUE(lint_finds(whole, generic, "gcode.tool", 18));
  std::string where;
  EXPECT_EQ(refusal("G21 G90 G17\nT100000000000000000000 M06\n", &generic, &where), "gcode.tool");
  EXPECT_EQ(where, "line 2");
  EXPECT_TRUE(lint_finds("G21 G90 G17\nT100000000000000000000 M06\nM30\n", generic, "gcode.tool", 2));
  // The largest tool number still reads.
  EXPECT_EQ(refusal("G21 G90 G17\nT1000000000 M06\nM30\n", &generic), "");
}

TEST(FuzzRegression, AHugeG52OrderIsRefusedWithoutOverflow) {
  // The same conversion for the order L of a LinuxCNC G5.2 block.
  const MachineProfile linuxcnc = load_machine_profile("linuxcnc");
  const std::string text =
      "G21 G90 G17\nG00 X0. Y0. Z0.\nG01 F100.\nG5.2 L100000000000000000000 P1.\nX1. Y1. P1.\nG5.3\nM30\n";
  std::string where;
  EXPECT_EQ(refusal(text, &linuxcnc, &where), "gcode.rank");
  EXPECT_EQ(where, "line 4");
  EXPECT_EQ(refusal(text, nullptr), "gcode.rank");
  EXPECT_TRUE(lint_finds(text, linuxcnc, "gcode.rank", 4));
}
