// `simulate --listen` logs what happens to the controller (issue "Safe on
// the shop floor"): connections opened and closed, programs opened and
// completed, alarms. The events come from the controller itself, driven
// here over real sockets by the real sender.
#include <algorithm>
#include <condition_variable>
#include <gtest/gtest.h>
#include <mutex>
#include <string>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "support/link_test_util.hpp"
#include "support/server_rig.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace std::chrono_literals;

namespace {

struct Log {
  std::mutex m;
  std::condition_variable changed;
  std::vector<std::string> events;
  void add(const std::string& e) {
    {
      std::lock_guard lk(m);
      events.push_back(e);
    }
    changed.notify_all();
  }
  bool has_locked(const std::string& prefix) const {
    return std::any_of(events.begin(), events.end(), [&](const std::string& e) { return e.rfind(prefix, 0) == 0; });
  }
  bool has(const std::string& prefix) {
    std::lock_guard lk(m);
    return has_locked(prefix);
  }
  // Whether the event comes within the deadline (generous: only a failure
  // waits it out, and a busy machine may be slow to close a socket).
  bool waits_for(const std::string& prefix) {
    std::unique_lock lk(m);
    return changed.wait_for(lk, 60s, [&] { return has_locked(prefix); });
  }
  std::string all() {
    std::lock_guard lk(m);
    std::string s;
    for (const auto& e : events) s += e + "\n";
    return s;
  }
};

}  // namespace

TEST(OperatorLog, ConnectionsProgramsCompletionsAndAlarms) {
  auto log = std::make_shared<Log>();
  sim::ControllerConfig cfg;
  cfg.profile = load_machine_profile("fanuc");  // travel limits
  cfg.on_event = [log](const std::string& e) { log->add(e); };
  test::ServerRig rig(std::move(cfg));
  const std::string good = "G21 G90 G17\nG00 X0 Y0 Z5\nG01 Z-1 F100\nG01 X10\nG00 Z5\nM30\n";
  stream_program(good, rig.ep(), test::quick_stream(3000ms, 20s));
  ASSERT_TRUE(rig.ctl->wait_final(60s));
  EXPECT_TRUE(log->waits_for("connection 1 opened")) << log->all();
  EXPECT_TRUE(log->waits_for("program opened by connection ")) << log->all();
  EXPECT_TRUE(log->waits_for("program done: 6 lines, 4 motion blocks")) << log->all();

  const std::string bad = "G21 G90 G17\nG00 X0 Y0 Z5\nG01 X5000 F100\nM30\n";
  EXPECT_THROW(stream_program(bad, rig.ep(), test::quick_stream(3000ms, 20s)), ControllerError);
  ASSERT_TRUE(rig.ctl->wait_final(60s));
  EXPECT_TRUE(log->waits_for("alarm travel-limit: line 3: ")) << log->all();
  // Every connection the sender opened was closed again, and said so.
  EXPECT_TRUE(log->waits_for("connection 1 closed")) << log->all();
  EXPECT_TRUE(log->waits_for("connection 2 closed")) << log->all();
}
