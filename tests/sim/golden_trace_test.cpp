// Golden traces: every sample job is converted in process (machine
// generic, --output lines), executed by `simulate --program`'s path
// (SimController::run_program) and streamed over Modbus TCP on loopback to
// a simulated controller; the two traces must be identical byte for byte,
// and equal to tests/golden/<sample>.generic.trace within kTraceTolerance
// (1e-5 program units on numbers; every other token exactly).
//
// Regenerate after an intended change (then review the diff):
//   BEZCAM_UPDATE_GOLDEN=1 build/link_tests --gtest_filter='GoldenTrace*'
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <mutex>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "bezcam/sim/trace.hpp"
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

// A controller whose trace is collected in memory.
struct Traced {
  std::mutex m;
  std::string text;
  std::unique_ptr<SimController> ctl;
  explicit Traced(const MachineProfile& p) {
    ControllerConfig cfg;
    cfg.profile = p;
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

  // `simulate --program`: the file pushed through the controller directly.
  Traced direct(generic);
  const Status ds = direct.ctl->run_program(program);
  EXPECT_EQ(ds.state, State::done) << direct.ctl->alarm_text();
  const std::string trace = direct.get();

  // Streamed over Modbus TCP to another controller.
  Traced remote(generic);
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
