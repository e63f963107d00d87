// The simulated controller with a stock (ControllerConfig::stock): it cuts
// the same part as `bezcam verify` cuts from the same program, whether the
// program is run directly, streamed over Modbus TCP or executed at machine
// pace; the stock is kept from program to program; a tool the table lacks
// stops the program at its line; each program's trace ends with the stock.
#include <gtest/gtest.h>
#include <mutex>

#include "bezcam/error.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "bezcam/sim/trace.hpp"
#include "bezcam/verify/machined_program.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;

namespace {

const StockBox kBox{0, 0, -5, 100, 60, 0};
constexpr double kCell = 0.25;

StockConfig stock_config(StockTools tools = {{1, ToolShape::flat(3)}}) {
  StockConfig s;
  s.box = kBox;
  s.cell = kCell;
  s.tools = std::move(tools);
  return s;
}

struct Traced {
  std::mutex m;
  std::string text;
  std::unique_ptr<SimController> ctl;
  explicit Traced(std::optional<StockConfig> stock, double time_scale = 0) {
    ControllerConfig cfg;
    cfg.profile = load_machine_profile("generic");
    cfg.stock = std::move(stock);
    cfg.time_scale = time_scale;
    cfg.trace = [this](std::string_view t, bool restart) {
      std::lock_guard lk(m);
      if (restart) text.clear();
      text += t;
    };
    ctl = std::make_unique<SimController>(std::move(cfg));
  }
  std::string get() {
    std::lock_guard lk(m);
    return text;
  }
};

// The last record of a trace.
std::string last_line(const std::string& trace) {
  const auto end = trace.find_last_not_of('\n');
  const auto start = trace.rfind('\n', end);
  return trace.substr(start == std::string::npos ? 0 : start + 1,
                      end - (start == std::string::npos ? 0 : start + 1) + 1);
}

// The hash field of a trace's stock record.
std::string traced_hash(const std::string& trace) {
  const std::string last = last_line(trace);
  EXPECT_EQ(last.rfind("stock hash ", 0), 0u) << trace.substr(trace.size() > 400 ? trace.size() - 400 : 0);
  return last.substr(11, 16);
}

// What `bezcam verify` does with the programs, one after the other, in one stock.
const DexelGrid& verify_cut(StockCutter& c, const std::vector<std::string>& programs) {
  const MachineProfile generic = load_machine_profile("generic");
  for (const std::string& p : programs) cut_timeline(c, read_timeline(p, &generic));
  return c.grid();
}

std::string verify_hash(const std::vector<std::string>& programs, const StockTools& tools = {{1, ToolShape::flat(3)}}) {
  StockCutter c(kBox, kCell, tools);
  return verify_cut(c, programs).hash_hex();
}

// The hash of a stock nothing touched, from DexelGrid::hash()'s definition:
// FNV-1a over nx, ny and each floor in micrometres, little-endian 64 bits.
std::string untouched_hash(const StockBox& box, double cell) {
  const StockGridSize size = stock_grid_size(box, cell);
  std::uint64_t h = 14695981039346656037ull;
  auto word = [&](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xFF;
      h *= 1099511628211ull;
    }
  };
  word(size.nx);
  word(size.ny);
  const auto top = static_cast<std::uint64_t>(std::llround(box.z1 * 1000));
  for (std::size_t k = 0; k < size.nx * size.ny; ++k) word(top);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

const std::string kSecond =
    "G21 G90 G17\nT1 M06\nS10000 M03\nG00 Z5.\nX10. Y50.\nG01 Z-3. F300.\nG02 X30. Y50. I10. J0. F800.\nG00 Z5.\nM30\n";

}  // namespace

TEST(StockController, CutsThePartVerifyCuts) {
  const std::string program = test::zigzag_program(150);
  Traced t(stock_config());
  ASSERT_EQ(t.ctl->run_program(program).state, State::done) << t.ctl->alarm_text();
  StockCutter c(kBox, kCell, {{1, ToolShape::flat(3)}});
  const DexelGrid& g = verify_cut(c, {program});
  EXPECT_EQ(last_line(t.get()), trace_stock(g).substr(0, trace_stock(g).size() - 1));
  EXPECT_NE(g.hash_hex(), untouched_hash(kBox, kCell));
  EXPECT_GT(g.removed_volume(), 1000.0);
  EXPECT_DOUBLE_EQ(g.deepest().z, -1.0);
  // The record follows the program's final record.
  const std::string trace = t.get();
  EXPECT_NE(trace.find("\ndone lines "), std::string::npos);
  EXPECT_LT(trace.find("\ndone lines "), trace.find("\nstock hash "));
}

TEST(StockController, AProgramThatCutsNothingLeavesTheStockUntouched) {
  // Feed moves above the stock's top, rapids with no tool loaded.
  const std::string program = "G21 G90\nG00 X5. Y5. Z1.\nT1 M06\nG01 X50. Y40. Z0.5 F500.\nG00 Z10.\nM30\n";
  Traced t(stock_config());
  ASSERT_EQ(t.ctl->run_program(program).state, State::done) << t.ctl->alarm_text();
  const std::string last = last_line(t.get());
  EXPECT_EQ(traced_hash(t.get()), untouched_hash(kBox, kCell));
  EXPECT_NE(last.find(" removed 0.000000 deepest 0.000000 at "), std::string::npos) << last;
}

TEST(StockController, AToolTheTableLacksIsAnAlarmAtItsLine) {
  const std::string program = "G21 G90\nT1 M06\nG00 X5. Y5. Z1.\nG01 Z-1. F300.\nX20.\nT2 M06\nG01 X30. Y30.\nM30\n";
  for (const double scale : {0.0, 1000.0}) {
    SCOPED_TRACE(scale);
    Traced t(stock_config(), scale);
    const Status st = t.ctl->run_program(program);
    EXPECT_EQ(st.state, State::alarm);
    EXPECT_EQ(st.alarm, Alarm::gcode);
    EXPECT_EQ(st.alarm_line, 7u);
    EXPECT_EQ(t.ctl->alarm_id(), "verify.tool");
    // The refused line did not run: the machine stands where line 5 left it.
    EXPECT_EQ(st.pos[0], 20000);
    EXPECT_EQ(st.pos[1], 5000);
    EXPECT_EQ(st.lines_executed, 6u);
    EXPECT_NE(t.ctl->alarm_message().find("T2"), std::string::npos) << t.ctl->alarm_message();
    const std::string trace = t.get();
    EXPECT_NE(trace.find("\nalarm line 7 gcode verify.tool: "), std::string::npos) << trace;
    // The stock holds the lines before the refused one, nothing of it.
    EXPECT_EQ(traced_hash(trace), verify_hash({"G21 G90\nT1 M06\nG00 X5. Y5. Z1.\nG01 Z-1. F300.\nX20.\nM30\n"}));
  }
}

TEST(StockController, MachinePaceCutsTheSamePart) {
  const std::string program = test::zigzag_program(60);
  Traced t(stock_config(), 5000.0);
  ASSERT_EQ(t.ctl->run_program(program).state, State::done) << t.ctl->alarm_text();
  EXPECT_EQ(traced_hash(t.get()), verify_hash({program}));
}

TEST(StockController, StreamedOverModbusCutsTheSamePart) {
  const std::string program = test::zigzag_program(80);
  Traced direct(stock_config());
  ASSERT_EQ(direct.ctl->run_program(program).state, State::done);
  Traced remote(stock_config());
  ModbusServer server(*remote.ctl, ServerConfig{});
  server.start();
  stream_program(program, {"127.0.0.1", server.port()});
  ASSERT_TRUE(remote.ctl->wait_final(std::chrono::seconds(10)));
  server.stop();
  EXPECT_EQ(remote.get(), direct.get());
  EXPECT_EQ(traced_hash(direct.get()), verify_hash({program}));
}

TEST(StockController, TheStockIsKeptFromProgramToProgram) {
  const std::string first = test::zigzag_program(40);
  for (const double scale : {0.0, 5000.0}) {
    SCOPED_TRACE(scale);
    Traced t(stock_config(), scale);
    ASSERT_EQ(t.ctl->run_program(first).state, State::done);
    EXPECT_EQ(traced_hash(t.get()), verify_hash({first}));
    ASSERT_EQ(t.ctl->run_program(kSecond).state, State::done) << t.ctl->alarm_text();
    // The second program's trace ends with the stock both programs cut.
    EXPECT_EQ(traced_hash(t.get()), verify_hash({first, kSecond}));
    EXPECT_NE(traced_hash(t.get()), verify_hash({kSecond}));
  }
}

TEST(StockController, InchProgramsCutInMillimetres) {
  // The same moves in inches and in millimetres (1 in = 25.4 mm).
  const std::string inch =
      "G20 G90\nT1 M06\nG00 X0.5 Y0.5 Z0.2\nG01 Z-0.05 F10.\nX2.5 Y1.5\nG02 X3.5 Y0.5 I0. J-1.\nM30\n";
  const std::string mm =
      "G21 G90\nT1 M06\nG00 X12.7 Y12.7 Z5.08\nG01 Z-1.27 F254.\nX63.5 Y38.1\nG02 X88.9 Y12.7 I0. J-25.4\nM30\n";
  Traced a(stock_config()), b(stock_config());
  ASSERT_EQ(a.ctl->run_program(inch).state, State::done) << a.ctl->alarm_text();
  ASSERT_EQ(b.ctl->run_program(mm).state, State::done) << b.ctl->alarm_text();
  EXPECT_EQ(traced_hash(a.get()), traced_hash(b.get()));
  EXPECT_EQ(last_line(a.get()), last_line(b.get()));
  EXPECT_NE(traced_hash(a.get()), untouched_hash(kBox, kCell));
  EXPECT_NE(last_line(a.get()).find(" deepest -1.270000 "), std::string::npos) << last_line(a.get());
}

TEST(StockController, AStockTheGridRefusesIsRefusedBeforeAnythingRuns) {
  ControllerConfig cfg;
  cfg.profile = load_machine_profile("generic");
  cfg.stock = stock_config();
  cfg.stock->box = {0, 0, 0, 0, 60, 10};  // no extent in x
  try {
    SimController ctl(cfg);
    FAIL() << "accepted a box with no extent";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "stock.box");
  }
  cfg.stock = stock_config();
  cfg.stock->options.memory_limit = 1 << 20;
  cfg.stock->cell = 0.01;
  try {
    SimController ctl(cfg);
    FAIL() << "accepted a grid over the memory limit";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "stock.memory");
  }
}

TEST(TraceCompare, AHashIsComparedAsAWord) {
  // Both read as the number 0: compared as numbers they would be equal.
  const auto m = compare_traces("stock hash 0e00000000000001 removed 1.000000\n",
                                "stock hash 0e00000000000002 removed 1.000000\n");
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->line, 1u);
  EXPECT_FALSE(compare_traces("stock hash 0e00000000000001 removed 1.000000\n",
                              "stock hash 0e00000000000001 removed 1.000001\n"));
}
