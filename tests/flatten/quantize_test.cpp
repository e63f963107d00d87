// quantize() must give, bit for bit, the value the printed text reads back
// as (the G-code writer prints it; the proofs count on it). Its fast path
// skips the text; here it is checked against the text itself.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <random>

#include "bezcam/flatten/tolerance.hpp"

namespace {

double through_text(double v, int decimals) {
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  double out = 0;
  std::from_chars(buf, r.ptr, out);
  return out == 0 ? 0.0 : out;
}

void expect_same(double v, int d) {
  const double a = bezcam::quantize(v, d), b = through_text(v, d);
  std::uint64_t ua, ub;
  std::memcpy(&ua, &a, 8);
  std::memcpy(&ub, &b, 8);
  ASSERT_EQ(ua, ub) << "v " << v << " (" << std::hexfloat << v << std::defaultfloat << ") decimals " << d;
}

TEST(Quantize, SameBitsAsThePrintedTextReadBack) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> mant(-1, 1);
  std::uniform_int_distribution<int> expo(-12, 16), dec(0, 12);
  for (int i = 0; i < 400000; ++i) expect_same(std::ldexp(mant(rng), 0) * std::pow(10.0, expo(rng)), dec(rng));
}

TEST(Quantize, TiesAndNearTiesGoThroughTheText) {
  // Exact binary ties (x.5 units), the doubles on either side of them, and
  // decimal halves that are not exact in binary.
  for (int d = 0; d <= 9; ++d)
    for (long n = -2000; n <= 2000; ++n) {
      const double half = (double(n) + 0.5) / std::pow(10.0, d);
      for (double v : {half, std::nextafter(half, 1e300), std::nextafter(half, -1e300), double(n) * 0.125,
                       double(n) * 0.0625 + 1e-3})
        expect_same(v, d);
    }
}

TEST(Quantize, ZeroSignLargeValuesAndManyDecimals) {
  for (double v : {0.0, -0.0, -1e-9, 1e-9, -0.0004, 0.0004, 1e15, -1e15, 123456789012.345, 9.999999999999, -9.9999995})
    for (int d : {0, 1, 3, 4, 6, 9, 15, 22, 25}) expect_same(v, d);
  EXPECT_FALSE(std::signbit(bezcam::quantize(-0.0004, 3)));
  EXPECT_EQ(bezcam::quantize(1.23456, -1), 1.23456);
}

}  // namespace
