// The register map: layout invariants (what the documentation promises),
// byte order, chunk and command encodings, the status block round trip.
#include "bezcam/link/register_map.hpp"

#include <gtest/gtest.h>
#include <set>

#include "bezcam/link/crc32.hpp"

using namespace bezcam::link;

TEST(RegisterMap, BlocksDoNotOverlapAndFitTheFunctionCodes) {
  EXPECT_LE(reg::total_bytes + 2, reg::status_count);
  EXPECT_LE(reg::status_count, reg::alarm_text);
  EXPECT_EQ(reg::alarm_text + reg::alarm_text_count, reg::machine_name);
  EXPECT_EQ(reg::machine_name + reg::machine_name_count, reg::readable_end);
  EXPECT_LE(reg::readable_end, reg::command);
  EXPECT_LE(reg::command + 9, reg::chunk);
  // The whole status block is one FC 03 / FC 04 read (at most 125 registers).
  EXPECT_LE(reg::status_count, 125);
  // A full chunk is one FC 23 write (at most 121 registers) and one FC 16.
  EXPECT_EQ(reg::chunk_header + reg::chunk_data_max, 121);
  EXPECT_EQ(kMaxChunkBytes, 228);
}

TEST(RegisterMap, ThirtyTwoBitValuesAreHighWordFirst) {
  std::uint16_t r[2];
  put_u32(r, 0x12345678u);
  EXPECT_EQ(r[0], 0x1234);
  EXPECT_EQ(r[1], 0x5678);
  EXPECT_EQ(get_u32(r), 0x12345678u);
}

TEST(RegisterMap, TextIsTwoBytesPerRegisterFirstByteHigh) {
  std::uint16_t r[3];
  pack_text("G01", r, 3);
  EXPECT_EQ(r[0], ('G' << 8) | '0');
  EXPECT_EQ(r[1], ('1' << 8) | 0);
  EXPECT_EQ(r[2], 0);
  EXPECT_EQ(unpack_text(r, 6, true), "G01");
  EXPECT_EQ(unpack_text(r, 3, false), "G01");
  EXPECT_EQ(unpack_text(r, 4, false), std::string("G01\0", 4));
}

TEST(RegisterMap, ChunkEncodingMatchesTheDocumentedLayout) {
  const auto r = encode_chunk({0xA1B2C3D4u, 7, "X1\n"});
  ASSERT_EQ(r.size(), 9u);  // 7 header registers + 2 for 3 bytes
  EXPECT_EQ(r[0], 0xA1B2);
  EXPECT_EQ(r[1], 0xC3D4);
  EXPECT_EQ(r[2], 0);
  EXPECT_EQ(r[3], 7);
  EXPECT_EQ(r[4], 3);
  EXPECT_EQ(get_u32(&r[5]), crc32("X1\n"));
  EXPECT_EQ(r[7], ('X' << 8) | '1');
  EXPECT_EQ(r[8], ('\n' << 8) | 0);
}

TEST(RegisterMap, CommandsHaveTheirDocumentedLengths) {
  EXPECT_EQ(command_length(Command::open), 5);
  EXPECT_EQ(command_length(Command::resume), 5);
  EXPECT_EQ(command_length(Command::commit), 9);
  EXPECT_EQ(command_length(Command::abort), 5);
  EXPECT_EQ(command_length(Command::reset), 1);
  const std::uint32_t args[2] = {0x01020304u, 1000};
  const auto r = encode_command(Command::open, args);
  EXPECT_EQ(r, (std::vector<std::uint16_t>{1, 0x0102, 0x0304, 0, 1000}));
  EXPECT_EQ(r.size(), command_length(Command::open));
}

TEST(RegisterMap, StatusRoundTripsEveryField) {
  Status s;
  s.magic = kMagic;
  s.version = kProtocolVersion;
  s.buffer_capacity = 4096;
  s.max_chunk = kMaxChunkBytes;
  s.session = 0xDEADBEEFu;
  s.state = State::finishing;
  s.alarm = Alarm::travel_limit;
  s.alarm_line = 70000;
  s.ack_seq = 123456;
  s.ack_bytes = 9876543;
  s.buffer_free = 1234;
  s.last_reject = Reject::seq_gap;
  s.lines_executed = 65537;
  s.blocks_executed = 65539;
  s.program_crc = 0xCBF43926u;
  s.pos[0] = -1500;
  s.pos[1] = 2147483647;
  s.pos[2] = -2147483647 - 1;
  s.feed_tenths = 8000;
  s.spindle_rpm = 24000;
  s.flags = flag::spindle_on | flag::program_end;
  s.tool = 3;
  s.motion = 2;
  s.connections = 5;
  s.duplicates = 2;
  s.rejects = 9;
  s.total_bytes = 100000;
  const auto regs = s.encode();
  const Status d = Status::decode(regs);
  EXPECT_EQ(d.encode(), regs);
  EXPECT_EQ(d.pos[0], -1500);
  EXPECT_EQ(d.pos[2], -2147483647 - 1);
  EXPECT_EQ(d.session, 0xDEADBEEFu);
  EXPECT_EQ(regs[reg::magic], 0x425A);
  EXPECT_EQ(regs[reg::session], 0xDEAD);
  EXPECT_EQ(regs[reg::session + 1], 0xBEEF);
}

TEST(RegisterMap, EveryCodeHasANameAndRefusalsMapToStandardExceptions) {
  std::set<std::string> names;
  for (int i = 0; i <= 4; ++i) names.insert(to_string(static_cast<State>(i)));
  EXPECT_EQ(names.size(), 5u);
  names.clear();
  for (int i = 0; i <= 9; ++i) names.insert(to_string(static_cast<Alarm>(i)));
  EXPECT_EQ(names.size(), 10u);
  EXPECT_EQ(names.count("unknown"), 0u);
  names.clear();
  for (int i = 0; i <= 17; ++i) {
    const auto r = static_cast<Reject>(i);
    names.insert(to_string(r));
    EXPECT_NE(describe(r), "unknown refusal code");
    const int e = exception_for(r);
    EXPECT_TRUE(i == 0 ? e == 0 : (e == 1 || e == 2 || e == 3 || e == 4 || e == 6)) << to_string(r);
  }
  EXPECT_EQ(names.size(), 18u);
  EXPECT_EQ(names.count("unknown"), 0u);
  EXPECT_EQ(exception_for(Reject::bad_function), 1);
  EXPECT_EQ(exception_for(Reject::read_only), 2);
  EXPECT_EQ(exception_for(Reject::seq_gap), 3);
  EXPECT_EQ(exception_for(Reject::in_alarm), 4);
  EXPECT_EQ(exception_for(Reject::busy), 6);
  EXPECT_STREQ(to_string(static_cast<Reject>(999)), "unknown");
}
