// The real sender against the simulated controller over the in-process
// transport (sim/in_process_transport.hpp): no sockets, faults placed at
// exact requests. Checks the retry and resume logic: reconnection after a
// drop mid-transfer, resumption that sends nothing twice, a lost reply to
// OPEN, and giving up once the retry budget is spent. The same scenarios
// over real sockets are in sim_server_test.cpp.
#include <gtest/gtest.h>
#include <mutex>
#include <string>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/link/crc32.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/sim/in_process_transport.hpp"
#include "support/link_test_util.hpp"
#include "support/server_rig.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;
using namespace std::chrono_literals;

namespace {

// A controller (generic profile) recording the lines its executor takes.
struct Rig {
  std::mutex m;
  std::vector<std::string> lines;
  std::unique_ptr<SimController> ctl;

  explicit Rig(ControllerConfig cfg = {}) {
    cfg.profile = load_machine_profile("generic");
    cfg.on_line = [this](long, std::string_view t) {
      std::lock_guard lk(m);
      lines.emplace_back(t);
    };
    ctl = std::make_unique<SimController>(std::move(cfg));
  }
  ~Rig() { ctl->stop(); }
  std::vector<std::string> executed() {
    std::lock_guard lk(m);
    return lines;
  }
};

StreamOptions quick() { return test::quick_stream(2000ms, 10s); }

}  // namespace

TEST(InProcessStream, AProgramStreamsWithoutSockets) {
  Rig rig;
  const InProcessLink link(*rig.ctl);
  const std::string program = test::zigzag_program(400);
  const StreamResult r = stream_program(program, link.factory(), "in-process", quick());
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(r.reconnects, 0);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
  EXPECT_EQ(rig.ctl->status().state, State::done);
  const LinkStats s = link.stats();
  EXPECT_EQ(s.connects, 1);
  EXPECT_EQ(s.open, 0);                 // the sender closed its connection
  EXPECT_GE(s.requests, r.chunks + 3);  // status, OPEN, chunks, COMMIT
}

TEST(InProcessStream, ADropMidTransferIsResumedAndNothingIsSentTwice) {
  Rig rig;
  // Request 1 reads the status, 2 opens: the others fall among the chunks.
  // Dropped before: the chunk never arrived and must be sent again. Dropped
  // after: it was applied and only its reply was lost; it must not be resent.
  LinkFaults faults;
  faults.drop_before = {5, 30};
  faults.drop_after = {12, 45};
  const InProcessLink link(*rig.ctl, faults);
  const std::string program = test::zigzag_program(600);
  std::vector<std::string> events;
  auto opt = quick();
  opt.on_event = [&](const std::string& e) { events.push_back(e); };
  const StreamResult r = stream_program(program, link.factory(), "in-process", opt);
  EXPECT_EQ(r.reconnects, 4);
  EXPECT_EQ(link.stats().connects, 5);
  EXPECT_EQ(rig.executed(), test::split_lines(program));  // every line once, in order
  const Status s = rig.ctl->status();
  EXPECT_EQ(s.state, State::done);
  EXPECT_EQ(s.duplicates, 0u);  // the resume started from the controller's position
  EXPECT_EQ(s.program_crc, crc32(program));
  int resumed = 0;
  for (const auto& e : events) resumed += e.rfind("reconnected; resuming at byte", 0) == 0;
  EXPECT_EQ(resumed, 4);
}

TEST(InProcessStream, ControllerSideDropsOfChunksAreResumedToo) {
  ControllerConfig cfg;
  cfg.drop_before_chunk = {2, 9};
  cfg.drop_after_chunk = {4, 15};
  Rig rig(cfg);
  const InProcessLink link(*rig.ctl);
  const std::string program = test::zigzag_program(600);
  const StreamResult r = stream_program(program, link.factory(), "in-process", quick());
  EXPECT_EQ(r.reconnects, 4);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
  EXPECT_EQ(rig.ctl->status().duplicates, 0u);
}

TEST(InProcessStream, ALostReplyToOpenIsAskedAgainWithTheSameToken) {
  Rig rig;
  LinkFaults faults;
  faults.drop_after = {2};  // OPEN applied, its reply lost
  const InProcessLink link(*rig.ctl, faults);
  const std::string program = test::zigzag_program(50);
  const StreamResult r = stream_program(program, link.factory(), "in-process", quick());
  EXPECT_EQ(r.reconnects, 1);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
  EXPECT_EQ(rig.ctl->status().rejects, 0u);  // the second OPEN was the same transfer, not "busy"
}

TEST(InProcessStream, ConnectionAttemptsThatFailAreRetriedWithinTheBudget) {
  Rig rig;
  LinkFaults faults;
  faults.drop_before = {8};
  faults.failed_connects = {2, 3};  // 4 succeeds
  const InProcessLink link(*rig.ctl, faults);
  const std::string program = test::zigzag_program(300);
  auto opt = quick();
  opt.retries = 3;
  const StreamResult r = stream_program(program, link.factory(), "in-process", opt);
  EXPECT_EQ(r.reconnects, 1);
  EXPECT_EQ(link.stats().connects, 4);
  EXPECT_EQ(rig.executed(), test::split_lines(program));
}

TEST(InProcessStream, TheSenderGivesUpOnceTheRetryBudgetIsSpent) {
  Rig rig;
  LinkFaults faults;
  faults.drop_before = {8};
  for (int i = 2; i < 100; ++i) faults.failed_connects.push_back(i);  // never reached again
  const InProcessLink link(*rig.ctl, faults);
  const std::string program = test::zigzag_program(600);
  auto opt = quick();
  opt.retries = 3;
  try {
    stream_program(program, link.factory(), "in-process", opt);
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_EQ(e.id(), "link.lost");
    EXPECT_NE(e.message().find("3 attempts"), std::string::npos) << e.message();
  }
  EXPECT_EQ(link.stats().connects, 1 + 3);  // the first connection, then exactly `retries` attempts
  EXPECT_EQ(link.stats().open, 0);
  // The controller keeps the transfer for its owner to resume; nothing
  // was executed beyond what was acknowledged.
  const Status s = rig.ctl->status();
  EXPECT_EQ(s.state, State::receiving);
  EXPECT_LT(s.ack_bytes, program.size());
}

TEST(InProcessStream, TheBudgetStartsAfreshAfterProgress) {
  Rig rig;
  // Three separate outages with two failed attempts each would spend a
  // budget of 3 if it were not renewed by the progress in between.
  LinkFaults faults;
  faults.drop_before = {6, 20, 40};
  faults.failed_connects = {2, 3, 5, 6, 8, 9};
  const InProcessLink link(*rig.ctl, faults);
  const std::string program = test::zigzag_program(600);
  auto opt = quick();
  opt.retries = 3;
  const StreamResult r = stream_program(program, link.factory(), "in-process", opt);
  EXPECT_EQ(r.reconnects, 3);
  EXPECT_EQ(link.stats().connects, 10);  // 6 failed attempts in all, 3 at most per outage
  EXPECT_EQ(rig.executed(), test::split_lines(program));
}
