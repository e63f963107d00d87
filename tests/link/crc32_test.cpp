// CRC-32: the standard check values, and incremental = whole.
#include "bezcam/link/crc32.hpp"

#include <gtest/gtest.h>
#include <random>
#include <string>

using namespace bezcam::link;

TEST(Crc32, StandardCheckValues) {
  // The catalogue's check value for CRC-32/ISO-HDLC (zlib, Ethernet).
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0x00000000u);
  EXPECT_EQ(crc32("a"), 0xE8B7BE43u);
  EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
}

TEST(Crc32, IncrementalEqualsWholeForEverySplit) {
  std::mt19937 rng(12345);
  std::string s(1000, '\0');
  for (auto& c : s) c = static_cast<char>(rng() & 0xFF);
  const std::uint32_t whole = crc32(s);
  for (std::size_t cut :
       {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{500}, std::size_t{999}, std::size_t{1000}}) {
    Crc32 c;
    c.update(std::string_view(s).substr(0, cut));
    c.update(std::string_view(s).substr(cut));
    EXPECT_EQ(c.value(), whole) << "split at " << cut;
  }
}

TEST(Crc32, DetectsEverySingleBitFlip) {
  const std::string s = "G01 X1.000 Y2.000 F800.\n";
  const std::uint32_t ref = crc32(s);
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string t = s;
      t[i] = static_cast<char>(t[i] ^ (1 << bit));
      EXPECT_NE(crc32(t), ref) << "byte " << i << " bit " << bit;
    }
}

// Messages show CRC-32s and session ids as eight upper-case hex digits,
// leading zeros kept.
TEST(Crc32, Hex32IsEightUpperCaseDigits) {
  EXPECT_EQ(hex32(crc32("123456789")), "CBF43926");
  EXPECT_EQ(hex32(0), "00000000");
  EXPECT_EQ(hex32(0x425Au), "0000425A");
  EXPECT_EQ(hex32(0xFFFFFFFFu), "FFFFFFFF");
}
