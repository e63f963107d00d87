// `simulate --listen` logs what happens to the controller (issue "Safe on
// the shop floor"): connections opened and closed, programs opened and
// completed, alarms. The events come from the controller itself, driven
// here over real sockets by the real sender.
#include <algorithm>
#include <gtest/gtest.h>
#include <mutex>
#include <string>
#include <thread>
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
  std::vector<std::string> events;
  bool has(const std::string& prefix) {
    std::lock_guard lk(m);
    return std::any_of(events.begin(), events.end(), [&](const std::string& e) { return e.rfind(prefix, 0) == 0; });
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
  cfg.on_event = [log](const std::string& e) {
    std::lock_guard lk(log->m);
    log->events.push_back(e);
  };
  test::ServerRig rig(std::move(cfg));
  const std::string good = "G21 G90 G17\nG00 X0 Y0 Z5\nG01 Z-1 F100\nG01 X10\nG00 Z5\nM30\n";
  stream_program(good, rig.ep(), test::quick_stream(3000ms, 20s));
  ASSERT_TRUE(rig.ctl->wait_final(5s));
  EXPECT_TRUE(log->has("connection 1 opened")) << log->all();
  EXPECT_TRUE(log->has("program opened by connection ")) << log->all();
  EXPECT_TRUE(log->has("program done: 6 lines, 4 motion blocks")) << log->all();

  const std::string bad = "G21 G90 G17\nG00 X0 Y0 Z5\nG01 X5000 F100\nM30\n";
  EXPECT_THROW(stream_program(bad, rig.ep(), test::quick_stream(3000ms, 20s)), ControllerError);
  ASSERT_TRUE(rig.ctl->wait_final(5s));
  EXPECT_TRUE(log->has("alarm travel-limit: line 3: ")) << log->all();
  // Every connection the sender opened was closed again, and said so.
  for (int tries = 0; tries < 200 && !log->has("connection 2 closed"); ++tries) std::this_thread::sleep_for(10ms);
  EXPECT_TRUE(log->has("connection 1 closed")) << log->all();
}
