// Golden traces: every sample job is converted in process (machine
// generic, --output lines), executed by `simulate --program`'s path
// (SimController::run_program) and streamed over Modbus TCP on loopback to
// a simulated controller, both cutting a stock; the two traces must be
// identical byte for byte, and equal to tests/golden/<sample>.generic.trace
// within kTraceTolerance (1e-5 program units on numbers; every other token,
// the machined part's hash included, exactly). The stock is the box the
// program fills (verify's default), cut with the tools of kGoldenTools at
// cells of kGoldenCell: a change to the machined part fails the golden even
// where the moves' text would not show it.
//
// Regenerate after an intended change (then review the diff):
//   BEZCAM_UPDATE_GOLDEN=1 build/link_tests --gtest_filter='GoldenTrace*'
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <mutex>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "bezcam/sim/trace.hpp"
#include "bezcam/verify/machined_program.hpp"
#include "support/link_test_util.hpp"
#include "support/sample_job.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> sample_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(BEZCAM_SOURCE_DIR) / "samples"))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool updating() {
  const char* v = std::getenv("BEZCAM_UPDATE_GOLDEN");
  return v && std::string(v) == "1";
}

// The golden runs' tools (mm) and cell: the stock's shape, not the jobs'.
const StockTools kGoldenTools = {{1, ToolShape::flat(3)}, {2, ToolShape::ball(2)}, {3, ToolShape::flat(6)}};
constexpr double kGoldenCell = 0.1;

// The stock a program fills, as verify takes it when none is given.
StockConfig golden_stock(const std::string& program, const MachineProfile& p, StockTools tools = kGoldenTools) {
  StockConfig s;
  s.box = program_stock_box(read_timeline(program, &p), tools);
  s.cell = kGoldenCell;
  s.tools = std::move(tools);
  return s;
}

// A controller whose trace is collected in memory.
struct Traced {
  std::mutex m;
  std::string text;
  std::unique_ptr<SimController> ctl;
  explicit Traced(const MachineProfile& p, std::optional<StockConfig> stock = std::nullopt) {
    ControllerConfig cfg;
    cfg.profile = p;
    cfg.stock = std::move(stock);
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

class GoldenTrace : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(GoldenTrace, StreamedEqualsDirectEqualsGolden) {
  const std::string name = GetParam();
  const fs::path src = fs::path(BEZCAM_SOURCE_DIR) / "samples" / (name + ".json");
  const MachineProfile generic = load_machine_profile("generic");
  ConvertOptions opt;
  opt.output = OutputMode::lines;
  const std::string program = convert(test::load_sample(src.string()), generic, opt).gcode;
  const StockConfig stock = golden_stock(program, generic);

  // `simulate --program`: the file pushed through the controller directly.
  Traced direct(generic, stock);
  const Status ds = direct.ctl->run_program(program);
  EXPECT_EQ(ds.state, State::done) << direct.ctl->alarm_text();
  const std::string trace = direct.get();

  // Streamed over Modbus TCP to another controller.
  Traced remote(generic, stock);
  ModbusServer server(*remote.ctl, ServerConfig{});
  server.start();
  const StreamResult r = stream_program(program, {"127.0.0.1", server.port()});
  ASSERT_TRUE(remote.ctl->wait_final(std::chrono::seconds(10)));
  server.stop();
  EXPECT_EQ(r.lines_executed, ds.lines_executed);
  EXPECT_EQ(remote.get(), trace) << "the streamed program's trace differs from simulate --program's";

  const fs::path golden = fs::path(BEZCAM_SOURCE_DIR) / "tests" / "golden" / (name + ".generic.trace");
  if (updating()) {
    test::write_file(golden, trace);
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; create it with BEZCAM_UPDATE_GOLDEN=1 and review it";
  if (const auto m = compare_traces(test::slurp(golden), trace, kTraceTolerance))
    ADD_FAILURE() << golden.filename() << " line " << m->line << ": " << m->why << "\n  golden: " << m->expected
                  << "\n  now:    " << m->actual
                  << "\n(if the change is intended, regenerate with BEZCAM_UPDATE_GOLDEN=1 and review the diff)";
}

namespace {

// A sample's program, its trace on the stock, and the trace without the
// stock's record.
struct GoldenRun {
  std::string trace, moves;
};
GoldenRun run_golden(const std::string& program, const StockConfig& stock) {
  const MachineProfile generic = load_machine_profile("generic");
  Traced t(generic, stock);
  EXPECT_EQ(t.ctl->run_program(program).state, State::done) << t.ctl->alarm_text();
  GoldenRun r{t.get(), {}};
  const auto at = r.trace.rfind("\nstock hash ");
  EXPECT_NE(at, std::string::npos);
  r.moves = r.trace.substr(0, at + 1);
  return r;
}

std::string semicircle_program() {
  ConvertOptions opt;
  opt.output = OutputMode::lines;
  const fs::path src = fs::path(BEZCAM_SOURCE_DIR) / "samples" / "curve-semicircle.json";
  return convert(load_job(src.string()), load_machine_profile("generic"), opt).gcode;
}

}  // namespace

// A part that changes while every move stays the same (a tool 0.05 mm
// larger) fails the golden comparison, at the stock's record.
TEST(StockGolden, APartChangeTheMovesDoNotShowFailsTheGolden) {
  const std::string program = semicircle_program();
  const MachineProfile generic = load_machine_profile("generic");
  StockTools wider = kGoldenTools;
  wider.insert_or_assign(1, ToolShape::flat(3.05));
  const GoldenRun golden = run_golden(program, golden_stock(program, generic));
  StockConfig s = golden_stock(program, generic);
  s.tools = wider;
  const GoldenRun changed = run_golden(program, s);
  EXPECT_FALSE(compare_traces(golden.moves, changed.moves)) << "the moves differ: not the case this test is about";
  const auto m = compare_traces(golden.trace, changed.trace);
  ASSERT_TRUE(m.has_value()) << "a part cut with a wider tool passed the golden";
  EXPECT_EQ(m->expected.rfind("stock hash ", 0), 0u) << m->expected;
  EXPECT_NE(m->why.find("field 3"), std::string::npos) << m->why;
}

// One coordinate of one move 0.05 mm deeper: another part, another hash.
TEST(StockGolden, ACoordinateMovedFiveHundredthsChangesTheHash) {
  const std::string program = semicircle_program();
  const auto at = program.find("\nG01 Z");
  ASSERT_NE(at, std::string::npos) << program;
  const auto end = program.find_first_of(" \n", at + 7);
  const double z = std::stod(program.substr(at + 6, end - at - 6));
  const std::string moved = program.substr(0, at + 6) + std::to_string(z - 0.05) + program.substr(end);
  const MachineProfile generic = load_machine_profile("generic");
  const StockConfig stock = golden_stock(program, generic);  // the same stock for both
  const GoldenRun a = run_golden(program, stock), b = run_golden(moved, stock);
  const std::string ha = a.trace.substr(a.trace.rfind("stock hash ")),
                    hb = b.trace.substr(b.trace.rfind("stock hash "));
  EXPECT_NE(ha.substr(0, 27), hb.substr(0, 27)) << ha << hb;
}

INSTANTIATE_TEST_SUITE_P(Samples, GoldenTrace, ::testing::ValuesIn(sample_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           std::replace_if(
                               n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
                               '_');
                           return n;
                         });

// Every dialect the profiles emit (arcs, Fanuc NURBS blocks, LinuxCNC G5 /
// G5.2) runs on the controller with that profile, and streaming changes
// nothing in the trace. No goldens here: the G-code of these modes belongs
// to the post-processor's own golden tests.
class DialectTrace : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(DialectTrace, StreamedEqualsDirect) {
  const auto& [machine, output] = GetParam();
  const MachineProfile profile = load_machine_profile(machine);
  ConvertOptions opt;
  opt.output = parse_output_mode(output);
  bool sampled = false;  // a 3D polyline has no arc: look at the samples together
  for (const std::string sample : {"curve-semicircle", "curve-rational-quarter-circle", "curve-cube-3d"}) {
    SCOPED_TRACE(sample);
    const Job job = test::load_sample((fs::path(BEZCAM_SOURCE_DIR) / "samples" / (sample + ".json")).string());
    const std::string program = convert(job, profile, opt).gcode;
    Traced direct(profile);
    const Status ds = direct.ctl->run_program(program);
    EXPECT_EQ(ds.state, State::done) << direct.ctl->alarm_text();
    Traced remote(profile);
    ModbusServer server(*remote.ctl, ServerConfig{});
    server.start();
    stream_program(program, {"127.0.0.1", server.port()});
    ASSERT_TRUE(remote.ctl->wait_final(std::chrono::seconds(10)));
    server.stop();
    const std::string trace = direct.get();
    EXPECT_EQ(remote.get(), trace);
    EXPECT_NE(trace.find("\ndone lines "), std::string::npos);
    sampled = sampled || trace.find("\n  at ") != std::string::npos;
  }
  EXPECT_TRUE(sampled) << "no arc or curve was sampled in " << output << " mode";
}

INSTANTIATE_TEST_SUITE_P(Profiles, DialectTrace,
                         ::testing::Values(std::make_tuple("generic", "arcs"), std::make_tuple("grbl", "arcs"),
                                           std::make_tuple("fanuc", "nurbs"), std::make_tuple("fanuc-g063", "nurbs"),
                                           std::make_tuple("linuxcnc", "nurbs"), std::make_tuple("linuxcnc", "arcs")),
                         [](const auto& i) {
                           std::string n = std::get<0>(i.param) + "_" + std::get<1>(i.param);
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });
