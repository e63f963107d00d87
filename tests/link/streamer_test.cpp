// The sender against the real simulator process (bezcam simulate --listen,
// readiness read from its stdout, stopped by PID): a controller restarted
// mid-transfer is detected and never resumed into; a controller that stays
// away gives a bounded IoError; the `stream` subcommand's exit codes,
// progress lines and fault recovery; SIGTERM flushes the trace.
#include "bezcam/link/streamer.hpp"

#include <chrono>
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/link/crc32.hpp"
#include "bezcam/link/register_map.hpp"
#include "bezcam/link/transport.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace std::chrono_literals;

namespace {

Status read_status(const Endpoint& ep) {
  ModbusClient c(ep, 2000ms);
  std::array<std::uint16_t, reg::status_count> r{};
  c.read_holding(0, r);
  return Status::decode(r);
}

}  // namespace

TEST(Streamer, ARestartedControllerIsDetectedAndNeverResumedInto) {
  test::TempDir dir;
  auto first =
      std::make_unique<test::SimProcess>(dir, std::vector<std::string>{"--buffer", "512", "--exec-delay-ms", "1"});
  const std::uint16_t port = first->port();
  std::unique_ptr<test::SimProcess> second;
  const std::string program = test::zigzag_program(400);
  StreamOptions opt;
  opt.timeout = 1000ms;
  opt.retries = 5;
  opt.retry_time = 10s;
  opt.on_progress = [&](const StreamProgress& p) {
    // Mid-transfer, the controller dies (power cut: SIGKILL, no goodbye)
    // and comes back on the same port with its memory empty.
    if (!second && p.bytes_acked > 2000) {
      first->child().signal(SIGKILL);
      first->child().wait();
      second = std::make_unique<test::SimProcess>(dir, std::vector<std::string>{"--buffer", "512"}, port);
    }
  };
  try {
    stream_program(program, {"127.0.0.1", port}, opt);
    ADD_FAILURE() << "the restart went unnoticed";
  } catch (const ControllerError& e) {
    EXPECT_EQ(e.id(), "link.restarted");
    const std::string w = e.what();
    EXPECT_NE(w.find("restarted"), std::string::npos) << w;
    EXPECT_NE(w.find("nothing was resumed"), std::string::npos) << w;
    EXPECT_EQ(e.family(), ErrorFamily::controller);
  }
  ASSERT_TRUE(second);
  // The new controller received nothing of the old program.
  const Status s = read_status({"127.0.0.1", port});
  EXPECT_EQ(s.state, State::idle);
  EXPECT_EQ(s.ack_bytes, 0u);
  EXPECT_EQ(s.session, 0u);
  EXPECT_EQ(second->stop(), 0);
}

TEST(Streamer, AControllerThatStaysAwayGivesAnIoErrorWithinTheRetryBudget) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "512", "--exec-delay-ms", "1"});
  StreamOptions opt;
  opt.timeout = 500ms;
  opt.retries = 3;
  opt.retry_time = 3s;
  bool killed = false;
  opt.on_progress = [&](const StreamProgress& p) {
    if (!killed && p.bytes_acked > 1000) {
      killed = true;
      sim.child().signal(SIGKILL);
      sim.child().wait();
    }
  };
  const auto t0 = std::chrono::steady_clock::now();
  try {
    stream_program(test::zigzag_program(300), {"127.0.0.1", sim.port()}, opt);
    ADD_FAILURE() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(e.id(), "link.lost");
    EXPECT_NE(std::string(e.what()).find("3 attempts"), std::string::npos) << e.what();
    EXPECT_EQ(e.family(), ErrorFamily::io);
  }
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 5s);
}

TEST(Streamer, RefusesProgramsThatAreNotText) {
  EXPECT_THROW(stream_program("", {"127.0.0.1", 1}), InputError);
  try {
    stream_program(std::string("G21\nX1\0\n", 8), {"127.0.0.1", 1});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "line 2");
  }
}

// A controller that cannot be reached, or an address that is not one, is
// named as the place of the error (Place::file).
TEST(Streamer, TheControllersAddressIsThePlace) {
  try {
    stream_program("G21\n", {"127.0.0.1", 1}, {});
    ADD_FAILURE() << "connected to port 1";
  } catch (const IoError& e) {
    EXPECT_EQ(e.place().file, "127.0.0.1:1") << e.what();
    EXPECT_EQ(e.where(), "127.0.0.1:1");
  }
  try {
    parse_endpoint("localhost");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, "localhost");
  }
}

TEST(StreamCommand, ExitCodesAndProgressLines) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "1024", "--trace", (dir / "listen.trace").string(), "--fault", "drop-after:3",
                             "--fault", "drop-before:9"});
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  const std::string program = test::zigzag_program(500);
  test::write_file(dir / "good.nc", program);

  // Success, through two dropped connections; plain progress lines on a pipe.
  auto r = test::run_bezcam({"stream", (dir / "good.nc").string(), "--to", to}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("bezcam: stream: reconnected; resuming at byte"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bezcam: stream: 100% ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the controller confirmed CRC-32"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);  // no bar redraws off a terminal

  // On a terminal (forced here): one bar redrawn in place, then a newline.
  r = test::run_bezcam({"stream", (dir / "good.nc").string(), "--to", to, "--progress", "bar"}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("\rstream [####################] 100%"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lines"), std::string::npos);
  EXPECT_NE(r.err.find("done, 511 executed"), std::string::npos) << r.err;

  // The trace of the streamed program equals `simulate --program` on the file.
  auto local = test::run_bezcam(
      {"simulate", "--program", (dir / "good.nc").string(), "--trace", (dir / "local.trace").string()}, dir);
  EXPECT_EQ(local.status, 0) << local.err;
  EXPECT_EQ(test::slurp(dir / "listen.trace"), test::slurp(dir / "local.trace"));

  // A malformed line sent anyway (--no-preflight; the preflight would
  // refuse it, stop_and_status_test.cpp): exit 4, the line named.
  auto lines = test::split_lines(program);
  lines[41] = "G01 X1. Q";
  std::string bad;
  for (const auto& l : lines) bad += l + "\n";
  test::write_file(dir / "bad.nc", bad);
  r = test::run_bezcam({"stream", (dir / "bad.nc").string(), "--to", to, "-q", "--no-preflight"}, dir);
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_NE(r.err.find("bezcam: error: line 42: the controller stopped with alarm gcode (1)"), std::string::npos)
      << r.err;
  // The same file run directly is invalid input: exit 2, the line named.
  r = test::run_bezcam({"simulate", "--program", (dir / "bad.nc").string()}, dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("line 42:"), std::string::npos) << r.err;

  // Nobody listening: exit 3.
  EXPECT_EQ(sim.stop(), 0);
  r = test::run_bezcam({"stream", (dir / "good.nc").string(), "--to", to, "--timeout", "0.5"}, dir);
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("cannot connect"), std::string::npos) << r.err;
  // Usage and file errors.
  EXPECT_EQ(test::run_bezcam({"stream", (dir / "good.nc").string(), "--to", "nowhere"}, dir).status, 2);
  EXPECT_EQ(test::run_bezcam({"stream", (dir / "missing.nc").string(), "--to", to}, dir).status, 3);
}

TEST(StreamCommand, ABusyControllerRefusesASecondSenderWithExit4) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "256", "--exec-delay-ms", "2"});
  const Endpoint ep{"127.0.0.1", sim.port()};
  test::write_file(dir / "p.nc", test::zigzag_program(20));
  bool tried = false;
  StreamOptions opt;
  opt.on_event = [&](const std::string& e) {
    if (tried || e.rfind("transfer opened", 0) != 0) return;
    tried = true;
    const auto r = test::run_bezcam({"stream", (dir / "p.nc").string(), "--to", ep.str()}, dir);
    EXPECT_EQ(r.status, 4) << r.err;
    EXPECT_NE(r.err.find("busy with another sender"), std::string::npos) << r.err;
  };
  const auto res = stream_program(test::zigzag_program(200), ep, opt);
  EXPECT_TRUE(tried);
  EXPECT_GT(res.lines_executed, 200u);
  EXPECT_EQ(sim.stop(), 0);
}

TEST(SimulateCommand, SigtermStopsCleanlyWithTheTraceFlushed) {
  test::TempDir dir;
  const auto trace = dir / "t.trace";
  test::SimProcess sim(dir, {"--buffer", "256", "--exec-delay-ms", "2", "--trace", trace.string()});
  StreamOptions opt;
  opt.timeout = 1000ms;
  opt.retries = 0;
  int status = -1;
  opt.on_progress = [&](const StreamProgress& p) {
    if (status < 0 && p.lines_executed >= 20) status = sim.stop();  // SIGTERM mid-program
  };
  EXPECT_THROW(stream_program(test::zigzag_program(400), {"127.0.0.1", sim.port()}, opt), Error);
  EXPECT_EQ(status, 0);
  const std::string t = test::slurp(trace);
  EXPECT_EQ(t.rfind("bezcam-trace 1 machine generic\n", 0), 0u);
  const auto stop = t.rfind("stopped after line ");
  ASSERT_NE(stop, std::string::npos) << t;
  // Every line up to the one in progress is in the trace, then the record.
  const long n = std::stol(t.substr(stop + 19));
  EXPECT_GE(n, 20);
  EXPECT_NE(t.find("line " + std::to_string(n) + " linear to"), std::string::npos);
  EXPECT_EQ(t.back(), '\n');
  EXPECT_NE(sim.child().stderr_text().find("stopped by signal 15"), std::string::npos);
}
