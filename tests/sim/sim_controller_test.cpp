// The simulated controller's protocol state machine, in process: raw
// Modbus TCP frames as the server hands them over (no socket), run_program,
// the receive buffer, alarms that name their line. The same class is
// exercised over real sockets in sim_server_test.cpp and streamer_test.cpp.
#include "bezcam/sim/sim_controller.hpp"

#include <gtest/gtest.h>
#include <mutex>
#include <random>
#include <set>

#include "bezcam/error.hpp"
#include "bezcam/link/crc32.hpp"
#include "bezcam/sim/trace.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;
using namespace std::chrono_literals;

namespace {

MachineProfile generic() { return load_machine_profile("generic"); }

// A client speaking raw frames to handle_frame(), as one connection.
struct Local {
  SimController& c;
  ConnId id;
  std::uint16_t tid = 0;
  explicit Local(SimController& ctl) : c(ctl), id(ctl.connection_opened()) {}

  FrameReply raw(std::uint8_t fc, const std::vector<std::uint8_t>& data) {
    std::vector<std::uint8_t> f;
    ++tid;
    const std::size_t len = 2 + data.size();
    f = {static_cast<std::uint8_t>(tid >> 8), static_cast<std::uint8_t>(tid), 0, 0,
         static_cast<std::uint8_t>(len >> 8), static_cast<std::uint8_t>(len), 1, fc};
    f.insert(f.end(), data.begin(), data.end());
    return c.handle_frame(id, f);
  }
  static void put16(std::vector<std::uint8_t>& d, std::uint16_t v) {
    d.push_back(static_cast<std::uint8_t>(v >> 8));
    d.push_back(static_cast<std::uint8_t>(v));
  }
  FrameReply read(std::uint16_t addr, std::uint16_t n, bool input = false) {
    std::vector<std::uint8_t> d;
    put16(d, addr);
    put16(d, n);
    return raw(input ? 4 : 3, d);
  }
  FrameReply write(std::uint16_t addr, const std::vector<std::uint16_t>& regs) {
    std::vector<std::uint8_t> d;
    put16(d, addr);
    put16(d, static_cast<std::uint16_t>(regs.size()));
    d.push_back(static_cast<std::uint8_t>(2 * regs.size()));
    for (auto r : regs) put16(d, r);
    return raw(16, d);
  }
  FrameReply write_read(std::uint16_t waddr, const std::vector<std::uint16_t>& regs, std::uint16_t raddr = 0,
                        std::uint16_t rn = reg::status_count) {
    std::vector<std::uint8_t> d;
    put16(d, raddr);
    put16(d, rn);
    put16(d, waddr);
    put16(d, static_cast<std::uint16_t>(regs.size()));
    d.push_back(static_cast<std::uint8_t>(2 * regs.size()));
    for (auto r : regs) put16(d, r);
    return raw(23, d);
  }
  Status status() {
    const auto r = read(0, reg::status_count);
    EXPECT_EQ(r.exception, 0);
    return Status::decode(r.regs);
  }
  std::string alarm_text() {
    const auto r = read(reg::alarm_text, reg::alarm_text_count);
    return unpack_text(r.regs, 128, true);
  }
  FrameReply open(std::uint32_t token, std::uint32_t total = 0) {
    return write(reg::command, encode_command(Command::open, std::array<std::uint32_t, 2>{token, total}));
  }
  FrameReply chunk(std::uint32_t session, std::uint32_t seq, std::string_view payload) {
    return write(reg::chunk, encode_chunk({session, seq, payload}));
  }
  FrameReply commit(std::uint32_t token, std::uint32_t session, std::string_view program) {
    return write(reg::command,
                 encode_command(Command::commit,
                                std::array<std::uint32_t, 4>{token, session, static_cast<std::uint32_t>(program.size()),
                                                             crc32(program)}));
  }
};

// Collects what the controller executes and traces (thread-safe).
struct Recorder {
  std::mutex m;
  std::vector<std::string> lines;
  std::vector<long> numbers;
  std::string trace;
  void attach(ControllerConfig& cfg) {
    cfg.on_line = [this](long n, std::string_view t) {
      std::lock_guard lk(m);
      numbers.push_back(n);
      lines.emplace_back(t);
    };
    cfg.trace = [this](std::string_view t, bool restart) {
      std::lock_guard lk(m);
      if (restart) trace.clear();
      trace += t;
    };
  }
};

}  // namespace

TEST(SimController, StatusIdentifiesTheProtocolOnHoldingAndInputRegisters) {
  ControllerConfig cfg;
  cfg.profile = generic();
  SimController ctl(cfg);
  Local a(ctl);
  const auto hold = a.read(0, reg::readable_end - 64);
  const auto in = a.read(0, reg::readable_end - 64, true);
  ASSERT_EQ(hold.exception, 0);
  ASSERT_EQ(in.exception, 0);
  EXPECT_TRUE(in.read_input);
  EXPECT_EQ(hold.regs, in.regs);
  const Status s = Status::decode(hold.regs);
  EXPECT_EQ(s.magic, 0x425A);
  EXPECT_EQ(s.version, kProtocolVersion);
  EXPECT_EQ(s.buffer_capacity, 4096);
  EXPECT_EQ(s.buffer_free, 4096);
  EXPECT_EQ(s.max_chunk, kMaxChunkBytes);
  EXPECT_EQ(s.state, State::idle);
  EXPECT_EQ(s.session, 0u);
  EXPECT_EQ(s.connections, 1);
  const auto name = a.read(reg::machine_name, reg::machine_name_count);
  EXPECT_EQ(unpack_text(name.regs, 32, true), "generic");
}

TEST(SimController, RequestsOutsideTheMapGetModbusExceptionsAndAReason) {
  ControllerConfig cfg;
  cfg.profile = generic();
  SimController ctl(cfg);
  Local a(ctl);
  auto reason = [&] { return a.status().last_reject; };
  EXPECT_EQ(a.read(reg::readable_end - 4, 5).exception, 2);  // crosses the end of the readable registers
  EXPECT_EQ(reason(), Reject::bad_address);
  EXPECT_EQ(a.read(reg::command, 1).exception, 2);  // the command block is write-only
  EXPECT_EQ(a.read(0, 126).exception, 3);           // more than FC 03 allows
  EXPECT_EQ(reason(), Reject::bad_count);
  EXPECT_EQ(a.write(0, {1}).exception, 2);  // status is read-only
  EXPECT_EQ(reason(), Reject::read_only);
  EXPECT_EQ(a.write(reg::alarm_text + 3, {1, 2}).exception, 2);
  EXPECT_EQ(a.write(0x150, {1}).exception, 2);  // a hole in the map
  EXPECT_EQ(reason(), Reject::bad_address);
  EXPECT_EQ(a.write(reg::chunk + 1, {1, 2, 3}).exception, 2);  // chunks are written from the window's start
  EXPECT_EQ(a.write(0xFFFF, {1}).exception, 2);
  EXPECT_EQ(a.raw(1, {0, 0, 0, 8}).exception, 1);  // read coils: not a function of this map
  EXPECT_EQ(reason(), Reject::bad_function);
  EXPECT_EQ(a.raw(43, {14, 1, 0}).exception, 1);  // device identification
  // FC 16 whose byte count contradicts its register count.
  EXPECT_EQ(a.raw(16, {0x01, 0x00, 0x00, 0x02, 0x02, 0x00, 0x05}).exception, 3);
  EXPECT_EQ(reason(), Reject::bad_count);
  EXPECT_EQ(a.write(reg::command, {99}).exception, 3);  // unknown command
  EXPECT_EQ(reason(), Reject::bad_command);
  EXPECT_EQ(a.write(reg::command, {1, 0, 5}).exception, 3);  // OPEN with too few registers
  // A FC 06 may only RESET.
  EXPECT_EQ(a.raw(6, {0x00, 0x06, 0x00, 0x01}).exception, 2);
  EXPECT_EQ(a.raw(6, {0x01, 0x00, 0x00, 0x01}).exception, 3);
  EXPECT_EQ(a.raw(6, {0x01, 0x00, 0x00, 0x05}).exception, 0);
  EXPECT_EQ(reason(), Reject::none);  // cleared by the successful write
  const Status s = a.status();
  EXPECT_EQ(s.state, State::idle);
  EXPECT_GE(s.rejects, 13u);
  // A frame whose MBAP header contradicts its length is not answered at all.
  EXPECT_TRUE(ctl.handle_frame(a.id, std::vector<std::uint8_t>{0, 1, 0, 0, 0, 9, 1, 3, 0, 0, 0, 1}).drop);
  EXPECT_TRUE(ctl.handle_frame(a.id, std::vector<std::uint8_t>{0, 1, 0, 7, 0, 6, 1, 3, 0, 0, 0, 1}).drop);
}

TEST(SimController, SequenceNumbersAcknowledgeDuplicatesAndRefuseGaps) {
  ControllerConfig cfg;
  cfg.profile = generic();
  cfg.first_session = 0x1000;
  Recorder rec;
  rec.attach(cfg);
  SimController ctl(cfg);
  Local a(ctl), b(ctl);
  const std::string program = "G21 G90 G17\nG00 X1. Y1. Z5.\nG01 Z-1. F300.\nX2.\nY2.\nM30\n";
  ASSERT_EQ(a.open(0x77, static_cast<std::uint32_t>(program.size())).exception, 0);
  const Status s0 = a.status();
  EXPECT_EQ(s0.state, State::receiving);
  EXPECT_EQ(s0.session, 0x1000u);
  const std::uint32_t sess = s0.session;
  const std::string c1 = program.substr(0, 20), c2 = program.substr(20, 15), c3 = program.substr(35);
  // In order, with the acknowledgement read back in the same FC 23 transaction.
  const auto r1 = a.write_read(reg::chunk, encode_chunk({sess, 1, c1}));
  ASSERT_EQ(r1.exception, 0);
  EXPECT_EQ(Status::decode(r1.regs).ack_seq, 1u);
  EXPECT_EQ(Status::decode(r1.regs).ack_bytes, 20u);
  // Duplicate: acknowledged again, not applied.
  EXPECT_EQ(a.chunk(sess, 1, c1).exception, 0);
  Status s = a.status();
  EXPECT_EQ(s.ack_bytes, 20u);
  EXPECT_EQ(s.duplicates, 1u);
  // A "duplicate" that differs from what was applied under that number.
  EXPECT_EQ(a.chunk(sess, 1, "G01 X9.\n").exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::dup_mismatch);
  // A gap: chunk 3 before chunk 2.
  EXPECT_EQ(a.chunk(sess, 3, c3).exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::seq_gap);
  EXPECT_EQ(a.status().ack_bytes, 20u);
  // A corrupted chunk: its CRC does not match.
  auto bad = encode_chunk({sess, 2, c2});
  bad.back() ^= 0x0100;
  EXPECT_EQ(a.write(reg::chunk, bad).exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::bad_chunk_crc);
  // A length that does not match the registers written.
  auto shortlen = encode_chunk({sess, 2, c2});
  shortlen[4] = 40;
  EXPECT_EQ(a.write(reg::chunk, shortlen).exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::bad_length);
  // NUL bytes are not G-code.
  EXPECT_EQ(a.chunk(sess, 2, std::string("X1\0\n", 4)).exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::nul_byte);
  // Wrong session.
  EXPECT_EQ(a.chunk(sess + 1, 2, c2).exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::bad_session);
  // Another connection: may read, may not write chunks or open.
  EXPECT_EQ(b.chunk(sess, 2, c2).exception, 6);
  EXPECT_EQ(b.status().last_reject, Reject::not_owner);
  EXPECT_EQ(b.open(0x99).exception, 6);
  EXPECT_EQ(b.status().last_reject, Reject::busy);
  EXPECT_EQ(b.status().session, sess);
  // Now in order again.
  EXPECT_EQ(a.chunk(sess, 2, c2).exception, 0);
  EXPECT_EQ(a.chunk(sess, 3, c3).exception, 0);
  EXPECT_EQ(a.chunk(sess, 3, c3).exception, 0);  // duplicate of the last one
  ASSERT_EQ(a.commit(0x77, sess, program).exception, 0);
  ASSERT_TRUE(ctl.wait_final(5s));
  s = a.status();
  EXPECT_EQ(s.state, State::done);
  EXPECT_EQ(s.ack_bytes, program.size());
  EXPECT_EQ(s.program_crc, crc32(program));
  EXPECT_EQ(s.duplicates, 2u);
  EXPECT_EQ(s.lines_executed, 6u);
  EXPECT_EQ(s.blocks_executed, 4u);
  EXPECT_EQ(s.pos[0], 2000);
  EXPECT_EQ(s.pos[1], 2000);
  EXPECT_EQ(s.pos[2], -1000);
  std::lock_guard lk(rec.m);
  EXPECT_EQ(rec.lines, test::split_lines(program));  // each line once, in order
  EXPECT_EQ(rec.numbers, (std::vector<long>{1, 2, 3, 4, 5, 6}));
  EXPECT_NE(rec.trace.find("done lines 6 blocks 4 at 2.000000 2.000000 -1.000000\n"), std::string::npos) << rec.trace;
}

TEST(SimController, CommitConfirmsLengthAndCrcOrRaisesAnAlarm) {
  ControllerConfig cfg;
  cfg.profile = generic();
  SimController ctl(cfg);
  Local a(ctl);
  const std::string program = "G21 G90\nG00 X1. Y1. Z1.\n";
  ASSERT_EQ(a.open(5).exception, 0);
  const auto sess = a.status().session;
  ASSERT_EQ(a.chunk(sess, 1, program).exception, 0);
  // COMMIT with someone else's token is refused and changes nothing.
  EXPECT_EQ(a.commit(6, sess, program).exception, 3);
  EXPECT_EQ(a.status().last_reject, Reject::bad_token);
  EXPECT_EQ(a.status().state, State::receiving);
  // A CRC that differs: the program is stopped, never reported done.
  EXPECT_EQ(a.commit(5, sess, "G21 G90\nG00 X1. Y1. Z2.\n").exception, 4);
  ASSERT_TRUE(ctl.wait_final(5s));
  const Status s = a.status();
  EXPECT_EQ(s.state, State::alarm);
  EXPECT_EQ(s.alarm, Alarm::crc_mismatch);
  EXPECT_NE(a.alarm_text().find("CRC-32 of the received program is"), std::string::npos) << a.alarm_text();
  // Chunks and COMMIT are refused in alarm; a new OPEN starts afresh.
  EXPECT_EQ(a.chunk(sess, 2, "X1.\n").exception, 4);
  EXPECT_EQ(a.status().last_reject, Reject::in_alarm);
  ASSERT_EQ(a.open(8).exception, 0);
  const auto sess2 = a.status().session;
  EXPECT_NE(sess2, sess);
  ASSERT_EQ(a.chunk(sess2, 1, program).exception, 0);
  // A length that differs.
  EXPECT_EQ(a.commit(8, sess2, program + "X2.\n").exception, 4);
  ASSERT_TRUE(ctl.wait_final(5s));
  EXPECT_EQ(a.status().alarm, Alarm::length_mismatch);
}

TEST(SimController, RunProgramDripFeedsAProgramFarLargerThanTheBuffer) {
  ControllerConfig cfg;
  cfg.profile = generic();
  cfg.buffer_bytes = kMinBuffer;  // 228 bytes
  Recorder rec;
  rec.attach(cfg);
  SimController ctl(cfg);
  const std::string program = test::zigzag_program(3000);
  ASSERT_GT(program.size(), 200 * cfg.buffer_bytes);
  const Status s = ctl.run_program(program);
  EXPECT_EQ(s.state, State::done) << ctl.alarm_text();
  EXPECT_EQ(s.program_crc, crc32(program));
  std::lock_guard lk(rec.m);
  const auto expected = test::split_lines(program);
  EXPECT_EQ(rec.lines, expected);
  EXPECT_EQ(s.lines_executed, expected.size());
  EXPECT_EQ(rec.trace.rfind("bezcam-trace 1 machine generic\n", 0), 0u);
  EXPECT_NE(rec.trace.find("\ndone lines " + std::to_string(expected.size()) + " blocks "), std::string::npos);
}

TEST(SimController, AMalformedLineRaisesAnAlarmNamingItsLine) {
  ControllerConfig cfg;
  cfg.profile = generic();
  Recorder rec;
  rec.attach(cfg);
  SimController ctl(cfg);
  const std::string program = "G21 G90 G17\nG00 X1. Y1. Z5.\nG01 X2. F100.\nG01 X3. Y&7\nX4.\nM30\n";
  const Status s = ctl.run_program(program);
  EXPECT_EQ(s.state, State::alarm);
  EXPECT_EQ(s.alarm, Alarm::gcode);
  EXPECT_EQ(s.alarm_line, 4u);
  EXPECT_EQ(ctl.alarm_text().rfind("line 4: ", 0), 0u) << ctl.alarm_text();
  // The message and its line are kept apart; only the text for people joins them.
  EXPECT_EQ(ctl.alarm_text(), "line 4: " + ctl.alarm_message());
  EXPECT_EQ(ctl.alarm_message().find("line 4"), std::string::npos) << ctl.alarm_message();
  std::lock_guard lk(rec.m);
  // Lines after the refused one are never executed.
  EXPECT_EQ(rec.numbers, (std::vector<long>{1, 2, 3, 4}));
  EXPECT_NE(rec.trace.find("alarm line 4 gcode gcode."), std::string::npos) << rec.trace;
  EXPECT_EQ(rec.trace.find("done"), std::string::npos);
}

TEST(SimController, TravelLimitsOfTheProfileAreEnforced) {
  ControllerConfig cfg;
  cfg.profile = load_machine_profile("unisurf");  // 1500 x 1200 x 800 mm
  SimController ctl(cfg);
  const Status s = ctl.run_program("G21 G90 G17\nG00 Z5.\nG00 X10. Y10.\nG01 X1600. F100.\nM30\n");
  EXPECT_EQ(s.state, State::alarm);
  EXPECT_EQ(s.alarm, Alarm::travel_limit) << ctl.alarm_text();
  EXPECT_EQ(s.alarm_line, 4u);
}

TEST(SimController, AFeedAboveTheMachinesIsTheFeedLimitAlarm) {
  // The alarm code comes from the error id (gcode.feed-limit), and a
  // negative feed (gcode.feed) is a plain G-code alarm.
  ControllerConfig cfg;
  cfg.profile = load_machine_profile("unisurf");  // 2000 mm/min at most
  SimController ctl(cfg);
  Status s = ctl.run_program("G21 G90 G17\nG00 Z5.\nG00 X10. Y10.\nG01 X20. F3000.\nM30\n");
  EXPECT_EQ(s.alarm, Alarm::feed_limit) << ctl.alarm_text();
  EXPECT_EQ(s.alarm_line, 4u);
  SimController neg(cfg);
  s = neg.run_program("G21 G90 G17\nG00 Z5.\nG01 X20. F-3.\nM30\n");
  EXPECT_EQ(s.alarm, Alarm::gcode) << neg.alarm_text();
}

TEST(SimController, ALineLongerThanTheBufferIsRefusedNotHung) {
  ControllerConfig cfg;
  cfg.profile = generic();
  cfg.buffer_bytes = 256;
  SimController ctl(cfg);
  const std::string program = "G21 G90\n(" + std::string(400, 'x') + ")\nG00 X1.\n";
  const Status s = ctl.run_program(program);
  EXPECT_EQ(s.state, State::alarm);
  EXPECT_EQ(s.alarm, Alarm::line_too_long);
  EXPECT_EQ(s.alarm_line, 2u);
}

TEST(SimController, ASilentOwnerLosesTheTransferAfterTheSessionTimeout) {
  ControllerConfig cfg;
  cfg.profile = generic();
  cfg.session_timeout = 150ms;
  SimController ctl(cfg);
  Local a(ctl);
  ASSERT_EQ(a.open(1).exception, 0);
  const auto sess = a.status().session;
  ASSERT_EQ(a.chunk(sess, 1, "G21 G90\nG00 X1.\n").exception, 0);
  ctl.connection_closed(a.id);
  ASSERT_TRUE(ctl.wait_final(5s));
  const Status s = ctl.status();
  EXPECT_EQ(s.state, State::alarm);
  EXPECT_EQ(s.alarm, Alarm::sender_lost);
  EXPECT_EQ(s.lines_executed, 2u);
}

TEST(SimController, ResumeNeedsTheOwnersTokenAndTheSession) {
  ControllerConfig cfg;
  cfg.profile = generic();
  SimController ctl(cfg);
  Local a(ctl), b(ctl);
  ASSERT_EQ(a.open(0xABCD).exception, 0);
  const auto sess = a.status().session;
  auto resume = [&](Local& l, std::uint32_t token, std::uint32_t s) {
    return l.write(reg::command, encode_command(Command::resume, std::array<std::uint32_t, 2>{token, s})).exception;
  };
  EXPECT_EQ(resume(b, 0xABCE, sess), 3);
  EXPECT_EQ(b.status().last_reject, Reject::bad_token);
  EXPECT_EQ(resume(b, 0xABCD, sess + 1), 3);
  EXPECT_EQ(b.status().last_reject, Reject::bad_session);
  EXPECT_EQ(ctl.owner(), a.id);
  EXPECT_EQ(resume(b, 0xABCD, sess), 0);  // the sender came back on a new connection
  EXPECT_EQ(ctl.owner(), b.id);
  EXPECT_EQ(a.chunk(sess, 1, "G21\n").exception, 6);  // the old connection is no longer the owner
  EXPECT_EQ(b.chunk(sess, 1, "G21\n").exception, 0);
  // ABORT stops the program with an alarm; RESET then clears it.
  EXPECT_EQ(b.write(reg::command, encode_command(Command::abort, std::array<std::uint32_t, 2>{0xABCD, sess})).exception,
            0);
  ASSERT_TRUE(ctl.wait_final(5s));
  EXPECT_EQ(b.status().alarm, Alarm::aborted);
  EXPECT_EQ(b.write(reg::command, {5}).exception, 0);
  EXPECT_EQ(b.status().state, State::idle);
  EXPECT_EQ(b.status().session, 0u);
}

TEST(SimController, SessionIdsAreRandomPerController) {
  // A restarted controller must not reuse the session id of the transfer it
  // lost; with random ids, two controllers practically never agree.
  std::set<std::uint32_t> seen;
  for (int i = 0; i < 8; ++i) {
    ControllerConfig cfg;
    cfg.profile = generic();
    SimController ctl(cfg);
    Local a(ctl);
    ASSERT_EQ(a.open(1).exception, 0);
    const auto s = a.status().session;
    EXPECT_NE(s, 0u);
    seen.insert(s);
  }
  EXPECT_EQ(seen.size(), 8u);
}

TEST(SimController, ArbitraryFramesNeverCrashOrCorruptTheProgram) {
  ControllerConfig cfg;
  cfg.profile = generic();
  Recorder rec;
  rec.attach(cfg);
  SimController ctl(cfg);
  Local a(ctl), noise(ctl);
  const std::string program = test::zigzag_program(40);
  ASSERT_EQ(a.open(3, static_cast<std::uint32_t>(program.size())).exception, 0);
  const auto sess = a.status().session;
  std::mt19937 rng(2024);
  std::uint32_t seq = 0;
  std::size_t off = 0;
  for (int round = 0; off < program.size(); ++round) {
    // Garbage from another connection: random function codes, addresses,
    // lengths and bytes, some of them aimed at the chunk window.
    for (int k = 0; k < 20; ++k) {
      std::vector<std::uint8_t> f(8 + rng() % 250);
      for (auto& b : f) b = static_cast<std::uint8_t>(rng());
      f[2] = f[3] = 0;
      f[4] = static_cast<std::uint8_t>((f.size() - 6) >> 8);
      f[5] = static_cast<std::uint8_t>(f.size() - 6);
      if (k % 3 == 0) f[7] = 16, f[8] = 0x02, f[9] = 0x00;
      const auto r = ctl.handle_frame(noise.id, f);
      EXPECT_TRUE(r.drop || r.exception != 0 || !r.regs.empty() || f[7] == 6 || f[7] == 16) << int(f[7]);
    }
    const std::size_t n = std::min<std::size_t>(100, program.size() - off);
    ASSERT_EQ(a.chunk(sess, ++seq, std::string_view(program).substr(off, n)).exception, 0) << "round " << round;
    off += n;
  }
  ASSERT_EQ(a.commit(3, sess, program).exception, 0);
  ASSERT_TRUE(ctl.wait_final(5s));
  EXPECT_EQ(a.status().state, State::done);
  std::lock_guard lk(rec.m);
  EXPECT_EQ(rec.lines, test::split_lines(program));
}

TEST(SimController, RejectsBadConfiguration) {
  ControllerConfig cfg;
  cfg.profile = generic();
  cfg.buffer_bytes = 100;
  EXPECT_THROW(SimController{cfg}, InputError);
  cfg.buffer_bytes = 70000;
  EXPECT_THROW(SimController{cfg}, InputError);
}
