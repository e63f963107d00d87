// The controller behind its Modbus TCP server, over real sockets on
// 127.0.0.1 (ports chosen by the system), driven by the real sender and by
// a raw libmodbus client: drip feed, dropped connections, duplicated and
// out-of-order chunks, a second sender, a slow controller, writes outside
// the map, a malformed line, the CRC-32 confirmation, and abuse (idle
// connections, half frames, more connections than the cap).
#include "bezcam/sim/sim_server.hpp"

#include <arpa/inet.h>
#include <atomic>
#include <future>
#include <gtest/gtest.h>
#include <mutex>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "bezcam/error.hpp"
#include "bezcam/link/crc32.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/link/transport.hpp"
#include "support/link_test_util.hpp"
#include "support/server_rig.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;
using namespace std::chrono_literals;

namespace {

using Rig = test::ServerRig;
using test::read_status;

StreamOptions quick() { return test::quick_stream(2000ms, 10s); }

}  // namespace

TEST(SimServer, AProgramFarLargerThanTheBufferIsDripFed) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 512;
  Rig rig(cfg);
  const std::string program = test::zigzag_program(6000);  // ~120 KB, 240 times the buffer
  ASSERT_GT(program.size(), 200u * 512u);
  auto opt = quick();
  std::uint64_t last = 0;
  opt.on_progress = [&](const StreamProgress& p) {
    EXPECT_LE(p.bytes_acked, p.bytes_total);
    EXPECT_GE(p.bytes_acked, last);  // acknowledgements only move forward
    last = p.bytes_acked;
  };
  const StreamResult r = stream_program(program, rig.ep(), opt);
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(r.bytes, program.size());
  const auto expected = test::split_lines(program);
  EXPECT_EQ(r.lines_executed, expected.size());
  EXPECT_EQ(rig.executed(), expected);  // every line once, in order, byte for byte
  const Status s = rig.ctl->status();
  EXPECT_EQ(s.state, State::done);
  EXPECT_EQ(s.rejects, 0u);  // the sender never overran the buffer
  EXPECT_EQ(s.duplicates, 0u);
  EXPECT_GE(r.chunks, program.size() / kMaxChunkBytes);
}

TEST(SimServer, DroppedConnectionsResumeFromTheAcknowledgedPosition) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 1024;
  // Six drops: three before the chunk is applied (the sender must resend
  // it), three after (the acknowledgement is lost; it must not resend it).
  cfg.drop_before_chunk = {3, 17, 40};
  cfg.drop_after_chunk = {8, 25, 41};
  Rig rig(cfg);
  const std::string program = test::zigzag_program(800);
  std::vector<std::string> events;
  auto opt = quick();
  opt.on_event = [&](const std::string& e) { events.push_back(e); };
  const StreamResult r = stream_program(program, rig.ep(), opt);
  EXPECT_EQ(r.reconnects, 6);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
  const Status s = rig.ctl->status();
  EXPECT_EQ(s.state, State::done);
  EXPECT_EQ(s.program_crc, crc32(program));
  EXPECT_EQ(s.duplicates, 0u);  // resumed from the controller's position, not the sender's guess
  int resumed = 0;
  for (const auto& e : events) resumed += e.rfind("reconnected; resuming at byte", 0) == 0;
  EXPECT_EQ(resumed, 6);
}

TEST(SimServer, ASecondSenderIsRefusedWhileReadersPoll) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 256;
  cfg.exec_delay = 1ms;  // keeps the first transfer busy
  Rig rig(cfg);
  const std::string program = test::zigzag_program(300);
  std::promise<void> opened;
  std::atomic<bool> signalled{false};
  auto opt = quick();
  opt.on_event = [&](const std::string& e) {
    if (e.rfind("transfer opened", 0) == 0 && !signalled.exchange(true)) opened.set_value();
  };
  auto first = std::async(std::launch::async, [&] { return stream_program(program, rig.ep(), opt); });
  opened.get_future().wait();
  // A second sender: refused, clearly, with exit status 4 (ControllerError).
  try {
    stream_program("G21\nG00 X1.\n", rig.ep(), quick());
    ADD_FAILURE() << "the second sender was not refused";
  } catch (const ControllerError& e) {
    EXPECT_EQ(e.id(), "link.busy");
    EXPECT_NE(std::string(e.what()).find("busy with another sender"), std::string::npos) << e.what();
  }
  // Readers poll holding and input registers meanwhile.
  ModbusClient reader(rig.ep(), 2000ms);
  std::uint32_t last_ack = 0;
  for (int i = 0; i < 50; ++i) {
    const Status s = read_status(reader);
    EXPECT_EQ(s.magic, kMagic);
    EXPECT_GE(s.ack_bytes, last_ack);
    last_ack = s.ack_bytes;
    std::array<std::uint16_t, 8> in{};
    reader.read_input(0, in);
    EXPECT_EQ(in[0], kMagic);
  }
  const StreamResult r = first.get();
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(rig.executed(), test::split_lines(program));  // the refused sender left no trace in the program
}

TEST(SimServer, ASlowControllerIsWaitedForWithoutOverrun) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 256;
  cfg.exec_delay = 2ms;
  Rig rig(cfg);
  const std::string program = test::zigzag_program(150);
  bool waited = false;
  auto opt = quick();
  opt.on_progress = [&](const StreamProgress& p) { waited = waited || p.waiting; };
  const StreamResult r = stream_program(program, rig.ep(), opt);
  EXPECT_TRUE(waited);
  EXPECT_EQ(r.lines_executed, test::split_lines(program).size());
  EXPECT_EQ(rig.ctl->status().rejects, 0u);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
}

TEST(SimServer, ASenderThatStallsTooLongGivesUpClearly) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 256;
  cfg.exec_delay = 400ms;  // far slower than the sender will wait
  Rig rig(cfg);
  auto opt = quick();
  opt.stall_timeout = 300ms;
  try {
    stream_program(test::zigzag_program(40), rig.ep(), opt);
    ADD_FAILURE() << "no stall reported";
  } catch (const ControllerError& e) {
    EXPECT_EQ(e.id(), "link.stalled");
  }
}

TEST(SimServer, DuplicatedAndOutOfOrderChunksOverTheWire) {
  ControllerConfig cfg;
  Rig rig(cfg);
  ModbusClient c(rig.ep(), 2000ms);
  const std::string program = "G21 G90 G17\nG00 X1. Y1. Z5.\nG01 Z-1. F300.\nX2.\nY2.\nM30\n";
  const std::string p1 = program.substr(0, 25), p2 = program.substr(25, 20), p3 = program.substr(45);
  c.write_registers(reg::command, encode_command(Command::open, std::array<std::uint32_t, 2>{42, 0}));
  const std::uint32_t s = read_status(c).session;
  c.write_registers(reg::chunk, encode_chunk({s, 1, p1}));
  c.write_registers(reg::chunk, encode_chunk({s, 1, p1}));  // duplicate: acknowledged
  try {
    c.write_registers(reg::chunk, encode_chunk({s, 3, p3}));  // gap
    ADD_FAILURE() << "gap accepted";
  } catch (const ModbusException& e) {
    EXPECT_EQ(e.code(), 3);
  }
  EXPECT_EQ(read_status(c).last_reject, Reject::seq_gap);
  c.write_registers(reg::chunk, encode_chunk({s, 2, p2}));
  c.write_registers(reg::chunk, encode_chunk({s, 3, p3}));
  c.write_registers(reg::chunk, encode_chunk({s, 2, p2}));  // late duplicate
  c.write_registers(
      reg::command,
      encode_command(Command::commit,
                     std::array<std::uint32_t, 4>{42, s, static_cast<std::uint32_t>(program.size()), crc32(program)}));
  ASSERT_TRUE(rig.ctl->wait_final(5s));
  const Status st = read_status(c);
  EXPECT_EQ(st.state, State::done);
  EXPECT_EQ(st.duplicates, 2u);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
}

TEST(SimServer, WritesOutsideTheMapGetModbusExceptions) {
  ControllerConfig cfg;
  Rig rig(cfg);
  ModbusClient c(rig.ep(), 2000ms);
  auto code_of = [](auto&& f) {
    try {
      f();
    } catch (const ModbusException& e) {
      return e.code();
    }
    return 0;
  };
  EXPECT_EQ(code_of([&] { c.write_register(0, 1); }), 2);
  EXPECT_EQ(code_of([&] { c.write_register(0x0300, 1); }), 2);
  EXPECT_EQ(code_of([&] { c.write_registers(0x0150, std::vector<std::uint16_t>{1, 2}); }), 2);
  std::array<std::uint16_t, 4> r{};
  EXPECT_EQ(code_of([&] { c.read_holding(reg::chunk, r); }), 2);
  EXPECT_EQ(code_of([&] { c.read_input(0x1000, r); }), 2);
  // The connection survives every refusal.
  EXPECT_EQ(read_status(c).magic, kMagic);
  EXPECT_EQ(read_status(c).state, State::idle);
}

TEST(SimServer, AMalformedLineIsReportedByTheSenderWithItsLineNumber) {
  ControllerConfig cfg;
  Rig rig(cfg);
  std::string program = test::zigzag_program(50);
  // Line 30 becomes nonsense.
  auto lines = test::split_lines(program);
  lines[29] = "G01 X1. Y#2";
  program.clear();
  for (const auto& l : lines) program += l + "\n";
  try {
    stream_program(program, rig.ep(), quick());
    ADD_FAILURE() << "no alarm";
  } catch (const ControllerError& e) {
    EXPECT_EQ(e.id(), "controller.alarm");
    EXPECT_EQ(e.where(), "line 30");
    // The line arrives as a number, not as text to parse.
    EXPECT_EQ(e.place().line, 30);
    EXPECT_EQ(e.message().find("line 30"), std::string::npos) << e.message();
    EXPECT_NE(std::string(e.what()).find("alarm gcode (1)"), std::string::npos) << e.what();
  }
  const auto done = rig.executed();
  ASSERT_EQ(done.size(), 30u);
  EXPECT_EQ(done.back(), "G01 X1. Y#2");
}

TEST(SimServer, SuccessOnlyWhenTheControllerConfirmsTheCrc) {
  ControllerConfig cfg;
  cfg.corrupt_chunk = {4};  // acknowledged, but stored wrong
  Rig rig(cfg);
  const std::string program = test::zigzag_program(60);
  try {
    stream_program(program, rig.ep(), quick());
    ADD_FAILURE() << "a corrupted program was reported as sent";
  } catch (const ControllerError& e) {
    EXPECT_EQ(e.id(), "controller.alarm");
    EXPECT_NE(std::string(e.what()).find("crc-mismatch"), std::string::npos) << e.what();
  }
  EXPECT_EQ(rig.ctl->status().alarm, Alarm::crc_mismatch);
  EXPECT_NE(rig.ctl->status().state, State::done);
}

TEST(SimServer, StaysResponsiveUnderIdleConnectionsHalfFramesAndTheCap) {
  ControllerConfig cfg;
  ServerConfig scfg;
  scfg.max_connections = 4;
  scfg.idle_timeout = 2000ms;
  scfg.frame_timeout = 200ms;
  Rig rig(cfg, scfg);
  auto raw = [&] { return rig.raw(); };
  std::vector<int> fds;
  for (int i = 0; i < 10; ++i) fds.push_back(raw());  // open and never speak
  for (int i = 0; i < 3; ++i) {                       // half a frame, then nothing
    const int fd = raw();
    const unsigned char half[] = {0, 1, 0, 0, 0, 6, 1, 3, 0};
    EXPECT_EQ(::send(fd, half, sizeof half, 0), static_cast<ssize_t>(sizeof half));
    fds.push_back(fd);
  }
  const std::string program = test::zigzag_program(200);
  const StreamResult r = stream_program(program, rig.ep(), quick());
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(rig.executed(), test::split_lines(program));
  ModbusClient c(rig.ep(), 2000ms);
  EXPECT_LE(read_status(c).connections, 4);
  for (int fd : fds) ::close(fd);
}
