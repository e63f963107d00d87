// Execution at machine pace (issue 16, docs/motion.md "Streaming at machine
// pace"): the windowed planning agrees with the whole program's plan, the
// controller takes real time over real sockets and does not starve when the
// sender keeps up, and counts the stall when it does not.
#include "bezcam/sim/machine_pace.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <thread>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/link/transport.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
namespace test = bezcam::test;

namespace {

// Short G01 blocks at the generic profile's top feed (20000 mm/min) and
// block rate (1000 blocks/s): 0.333 mm each, gently turning.
std::string short_blocks(int n, double feed = 20000) {
  std::string p = "G21 G90 G17\nG0 X0 Y0 Z0\nS10000 M3\nG1 F" + std::to_string(static_cast<int>(feed)) + "\n";
  double x = 0, y = 0;
  char b[64];
  for (int i = 0; i < n; ++i) {
    const double a = (i % 400) / 400.0 * 2 * M_PI;
    x += 0.3333 * std::cos(a);
    y += 0.3333 * std::sin(a);
    std::snprintf(b, sizeof b, "X%.4f Y%.4f\n", x, y);
    p += b;
  }
  return p + "M30\n";
}

double planned_cycle(const std::string& program, const MachineProfile& m) {
  return plan_motion(read_timeline(program, &m), *m.motion).cycle_time_s;
}

// Feeds a whole program through MachinePace as the executor does when the
// buffer always holds more: commit whenever the window is full, dry at the end.
double paced_cycle(const std::string& program, const MachineProfile& m, int dry_every = 0) {
  sim::MachinePace pace(*m.motion);
  GcodeInterpreter in(&m);
  int no = 0, since_dry = 0;
  size_t pos = 0;
  while (pos < program.size()) {
    size_t end = program.find('\n', pos);
    if (end == std::string::npos) end = program.size();
    const MachineState before = in.state();
    const auto blocks = in.feed_line(std::string_view(program).substr(pos, end - pos), ++no);
    pace.add(blocks, before, in.state(), no);
    pos = end + 1;
    while (pace.window_full()) pace.commit(false);
    if (dry_every > 0 && ++since_dry == dry_every) {
      since_dry = 0;
      pace.commit(true);  // the buffer ran dry here: the machine stops
    }
  }
  pace.commit(true);
  return pace.committed_until();
}

// A transport that holds the `nth` chunk write for `hold`: a sender that
// falls behind once.
class SlowOnce final : public Transport {
 public:
  SlowOnce(std::unique_ptr<Transport> t, int* count, int nth, std::chrono::milliseconds hold)
      : t_(std::move(t)), count_(count), nth_(nth), hold_(hold) {}
  void read_holding(std::uint16_t a, std::span<std::uint16_t> o) override { t_->read_holding(a, o); }
  void read_input(std::uint16_t a, std::span<std::uint16_t> o) override { t_->read_input(a, o); }
  void write_register(std::uint16_t a, std::uint16_t v) override { t_->write_register(a, v); }
  void write_registers(std::uint16_t a, std::span<const std::uint16_t> v) override {
    delay(a, v.size());
    t_->write_registers(a, v);
  }
  void write_and_read(std::uint16_t w, std::span<const std::uint16_t> v, std::uint16_t r,
                      std::span<std::uint16_t> o) override {
    delay(w, v.size());
    t_->write_and_read(w, v, r, o);
  }
  void close() override { t_->close(); }

 private:
  // Counts the payload bytes sent; holds once when they pass `nth_`.
  void delay(std::uint16_t addr, std::size_t regs) {
    if (addr != reg::chunk || regs <= reg::chunk_header) return;
    const int before = *count_;
    *count_ += static_cast<int>(2 * (regs - reg::chunk_header));
    if (before < nth_ && *count_ >= nth_) std::this_thread::sleep_for(hold_);
  }
  std::unique_ptr<Transport> t_;
  int* count_;
  int nth_;
  std::chrono::milliseconds hold_;
};

}  // namespace

TEST(MachinePace, TheWindowedPlanAgreesWithTheWholeProgramsPlan) {
  for (const char* machine : {"generic", "linuxcnc", "grbl"}) {
    const MachineProfile m = load_machine_profile(machine);
    for (const std::string& prog : {short_blocks(1500, m.max_feed_mm_min), test::zigzag_program(800)}) {
      const double whole = planned_cycle(prog, m), paced = paced_cycle(prog, m);
      EXPECT_NEAR(paced, whole, 0.04 * whole) << machine;  // grbl (16 blocks) differs most: 3 %
    }
  }
}

TEST(MachinePace, RunningDryMakesTheMachineStop) {
  // Each time the buffer runs dry the machine must be able to stop at the
  // end of what it has: the program takes longer.
  const MachineProfile m = load_machine_profile("generic");
  const std::string prog = short_blocks(1500);
  const double smooth = paced_cycle(prog, m), dry = paced_cycle(prog, m, 50);
  EXPECT_GT(dry, smooth * 1.2);
}

// Streams `prog` to a simulator at `scale` times real time. The machine
// must not starve, and the wall time must follow the machine's pace. Both
// depend on the processes getting the processor: on a machine busy with
// other work a run can starve for want of it, so a starved run is tried
// again, up to three times; a sender or controller that cannot keep up
// starves every time.
namespace {
struct PacedRun {
  StreamResult result;
  double wall = 0;
  int attempts = 0;
};
PacedRun stream_at_pace(const std::string& prog, const std::string& scale, double cycle) {
  PacedRun run;
  for (run.attempts = 1; run.attempts <= 3; ++run.attempts) {
    test::TempDir dir;
    test::SimProcess sim(dir, {"--machine", "generic", "--time-scale", scale, "--buffer", "65535", "-q"});
    const auto t0 = std::chrono::steady_clock::now();
    run.result = stream_program(prog, Endpoint{"127.0.0.1", sim.port()});
    run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(sim.stop(), 0);
    const double pace = cycle / std::stod(scale);
    if (run.result.starved_ms == 0 && run.wall <= 1.25 * pace + 0.5) break;
  }
  return run;
}
}  // namespace

TEST(MachinePaceLink, AThousandShortBlocksStreamInRealTimeWithoutStarving) {
  const std::string prog = short_blocks(1000);
  const double cycle = planned_cycle(prog, load_machine_profile("generic"));
  const PacedRun run = stream_at_pace(prog, "1", cycle);
  EXPECT_EQ(run.result.starved_ms, 0u) << run.attempts << " attempts";
  EXPECT_EQ(run.result.stalls, 0u);
  EXPECT_EQ(run.result.lines_executed, 1005u);
  // At machine pace: not faster than the machine, and not much slower.
  EXPECT_GE(run.wall, 0.97 * cycle);
  EXPECT_LE(run.wall, 1.25 * cycle + 0.5);
}

#if !defined(__SANITIZE_ADDRESS__)
// 1,000 blocks a second of machine time at 20 times real time: the link
// carries 20,000 blocks a second (bench/modbus_link measures how far it goes).
TEST(MachinePaceLink, TwentyThousandLinesAtTwentyTimesRealTimeWithoutStarving) {
  const std::string prog = short_blocks(20000);
  const double cycle = planned_cycle(prog, load_machine_profile("generic"));
  const PacedRun run = stream_at_pace(prog, "20", cycle);
  EXPECT_EQ(run.result.starved_ms, 0u) << run.attempts << " attempts";
  EXPECT_EQ(run.result.lines_executed, 20005u);
  EXPECT_GE(run.wall, 0.97 * cycle / 20);
}
#endif

TEST(MachinePaceLink, ASenderThatFallsBehindStarvesTheMachineAndItIsCounted) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--machine", "generic", "--time-scale", "1", "--buffer", "512"});
  const std::string prog = short_blocks(1000);
  int chunks = 0;
  const Endpoint to{"127.0.0.1", sim.port()};
  const TransportFactory slow = [&](std::chrono::milliseconds timeout) -> std::unique_ptr<Transport> {
    // At 70 % of the program: well after the spindle's start, the machine
    // moving, with the interpreted window and the buffer (about 230 lines,
    // 0.6 s of motion) ahead of it.
    return std::make_unique<SlowOnce>(modbus_transport(to)(timeout), &chunks, static_cast<int>(prog.size() * 7 / 10),
                                      std::chrono::milliseconds(1200));
  };
  const StreamResult r = stream_program(prog, slow, to.str());
  // The window (200 blocks) and the 512-byte buffer (about 28 lines) hold
  // about 0.6 s of motion: a 1.2 s hold runs the machine dry for about half
  // of it.
  EXPECT_GE(r.stalls, 1u);
  EXPECT_GE(r.starved_ms, 300u);
  EXPECT_LE(r.starved_ms, 1200u);
  // Read over Modbus like any client, and logged for the operator.
  const ControllerReport c = controller_status(to, std::chrono::milliseconds(2000));
  EXPECT_EQ(c.status.starved_ms, r.starved_ms);
  EXPECT_EQ(c.status.stalls, r.stalls);
  EXPECT_EQ(sim.stop(), 0);
  EXPECT_NE(sim.child().stderr_text().find("machine starved"), std::string::npos) << sim.child().stderr_text();
}

TEST(MachinePaceLink, ATimeScaleOutOfRangeIsRefused) {
  test::TempDir dir;
  for (const char* k : {"0", "0.001", "200000", "fast", "1x"}) {
    const auto r = test::run_bezcam({"simulate", "--listen", "127.0.0.1:0", "--time-scale", k}, dir);
    EXPECT_EQ(r.status, 2) << k;
    EXPECT_NE(r.err.find("--time-scale"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("0.01 to 100000"), std::string::npos) << r.err;
  }
}
