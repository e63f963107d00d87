// format_number() prints what the general printer (to_chars, fixed) would,
// trimmed; its fast path for values whose digits are certain must give the
// same text. Checked against the printer itself.
#include "bezcam/gcode/number_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>

#include "bezcam/flatten/tolerance.hpp"

namespace {

std::string through_printer(double v, int decimals) {
  char buf[400];
  char* end = std::to_chars(buf, buf + sizeof buf - 1, v, std::chars_format::fixed, decimals < 0 ? 6 : decimals).ptr;
  if (std::find(buf, end, '.') == end) *end++ = '.';
  while (end[-1] == '0') --end;
  if (end - buf == 3 && buf[0] == '-' && buf[1] == '0' && buf[2] == '.') return "0.";
  return std::string(buf, end);
}

TEST(NumberFormat, SameTextAsThePrinter) {
  std::mt19937_64 rng(1126);
  std::uniform_real_distribution<double> mant(-1, 1);
  std::uniform_int_distribution<int> expo(-10, 16), dec(-1, 12);
  for (int i = 0; i < 300000; ++i) {
    const double v = mant(rng) * std::pow(10.0, expo(rng));
    const int d = dec(rng);
    ASSERT_EQ(bezcam::format_number(v, d), through_printer(v, d)) << "v " << v << " decimals " << d;
    // and the values a program really prints: already quantized
    const double q = bezcam::quantize(v, d);
    ASSERT_EQ(bezcam::format_number(q, d), through_printer(q, d)) << "q " << q << " decimals " << d;
  }
}

TEST(NumberFormat, EdgeCases) {
  for (double v : {0.0, -0.0, -1e-9, 1e-9, -0.0004, 0.0005, 0.0015, 0.125, -0.125, 10.0, -10.0, 100.5, 1e15, -1e15,
                   123456.7890123, 0.1, 0.7, 1e-7})
    for (int d : {-1, 0, 1, 2, 3, 4, 6, 9, 15, 22, 25})
      EXPECT_EQ(bezcam::format_number(v, d), through_printer(v, d)) << v << " " << d;
  EXPECT_EQ(bezcam::format_number(-0.0004, 3), "0.");
  EXPECT_EQ(bezcam::format_number(-0.003, 3), "-0.003");
  EXPECT_EQ(bezcam::format_number(10, 0), "10.");
  EXPECT_EQ(bezcam::format_number(2.5, 4), "2.5");
}

}  // namespace
