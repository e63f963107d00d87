// A sender that can stop, and a controller anyone can ask (issue "Safe on
// the shop floor", bugs 3 and 4): Ctrl-C aborts the transfer and says what
// was done; `stream --abort` stops a transfer whose sender is gone;
// `status` prints state, machine and buffer; a program the controller's
// profile would refuse mid-cut is refused before anything is sent. Real
// processes: the simulated controller and the sender are both `bezcam`.
#include <chrono>
#include <csignal>
#include <gtest/gtest.h>
#include <thread>

#include "bezcam/link/register_map.hpp"
#include "bezcam/link/transport.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace std::chrono_literals;

namespace {

Status status_of(std::uint16_t port) {
  ModbusClient c({"127.0.0.1", port}, 2000ms);
  std::array<std::uint16_t, reg::status_count> r{};
  c.read_holding(0, r);
  return Status::decode(r);
}

// Polls the controller until `done` holds (no sleeping on a guess: the
// state is read, at most every 5 ms, up to the deadline).
template <class F>
Status wait_for(std::uint16_t port, F done, std::chrono::seconds limit = 20s) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  Status s = status_of(port);
  while (!done(s) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(5ms);
    s = status_of(port);
  }
  return s;
}

std::filesystem::path write_program(const test::TempDir& dir, const std::string& text) {
  test::write_file(dir / "p.nc", text);
  return dir / "p.nc";
}

}  // namespace

TEST(StopAndStatus, CtrlCAbortsTheTransferAndSaysWhatWasDone) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "512", "--exec-delay-ms", "5"});
  const auto prog = write_program(dir, test::zigzag_program(400));
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  test::Child sender({BEZCAM_EXE, "stream", prog.string(), "--to", to, "--progress", "off"}, dir / "stream.err");
  // Cutting: lines executed and the spindle on.
  const Status cutting = wait_for(sim.port(), [](const Status& s) { return s.lines_executed > 20; });
  ASSERT_GT(cutting.lines_executed, 20u);
  EXPECT_TRUE(cutting.flags & flag::spindle_on);
  sender.signal(SIGINT);
  EXPECT_EQ(sender.wait(), 130) << sender.stderr_text();
  const std::string err = sender.stderr_text();
  EXPECT_NE(err.find("interrupted: sent ABORT"), std::string::npos) << err;
  EXPECT_NE(err.find("bytes acknowledged"), std::string::npos) << err;
  EXPECT_NE(err.find("lines executed"), std::string::npos) << err;
  // The controller stopped at once: alarm "aborted", spindle off; it does
  // not wait for the session timeout.
  const Status after = status_of(sim.port());
  EXPECT_EQ(after.state, State::alarm);
  EXPECT_EQ(after.alarm, Alarm::aborted);
  EXPECT_FALSE(after.flags & flag::spindle_on);
  EXPECT_LT(after.lines_executed, 400u);
  EXPECT_EQ(sim.stop(), 0);
}

TEST(StopAndStatus, AbortStopsATransferWhoseSenderIsGone) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "512", "--exec-delay-ms", "5", "--session-timeout", "60"});
  const auto prog = write_program(dir, test::zigzag_program(400));
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  {
    test::Child sender({BEZCAM_EXE, "stream", prog.string(), "--to", to, "--progress", "off"}, dir / "stream.err");
    wait_for(sim.port(), [](const Status& s) { return s.lines_executed > 10; });
    sender.signal(SIGKILL);  // a crashed sender: no ABORT
    sender.wait();
  }
  EXPECT_EQ(status_of(sim.port()).state, State::receiving);
  const auto r = test::run_bezcam({"stream", "--abort", "--to", to}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("stopped the transfer"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("state alarm, alarm aborted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spindle off"), std::string::npos) << r.out;
  const Status after = status_of(sim.port());
  EXPECT_EQ(after.state, State::alarm);
  EXPECT_EQ(after.alarm, Alarm::aborted);
  // Nothing open: a second --abort says so and changes nothing.
  const auto again = test::run_bezcam({"stream", "--abort", "--to", to}, dir);
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("no transfer was open"), std::string::npos) << again.err;
  EXPECT_EQ(sim.stop(), 0);
}

TEST(StopAndStatus, StatusSaysStateMachineAndBuffer) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "1024", "--machine", "unisurf"});
  const auto r = test::run_bezcam({"status", "--to", "127.0.0.1:" + std::to_string(sim.port())}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("state idle"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("machine unisurf"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("buffer 1024 of 1024 bytes free"), std::string::npos) << r.out;
  EXPECT_EQ(sim.stop(), 0);
  // Nobody there: exit 3.
  const auto gone =
      test::run_bezcam({"status", "--to", "127.0.0.1:" + std::to_string(sim.port()), "--timeout", "1"}, dir);
  EXPECT_EQ(gone.status, 3) << gone.err;
}

TEST(StopAndStatus, APortMissingFromToIsNamed) {
  test::TempDir dir;
  const auto r = test::run_bezcam({"status", "--to", "127.0.0.1"}, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the port is missing"), std::string::npos) << r.err;
}

TEST(StopAndStatus, PreflightRefusesAProgramTheControllersProfileWouldStop) {
  test::TempDir dir;
  // unisurf's travel is X -750..750: X800 would stop the cut at that line.
  test::SimProcess sim(dir, {"--machine", "unisurf"});
  const auto prog = write_program(dir, "G21 G90 G17\nG00 Z5.\nX0. Y0.\nG01 Z-1. F300.\nX800. F1000.\nG00 Z5.\nM30\n");
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  const auto r = test::run_bezcam({"stream", prog.string(), "--to", to, "--progress", "off"}, dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("for machine \"unisurf\", the profile the controller at"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(":5: "), std::string::npos) << r.err;  // the finding names the line
  EXPECT_NE(r.err.find("Nothing was sent"), std::string::npos) << r.err;
  const Status s = status_of(sim.port());
  EXPECT_EQ(s.state, State::idle);
  EXPECT_EQ(s.ack_bytes, 0u);
  // --no-preflight sends it: the controller stops at line 5 (exit 4).
  const auto forced =
      test::run_bezcam({"stream", prog.string(), "--to", to, "--progress", "off", "--no-preflight"}, dir);
  EXPECT_EQ(forced.status, 4) << forced.err;
  EXPECT_EQ(status_of(sim.port()).alarm_line, 5u);
  EXPECT_EQ(sim.stop(), 0);
}
