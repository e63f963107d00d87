// Resume from a line over real sockets: the simulated controller runs as a
// child process (`bezcam simulate --listen 127.0.0.1:0`, readiness read from
// its stdout, stopped by its PID), `bezcam stream FILE --from-line N` sends
// the resumed program, and the controller's trace of it is compared with
// its trace of the whole program: the records of the tail, renumbered by
// the plan's offset (the controller numbers the lines it receives from 1),
// equal the full run's records from the start line on, numbers within the
// trace tolerance. The preamble's modal state is compared through the
// controller's status registers: the first lines of the program (up to the
// start line) streamed alone against the preamble streamed alone.
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/gcode/resume.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/sim/trace.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;

namespace {

std::string data_file(const std::string& name) {
  return std::string(BEZCAM_SOURCE_DIR) + "/tests/gcode/data/resume/" + name;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One record of a trace: its first line and its sample lines ("  at ...").
struct Record {
  long first = 0, last = 0;  // the program lines it names; 0 for the header and "done"
  std::string text;          // the record with its label removed
};

// Splits a trace into records, reading each record's line label ("line N",
// "lines A-B", "alarm line N").
std::vector<Record> records(const std::string& trace) {
  std::vector<Record> out;
  std::istringstream in(trace);
  for (std::string l; std::getline(in, l);) {
    if (l.rfind("  ", 0) == 0 && !out.empty()) {
      out.back().text += "\n" + l;
      continue;
    }
    Record r;
    std::string rest = l;
    if (l.rfind("lines ", 0) == 0) {
      r.first = std::stol(l.substr(6));
      r.last = std::stol(l.substr(l.find('-') + 1));
      rest = l.substr(l.find(' ', 6));
    } else if (l.rfind("line ", 0) == 0) {
      r.first = r.last = std::stol(l.substr(5));
      rest = l.substr(l.find(' ', 5));
    }
    r.text = rest;
    out.push_back(r);
  }
  return out;
}

std::string join(const std::vector<Record>& rs, long offset) {
  std::string s;
  for (const auto& r : rs)
    s += (r.first == r.last ? "line " + std::to_string(r.first + offset)
                            : "lines " + std::to_string(r.first + offset) + "-" + std::to_string(r.last + offset)) +
         r.text + "\n";
  return s;
}

struct Case {
  const char* file;
  const char* machine;
  int asked, start;
};

class ResumeOverTheLink : public ::testing::TestWithParam<Case> {};

TEST_P(ResumeOverTheLink, TheTailsTraceEqualsTheFullRunsAndThePreambleRestoresItsState) {
  const Case c = GetParam();
  const std::string file = data_file(c.file);
  const std::string program = read(file);
  const MachineProfile m = load_machine_profile(c.machine);
  const ResumePlan plan = plan_resume(program, &m, c.asked);
  ASSERT_EQ(plan.start_line, c.start) << plan.reason;

  test::TempDir dir;
  const std::string trace = (dir / "trace.txt").string();
  test::SimProcess sim(dir, {"--machine", c.machine, "--trace", trace, "-q"});
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());

  // The whole program, then the resumed one, each with `bezcam stream`.
  auto r = test::run_bezcam({"stream", file, "--to", to, "--progress", "off"}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string full = read(trace);
  r = test::run_bezcam({"stream", file, "--to", to, "--progress", "off", "--from-line", std::to_string(c.asked)}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string resumed = read(trace);
  EXPECT_NE(r.err.find("resuming " + file + " at line " + std::to_string(c.start)), std::string::npos) << r.err;
  if (c.asked != c.start)
    EXPECT_NE(r.err.find("not " + std::to_string(c.asked) + " as asked: line " + std::to_string(c.asked) +
                         " is no place to begin a cut"),
              std::string::npos)
        << r.err;

  // The tail: the full run's records from the start line on (its "done"
  // record apart) against the resumed run's after the preamble.
  std::vector<Record> want, tail, pre;
  for (const auto& rec : records(full))
    if (rec.first >= c.start) want.push_back(rec);
  for (const auto& rec : records(resumed)) {
    if (rec.first > plan.preamble_lines)
      tail.push_back(rec);
    else if (rec.first > 0)
      pre.push_back(rec);
  }
  ASSERT_FALSE(want.empty());
  const auto mismatch = sim::compare_traces(join(want, 0), join(tail, plan.line_offset()));
  EXPECT_FALSE(mismatch) << "line " << mismatch->line << ": expected " << mismatch->expected << ", got "
                         << mismatch->actual << " (" << mismatch->why << ")\n--- full run's tail\n"
                         << join(want, 0) << "--- resumed\n"
                         << resumed;
  // The preamble's own records are on its lines, and it moves: at least
  // the retract and the move over the resume point.
  EXPECT_GE(std::count_if(pre.begin(), pre.end(), [](const Record& x) { return x.text.find(" rapid to ") == 0; }), 2)
      << resumed;
  // Both runs end at the same place, every line executed.
  const std::string done_full = full.substr(full.rfind("done lines ")),
                    done_res = resumed.substr(resumed.rfind("done lines "));
  EXPECT_EQ(done_full.substr(done_full.find(" at ")), done_res.substr(done_res.find(" at ")));
  EXPECT_EQ(std::stol(done_full.substr(11)), std::stol(done_res.substr(11)) + plan.line_offset());

  // `simulate --program FILE --from-line N` runs the same resumed program:
  // the same trace, byte for byte.
  const std::string direct = (dir / "direct.txt").string();
  r = test::run_bezcam({"simulate", "--program", file, "--machine", c.machine, "--from-line", std::to_string(c.asked),
                        "--trace", direct, "-q"},
                       dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(direct), resumed);

  // The preamble's modal state, as the controller reports it: the
  // program's lines before the start line, then the preamble alone.
  const Endpoint ep{"127.0.0.1", sim.port()};
  const auto nl = [&] {
    std::size_t at = 0;
    for (int i = 1; i < c.start; ++i) at = program.find('\n', at) + 1;
    return at;
  }();
  stream_program(program.substr(0, nl), ep);
  const Status head = controller_status(ep, std::chrono::milliseconds(5000)).status;
  stream_program(plan.preamble, ep);
  const Status pst = controller_status(ep, std::chrono::milliseconds(5000)).status;
  ASSERT_EQ(head.state, State::done);
  ASSERT_EQ(pst.state, State::done);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(pst.pos[a], head.pos[a]) << "axis " << a;
  EXPECT_EQ(pst.feed_tenths, head.feed_tenths);
  EXPECT_EQ(pst.spindle_rpm, head.spindle_rpm);
  EXPECT_EQ(pst.flags & 7, head.flags & 7);  // spindle on, inch, incremental
  EXPECT_EQ(pst.tool, head.tool);
  // G00 (0), G01 (1), none: the motions a preamble restores without moving
  if (head.motion <= 1 || head.motion == 0xFFFF) EXPECT_EQ(pst.motion, head.motion);

  EXPECT_EQ(sim.stop(), 0);
}

INSTANTIATE_TEST_SUITE_P(Cases, ResumeOverTheLink,
                         ::testing::Values(Case{"two-tools-fanuc.nc", "fanuc", 25, 22},      // in a G06.2 block
                                           Case{"two-tools-fanuc.nc", "fanuc", 33, 31},      // in the next one
                                           Case{"keyhole-linuxcnc.nc", "linuxcnc", 19, 17},  // in a G5.2 block
                                           Case{"g5-chain-linuxcnc.nc", "linuxcnc", 11, 9},  // in a G5 chain
                                           Case{"two-tools-arcs.nc", "generic", 21, 21},     // at an arc
                                           Case{"two-tools-arcs.nc", "generic", 40, 40},     // after a tool change
                                           Case{"two-tools-fanuc.nc", "fanuc", 53, 52},      // after a tool change
                                           Case{"semicircle-inch.nc", "generic", 17, 17}),   // inch
                         [](const auto& info) {
                           std::string n = std::string(info.param.file) + "_" + std::to_string(info.param.asked);
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

// Refusals of `stream --from-line`: exit 2 naming the file and the line,
// and nothing sent (the controller is still idle).
TEST(ResumeOverTheLink, BadLinesAreRefusedBeforeAnythingIsSent) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--machine", "generic", "-q"});
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  const std::string good = data_file("two-tools-arcs.nc");
  { std::ofstream(dir / "g93.nc") << "G21 G90\nG00 Z5.\nG93\nG00 X1.\nG00 X2.\nM30\n"; }
  struct Bad {
    std::string file, line, place, id;
  };
  const Bad bad[] = {
      {good, "52", good + ": line 52", "resume.no-line"},
      {good, "13", good + ": line 13", "resume.no-code"},  // a comment
      {(dir / "g93.nc").string(), "5", (dir / "g93.nc").string() + ": line 3", "resume.state-unknown"},
  };
  for (const auto& b : bad) {
    const auto r = test::run_bezcam({"stream", b.file, "--to", to, "--progress", "off", "--from-line", b.line}, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("bezcam: error: " + b.place + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("(error id: " + b.id + ")"), std::string::npos) << r.err;
  }
  const Status st = controller_status({"127.0.0.1", sim.port()}, std::chrono::milliseconds(5000)).status;
  EXPECT_EQ(st.state, State::idle);
  EXPECT_EQ(st.session, 0u);
  EXPECT_EQ(sim.stop(), 0);
}

// An alarm in the tail names the file's line, not the resumed program's.
TEST(ResumeOverTheLink, AnAlarmInTheTailNamesTheLineOfTheFile) {
  test::TempDir dir;
  test::SimProcess sim(dir, {"--machine", "fanuc", "-q"});
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  const std::string f = (dir / "far.nc").string();
  {
    // Line 8 leaves fanuc's X travel (-2000..2000 mm); lint would refuse it
    // before sending, so the preflight is off.
    std::ofstream(f) << "G21 G90 G17\nT1 M06\nS1000 M03\nG00 Z5.\nX0. Y0.\nG01 Z-1. F100.\nX10.\nX3000.\nM30\n";
  }
  // The preflight lints the resumed program and names the file's line.
  const auto pf = test::run_bezcam({"stream", f, "--to", to, "--progress", "off", "--from-line", "7"}, dir);
  EXPECT_EQ(pf.status, 2) << pf.err;
  EXPECT_NE(pf.err.find("\n  " + f + ":8: the move reaches X = 3000 mm"), std::string::npos) << pf.err;
  const auto r =
      test::run_bezcam({"stream", f, "--to", to, "--progress", "off", "--no-preflight", "--from-line", "7"}, dir);
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_NE(r.err.find("bezcam: error: " + f + ": line 8: "), std::string::npos) << r.err;
  const auto s = test::run_bezcam({"simulate", "--program", f, "--machine", "fanuc", "--from-line", "7"}, dir);
  EXPECT_EQ(s.status, 2) << s.err;
  EXPECT_NE(s.err.find("bezcam: error: " + f + ": line 8: "), std::string::npos) << s.err;
  EXPECT_EQ(sim.stop(), 0);
}

}  // namespace
